# The generated scheme tables in doc/tables/, and the figures of doc/figures/
# that subdiv-doc-tables draws, must be what it writes now. Included by
# test/CMakeLists.txt, this file adds the test; run with `cmake -P` (by that
# test) it regenerates the tables and figures into the build tree and
# compares them with the committed ones, file by file (doc/figures/ has
# other figures too: only those the tool writes are compared).
if(NOT CMAKE_SCRIPT_MODE_FILE)
  if(TARGET subdiv-doc-tables)
    add_test(NAME doc_tables
             COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:subdiv-doc-tables>
                     -DFRESH=${CMAKE_CURRENT_BINARY_DIR}/doc_tables
                     -DCOMMITTED=${PROJECT_SOURCE_DIR}/doc/tables
                     -DFRESH_FIGURES=${CMAKE_CURRENT_BINARY_DIR}/doc_figures
                     -DCOMMITTED_FIGURES=${PROJECT_SOURCE_DIR}/doc/figures
                     -P ${CMAKE_CURRENT_LIST_FILE})
    subdiv_timeout(timeout 300)
    set_tests_properties(doc_tables PROPERTIES TIMEOUT ${timeout} LABELS doc)
  endif()
  return()
endif()

cmake_minimum_required(VERSION 3.16)
set(regenerate "regenerate them with: ${EXE} ${COMMITTED} --figures ${COMMITTED_FIGURES}  (from a checkout: build/src/subdiv-doc-tables doc/tables --figures doc/figures), then commit doc/tables and doc/figures")
file(REMOVE_RECURSE "${FRESH}" "${FRESH_FIGURES}")
execute_process(COMMAND "${EXE}" "${FRESH}" --figures "${FRESH_FIGURES}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "subdiv-doc-tables failed (exit ${rc}):\n${out}${err}")
endif()
# appends to `problems` every file of FRESH_DIR that COMMITTED_DIR lacks or
# has otherwise, named with PREFIX
function(compare_with_committed FRESH_DIR COMMITTED_DIR PREFIX)
  file(GLOB names RELATIVE "${FRESH_DIR}" "${FRESH_DIR}/*")
  list(SORT names)
  foreach(name IN LISTS names)
    if(NOT EXISTS "${COMMITTED_DIR}/${name}")
      string(APPEND problems "\n  ${PREFIX}${name}: missing from ${COMMITTED_DIR}")
      continue()
    endif()
    file(READ "${FRESH_DIR}/${name}" a)
    file(READ "${COMMITTED_DIR}/${name}" b)
    if(NOT a STREQUAL b)
      string(APPEND problems "\n  ${PREFIX}${name}: differs from a fresh run (fresh copy: ${FRESH_DIR}/${name})")
    endif()
  endforeach()
  set(problems "${problems}" PARENT_SCOPE)
endfunction()

set(problems "")
compare_with_committed("${FRESH}" "${COMMITTED}" "")
compare_with_committed("${FRESH_FIGURES}" "${COMMITTED_FIGURES}" "figures/")
# every committed table is still generated (doc/figures/ has other figures too)
file(GLOB fresh_files RELATIVE "${FRESH}" "${FRESH}/*")
file(GLOB fresh_figures RELATIVE "${FRESH_FIGURES}" "${FRESH_FIGURES}/*")
file(GLOB committed_files RELATIVE "${COMMITTED}" "${COMMITTED}/*")
foreach(name IN LISTS committed_files)
  if(NOT EXISTS "${FRESH}/${name}")
    string(APPEND problems "\n  ${name}: no longer generated")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "the committed scheme tables or figures are out of date:${problems}\n${regenerate}")
endif()
list(LENGTH fresh_files n)
list(LENGTH fresh_figures m)
message(STATUS "doc/tables: ${n} files up to date; doc/figures: ${m} generated figures up to date")
