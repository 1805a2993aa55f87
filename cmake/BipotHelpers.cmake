# bipot_add_library(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# One CMake target per layer; headers are found as "fem/core/x.hpp" from the source root.
# The target is exported as bipot::<name> and its headers installed beside the sources' paths.
function(bipot_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(bipot_${name} ${ARG_SOURCES})
  add_library(bipot::${name} ALIAS bipot_${name})
  set_property(GLOBAL APPEND PROPERTY BIPOT_LIBRARIES bipot_${name})
  set_target_properties(bipot_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME bipot_${name})
  target_include_directories(bipot_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/bipot>)
  target_compile_features(bipot_${name} PUBLIC cxx_std_17)
  target_compile_options(bipot_${name} PRIVATE ${BIPOT_WARNINGS})
  target_link_libraries(bipot_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  install(TARGETS bipot_${name} EXPORT bipotTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  file(GLOB headers ${CMAKE_CURRENT_SOURCE_DIR}/*.hpp)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/bipot/${rel})
endfunction()

# bipot_add_test(<name> SOURCES ... LIBS ... [RANKS 1 2] [MPI_MAIN] [LABELS ...])
# GoogleTest executable registered with CTest. With RANKS, one CTest entry per rank count
# (name_np1, name_np2) run through mpiexec; MPI_MAIN links the main that starts MPI/Kokkos.
function(bipot_add_test name)
  cmake_parse_arguments(ARG "MPI_MAIN" "" "SOURCES;LIBS;RANKS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${BIPOT_WARNINGS})
  if(ARG_MPI_MAIN)
    target_link_libraries(${name} PRIVATE ${ARG_LIBS} bipot_test_mpi_main GTest::gtest)
  else()
    target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main)
  endif()
  if(ARG_RANKS)
    foreach(np ${ARG_RANKS})
      add_test(NAME ${name}_np${np}
        COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} --allow-run-as-root
                --oversubscribe ${MPIEXEC_PREFLAGS} $<TARGET_FILE:${name}> ${MPIEXEC_POSTFLAGS})
      set_tests_properties(${name}_np${np} PROPERTIES PROCESSORS ${np}
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} LABELS "${ARG_LABELS}")
    endforeach()
  else()
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
      LABELS "${ARG_LABELS}")
  endif()
endfunction()
