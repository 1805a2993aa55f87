# Makes the comparison figure of the three shrunk runs and the RCCM profiles figure, and checks
# that both are non-empty PNG files (the 8-byte PNG signature, and more than a header).
set(curves ${WORK}/three_laws.png)
set(profiles ${WORK}/rccm_profiles.png)
file(REMOVE ${curves} ${profiles})
execute_process(COMMAND ${SCRIPT} curves ${curves} RCCM=${WORK}/rccm_np1/results
                        Coulomb=${WORK}/coulomb_np1/results bonded=${WORK}/bonded_np1/results
                RESULT_VARIABLE rc1)
execute_process(COMMAND ${SCRIPT} profiles ${profiles} ${WORK}/rccm_np1/results
                RESULT_VARIABLE rc2)
if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0)
  message(FATAL_ERROR "plot_pullout.py failed: curves ${rc1}, profiles ${rc2}")
endif()
foreach(png ${curves} ${profiles})
  if(NOT EXISTS ${png})
    message(FATAL_ERROR "${png} was not written")
  endif()
  file(SIZE ${png} size)
  file(READ ${png} magic LIMIT 8 HEX)
  if(size LESS 10000 OR NOT magic STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${png} is not a non-empty PNG (${size} bytes, starts ${magic})")
  endif()
  message(STATUS "${png}: ${size} bytes")
endforeach()
