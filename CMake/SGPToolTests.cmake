# sgp_add_tool_test(NAME n NEEDS --program NAME|--module NAME ... COMMAND ...): add_test for a
# test that needs tools beyond the build. Inside Slicer, whose extension factory runs the tests on
# machines without Chromium, Snakemake, Slurm or pyflakes (issue 33 item 6), it runs through
# Tools/run_if_tools.py and is reported skipped (SKIP_RETURN_CODE 77, one SKIPPED line naming the
# tool) where one is missing. Standalone it is a plain add_test: a missing tool fails it.
function(sgp_add_tool_test)
  cmake_parse_arguments(MY "" "NAME;WORKING_DIRECTORY" "NEEDS;COMMAND" ${ARGN})
  set(command ${MY_COMMAND})
  if(SGP_SLICER_BUILD)
    set(command ${SGP_PYTHON} ${PROJECT_SOURCE_DIR}/Testing/Tools/run_if_tools.py ${MY_NEEDS} -- ${MY_COMMAND})
  endif()
  if(MY_WORKING_DIRECTORY)
    add_test(NAME ${MY_NAME} COMMAND ${command} WORKING_DIRECTORY ${MY_WORKING_DIRECTORY})
  else()
    add_test(NAME ${MY_NAME} COMMAND ${command})
  endif()
  if(SGP_SLICER_BUILD)
    set_tests_properties(${MY_NAME} PROPERTIES SKIP_RETURN_CODE 77)
  endif()
endfunction()
