# Installs the build tree into a scratch prefix, then builds and runs an outside project
# against it with find_package(bipot); then moves the installed tree and runs its bipot, which
# must find its own libraries there (RUNPATH $ORIGIN/../lib, not the configured prefix).
# Arguments: -DBUILD_DIR= -DSOURCE_DIR= -DWORK_DIR= [-DCONSUMER_FLAGS=compile and link flags]
file(REMOVE_RECURSE ${WORK_DIR})
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD_DIR};--prefix;${WORK_DIR}/prefix"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR}/tests/install/consumer;-B;${WORK_DIR}/build;-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix;-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}"
    "${CMAKE_COMMAND};--build;${WORK_DIR}/build"
    "${WORK_DIR}/build/consumer"
    "${CMAKE_COMMAND};-E;rename;${WORK_DIR}/prefix;${WORK_DIR}/moved"
    "${WORK_DIR}/moved/bin/bipot;describe;linear_elastic")
  execute_process(COMMAND ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "step failed (${rc}): ${step}\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "${out}")
