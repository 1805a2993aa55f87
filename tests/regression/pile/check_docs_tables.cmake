# docs/pile_pullout.md must contain the input tables exactly as `pile_pullout describe
# --markdown` prints them from the schemas, so the docs cannot drift from the code.
execute_process(COMMAND ${APP} describe --markdown OUTPUT_VARIABLE tables RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pile_pullout describe --markdown failed (${rc})")
endif()
file(READ ${DOC} doc)
string(FIND "${doc}" "${tables}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${DOC} does not contain the current input tables; paste the output of "
                      "'pile_pullout describe --markdown' into its Input reference section:\n${tables}")
endif()
