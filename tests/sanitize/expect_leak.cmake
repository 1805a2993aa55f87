# Runs COMMAND (its words separated by '|') and expects a non-zero exit code and a
# LeakSanitizer report whose stack names leak_is_reported.cpp.
string(REPLACE "|" ";" cmd "${COMMAND}")
execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "exit code 0: the leak did not fail the run\n${out}\n${err}")
endif()
if(NOT err MATCHES "LeakSanitizer: detected memory leaks.*leak_is_reported.cpp")
  message(FATAL_ERROR "no leak report naming leak_is_reported.cpp:\n${out}\n${err}")
endif()
message(STATUS "ok: exit code ${rc}, leak reported")
