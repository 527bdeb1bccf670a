# The generated scheme tables in doc/tables/ must be what subdiv-doc-tables
# writes now. Included by test/CMakeLists.txt, this file adds the test; run
# with `cmake -P` (by that test) it regenerates the tables into the build
# tree and compares them with the committed ones, file by file.
if(NOT CMAKE_SCRIPT_MODE_FILE)
  if(TARGET subdiv-doc-tables)
    add_test(NAME doc_tables
             COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:subdiv-doc-tables>
                     -DFRESH=${CMAKE_CURRENT_BINARY_DIR}/doc_tables
                     -DCOMMITTED=${PROJECT_SOURCE_DIR}/doc/tables
                     -P ${CMAKE_CURRENT_LIST_FILE})
    set_tests_properties(doc_tables PROPERTIES TIMEOUT 300 LABELS doc)
  endif()
  return()
endif()

cmake_minimum_required(VERSION 3.16)
set(regenerate "regenerate them with: ${EXE} ${COMMITTED}  (from a checkout: build/src/subdiv-doc-tables doc/tables), then commit doc/tables")
file(REMOVE_RECURSE "${FRESH}")
execute_process(COMMAND "${EXE}" "${FRESH}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
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
if(problems)
  message(FATAL_ERROR "the committed scheme tables in ${COMMITTED} are out of date:${problems}\n${regenerate}")
endif()
list(LENGTH fresh_files n)
message(STATUS "doc/tables: ${n} files up to date")
