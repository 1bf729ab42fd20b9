# Runs one example program (PROGRAM) in WORK_DIR and saves what it prints to OUTPUT, for the
# manual's chapters (`@verbinclude NAME.txt`); fails, with its output, when the program does.
# Optional: ARGS, the program's arguments as one string (split as a Unix shell would); SHOW, a
# name for the program: the output then starts with the command line `$ SHOW ARGS`, as typed,
# and says SHOW wherever the program printed its own path;
# APPEND=ON adds to OUTPUT instead of replacing it (a session of several commands).
file(MAKE_DIRECTORY ${WORK_DIR})
separate_arguments(arguments UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${PROGRAM} ${arguments} WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} ${ARGS} failed (${status}):\n${out}${err}")
endif()
if(SHOW)  # and SHOW, not the path of the build, in what it printed (its usage line)
  string(REPLACE "${PROGRAM}" "${SHOW}" out "${out}")
  string(STRIP "${SHOW} ${ARGS}" command_line)
  set(out "$ ${command_line}\n${out}")
endif()
if(APPEND)
  file(APPEND ${OUTPUT} "${out}")
else()
  file(WRITE ${OUTPUT} "${out}")
endif()
