# Included by test/CMakeLists.txt: format_check runs src/scripts/check_format.sh,
# which fails when a tracked *.h or *.cpp file is not formatted as
# .clang-format says (Debian 12's clang-format 14). Outside a git checkout,
# or without that clang-format, the script exits with 77 and the test is
# reported as skipped, with the reason in its output (ctest -V).
find_program(SUBDIV_BASH bash)
if(SUBDIV_BASH)
  add_test(NAME format_check COMMAND ${SUBDIV_BASH} ${PROJECT_SOURCE_DIR}/src/scripts/check_format.sh)
  subdiv_timeout(timeout 120)
  set_tests_properties(format_check PROPERTIES LABELS format SKIP_RETURN_CODE 77 TIMEOUT ${timeout})
endif()
