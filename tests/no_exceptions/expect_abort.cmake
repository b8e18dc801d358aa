# Run as cmake -DPROGRAM=... -DEXPECTED=... -P expect_abort.cmake: runs `PROGRAM --abort`,
# which must end abnormally (abort) after printing EXPECTED on stderr: a throwing entry
# point of mink built without exceptions, given bad input.
foreach(var PROGRAM EXPECTED)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "expect_abort: -D${var}=... is required")
  endif()
endforeach()
execute_process(COMMAND "${PROGRAM}" --abort RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if("${rc}" STREQUAL "0")
  message(FATAL_ERROR "expect_abort: ${PROGRAM} --abort exited normally:\n${out}${err}")
endif()
string(FIND "${err}" "${EXPECTED}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "expect_abort: stderr lacks '${EXPECTED}' (exit: ${rc}):\n${err}")
endif()
message(STATUS "expect_abort: ${PROGRAM} --abort printed '${EXPECTED}' and ended with: ${rc}")
