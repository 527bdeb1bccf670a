# Included by test/CMakeLists.txt.
#
# 1. Every program doc/examples/*.cpp is built and run as a test (CGAL's
#    create_single_source_cgal_program habit): target example_<name>, test
#    example.<name>; an example passes when it exits with 0. Examples that
#    read a bundled input find doc/data through SUBDIV_EXAMPLE_DATA_DIR (ctest
#    runs them in the build tree), or take a file as their first argument.
# 2. install.consumer installs this build tree into a temporary prefix and
#    builds and runs the outside project doc/examples/consumer against that
#    prefix only (find_package(CGALSubdiv) + CGAL::Subdiv).

set(SUBDIV_EXAMPLES_DIR ${PROJECT_SOURCE_DIR}/doc/examples)

file(GLOB SUBDIV_EXAMPLE_SOURCES CONFIGURE_DEPENDS ${SUBDIV_EXAMPLES_DIR}/*.cpp)
foreach(source ${SUBDIV_EXAMPLE_SOURCES})
  get_filename_component(name ${source} NAME_WE)
  add_executable(example_${name} ${source})
  target_link_libraries(example_${name} PRIVATE CGAL::Subdiv subdiv_warnings)
  target_compile_definitions(example_${name} PRIVATE SUBDIV_EXAMPLE_DATA_DIR="${PROJECT_SOURCE_DIR}/doc/data")
  add_test(NAME example.${name} COMMAND example_${name})
  subdiv_timeout(timeout 120)
  set_tests_properties(example.${name} PROPERTIES LABELS example TIMEOUT ${timeout})
endforeach()

add_test(NAME install.consumer
  COMMAND ${CMAKE_COMMAND}
    -DBUILD_DIR=${PROJECT_BINARY_DIR}
    -DPREFIX=${PROJECT_BINARY_DIR}/install-test-prefix
    -DCONSUMER_SOURCE_DIR=${SUBDIV_EXAMPLES_DIR}/consumer
    -DCONSUMER_BINARY_DIR=${PROJECT_BINARY_DIR}/install-test-consumer
    -DGENERATOR=${CMAKE_GENERATOR}
    -DMAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DBUILD_TYPE=$<CONFIG>
    -P ${CMAKE_CURRENT_SOURCE_DIR}/install/install_and_consume.cmake)
# compiling the consumer (CGAL, GMP) takes a while on a loaded machine
subdiv_timeout(timeout 900)
set_tests_properties(install.consumer PROPERTIES LABELS install TIMEOUT ${timeout})
