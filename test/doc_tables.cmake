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
file(GLOB fresh_files RELATIVE "${FRESH}" "${FRESH}/*")
file(GLOB committed_files RELATIVE "${COMMITTED}" "${COMMITTED}/*")
list(SORT fresh_files)
list(SORT committed_files)
set(problems "")
foreach(name IN LISTS fresh_files)
  if(NOT EXISTS "${COMMITTED}/${name}")
    string(APPEND problems "\n  ${name}: missing from ${COMMITTED}")
    continue()
  endif()
  file(READ "${FRESH}/${name}" a)
  file(READ "${COMMITTED}/${name}" b)
  if(NOT a STREQUAL b)
    string(APPEND problems "\n  ${name}: differs from a fresh run (fresh copy: ${FRESH}/${name})")
  endif()
endforeach()
foreach(name IN LISTS committed_files)
  if(NOT EXISTS "${FRESH}/${name}")
    string(APPEND problems "\n  ${name}: no longer generated")
  endif()
endforeach()
file(GLOB fresh_figures RELATIVE "${FRESH_FIGURES}" "${FRESH_FIGURES}/*")
list(SORT fresh_figures)
foreach(name IN LISTS fresh_figures)
  if(NOT EXISTS "${COMMITTED_FIGURES}/${name}")
    string(APPEND problems "\n  figures/${name}: missing from ${COMMITTED_FIGURES}")
    continue()
  endif()
  file(READ "${FRESH_FIGURES}/${name}" a)
  file(READ "${COMMITTED_FIGURES}/${name}" b)
  if(NOT a STREQUAL b)
    string(APPEND problems "\n  figures/${name}: differs from a fresh run (fresh copy: ${FRESH_FIGURES}/${name})")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "the committed scheme tables or figures are out of date:${problems}\n${regenerate}")
endif()
list(LENGTH fresh_files n)
list(LENGTH fresh_figures m)
message(STATUS "doc/tables: ${n} files up to date; doc/figures: ${m} generated figures up to date")
