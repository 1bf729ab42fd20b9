# Fails when Doxygen's warning log is not empty, printing it.
file(READ ${LOG} warnings)
if(NOT warnings STREQUAL "")
  message(FATAL_ERROR "Doxygen warnings:\n${warnings}")
endif()
message(STATUS "The manual has no Doxygen warning")
