# cmake -DBUILD_DIR=... -DPREFIX=... -DCONSUMER_SOURCE_DIR=... -DCONSUMER_BINARY_DIR=...
#       [-DGENERATOR=...] [-DMAKE_PROGRAM=...] [-DCXX_COMPILER=...] [-DBUILD_TYPE=...]
#       -P install_and_consume.cmake
#
# Installs the (built) build tree BUILD_DIR into a fresh PREFIX, then
# configures, builds and runs the consumer project against PREFIX only: no
# package registry, no system-wide CGALSubdiv, no path into the source tree.
# Fails (non-zero exit) at the first step that fails.

cmake_minimum_required(VERSION 3.16)

foreach(var BUILD_DIR PREFIX CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "install_and_consume.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run step)
  message(STATUS "[${step}] ${ARGN}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "[${step}] failed (${result})")
  endif()
endfunction()

file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BINARY_DIR})

# 1. install
set(config_args)
if(BUILD_TYPE)
  set(config_args --config ${BUILD_TYPE})
endif()
run(install ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX} ${config_args})

file(GLOB_RECURSE package_config ${PREFIX}/*/CGALSubdivConfig.cmake)
if(NOT package_config)
  message(FATAL_ERROR "[install] no CGALSubdivConfig.cmake under ${PREFIX}")
endif()
if(NOT EXISTS ${PREFIX}/include/CGAL/Subdiv.h)
  message(FATAL_ERROR "[install] ${PREFIX}/include/CGAL/Subdiv.h is missing")
endif()

# 2. configure the consumer against PREFIX only
set(configure_args
  -S ${CONSUMER_SOURCE_DIR} -B ${CONSUMER_BINARY_DIR}
  -DCMAKE_PREFIX_PATH=${PREFIX}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
if(GENERATOR)
  list(APPEND configure_args -G ${GENERATOR})
endif()
if(MAKE_PROGRAM)
  list(APPEND configure_args -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
endif()
if(CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(BUILD_TYPE)
  list(APPEND configure_args -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
endif()
run(configure ${CMAKE_COMMAND} ${configure_args})

# the package must have come from PREFIX, not from somewhere else on the machine
file(STRINGS ${CONSUMER_BINARY_DIR}/CMakeCache.txt found_dir REGEX "^CGALSubdiv_DIR:")
string(REGEX REPLACE "^CGALSubdiv_DIR:[A-Z]+=" "" found_dir "${found_dir}")
get_filename_component(found_dir "${found_dir}" REALPATH)
get_filename_component(real_prefix "${PREFIX}" REALPATH)
string(FIND "${found_dir}/" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "[configure] CGALSubdiv was found in ${found_dir}, not under ${PREFIX}")
endif()

# 3. build and 4. run
run(build ${CMAKE_COMMAND} --build ${CONSUMER_BINARY_DIR} ${config_args})
find_program(consumer_exe NAMES consumer
  PATHS ${CONSUMER_BINARY_DIR} ${CONSUMER_BINARY_DIR}/${BUILD_TYPE} NO_DEFAULT_PATH)
if(NOT consumer_exe)
  message(FATAL_ERROR "[build] the consumer executable was not built")
endif()
run(run ${consumer_exe})
message(STATUS "installed package consumed successfully from ${PREFIX}")
