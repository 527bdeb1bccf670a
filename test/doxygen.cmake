# Included by test/CMakeLists.txt: the test doxygen builds the reference manual
# (target subdiv_doc, doc/CMakeLists.txt) and fails on any Doxygen warning
# (FAIL_ON_WARNINGS in doc/Doxyfile.in makes Doxygen exit non-zero; the output
# is checked for "warning:" too). Without Doxygen the target does not exist
# and the test exits with 77, which ctest reports as skipped.
if(TARGET subdiv_doc)
  add_test(NAME doxygen COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --target subdiv_doc)
  set_tests_properties(doxygen PROPERTIES FAIL_REGULAR_EXPRESSION "warning: |error: ")
else()
  find_program(SUBDIV_SH sh)
  if(SUBDIV_SH)
    add_test(NAME doxygen COMMAND ${SUBDIV_SH} -c "echo 'doxygen skipped: Doxygen was not found when CMake ran'; exit 77")
  else() # no shell to exit with 77: skipped by its output
    add_test(NAME doxygen COMMAND ${CMAKE_COMMAND} -E echo "doxygen skipped: Doxygen was not found when CMake ran")
    set_tests_properties(doxygen PROPERTIES SKIP_REGULAR_EXPRESSION "doxygen skipped")
  endif()
endif()
subdiv_timeout(timeout 120)
set_tests_properties(doxygen PROPERTIES LABELS doc SKIP_RETURN_CODE 77 TIMEOUT ${timeout})
