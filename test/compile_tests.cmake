# Included by test/CMakeLists.txt: what the headers let a program compile.
# The scheme's own header (loop_subdivision.h) is enough on its own, and a
# mask whose host is not included is refused by a static_assert that names
# the headers (hosts/Host_for.h), not by an incomplete type deep in
# subdivide(). Syntax only: a few seconds each.
get_target_property(subdiv_test_include_dirs CGAL::Subdiv INTERFACE_INCLUDE_DIRECTORIES)
set(subdiv_compile_flags -std=c++17 -fsyntax-only)
foreach(dir ${subdiv_test_include_dirs})
  if(NOT dir MATCHES "\\$<")
    list(APPEND subdiv_compile_flags -I${dir})
  endif()
endforeach()
list(APPEND subdiv_compile_flags -I${PROJECT_SOURCE_DIR}/include)
add_test(NAME compile.loop_subdivision_alone
         COMMAND ${CMAKE_CXX_COMPILER} ${subdiv_compile_flags}
                 ${CMAKE_CURRENT_SOURCE_DIR}/compile/loop_subdivision_alone.cpp)
add_test(NAME compile.host_not_included
         COMMAND ${CMAKE_CXX_COMPILER} ${subdiv_compile_flags}
                 ${CMAKE_CURRENT_SOURCE_DIR}/compile/host_not_included.cpp)
set_tests_properties(compile.host_not_included PROPERTIES
                     PASS_REGULAR_EXPRESSION "the host of this mask's split is not included")
subdiv_timeout(timeout 120)
set_tests_properties(compile.loop_subdivision_alone compile.host_not_included PROPERTIES LABELS compile TIMEOUT ${timeout})
