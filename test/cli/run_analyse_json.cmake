# Runs `cgal-subdiv analyse ... --json`, checks that stdout is one valid JSON
# object (python3 -m json.tool) and runs the named check of analyse_checks.py.
#   cmake -DEXE=... -DPYTHON=... -DWORKDIR=... -DARGS="analyse|--scheme|loop|..." -DCASE=loop3 -P run_analyse_json.cmake
cmake_minimum_required(VERSION 3.16)
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
string(REPLACE "|" ";" argv "${ARGS}")
execute_process(COMMAND "${EXE}" ${argv} RESULT_VARIABLE rc OUTPUT_FILE "${WORKDIR}/out.json" ERROR_VARIABLE err)
file(READ "${WORKDIR}/out.json" out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cgal-subdiv ${ARGS}: exit code ${rc}\n${out}${err}")
endif()
execute_process(COMMAND "${PYTHON}" -m json.tool "${WORKDIR}/out.json" RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE json_err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cgal-subdiv ${ARGS}: not valid JSON: ${json_err}\n${out}")
endif()
execute_process(COMMAND "${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/analyse_checks.py" "${CASE}" "${WORKDIR}/out.json"
                RESULT_VARIABLE rc OUTPUT_VARIABLE check_out ERROR_VARIABLE check_err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cgal-subdiv ${ARGS}:\n${check_out}${check_err}")
endif()
