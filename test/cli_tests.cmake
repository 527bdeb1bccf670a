# Tests of the cgal-subdiv command-line tool (src/cli/): each runs the built
# tool through test/cli/run_cli.cmake, which checks the exit code, stdout,
# stderr, the output file (point count, exact values) and, for failures, that
# no output file was left behind.
if(TARGET cgal-subdiv)

set(SUBDIV_CLI_DIR ${CMAKE_CURRENT_SOURCE_DIR}/cli)
set(SUBDIV_CLI_POLYGON ${PROJECT_SOURCE_DIR}/doc/data/polygon.txt)

# subdiv_cli_test(name ARGS arg... [CONTAINS line...] [RC n] [OUTPUT f] [POINTS n] ...)
# see run_cli.cmake for the checks; @WORK@ is the test's own empty directory.
function(subdiv_cli_test name)
  set(single RC STDOUT_REGEX STDERR_REGEX STDERR_LINES OUTPUT POINTS FIRST_LINE LAST_LINE FILE FILE_REGEX TIMEOUT)
  cmake_parse_arguments(T "" "${single}" "ARGS;CONTAINS" ${ARGN})
  list(JOIN T_ARGS "|" args)
  set(defs -DEXE=$<TARGET_FILE:cgal-subdiv> -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli/${name} "-DARGS=${args}")
  foreach(key IN LISTS single)
    if(DEFINED T_${key} AND NOT key STREQUAL "TIMEOUT")
      list(APPEND defs "-D${key}=${T_${key}}")
    endif()
  endforeach()
  if(T_CONTAINS)
    list(JOIN T_CONTAINS "|" contains)
    list(APPEND defs "-DCONTAINS=${contains}")
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 60)
  endif()
  add_test(NAME cli_${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${SUBDIV_CLI_DIR}/run_cli.cmake)
  set_tests_properties(cli_${name} PROPERTIES TIMEOUT ${T_TIMEOUT} LABELS cli)
endfunction()

# an error: exit code, one line on stderr that matches, no output file
function(subdiv_cli_error name rc regex)
  subdiv_cli_test(${name} RC ${rc} STDERR_REGEX "^cgal-subdiv: error: .*${regex}" STDERR_LINES 1
                  OUTPUT @WORK@/out.txt ${ARGN})
endfunction()

set(square ${SUBDIV_CLI_DIR}/square.txt)
set(out -o @WORK@/out.txt)

# --- help -------------------------------------------------------------------
subdiv_cli_test(help ARGS --help STDOUT_REGEX "curve.*demo.*Exit status")
subdiv_cli_test(curve_help ARGS curve --help
  STDOUT_REGEX "--scheme.*--levels.*--tolerance.*--closed.*--degree.*--a A.*--w W.*--end-rule.*--exact.*--svg.*--report.*Exit status")
subdiv_cli_test(demo_help ARGS demo --help STDOUT_REGEX "--output-dir.*index.md")

# --- every scheme, exact values -----------------------------------------------
# Chaikin on the unit square: 1/4 and 3/4 along every edge
subdiv_cli_test(chaikin_square_exact ARGS curve ${square} ${out} --scheme chaikin --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 FIRST_LINE "1/4 0" CONTAINS "3/4 0" "1 1/4" "1 3/4" "0 1/4")
subdiv_cli_test(chaikin_three_levels ARGS curve ${square} ${out} --scheme chaikin --levels 3 --closed
  OUTPUT @WORK@/out.txt POINTS 32)
# four-point keeps the old points at the even positions; w = 1/16 edge point (1/2, -1/8)
subdiv_cli_test(four_point_keeps_old_points ARGS curve ${square} ${out} --scheme four-point --levels 2 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 16 FIRST_LINE "0 0" CONTAINS "1 0" "1 1" "0 1" "1/2 -1/8")
# w = 0.1 (a decimal, read exactly): (3/5)(p1 + p2) - (1/10)(p0 + p3) = (1/2, -1/5)
subdiv_cli_test(four_point_decimal_w ARGS curve ${square} ${out} --scheme four-point --w 0.1 --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 CONTAINS "1/2 -1/5")
# cubic B-spline: vertex rule (1, 6, 1)/8, edge rule (1, 1)/2
subdiv_cli_test(bspline_cubic_square_exact ARGS curve ${square} ${out} --scheme bspline --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 FIRST_LINE "1/8 1/8" CONTAINS "1/2 0" "7/8 1/8")
# open, shrink: 2n - k points per level (10 -> 15 -> 25 for degree 5)
subdiv_cli_test(bspline_degree5_open ARGS curve ${SUBDIV_CLI_POLYGON} ${out} --scheme bspline --degree 5 --levels 2
  OUTPUT @WORK@/out.txt POINTS 25)
subdiv_cli_test(bspline_open_shrink ARGS curve ${square} ${out} --scheme bspline --levels 1 --exact
  OUTPUT @WORK@/out.txt POINTS 5 FIRST_LINE "1/2 0" LAST_LINE "1/2 1")
# keep-ends: the end points stay
subdiv_cli_test(bspline_open_keep_ends ARGS curve ${square} ${out} --scheme bspline --levels 1 --exact --end-rule keep-ends
  OUTPUT @WORK@/out.txt POINTS 7 FIRST_LINE "0 0" LAST_LINE "0 1" CONTAINS "7/8 1/8")
subdiv_cli_test(corner_cutting_exact ARGS curve ${square} ${out} --scheme corner-cutting --a 1/10 --b 3/5 --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 FIRST_LINE "1/10 0" CONTAINS "3/5 0" "1 1/10")
# Bezier: the midpoint of the cubic (0,0) (1,0) (1,1) (0,1) is (3/4, 1/2); 2^2 * 3 + 1 points
subdiv_cli_test(bezier_open_cubic ARGS curve ${square} ${out} --scheme bezier --levels 2 --exact
  OUTPUT @WORK@/out.txt POINTS 13 FIRST_LINE "0 0" LAST_LINE "0 1" CONTAINS "3/4 1/2")
subdiv_cli_test(bezier_closed_quadratic ARGS curve ${square} ${out} --scheme bezier --degree 2 --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 FIRST_LINE "0 0" CONTAINS "3/4 1/4" "1 1")
subdiv_cli_test(bezier_tolerance ARGS curve ${SUBDIV_CLI_POLYGON} ${out} --scheme bezier --tolerance 1/100
  OUTPUT @WORK@/out.txt FIRST_LINE "0 0" LAST_LINE "1 2.5")

# --- input and output formats -------------------------------------------------
subdiv_cli_test(levels_zero_double ARGS curve ${SUBDIV_CLI_DIR}/numbers.txt ${out} --scheme chaikin --levels 0
  OUTPUT @WORK@/out.txt POINTS 3 FIRST_LINE "0.10000000000000001 0" CONTAINS "5.666666666666667 -0.25")
subdiv_cli_test(levels_zero_exact ARGS curve ${SUBDIV_CLI_DIR}/numbers.txt ${out} --scheme chaikin --levels 0 --exact
  OUTPUT @WORK@/out.txt POINTS 3 FIRST_LINE "1/10 0" CONTAINS "17/3 -1/4")
subdiv_cli_test(points_3d ARGS curve ${SUBDIV_CLI_DIR}/square_3d.txt ${out} --scheme chaikin --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 FIRST_LINE "1/4 0 1")
subdiv_cli_test(polygon_on_one_line ARGS curve ${SUBDIV_CLI_DIR}/square_one_line.dat ${out} --scheme chaikin --levels 1 --closed --exact
  OUTPUT @WORK@/out.txt POINTS 8 FIRST_LINE "1/4 0")
subdiv_cli_test(polygon_with_hole ARGS curve ${SUBDIV_CLI_DIR}/square_with_hole.dat ${out} --scheme chaikin --levels 1 --closed
  OUTPUT @WORK@/out.txt POINTS 8 STDERR_REGEX "note: read the first polygon \\(4 points\\).*ignored 1 hole")
subdiv_cli_test(closing_point_dropped ARGS curve ${SUBDIV_CLI_DIR}/square_repeated.txt ${out} --scheme chaikin --levels 1 --closed
  OUTPUT @WORK@/out.txt POINTS 8 STDERR_REGEX "note: dropped the last point")
subdiv_cli_test(svg_figure ARGS curve ${SUBDIV_CLI_POLYGON} ${out} --scheme chaikin --levels 4 --closed --svg @WORK@/fig.svg
  OUTPUT @WORK@/out.txt POINTS 160 FILE @WORK@/fig.svg FILE_REGEX "^<svg .*<polygon .*curvature.*</svg>\n$")
subdiv_cli_test(report_cubic ARGS curve ${SUBDIV_CLI_POLYGON} ${out} --scheme bspline --levels 4 --closed --report
  OUTPUT @WORK@/out.txt POINTS 160
  STDOUT_REGEX "\\| 4 \\| 160 \\|.*eigenvalues[^\n]*: 1, 0.5 \\(1/2\\), 0.25 \\(1/4\\).*limit mask[^\n]*: 1/6, 2/3, 1/6.*C\\^2.*predicted rate[^\n]*0.25")
subdiv_cli_test(report_bezier ARGS curve ${square} ${out} --scheme bezier --levels 3 --report
  OUTPUT @WORK@/out.txt POINTS 25 STDOUT_REGEX "\\| 3 \\| 25 \\|.*C\\^inf")
subdiv_cli_test(demo ARGS demo --output-dir @WORK@/demo TIMEOUT 30
  STDOUT_REGEX "bspline-5-closed.*four-point-w1_5-closed.*bezier-3-open.*/demo\n$"
  FILE @WORK@/demo/index.md FILE_REGEX "chaikin-closed.svg")

# --- bad input: one line on stderr, exit code, no output file ------------------
subdiv_cli_error(missing_file 1 "cannot read '[^']*missing.txt': No such file"
  ARGS curve missing.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(directory_as_input 1 "is a directory" ARGS curve ${SUBDIV_CLI_DIR} ${out} --scheme chaikin --levels 1)
subdiv_cli_error(empty_file 1 "contains no points" ARGS curve ${SUBDIV_CLI_DIR}/empty.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(unparsable_line 1 "bad_line.txt:3: cannot parse \"1 abc\": \"abc\": not a number"
  ARGS curve ${SUBDIV_CLI_DIR}/bad_line.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(mixed_dimensions 1 "mixed_dimensions.txt:2: .*3 coordinates, but the first point has 2"
  ARGS curve ${SUBDIV_CLI_DIR}/mixed_dimensions.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(zero_denominator 1 "zero_denominator.txt:2: .*zero denominator"
  ARGS curve ${SUBDIV_CLI_DIR}/zero_denominator.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(short_polygon 1 "announces 5 points, but only 6 coordinates follow"
  ARGS curve ${SUBDIV_CLI_DIR}/short_polygon.dat ${out} --scheme chaikin --levels 1)
subdiv_cli_error(too_large_for_double 1 "input point 3: the number 1000.* is too large for a double \\(use --exact\\)"
  ARGS curve ${SUBDIV_CLI_DIR}/huge.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(too_few_points 1 "at least 2 points, got 1"
  ARGS curve ${SUBDIV_CLI_DIR}/one_point.txt ${out} --scheme chaikin --levels 1)
subdiv_cli_error(too_short_after_shrinking 1 "level 2 of 2: .*too short for four-point"
  ARGS curve ${square} ${out} --scheme four-point --levels 2)
subdiv_cli_error(bezier_point_count 1 "closed chain of Bezier segments of degree 3 needs"
  ARGS curve ${square} ${out} --scheme bezier --levels 1 --closed)
subdiv_cli_error(corner_cutting_range 1 "0 < a < b < 1"
  ARGS curve ${square} ${out} --scheme corner-cutting --a 3/4 --b 1/4 --levels 1)
subdiv_cli_error(four_point_range 1 "0 <= w < 1/4" ARGS curve ${square} ${out} --scheme four-point --w 0.25 --levels 1)
subdiv_cli_error(degree_range 1 "degree must be between 1 and 64, got 0"
  ARGS curve ${square} ${out} --scheme bspline --degree 0 --levels 1)
subdiv_cli_error(negative_levels 1 "must not be negative, got -1" ARGS curve ${square} ${out} --scheme chaikin --levels -1)
subdiv_cli_error(too_many_levels 1 "40 levels on 4 points would make more than .* points"
  ARGS curve ${square} ${out} --scheme chaikin --levels 40 --exact)
subdiv_cli_error(bad_tolerance 1 "tolerance must be positive" ARGS curve ${square} ${out} --scheme bezier --tolerance 0)
subdiv_cli_error(unwritable_output 1 "cannot write '[^']*/no/such/dir/out.txt'"
  ARGS curve ${square} -o @WORK@/no/such/dir/out.txt --scheme chaikin --levels 1)
subdiv_cli_error(unknown_scheme 2 "unknown scheme 'loop'" ARGS curve ${square} ${out} --scheme loop --levels 1)
subdiv_cli_error(unknown_option 2 "unknown option '--frobnicate'"
  ARGS curve ${square} ${out} --scheme chaikin --levels 1 --frobnicate)
subdiv_cli_error(missing_output 2 "missing -o OUTPUT" ARGS curve ${square} --scheme chaikin --levels 1)
subdiv_cli_error(missing_levels 2 "missing --levels" ARGS curve ${square} ${out} --scheme chaikin)
subdiv_cli_error(missing_scheme 2 "missing --scheme" ARGS curve ${square} ${out} --levels 1)
subdiv_cli_error(bad_number_option 2 "--w expects a number such as 0.25 or 1/4, got 'abc'"
  ARGS curve ${square} ${out} --scheme four-point --w abc --levels 1)
subdiv_cli_error(option_for_other_scheme 2 "--w applies to four-point only"
  ARGS curve ${square} ${out} --scheme chaikin --w 0.1 --levels 1)
subdiv_cli_error(levels_and_tolerance 2 "--levels or --tolerance, not both"
  ARGS curve ${square} ${out} --scheme bezier --levels 1 --tolerance 0.1)
subdiv_cli_error(unknown_command 2 "unknown command 'surfce'" ARGS surfce ${square} ${out})

endif()
