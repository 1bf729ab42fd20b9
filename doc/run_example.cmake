# Runs one example program (PROGRAM) in WORK_DIR and saves what it prints to OUTPUT, for the
# manual's chapters (`@verbinclude NAME.txt`); fails, with its output, when the program does.
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${PROGRAM} WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed (${status}):\n${out}${err}")
endif()
file(WRITE ${OUTPUT} "${out}")
