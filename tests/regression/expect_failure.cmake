# Runs `bipot run|check INPUT` (or `bipot ARGS`, ARGS separated by '|'), expects exit code
# EXPECT_CODE, the regex EXPECT in stderr, and (optionally) that EXPECT_FILE exists afterwards
# (results already computed are kept).
file(REMOVE_RECURSE results)
if(DEFINED ARGS)
  string(REPLACE "|" ";" cmd "${ARGS}")
elseif(EXPECT_CODE EQUAL 2)
  set(cmd check ${INPUT})
else()
  set(cmd run ${INPUT})
endif()
execute_process(COMMAND ${BIPOT} ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL EXPECT_CODE)
  message(FATAL_ERROR "exit code ${rc}, expected ${EXPECT_CODE}\n${out}\n${err}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT}':\n${err}")
endif()
if(EXPECT_FILE AND NOT EXISTS ${EXPECT_FILE})
  message(FATAL_ERROR "${EXPECT_FILE} is missing: converged results were lost")
endif()
message(STATUS "ok: ${err}")
