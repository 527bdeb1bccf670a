# Runs cgal-subdiv once and checks what it did; used by test/cli_tests.cmake.
#
#   cmake -DEXE=... -DWORKDIR=... -DARGS="curve|in.txt|-o|@WORK@/out.txt" [checks] -P run_cli.cmake
#
# ARGS and CONTAINS are lists separated by '|'; @WORK@ stands for WORKDIR,
# which is emptied first and is the working directory of the run.
# Checks (all optional):
#   RC             expected exit code (default 0)
#   STDOUT_REGEX   regular expression that stdout must match
#   STDERR_REGEX   regular expression that stderr must match
#   STDERR_LINES   number of lines on stderr (an error is exactly one)
#   OUTPUT         file that must exist after a successful run and must not
#                  exist after a failed one (no temporary file either)
#   POINTS         number of lines of OUTPUT
#   CONTAINS       lines that OUTPUT must contain, exactly
#   FIRST_LINE, LAST_LINE   first and last line of OUTPUT
#   FILE, FILE_REGEX        a further file and a regular expression it must match
cmake_minimum_required(VERSION 3.16)

function(fail message)
  message(FATAL_ERROR "cgal-subdiv ${ARGS}\n${message}\n--- stdout:\n${out}\n--- stderr:\n${err}")
endfunction()

file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
string(REPLACE "@WORK@" "${WORKDIR}" ARGS "${ARGS}")
string(REPLACE "|" ";" argv "${ARGS}")
string(REPLACE "@WORK@" "${WORKDIR}" OUTPUT "${OUTPUT}")
string(REPLACE "@WORK@" "${WORKDIR}" FILE "${FILE}")
if(NOT DEFINED RC)
  set(RC 0)
endif()

execute_process(COMMAND "${EXE}" ${argv} WORKING_DIRECTORY "${WORKDIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)

if(NOT rc STREQUAL "${RC}")
  fail("exit code ${rc}, expected ${RC}")
endif()
if(DEFINED STDOUT_REGEX AND NOT out MATCHES "${STDOUT_REGEX}")
  fail("stdout does not match '${STDOUT_REGEX}'")
endif()
if(DEFINED STDERR_REGEX AND NOT err MATCHES "${STDERR_REGEX}")
  fail("stderr does not match '${STDERR_REGEX}'")
endif()
if(DEFINED STDERR_LINES)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines n)
  if(NOT n EQUAL STDERR_LINES)
    fail("${n} lines on stderr, expected ${STDERR_LINES}")
  endif()
endif()

file(GLOB leftovers "${WORKDIR}/*.tmp*")
if(leftovers)
  fail("temporary files left behind: ${leftovers}")
endif()
if(OUTPUT)
  if(NOT rc EQUAL 0)
    if(EXISTS "${OUTPUT}")
      fail("a failed run created ${OUTPUT}")
    endif()
    return()
  endif()
  if(NOT EXISTS "${OUTPUT}")
    fail("${OUTPUT} was not written")
  endif()
  file(STRINGS "${OUTPUT}" lines)
  list(LENGTH lines n)
  if(DEFINED POINTS AND NOT n EQUAL POINTS)
    fail("${OUTPUT} has ${n} points, expected ${POINTS}")
  endif()
  string(REPLACE "|" ";" wanted "${CONTAINS}")
  foreach(line IN LISTS wanted)
    list(FIND lines "${line}" found)
    if(found LESS 0)
      fail("${OUTPUT} has no line '${line}'; it holds: ${lines}")
    endif()
  endforeach()
  if(DEFINED FIRST_LINE)
    list(GET lines 0 first)
    if(NOT first STREQUAL FIRST_LINE)
      fail("first line '${first}', expected '${FIRST_LINE}'")
    endif()
  endif()
  if(DEFINED LAST_LINE)
    list(GET lines -1 last)
    if(NOT last STREQUAL LAST_LINE)
      fail("last line '${last}', expected '${LAST_LINE}'")
    endif()
  endif()
endif()
if(FILE)
  if(NOT EXISTS "${FILE}")
    fail("${FILE} was not written")
  endif()
  file(READ "${FILE}" content)
  if(DEFINED FILE_REGEX AND NOT content MATCHES "${FILE_REGEX}")
    fail("${FILE} does not match '${FILE_REGEX}'")
  endif()
endif()
