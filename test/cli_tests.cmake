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
  set(single RC STDOUT_REGEX STDERR_REGEX STDERR_LINES OUTPUT POINTS VERTICES FACES TEXTURE_POINTS NORMALS FIRST_LINE LAST_LINE FILE FILE_REGEX FILE_NOT_REGEX TIMEOUT)
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
  subdiv_timeout(timeout ${T_TIMEOUT})
  add_test(NAME cli_${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${SUBDIV_CLI_DIR}/run_cli.cmake)
  set_tests_properties(cli_${name} PROPERTIES TIMEOUT ${timeout} LABELS cli)
endfunction()

# an error: exit code, one line on stderr that matches, no output file
function(subdiv_cli_error name rc regex)
  subdiv_cli_test(${name} RC ${rc} STDERR_REGEX "^cgal-subdiv: error: .*${regex}" STDERR_LINES 1
                  OUTPUT @WORK@/out.txt ${ARGN})
endfunction()

set(square ${SUBDIV_CLI_DIR}/square.txt)
set(out -o @WORK@/out.txt)

# --- help -------------------------------------------------------------------
subdiv_cli_test(help ARGS --help STDOUT_REGEX "curve.*surface.*demo.*Exit status")
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
# the demo: every curve scheme, then every surface scheme on the bundled torus (64 triangles)
# and house (40 quads, 4 triangles); Catmull-Clark on the house: 44 -> 172 -> 688 -> 2752 faces
subdiv_cli_test(demo ARGS demo --output-dir @WORK@/demo TIMEOUT 30
  STDOUT_REGEX "bspline-5-closed.*four-point-w1_5-closed.*bezier-3-open.*surface-loop-torus +loop +torus +3 +32 / 64 +2048 / 4096.*surface-interpolating-sqrt3-torus.*surface-catmull-clark-house +catmull-clark +house +3 +44 / 44 +2754 / 2752.*surface-linear-house.*/demo\n$"
  FILE @WORK@/demo/index.md
  FILE_REGEX "chaikin-closed.svg.*## Surfaces.*\\| surface-sqrt3-torus \\| sqrt3 \\| torus \\| 3 \\| 32 / 64 \\| 864 / 1728 \\|.*surface-doo-sabin-house.off")

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
# a result that overflows the doubles is an error, and nothing is written
subdiv_cli_error(curve_non_finite_result 1
  "output point [0-9]+ has a non-finite coordinate: the input coordinates are too large for the scheme's weights in doubles \\(the largest, -1.7e\\+308, is at input point 1\\); scale the points down, or use --exact. Nothing was written"
  ARGS curve ${SUBDIV_CLI_DIR}/hostile/near_max_square.txt ${out} --scheme four-point --levels 1 --closed)
# the figure of a curve at 1e200 holds no NaN (its curvature is computed scaled)
subdiv_cli_test(curve_svg_of_huge_coordinates
  ARGS curve ${SUBDIV_CLI_DIR}/hostile/square_1e200.txt ${out} --scheme chaikin --levels 3 --closed --svg @WORK@/fig.svg
  OUTPUT @WORK@/out.txt FILE @WORK@/fig.svg FILE_REGEX "curvature" FILE_NOT_REGEX "nan|inf")
subdiv_cli_error(curve_tolerance_below_doubles 1 "--tolerance 1e-400 is below the smallest double: take a larger one, or --exact"
  ARGS curve ${square} ${out} --scheme bezier --degree 3 --tolerance 1e-400)
# a tolerance that may need too many points is refused at once (it grew past 1.1 GB)
subdiv_cli_error(curve_tolerance_too_small 1 "the flatness tolerance may need up to [0-9]+ points, more than the max_output_points limit"
  ARGS curve ${square} ${out} --scheme bezier --degree 3 --tolerance 1e-300 TIMEOUT 5)
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

# === cgal-subdiv surface =======================================================
set(tetra ${SUBDIV_CLI_DIR}/tetra.off)
set(cube ${SUBDIV_CLI_DIR}/cube.off)
set(mesh_out -o @WORK@/out.off)

# a test of a scheme the library does not offer yet is reported as skipped
function(subdiv_surface_scheme_test name)
  subdiv_cli_test(${name} ${ARGN})
  set_tests_properties(cli_${name} PROPERTIES SKIP_REGULAR_EXPRESSION "SUBDIV_SCHEME_NOT_AVAILABLE")
endfunction()

subdiv_cli_test(surface_help ARGS surface --help
  STDOUT_REGEX "--scheme.*triangle meshes only.*loop .*loop-warren.*sqrt3.*butterfly.*modified-butterfly.*interpolating-sqrt3.*any polygon mesh.*catmull-clark.*doo-sabin.*linear.*--levels.*--repair.*--verbose.*Exit status")

# --- every scheme: V and F of the result (OFF header) ---------------------------
# tetrahedron (4 V, 6 E, 4 F): 1-to-4 split V' = V + E, F' = 4F; sqrt3 V' = V + F, F' = 3F
foreach(scheme loop loop-warren butterfly modified-butterfly linear)
  subdiv_surface_scheme_test(surface_${scheme}_tetra ARGS surface ${tetra} ${mesh_out} --scheme ${scheme} --levels 2
    OUTPUT @WORK@/out.off VERTICES 34 FACES 64
    STDOUT_REGEX "^${scheme}, 2 levels: 4 V, 6 E, 4 F -> 34 V, 96 E, 64 F in [0-9.]+ s; wrote [^\n]*out.off\n$")
endforeach()
foreach(scheme sqrt3 interpolating-sqrt3)
  subdiv_surface_scheme_test(surface_${scheme}_tetra ARGS surface ${tetra} ${mesh_out} --scheme ${scheme} --levels 2
    OUTPUT @WORK@/out.off VERTICES 20 FACES 36 STDOUT_REGEX "-> 20 V, 54 E, 36 F")
endforeach()
# Catmull-Clark: V' = V + E + F, F' = sum of face sizes; Doo-Sabin: V' = sum of face sizes, F' = F + E + V
subdiv_surface_scheme_test(surface_catmull_clark_tetra ARGS surface ${tetra} ${mesh_out} --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.off VERTICES 14 FACES 12)
subdiv_surface_scheme_test(surface_catmull_clark_cube ARGS surface ${cube} ${mesh_out} --scheme catmull-clark --levels 2
  OUTPUT @WORK@/out.off VERTICES 98 FACES 96)
subdiv_surface_scheme_test(surface_doo_sabin_tetra ARGS surface ${tetra} ${mesh_out} --scheme doo-sabin --levels 1
  OUTPUT @WORK@/out.off VERTICES 12 FACES 14)
subdiv_surface_scheme_test(surface_doo_sabin_cube ARGS surface ${cube} ${mesh_out} --scheme doo-sabin --levels 2
  OUTPUT @WORK@/out.off VERTICES 96 FACES 98)
# linear on quads: the quad split
subdiv_surface_scheme_test(surface_linear_cube ARGS surface ${cube} ${mesh_out} --scheme linear --levels 1
  OUTPUT @WORK@/out.off VERTICES 26 FACES 24)
subdiv_surface_scheme_test(surface_levels_zero ARGS surface ${cube} ${mesh_out} --scheme catmull-clark --levels 0
  OUTPUT @WORK@/out.off VERTICES 8 FACES 6)

# --- formats ---------------------------------------------------------------------
subdiv_cli_test(surface_obj ARGS surface ${SUBDIV_CLI_DIR}/tetra.obj -o @WORK@/out.obj --scheme loop --levels 1
  OUTPUT @WORK@/out.obj VERTICES 10 FACES 16)
subdiv_cli_test(surface_ply ARGS surface ${SUBDIV_CLI_DIR}/tetra.ply -o @WORK@/out.ply --scheme loop --levels 1
  OUTPUT @WORK@/out.ply VERTICES 10 FACES 16)
# STL: the shared corners of the facets become one vertex each
subdiv_cli_test(surface_stl ARGS surface ${SUBDIV_CLI_DIR}/tetra.stl -o @WORK@/out.stl --scheme loop --levels 1
  OUTPUT @WORK@/out.stl FACES 16 STDOUT_REGEX "4 V, 6 E, 4 F -> 10 V, 24 E, 16 F")
subdiv_cli_test(surface_off_to_upper_case_obj ARGS surface ${tetra} -o @WORK@/out.OBJ --scheme loop --levels 1
  OUTPUT @WORK@/out.OBJ VERTICES 10 FACES 16)
# 17 significant digits: the double nearest 0.1 is written so that it reads back the same
subdiv_cli_test(surface_full_precision ARGS surface ${SUBDIV_CLI_DIR}/tetra_decimal.off ${mesh_out} --scheme loop --levels 0
  OUTPUT @WORK@/out.off CONTAINS "0.10000000000000001 0.20000000000000001 0.29999999999999999")
subdiv_cli_test(surface_verbose ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 2 --verbose
  OUTPUT @WORK@/out.off STDERR_REGEX "loop level 1 of 2: 10 V, 24 E, 16 F .*loop level 2 of 2: 34 V, 96 E, 64 F")
subdiv_cli_test(surface_repair ARGS surface ${SUBDIV_CLI_DIR}/three_faces_on_an_edge.off ${mesh_out} --scheme loop --levels 1 --repair
  OUTPUT @WORK@/out.off FACES 12 STDERR_REGEX "note: read .* as a repaired, oriented polygon soup")

# --- bad input: one line on stderr, exit code, no output file --------------------
function(subdiv_surface_error name rc regex)
  subdiv_cli_test(${name} RC ${rc} STDERR_REGEX "^cgal-subdiv: error: .*${regex}" STDERR_LINES 1
                  OUTPUT @WORK@/out.off ${ARGN})
endfunction()
subdiv_surface_error(surface_missing_file 1 "cannot read '[^']*missing.off': no such file"
  ARGS surface missing.off ${mesh_out} --scheme loop --levels 1)
subdiv_surface_error(surface_unknown_input_extension 2 "INPUT '[^']*square.txt': unknown format '.txt' \\(expected .off, .obj, .ply or .stl\\)"
  ARGS surface ${square} ${mesh_out} --scheme loop --levels 1)
subdiv_surface_error(surface_unknown_output_extension 2 "OUTPUT '[^']*out.vtk': unknown format '.vtk'"
  ARGS surface ${tetra} -o @WORK@/out.vtk --scheme loop --levels 1)
# the counts promise more than the 17 bytes after them can hold: refused before reading on
subdiv_surface_error(surface_garbage 1 "'[^']*garbage.off' line 2: header says 4 vertices, but the file has only 17 bytes after the header"
  ARGS surface ${SUBDIV_CLI_DIR}/garbage.off ${mesh_out} --scheme loop --levels 1)
subdiv_surface_error(surface_not_obj 1 "'[^']*not_a_mesh.obj' holds no faces"
  ARGS surface ${SUBDIV_CLI_DIR}/not_a_mesh.obj ${mesh_out} --scheme loop --levels 1)
subdiv_surface_error(surface_non_manifold_edge 1
  "'[^']*three_faces_on_an_edge.off' is not a manifold polygon mesh: the edge from vertex 0 \\(0 0 0\\) to vertex 1 \\(1 0 0\\) belongs to 3 faces \\(--split-non-manifold refines it as OpenSubdiv does, --repair makes a manifold mesh of it\\)"
  ARGS surface ${SUBDIV_CLI_DIR}/three_faces_on_an_edge.off ${mesh_out} --scheme loop --levels 1)
subdiv_surface_error(surface_non_manifold_vertex 1 "vertex 0 \\(0 0 0\\) is non-manifold \\(its faces form 2 separate fans\\)"
  ARGS surface ${SUBDIV_CLI_DIR}/bowtie.off ${mesh_out} --scheme loop --levels 1)
subdiv_surface_error(surface_quads_for_loop 1 "Loop.* needs a mesh whose faces all have 3 vertices; face 0 has 4"
  ARGS surface ${cube} ${mesh_out} --scheme loop --levels 1)
foreach(scheme butterfly sqrt3)
  subdiv_surface_error(surface_quads_for_${scheme} 1 "needs a mesh whose faces all have 3 vertices; face 0 has 4"
    ARGS surface ${cube} ${mesh_out} --scheme ${scheme} --levels 1)
  set_tests_properties(cli_surface_quads_for_${scheme} PROPERTIES SKIP_REGULAR_EXPRESSION "SUBDIV_SCHEME_NOT_AVAILABLE")
endforeach()
subdiv_surface_error(surface_negative_levels 1 "the number of levels must not be negative, got -1"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels -1)
subdiv_surface_error(surface_huge_levels 1
  "loop: 40 levels on 4 faces would make about 10\\^24 faces, about 10\\^26 bytes at 90 bytes per face, more than the memory limit of [0-9.]+ GB \\(this machine's memory\\); --max-memory raises it"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 40 TIMEOUT 10)
# the estimate takes constant time, whatever the level count
subdiv_surface_error(surface_billion_levels 1 "loop: 999999999 levels on 4 faces would make about 10\\^602059991 faces"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 999999999 TIMEOUT 5)
# --max-memory: 12 levels of Loop on the tetrahedron make 67108864 faces, 6.0 GB at 90 B a face
subdiv_surface_error(surface_max_memory 1
  "loop: 12 levels on 4 faces would make 67108864 faces, about 6.0 GB at 90 bytes per face, more than the memory limit of 1 MB; --max-memory raises it"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 12 --max-memory 1M)
subdiv_cli_test(surface_max_memory_raised ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 3 --max-memory 2GiB
  OUTPUT @WORK@/out.off FACES 256)
subdiv_surface_error(surface_max_memory_not_a_size 2 "--max-memory expects a size such as 8G, 512MB or 2GiB, got '1X'"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --max-memory 1X)
subdiv_surface_error(surface_max_memory_zero 2 "--max-memory must be a positive size, got '0'"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --max-memory 0)
# --- hostile files (test/cli/hostile/): the checked reader refuses them with
# the file, the line or byte and the problem, before CGAL sees anything; each
# of these crashed or exhausted memory inside CGAL's readers before
set(hostile ${SUBDIV_CLI_DIR}/hostile)
foreach(case
    "binary_header_ascii_body.off|byte 23: header says 857747744 vertices, but the file has only 20 bytes after the header"
    "huge_coordinate.off|line 4: vertex 1 has the coordinate 1e400, which is not a finite number"
    "huge_list.ply|line 13: face 0 says it has 2147483647 vertices, but only 7 bytes are left"
    "index_far_out.ply|line 13: face 0 has vertex index 1000000, but the file has 3 vertices \\(0 to 2\\)"
    "negative_index.ply|line 13: face 0 has vertex index -1, but the file has 3 vertices \\(0 to 2\\)"
    "property_before_element.ply|line 3: a property line before any element line"
    "index_past_end.obj|line 4: face 0 has vertex index 4, but the file has 3 vertices \\(1 to 3\\)"
    "index_zero.obj|line 4: face 0 has vertex index 0 \\(OBJ counts vertices from 1, or from -1 backwards\\)"
    "relative_index_out.obj|line 4: face 0 has vertex index -4, but only 3 vertices precede it \\(-1 to -3\\)"
    # malformed vn lines and references
    "normal_two_values.obj|line 5: normal 2 has 2 values \\(expected x y z\\)"
    "normal_not_a_number.obj|line 4: normal 1: expected a number, found 'up'"
    "normal_not_finite.obj|line 4: normal 1 has the value 1e999, which is not a finite number"
    "normal_index_zero.obj|line 5: face 0 has normal index 0 \\(OBJ counts normals from 1, or from -1 backwards\\)"
    "normal_index_past_end.obj|line 6: face 1 has normal index 2, but the file has 1 normal \\(1 to 1\\)"
    "normal_relative_index_out.obj|line 5: face 0 has normal index -2, but only 1 normal precedes it \\(-1 to -1\\)"
    "normal_missing.obj|line 5: face 0: corner '2' has no normal \\(vn\\), but corner '1//1' has one")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 file)
  list(GET parts 1 regex)
  string(REGEX REPLACE "\\.[a-z]+$" "" stem ${file})
  subdiv_surface_error(surface_hostile_${stem} 1 "'[^']*${file}' ${regex}"
    ARGS surface ${hostile}/${file} ${mesh_out} --scheme loop --levels 1 TIMEOUT 10)
endforeach()
# --repair sees only the checked soup too (a negative PLY index aborted it, an
# OBJ index past the end failed a Boost assertion)
subdiv_surface_error(surface_hostile_repair_negative_index 1 "'[^']*negative_index.ply' line 13: face 0 has vertex index -1"
  ARGS surface ${hostile}/negative_index.ply ${mesh_out} --scheme loop --levels 1 --repair)
subdiv_surface_error(surface_hostile_repair_index_past_end 1 "'[^']*index_past_end.obj' line 4: face 0 has vertex index 4"
  ARGS surface ${hostile}/index_past_end.obj ${mesh_out} --scheme loop --levels 1 --repair)
# valid variants that crashed CGAL's reader: read, what is ignored is noted
subdiv_cli_test(surface_stoff ARGS surface ${hostile}/stoff.off ${mesh_out} --scheme loop --levels 1
  OUTPUT @WORK@/out.off FACES 4 STDERR_REGEX "^cgal-subdiv: note: ignored the vertex texture coordinates of '[^']*stoff.off'\n$")
subdiv_cli_test(surface_coff_short_colour ARGS surface ${hostile}/coff_short_colour.off ${mesh_out} --scheme loop --levels 1
  OUTPUT @WORK@/out.off FACES 4 FIRST_LINE OFF
  STDERR_REGEX "^cgal-subdiv: note: ignored the vertex colours of '[^']*coff_short_colour.off': vertex 0 \\(line 3\\) has 2 colour components \\(expected red green blue \\[alpha\\]\\)\n$")
# unreferenced vertices are dropped, with a note (OpenSubdiv accepts them)
subdiv_cli_test(surface_unreferenced_vertices ARGS surface ${hostile}/unreferenced.off ${mesh_out} --scheme loop --levels 1
  OUTPUT @WORK@/out.off VERTICES 6 FACES 4
  STDERR_REGEX "note: dropped the 2 vertices of '[^']*unreferenced.off' that no face uses \\(of 5\\)")
# the crease tag is read (on a border edge, which is sharp anyway); the vt
# lines are carried to an OBJ OUTPUT, and left out of an OFF one with a note
subdiv_cli_test(surface_obj_uv_and_tags ARGS surface ${hostile}/uv_and_tags.obj ${mesh_out} --scheme loop --levels 1
  OUTPUT @WORK@/out.off FACES 4
  STDERR_REGEX "^cgal-subdiv: note: left the texture coordinates \\(vt\\) of '[^']*uv_and_tags.obj' out: OUTPUT '[^']*out.off' is OFF, which holds none \\(write .obj to keep them\\)\n$")

# --- texture coordinates with seams (face-varying data, doc/provenance.md) ------
# two quads, each its own texture island, so that the edge between them is a
# seam: refined as two separate quads, each island keeps its corners (corners
# plus1, the default) and gets its edge midpoints and its centre
set(islands ${SUBDIV_CLI_DIR}/two_islands.obj)
subdiv_cli_test(surface_uv_seam ARGS surface ${islands} -o @WORK@/out.obj --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.obj VERTICES 15 FACES 8 TEXTURE_POINTS 18
  CONTAINS "vt 0 0" "vt 0.5 0" "vt 0.5 0.5" "vt 2 0" "vt 2.5 0.5" "t facevaryinginterpolateboundary 1/0/0 2"
  FILE @WORK@/out.obj FILE_NOT_REGEX "vt 0.125 0.125")
# two levels: 5 x 5 texture points per island
subdiv_cli_test(surface_uv_seam_two_levels ARGS surface ${islands} -o @WORK@/out.obj --scheme catmull-clark --levels 2
  OUTPUT @WORK@/out.obj VERTICES 45 FACES 32 TEXTURE_POINTS 50)
# none: smooth everywhere, the corner of an island follows the border rule
# (6 (0,0) + (1,0) + (0,1)) / 8
subdiv_cli_test(surface_uv_fvar_none ARGS surface ${islands} -o @WORK@/out.obj --scheme catmull-clark --levels 1
  --fvar none OUTPUT @WORK@/out.obj TEXTURE_POINTS 18
  CONTAINS "vt 0.125 0.125" "vt 2.875 0.875" "vt 0.5 0.5" "t facevaryinginterpolateboundary 1/0/0 0")
# the mode of the file's tag, and --fvar over it
subdiv_cli_test(surface_uv_fvar_tag ARGS surface ${SUBDIV_CLI_DIR}/two_islands_smooth.obj -o @WORK@/out.obj
  --scheme catmull-clark --levels 1 OUTPUT @WORK@/out.obj CONTAINS "vt 0.125 0.125" "t facevaryinginterpolateboundary 1/0/0 0")
subdiv_cli_test(surface_uv_fvar_over_tag ARGS surface ${SUBDIV_CLI_DIR}/two_islands_smooth.obj -o @WORK@/out.obj
  --scheme catmull-clark --levels 1 --fvar all OUTPUT @WORK@/out.obj CONTAINS "vt 0 0" "t facevaryinginterpolateboundary 1/0/0 5"
  FILE @WORK@/out.obj FILE_NOT_REGEX "vt 0.125 0.125")
# t facevaryingpropagatecorners 1 makes corners plus1 corners plus2, as in Hbr
subdiv_cli_test(surface_uv_propagate_corners ARGS surface ${SUBDIV_CLI_DIR}/two_islands_propagate.obj -o @WORK@/out.obj
  --scheme catmull-clark --levels 1 OUTPUT @WORK@/out.obj CONTAINS "t facevaryinginterpolateboundary 1/0/0 3")
# Loop and the linear split carry them too; 0 levels write them back as read
subdiv_cli_test(surface_uv_loop ARGS surface ${hostile}/uv_and_tags.obj -o @WORK@/out.obj --scheme loop --levels 1
  OUTPUT @WORK@/out.obj VERTICES 6 FACES 4 TEXTURE_POINTS 6 CONTAINS "vt 0 1" "vt 0.5 0.5" "f 1/1 4/2 6/3")
subdiv_cli_test(surface_uv_linear ARGS surface ${islands} -o @WORK@/out.obj --scheme linear --levels 1
  OUTPUT @WORK@/out.obj TEXTURE_POINTS 18 CONTAINS "vt 2.5 0.5" "vt 3 0.5")
subdiv_cli_test(surface_uv_zero_levels ARGS surface ${islands} -o @WORK@/out.obj --scheme catmull-clark --levels 0
  OUTPUT @WORK@/out.obj TEXTURE_POINTS 8 CONTAINS "f 1/1 2/2 5/3 4/4" "f 2/5 3/6 6/7 5/8" "vt 2 1")
# the schemes that make faces across the old edges carry them without seams
# only: with a seam they are left out, with a note naming it
subdiv_cli_test(surface_uv_doo_sabin ARGS surface ${islands} -o @WORK@/out.obj --scheme doo-sabin --levels 1
  OUTPUT @WORK@/out.obj TEXTURE_POINTS 0
  STDERR_REGEX "note: left the texture coordinates \\(vt\\) of '[^']*two_islands.obj' out: --scheme doo-sabin carries them without seams only \\(it makes faces across the old edges; loop, loop-warren, catmull-clark, linear and the butterflies carry seams\\), and vertex 2 has different ones in faces [01] and [01]\n$")
# one island: one vt per new vertex, the corner of the island kept and the
# border corner at Chaikin's point (3 (1,0) + (0,0)) / 4, as the points are
set(one_island ${SUBDIV_CLI_DIR}/two_quads_one_island.obj)
subdiv_cli_test(surface_uv_doo_sabin_one_island ARGS surface ${one_island} -o @WORK@/out.obj --scheme doo-sabin
  --levels 1 OUTPUT @WORK@/out.obj VERTICES 8 TEXTURE_POINTS 8 CONTAINS "vt 0 0" "vt 0.75 0" STDERR_REGEX "^$")
# all: the corner at (0,0) gets the centre of its quad, (1/4, 1/4)
subdiv_cli_test(surface_uv_doo_sabin_one_island_all ARGS surface ${one_island} -o @WORK@/out.obj --scheme doo-sabin
  --levels 1 --fvar all OUTPUT @WORK@/out.obj TEXTURE_POINTS 8 CONTAINS "vt 0.25 0.25"
  FILE @WORK@/out.obj FILE_NOT_REGEX "vt 0 0\n")
subdiv_cli_test(surface_uv_no_texture ARGS surface ${SUBDIV_CLI_DIR}/tetra.obj -o @WORK@/out.obj --scheme loop --levels 1
  --fvar all OUTPUT @WORK@/out.obj TEXTURE_POINTS 0 STDERR_REGEX "note: --fvar: '[^']*tetra.obj' has no texture coordinates")
subdiv_cli_error(surface_uv_bad_fvar 2 "--fvar is none, corners-only, corners-plus1, corners-plus2, boundaries or all, not 'linear'"
  ARGS surface ${islands} -o @WORK@/out.obj --scheme loop --levels 1 --fvar linear)
subdiv_cli_error(surface_uv_bad_fvar_tag 1 "fvar_mode_out_of_range.obj' line 19: tag 'facevaryinginterpolateboundary': is 0 \\(none\\), .* not 7"
  ARGS surface ${hostile}/fvar_mode_out_of_range.obj -o @WORK@/out.obj --scheme catmull-clark --levels 1)

# --- normals (OBJ vn), vertex data carried with the weights of the points ----
# flat inputs whose every normal is (0, 0, 1): every refined normal is too,
# one vn per vertex, numbered as the vertex, with the texture coordinates
set(flat_quads_normals ${SUBDIV_CLI_DIR}/flat_quads_normals.obj)
set(not_up "vn ([^0]|0 [^0]|0 0 [^1]|0 0 1[.e0-9])") # a vn line other than "vn 0 0 1"
subdiv_cli_test(surface_normals_catmull_clark ARGS surface ${flat_quads_normals} -o @WORK@/out.obj
  --scheme catmull-clark --levels 1 OUTPUT @WORK@/out.obj VERTICES 15 FACES 8 TEXTURE_POINTS 18 NORMALS 15
  CONTAINS "vn 0 0 1" "f 1/1/1 7/2/7 14/3/14 10/4/10" STDERR_REGEX "^$" FILE @WORK@/out.obj FILE_NOT_REGEX "${not_up}")
subdiv_cli_test(surface_normals_loop ARGS surface ${SUBDIV_CLI_DIR}/flat_triangles_normals.obj -o @WORK@/out.obj
  --scheme loop --levels 1 OUTPUT @WORK@/out.obj VERTICES 13 FACES 16 TEXTURE_POINTS 13 NORMALS 13
  CONTAINS "vn 0 0 1" "f 1/1/1 6/2/6 8/3/8" STDERR_REGEX "^$" FILE @WORK@/out.obj FILE_NOT_REGEX "${not_up}")
# without vt: f v//vn; the schemes that make faces across the old edges
# carry the normals too (vertex data), not the texture coordinates
subdiv_cli_test(surface_normals_doo_sabin ARGS surface ${flat_quads_normals} -o @WORK@/out.obj
  --scheme doo-sabin --levels 1 OUTPUT @WORK@/out.obj TEXTURE_POINTS 0 NORMALS 8 CONTAINS "vn 0 0 1" "f 2//2 3//3 4//4 1//1"
  FILE @WORK@/out.obj FILE_NOT_REGEX "${not_up}")
# split normals are averaged; where they cancel out, the surface's normal
subdiv_cli_test(surface_normals_split ARGS surface ${SUBDIV_CLI_DIR}/split_normals.obj -o @WORK@/out.obj
  --scheme loop --levels 0 OUTPUT @WORK@/out.obj
  CONTAINS "vn 0 0 1" "vn 0 0 -1" "f 1//1 2//2 3//3" "f 1//1 3//3 4//4"
  NORMALS 4
  STDERR_REGEX "^cgal-subdiv: note: averaged the normals \\(vn\\) of '[^']*split_normals.obj' at 2 vertices whose corners reference different ones \\(split normals\\)[^\n]*\ncgal-subdiv: note: 2 vertices of '[^']*out.obj' got the normal of the surface there: the normals \\(vn\\) carried to them summed to zero\n$")
# other formats hold none: a note
subdiv_cli_test(surface_normals_to_off ARGS surface ${flat_quads_normals} ${mesh_out} --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.off FACES 8
  STDERR_REGEX "^cgal-subdiv: note: left the texture coordinates \\(vt\\) of [^\n]*\ncgal-subdiv: note: left the normals \\(vn\\) of '[^']*flat_quads_normals.obj' out: OUTPUT '[^']*out.off' is OFF, which holds none \\(write .obj to keep them\\)\n$")
subdiv_cli_test(surface_normals_displace ARGS surface ${SUBDIV_CLI_DIR}/split_normals.obj -o @WORK@/out.obj
  --scheme loop --levels 1 --displace ${SUBDIV_CLI_DIR}/tetra_heights.txt OUTPUT @WORK@/out.obj
  STDERR_REGEX "note: left the normals \\(vn\\) of '[^']*split_normals.obj' out: --displace does not carry them yet"
  FILE @WORK@/out.obj FILE_NOT_REGEX "vn ")

# --- vertex colours (COFF, PLY), carried with the weights of the points ------
# the square's colour is (255 x, 255 y, 0): every new vertex keeps the colour
# of its position, rounded (128 for 127.5, 32 for 31.875)
set(coloured ${SUBDIV_CLI_DIR}/coloured_square)
subdiv_cli_test(surface_colours_off ARGS surface ${coloured}.off -o @WORK@/out.off --scheme linear --levels 1
  OUTPUT @WORK@/out.off VERTICES 9 FIRST_LINE COFF CONTAINS "0.5 0.5 0  128 128 0" "1 0.5 0  255 128 0" "0 0 0  0 0 0")
subdiv_cli_test(surface_colours_reals ARGS surface ${coloured}_reals.off -o @WORK@/out.off --scheme linear --levels 1
  OUTPUT @WORK@/out.off FIRST_LINE COFF CONTAINS "0.5 0.5 0  128 128 0" "0.5 1 0  128 255 0")
subdiv_cli_test(surface_colours_ply ARGS surface ${coloured}.ply -o @WORK@/out.ply --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.ply VERTICES 9 FILE @WORK@/out.ply
  FILE_REGEX "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n.*\n0.125 0.125 0 32 32 0 255 ?\n0.875 0.125 0 223 32 0 255 ?\n")
subdiv_cli_test(surface_colours_off_to_binary_ply ARGS surface ${coloured}.off -o @WORK@/out.ply --scheme catmull-clark
  --levels 2 --binary OUTPUT @WORK@/out.ply VERTICES 25 FILE @WORK@/out.ply FILE_REGEX "property uchar red\n")
# the copies of a split vertex keep its colour
subdiv_cli_test(surface_colours_split ARGS surface ${SUBDIV_CLI_DIR}/coloured_three_faces_on_an_edge.off
  -o @WORK@/out.off --scheme loop --levels 0 --split-non-manifold OUTPUT @WORK@/out.off VERTICES 9
  CONTAINS "0 0 0  10 20 30" "1 0 0  40 50 60" "0.5 0 1  130 140 150" FILE @WORK@/out.off
  FILE_REGEX "0 0 0  10 20 30\n.*0 0 0  10 20 30\n.*0 0 0  10 20 30\n" FILE_NOT_REGEX "0 0 0  [^1]")
# --limit moves the points, not the colours of the refined mesh
subdiv_cli_test(surface_colours_limit ARGS surface ${coloured}.off -o @WORK@/out.off --scheme catmull-clark --levels 1
  --limit OUTPUT @WORK@/out.off CONTAINS "0.5 0.5 0  128 128 0" "0.5 0.041666666666666664 0  128 0 0")
# outputs and options that cannot carry them leave them out, with a note
subdiv_cli_test(surface_colours_to_obj ARGS surface ${coloured}.off -o @WORK@/out.obj --scheme linear --levels 1
  OUTPUT @WORK@/out.obj VERTICES 9
  STDERR_REGEX "^cgal-subdiv: note: left the vertex colours of '[^']*coloured_square.off' out: OUTPUT '[^']*out.obj' is OBJ, which holds none \\(write .off or .ply to keep them\\)\n$")
subdiv_cli_test(surface_colours_displace ARGS surface ${coloured}.off -o @WORK@/out.off --scheme catmull-clark
  --levels 1 --displace ${SUBDIV_CLI_DIR}/tetra_heights.txt OUTPUT @WORK@/out.off FIRST_LINE OFF
  STDERR_REGEX "note: left the vertex colours of '[^']*coloured_square.off' out: --displace does not carry them yet")
subdiv_cli_test(surface_colours_repair ARGS surface ${coloured}.off -o @WORK@/out.off --scheme linear --levels 1
  --repair OUTPUT @WORK@/out.off FIRST_LINE OFF
  STDERR_REGEX "note: ignored the vertex colours of '[^']*coloured_square.off': --repair merges and splits vertices")
subdiv_cli_error(surface_colour_out_of_range 1
  "colour_out_of_range.off' line 4: vertex 1: the colour component '256' is out of range \\(integers from 0 to 255, or reals from 0 to 1\\)"
  ARGS surface ${hostile}/colour_out_of_range.off -o @WORK@/out.off --scheme loop --levels 1)

# --- OpenSubdiv's OBJ tags (doc/sharp_features.md) ------------------------------
# read, refined with, and written back for the children: of the cube's 12
# creases (catmark_cube_creases1), the 11 of sharpness 5 become 22 halves of
# sharpness 4, the one of 0.1 is smooth one level down
subdiv_cli_test(surface_obj_tags ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_cube_creases1.obj
  -o @WORK@/out.obj --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24
  FILE @WORK@/out.obj
  FILE_REGEX "\nt interpolateboundary 1/0/0 2\nt creasemethod 0/0/1 normal\n(t crease 2/1/0 [0-9]+ [0-9]+ 4\n)+t facevaryinginterpolateboundary 1/0/0 2\n$"
  FILE_NOT_REGEX "t corner")
foreach(bad
    "crease_not_an_edge|line 7: tag 'crease': vertices 1 and 3 are not joined by an edge of the mesh"
    "negative_sharpness|line 7: tag 'crease': the sharpness -1.000000 is negative or NaN"
    "vertex_out_of_range|line 7: tag 'corner': vertex 7 is out of range \\(the file has 4 vertices, numbered from 0 in tags\\)"
    "odd_crease|line 7: tag 'crease': needs pairs of vertices, got 3 numbers"
    "bad_interpolateboundary|line 7: tag 'interpolateboundary': is 0 \\(none\\), 1 \\(edges and corners\\) or 2 \\(edges only\\), not 5"
    "hole_out_of_range|line 7: tag 'hole': face 2 is out of range \\(the mesh has 2 faces, numbered from 0 in tags\\)"
    "bad_smoothtriangles|line 7: tag 'smoothtriangles': is 'catmark' or 'smooth', not 'round'")
  string(REPLACE "|" ";" parts "${bad}")
  list(GET parts 0 file)
  list(GET parts 1 message)
  subdiv_surface_error(surface_tag_${file} 1 "'[^']*tag_${file}.obj' ${message}"
    ARGS surface ${hostile}/tag_${file}.obj ${mesh_out} --scheme loop --levels 1)
endforeach()
# holes: kept and tagged in an OBJ OUTPUT (catmark_hole_test1: 1 hole face of
# 6, so 4 of the 24 children), left out of an OFF OUTPUT with the face point
# that only they used
subdiv_cli_test(surface_obj_holes ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_hole_test1.obj
  -o @WORK@/out.obj --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24
  FILE @WORK@/out.obj
  FILE_REGEX "\nt hole 1/0/0 [0-9]+\nt hole 1/0/0 [0-9]+\nt hole 1/0/0 [0-9]+\nt hole 1/0/0 [0-9]+\nt facevaryinginterpolateboundary 1/0/0 2\n$")
subdiv_cli_test(surface_off_without_holes ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_hole_test1.obj
  -o @WORK@/out.off --scheme catmull-clark --levels 1
  OUTPUT @WORK@/out.off VERTICES 25 FACES 20)
# the options override the file's tags, and are written back
subdiv_cli_test(surface_sharp_options ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_cube_creases1.obj
  -o @WORK@/out.obj --scheme catmull-clark --levels 1 --boundary edges-and-corners --crease-method chaikin
  --smooth-triangles
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24
  FILE @WORK@/out.obj
  FILE_REGEX "\nt interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 smooth\n")
subdiv_surface_error(surface_bad_boundary_option 2 "--boundary is none, edges or edges-and-corners, not 'sharp'"
  ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_cube.obj ${mesh_out} --scheme catmull-clark --levels 1
  --boundary sharp)
# linear carries the tags (and moves no point for them, which
# SharpFeatures.linear_carries_the_tags_and_moves_no_point checks): the cube's
# 12 creases (11 of 5, one of 0.1) come out as 22 halves of 4
subdiv_cli_test(surface_linear_carries_tags ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_cube_creases1.obj
  -o @WORK@/out.obj --scheme linear --levels 1 --boundary edges-and-corners
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24
  FILE @WORK@/out.obj
  FILE_REGEX "\nt interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 normal\n(t crease 2/1/0 [0-9]+ [0-9]+ 4\n)+t facevaryinginterpolateboundary 1/0/0 2\n$")
# doo-sabin with creases: the octahedron's equator (4 infinitely sharp edges)
# is refined by Chaikin's rule, the corners of its faces at an equator vertex
# welded across it: 24 - 8 vertices, 8 + 12 - 4 + 2 faces; Chaikin's point
# 3/4 (1, 0, 0) + 1/4 (0, 1, 0) is a vertex, and the 8 new crease edges are
# written back as tags
string(REPEAT "t crease 2/1/0 [0-9]+ [0-9]+ 10\n" 8 eight_creases)
subdiv_cli_test(surface_doo_sabin_creases ARGS surface ${SUBDIV_CLI_DIR}/octahedron_equator_crease.obj
  -o @WORK@/out.obj --scheme doo-sabin --levels 1
  OUTPUT @WORK@/out.obj VERTICES 16 FACES 18 FILE @WORK@/out.obj
  FILE_REGEX "\nv 0\\.75 0\\.25 0\n.*\nt creasemethod 0/0/1 normal\n${eight_creases}$")
# semi-sharp tags are refused, naming the line; so are --limit and --displace with tags
subdiv_surface_error(surface_doo_sabin_semisharp 1 "'[^']*catmark_cube_creases1.obj' line 56: tag 'crease': the sharpness 5\\.0* is semi-sharp: --scheme doo-sabin takes 0 or 10 and above only"
  ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_cube_creases1.obj ${mesh_out} --scheme doo-sabin --levels 1)
subdiv_surface_error(surface_doo_sabin_limit_with_creases 1 "--scheme doo-sabin refines with crease and corner tags, but its limit \\(--limit, --displace\\) does not take them: the limit of its creases is not derived"
  ARGS surface ${SUBDIV_CLI_DIR}/octahedron_equator_crease.obj ${mesh_out} --scheme doo-sabin --levels 1 --limit)
subdiv_surface_error(surface_doo_sabin_displace_with_creases 1 "--scheme doo-sabin refines with crease and corner tags, but its limit"
  ARGS surface ${SUBDIV_CLI_DIR}/octahedron_equator_crease.obj ${mesh_out} --scheme doo-sabin --levels 1
  --displace ${SUBDIV_CLI_DIR}/octahedron_heights_one.txt)
# butterfly with creases: --sharp-angle 60 makes the 6 edges of the
# tetrahedron (70.5 degrees) infinitely sharp, so every vertex is a corner and
# every edge a crease of one edge, whose four-point rule with reflected ends
# is the midpoint: the refined tetrahedron is the old one, with its 6 edge
# midpoints; --limit keeps them (an interpolating crease keeps its vertices)
foreach(scheme IN ITEMS butterfly modified-butterfly)
  foreach(limit IN ITEMS "" "--limit")
    string(REPLACE "-" "_" name "${scheme}${limit}")
    subdiv_cli_test(surface_creases_${name} ARGS surface ${tetra} -o @WORK@/out.off --scheme ${scheme}
      --levels 1 --sharp-angle 60 ${limit}
      OUTPUT @WORK@/out.off VERTICES 10 FACES 16
      CONTAINS "1 1 1" "1 -1 -1" "-1 1 -1" "-1 -1 1" "1 0 0" "0 1 0" "0 0 1" "0 0 -1" "0 -1 0" "-1 0 0")
  endforeach()
endforeach()
# sqrt3 with creases: --sharp-angle 60 makes the 6 edges of the tetrahedron
# sharp and its 4 vertices corners. The first level rests the creases (the
# corners stay, 4 face points), the second trisects every edge with the
# border rule, its ends reflected, which on a straight edge between corners
# gives its thirds (2 t + s) / 3 with either scheme; the 18 thirds are written
# back as creases. Without the tags sqrt3 would move the corners, and neither
# scheme would keep the edges
string(REPEAT "t crease 2/1/0 [0-9]+ [0-9]+ 10\n" 18 crease_thirds)
set(third_sqrt3 "v 1 0.33333333333333331 0.33333333333333331\n")
set(third_interpolating-sqrt3 "v 0.99999999999999978 0.33333333333333337 0.33333333333333337\n")
foreach(scheme IN ITEMS sqrt3 interpolating-sqrt3)
  string(REPLACE "-" "_" name "${scheme}")
  subdiv_cli_test(surface_creases_${name} ARGS surface ${tetra} -o @WORK@/out.obj --scheme ${scheme} --levels 2
    --sharp-angle 60
    OUTPUT @WORK@/out.obj VERTICES 20 FACES 36
    CONTAINS "v 1 1 1" "v 1 -1 -1" "v -1 1 -1" "v -1 -1 1"
    FILE @WORK@/out.obj FILE_REGEX "${third_${scheme}}.*\nt creasemethod 0/0/1 normal\n${crease_thirds}$")
endforeach()
# OpenSubdiv's subdivided icosahedron with 17 infinitely sharp edges and a
# corner, two sqrt3 levels (V + F, then V + F again: a crease edge adds two
# points where its two faces lose theirs): its 51 thirds and the corner are
# written back; the semi-sharp twin is refused
string(REPEAT "t crease 2/1/0 [0-9]+ [0-9]+ 10\n" 51 icos_thirds)
subdiv_cli_test(surface_sqrt3_infsharp ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/loop_icos_infsharp.obj
  -o @WORK@/out.obj --scheme sqrt3 --levels 2
  OUTPUT @WORK@/out.obj VERTICES 368 FACES 720 FILE @WORK@/out.obj
  FILE_REGEX "\nt creasemethod 0/0/1 normal\n${icos_thirds}t corner 1/1/0 4 10\n$")
subdiv_surface_error(surface_sqrt3_semisharp 1 "'[^']*loop_icos_semisharp.obj' line 63: tag 'corner': the sharpness 2\\.50* is semi-sharp: --scheme sqrt3 takes 0 or 10 and above only"
  ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/loop_icos_semisharp.obj ${mesh_out} --scheme sqrt3 --levels 1)
# --limit with tags for the sqrt3 schemes: on the octahedron with its
# equator sharp, an equator vertex goes to the limit of the border rule along
# the equator, Kobbelt's ternary cubic B-spline (u + 4 v + w) / 6 = (2/3, 0, 0)
# from (1, 0, 0) between (0, 1, 0) and (0, -1, 0); the interpolating scheme
# keeps it. --displace with heights of 1 pushes it out by 1 along the mean of
# its faces' normals, (1, 0, 0)
set(equator_limit_sqrt3 "\n0\\.6666666666666666[0-9]* 0 0\n")
set(equator_limit_interpolating-sqrt3 "\n1 0 0\n")
set(equator_displaced_sqrt3 "\n1\\.666666666666666[0-9]* 0 0\n")
set(equator_displaced_interpolating-sqrt3 "\n2 0 0\n")
foreach(scheme IN ITEMS sqrt3 interpolating-sqrt3)
  string(REPLACE "-" "_" name "${scheme}")
  subdiv_cli_test(surface_limit_with_creases_${name} ARGS surface ${SUBDIV_CLI_DIR}/octahedron_equator_crease.obj
    -o @WORK@/out.off --scheme ${scheme} --levels 0 --limit
    OUTPUT @WORK@/out.off VERTICES 6 FACES 8 FILE @WORK@/out.off FILE_REGEX "${equator_limit_${scheme}}")
  subdiv_cli_test(surface_displace_with_creases_${name} ARGS surface ${SUBDIV_CLI_DIR}/octahedron_equator_crease.obj
    -o @WORK@/out.off --scheme ${scheme} --levels 0 --displace ${SUBDIV_CLI_DIR}/octahedron_heights_one.txt
    OUTPUT @WORK@/out.off VERTICES 6 FACES 8 FILE @WORK@/out.off FILE_REGEX "${equator_displaced_${scheme}}")
endforeach()
# OpenSubdiv's icosahedron with infinitely sharp creases and corners, refined
# by the modified butterfly, writes the children's tags; its semi-sharp twin is
# refused by the butterflies, naming the line
subdiv_cli_test(surface_modified_butterfly_infsharp ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/loop_icos_infsharp.obj
  -o @WORK@/out.obj --scheme modified-butterfly --levels 2
  OUTPUT @WORK@/out.obj VERTICES 648 FACES 1280 FILE @WORK@/out.obj FILE_REGEX "\nt crease 2/1/0 [0-9]+ [0-9]+ 10\n.*\nt corner 1/1/0 [0-9]+ 10\n")
subdiv_surface_error(surface_butterfly_semisharp 1 "'[^']*loop_icos_semisharp.obj' line 63: tag 'corner': the sharpness 2\\.50* is semi-sharp: --scheme butterfly takes 0 or 10 and above only"
  ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/loop_icos_semisharp.obj ${mesh_out} --scheme butterfly --levels 1)
# --displace with tags: the cube with its 12 edges infinitely sharp is its
# own limit (surface_limit_with_creases), and heights of 1 push every point
# out by 1 along its normal: the faces' own at a face centre (a regular
# smooth vertex), and at a crease and a corner the normal of their tangent
# rows, which is OpenSubdiv Far's: the side of the first face at the vertex
# (doc/sharp_features.md). The first faces of the level are the children of
# the bottom face (z = 0) and of the top face: the 8 corners go to z = -1 and
# z = 2, and the crease point (0.5, 0, 0) to (0.5, 0, -1)
subdiv_cli_test(surface_displace_with_creases ARGS surface ${SUBDIV_CLI_DIR}/cube.off -o @WORK@/out.off
  --scheme catmull-clark --levels 1 --sharp-angle 60 --displace ${SUBDIV_CLI_DIR}/cube_heights_one.txt
  OUTPUT @WORK@/out.off VERTICES 26 FACES 24
  CONTAINS "0.5 0.5 -1" "0.5 0.5 2" "0.5 -1 0.5" "2 0.5 0.5"
  FILE @WORK@/out.off
  FILE_REGEX "\n0 0 -1\n1 0 -1\n1 1 -1\n0 1 -1\n0 0 2\n1 0 2\n1 1 2\n0 1 2\n.*\n0\\.5 0 -1\n")
# --limit with tags: the cube with its 12 edges infinitely sharp is its own
# limit (corners stay, the straight creases and flat faces keep their
# points), so its 26 points after a level are the cube's, exactly; without
# the tags they move inside (0.25 0.25 0.25 and the like)
subdiv_cli_test(surface_limit_with_creases ARGS surface ${SUBDIV_CLI_DIR}/cube.off -o @WORK@/out.off
  --scheme catmull-clark --levels 1 --sharp-angle 60 --limit
  OUTPUT @WORK@/out.off VERTICES 26 FACES 24
  CONTAINS "0 0 0" "1 0 0" "1 1 0" "0 1 0" "0 0 1" "1 0 1" "1 1 1" "0 1 1"
    "0.5 0 0" "1 0.5 0" "0.5 1 0" "0 0.5 0" "0.5 0 1" "1 0.5 1" "0.5 1 1" "0 0.5 1"
    "0 0 0.5" "1 0 0.5" "1 1 0.5" "0 1 0.5"
    "0.5 0.5 0" "0.5 0.5 1" "0.5 0 0.5" "1 0.5 0.5" "0.5 1 0.5" "0 0.5 0.5")
# --sharp-angle (CGAL::Subdiv::mark_sharp_edges): the cube's normals make 90
# degrees at its 12 edges, so 60 makes them all infinitely sharp (24 halves
# of sharpness 10 one level down), 100 none
string(REPEAT "t crease 2/1/0 [0-9]+ [0-9]+ 10\n" 24 sharp_halves)
subdiv_cli_test(surface_sharp_angle ARGS surface ${SUBDIV_CLI_DIR}/cube.off -o @WORK@/out.obj --scheme catmull-clark
  --levels 1 --sharp-angle 60
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24
  STDERR_REGEX "^cgal-subdiv: note: --sharp-angle 60 made 12 edges infinitely sharp\n$"
  FILE @WORK@/out.obj
  FILE_REGEX "\nt creasemethod 0/0/1 normal\n${sharp_halves}$")
subdiv_cli_test(surface_sharp_angle_above_every_edge ARGS surface ${SUBDIV_CLI_DIR}/cube.off -o @WORK@/out.obj
  --scheme catmull-clark --levels 1 --sharp-angle 100
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24
  STDERR_REGEX "^cgal-subdiv: note: --sharp-angle 100 made 0 edges infinitely sharp\n$"
  FILE @WORK@/out.obj
  FILE_NOT_REGEX "t crease [0-9]")
foreach(bad "200|--sharp-angle is an angle in degrees, from 0 to 180, not '200'" "-1|--sharp-angle" "sharp|--sharp-angle")
  string(REPLACE "|" ";" parts "${bad}")
  list(GET parts 0 value)
  list(GET parts 1 message)
  subdiv_surface_error(surface_sharp_angle_${value} 2 "${message}"
    ARGS surface ${SUBDIV_CLI_DIR}/cube.off ${mesh_out} --scheme catmull-clark --levels 1 --sharp-angle ${value})
endforeach()
# doo-sabin: --sharp-angle 60 makes the cube's 12 edges sharp, every vertex a
# corner that keeps its point: two levels give the cube back
subdiv_cli_test(surface_doo_sabin_sharp_angle ARGS surface ${SUBDIV_CLI_DIR}/cube.off ${mesh_out}
  --scheme doo-sabin --levels 2 --sharp-angle 60
  OUTPUT @WORK@/out.off VERTICES 8 FACES 6 CONTAINS "0 0 0" "1 0 0" "1 1 0" "0 1 0" "0 0 1" "1 0 1" "1 1 1" "0 1 1")
# --split-non-manifold (CGAL::Subdiv::split_non_manifold): the three
# triangles on one edge become three sheets (the edge's ends copied twice
# each, corners), the bowtie's vertex two corners; a manifold file is read as
# it is; the quadpole's folded quads keep their zero-length edges
subdiv_cli_test(surface_split_non_manifold_edge ARGS surface ${SUBDIV_CLI_DIR}/three_faces_on_an_edge.off ${mesh_out}
  --scheme loop --levels 1 --split-non-manifold
  OUTPUT @WORK@/out.off VERTICES 18 FACES 12
  STDERR_REGEX "^cgal-subdiv: note: split the non-manifold soup of '[^']*three_faces_on_an_edge.off': 1 non-manifold edge, 2 non-manifold vertices \\(2 made corners\\), 4 vertices copied\n$")
subdiv_cli_test(surface_split_bowtie_corners ARGS surface ${SUBDIV_CLI_DIR}/bowtie.off -o @WORK@/out.obj
  --scheme loop --levels 1 --split-non-manifold
  OUTPUT @WORK@/out.obj VERTICES 12 FACES 8
  FILE @WORK@/out.obj
  FILE_REGEX "\nt corner 1/1/0 [0-9]+ 10\nt corner 1/1/0 [0-9]+ 10\n$")
# the texture coordinates of a split soup: the copies of a vertex on the
# fan's non-manifold edges are one vertex whose values do not agree, so each
# value is kept, as OpenSubdiv keeps every value of a non-manifold vertex
# (Carried_data::non_manifold_copies): a value kept at level 1 gives (0.175,
# 0.675) at level 2, and the crease value (0.1502, 0.3498) is gone
subdiv_cli_test(surface_split_uv_non_manifold_copies ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_fan.obj
  -o @WORK@/out.obj --scheme catmull-clark --levels 2 --split-non-manifold
  OUTPUT @WORK@/out.obj VERTICES 275 FACES 208
  FILE @WORK@/out.obj FILE_REGEX "\nvt 0\\.17499999[0-9]* 0\\.6749999[0-9]*\n" FILE_NOT_REGEX "vt 0\\.150195312")
subdiv_cli_test(surface_split_manifold_input ARGS surface ${SUBDIV_CLI_DIR}/cube.off ${mesh_out}
  --scheme catmull-clark --levels 1 --split-non-manifold
  OUTPUT @WORK@/out.off VERTICES 26 FACES 24 STDERR_LINES 0)
subdiv_cli_test(surface_split_quadpole ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_nonman_quadpole8.obj
  ${mesh_out} --scheme catmull-clark --levels 2 --split-non-manifold
  OUTPUT @WORK@/out.off VERTICES 288 FACES 256
  STDERR_REGEX "8 non-manifold edges, 1 non-manifold vertex \\(1 made corners\\), 7 vertices copied")
subdiv_surface_error(surface_split_unsplittable 1
  "'[^']*catmark_nonman_edges.obj' cannot be split into a manifold mesh \\(--split-non-manifold\\): face 24 passes twice through vertex 52 \\(1.25 -0.3 1.08\\), and its other faces join the two passes into one vertex"
  ARGS surface ${SUBDIV_TEST_DATA_DIR}/opensubdiv/catmark_nonman_edges.obj ${mesh_out} --scheme catmull-clark --levels 1
  --split-non-manifold)
subdiv_surface_error(surface_split_and_repair 2 "--repair and --split-non-manifold are two ways to read a non-manifold INPUT: one at a time"
  ARGS surface ${SUBDIV_CLI_DIR}/bowtie.off ${mesh_out} --scheme loop --levels 1 --split-non-manifold --repair)
# doo-sabin splits the bowtie too: two triangles, whose corners all stay (a
# border vertex with one face, and the split vertex's copies are corners)
subdiv_cli_test(surface_doo_sabin_split_bowtie ARGS surface ${SUBDIV_CLI_DIR}/bowtie.off -o @WORK@/out.obj
  --scheme doo-sabin --levels 1 --split-non-manifold
  OUTPUT @WORK@/out.obj VERTICES 6 FACES 2
  FILE @WORK@/out.obj
  FILE_REGEX "\nt corner 1/1/0 [0-9]+ 10\nt corner 1/1/0 [0-9]+ 10\n$")

# --- SIGTERM while writing removes the temporary file ---------------------------
find_program(SUBDIV_SH sh)
if(SUBDIV_SH)
  add_test(NAME cli_signal_cleanup COMMAND ${SUBDIV_SH} ${SUBDIV_CLI_DIR}/signal_cleanup.sh $<TARGET_FILE:cgal-subdiv>
                                           ${CMAKE_CURRENT_BINARY_DIR}/cli/signal_cleanup ${PROJECT_SOURCE_DIR}/doc/data/torus.off)
  subdiv_timeout(signal_timeout 120)
  set_tests_properties(cli_signal_cleanup PROPERTIES LABELS cli TIMEOUT ${signal_timeout}
                       PASS_REGULAR_EXPRESSION "nothing left behind")
endif()

# an interior vertex of valence 2: Catmull-Clark's limit is the closed form
# (4 v + 4 (e1 + e2) + f1 + f2) / 14, here (3/7, 3/7) for the pillow's vertex 0
# (whose two faces share the opposite corner); Loop has no limit mask there:
# the reason, not a crash
subdiv_cli_test(surface_limit_valence_2 ARGS surface ${hostile}/pillow_valence_2.off -o @WORK@/out.off
  --scheme catmull-clark --levels 0 --limit
  OUTPUT @WORK@/out.off VERTICES 4 FACES 2
  CONTAINS "0.42857142857142855 0.42857142857142855 0" "0.5714285714285714 0.5714285714285714 0")
subdiv_surface_error(surface_limit_triangle_valence_2 1
  "project_to_limit \\(Loop[^)]*\\)\\): vertex 0: an interior vertex of valence 2: the eigen-analysis of triangle schemes covers valence 3 or more"
  ARGS surface ${hostile}/pillow_triangles_valence_2.off ${mesh_out} --scheme loop --levels 0 --limit)

# --- non-finite results are errors, nothing is written ---------------------------
subdiv_surface_error(surface_non_finite_result 1
  "butterfly, 2 levels on '[^']*near_max_cube.off' gives a non-finite coordinate \\(output vertex [0-9]+\\): the coordinates of '[^']*near_max_cube.off' are too large for the scheme's weights \\(the largest, -1.7e\\+308, is at vertex 0\\); scale the mesh down. Nothing was written"
  ARGS surface ${hostile}/near_max_cube.off ${mesh_out} --scheme butterfly --levels 2)
set_tests_properties(cli_surface_non_finite_result PROPERTIES SKIP_REGULAR_EXPRESSION "SUBDIV_SCHEME_NOT_AVAILABLE")

# --- binary outputs ----------------------------------------------------------------
subdiv_cli_test(surface_binary_ply ARGS surface ${tetra} -o @WORK@/out.ply --scheme loop --levels 1 --binary
  OUTPUT @WORK@/out.ply VERTICES 10 FACES 16 FILE @WORK@/out.ply FILE_REGEX "^ply\nformat binary_little_endian 1.0\n")
# binary STL, read back by the next test (its 16 facets, merged to 10 vertices)
subdiv_cli_test(surface_binary_stl ARGS surface ${tetra} -o @WORK@/out.stl --scheme loop --levels 1 --binary
  OUTPUT @WORK@/out.stl FILE @WORK@/out.stl FILE_REGEX "^cgal-subdiv binary STL")
subdiv_cli_test(surface_binary_stl_read_back
  ARGS surface ${CMAKE_CURRENT_BINARY_DIR}/cli/surface_binary_stl/out.stl ${mesh_out} --scheme linear --levels 0
  OUTPUT @WORK@/out.off STDOUT_REGEX "10 V, 24 E, 16 F -> 10 V, 24 E, 16 F")
set_tests_properties(cli_surface_binary_stl PROPERTIES FIXTURES_SETUP binary_stl)
set_tests_properties(cli_surface_binary_stl_read_back PROPERTIES FIXTURES_REQUIRED binary_stl)
# the STL normals of huge coordinates are finite (CGAL's writer gave "facet normal 0 0 -nan")
subdiv_cli_test(surface_stl_normals_of_huge_coordinates
  ARGS surface ${hostile}/near_max_octahedron.off -o @WORK@/out.stl --scheme linear --levels 0
  OUTPUT @WORK@/out.stl FILE @WORK@/out.stl FILE_REGEX "facet normal 0.57735026918962[0-9]* 0.57735026918962[0-9]* 0.57735026918962"
  FILE_NOT_REGEX "nan|inf")
subdiv_surface_error(surface_binary_off 2 "--binary writes PLY and STL only; OUTPUT '[^']*out.off' is OFF"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --binary)

subdiv_surface_error(surface_unknown_scheme 2 "unknown scheme 'chaikin' \\(expected loop, "
  ARGS surface ${tetra} ${mesh_out} --scheme chaikin --levels 1)
subdiv_surface_error(surface_missing_levels 2 "missing --levels" ARGS surface ${tetra} ${mesh_out} --scheme loop)
subdiv_surface_error(surface_missing_output 2 "missing -o OUTPUT" ARGS surface ${tetra} --scheme loop --levels 1)
subdiv_surface_error(surface_unknown_option 2 "unknown option '--closed'"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --closed)
subdiv_surface_error(surface_unwritable_output 1 "cannot write '[^']*/no/such/dir/out.off'"
  ARGS surface ${tetra} -o @WORK@/no/such/dir/out.off --scheme loop --levels 1)

# --- surface --limit and --displace (CGAL/Subdiv/analysis/limit.h) ---------------
# the tetrahedron (valence 3): Loop's limit mask 2/5, 1/5, 1/5, 1/5 puts (1,1,1) at (1/5,1/5,1/5)
set(near_fifth "0\\.(19999999999999|20000000000000)[0-9]*")
subdiv_cli_test(surface_limit_levels_zero ARGS surface ${tetra} ${mesh_out} --scheme loop-warren --levels 0 --limit
  OUTPUT @WORK@/out.off VERTICES 4 FACES 4 STDOUT_REGEX "loop-warren, 0 levels, limit: 4 V, 6 E, 4 F -> 4 V, 6 E, 4 F"
  FILE @WORK@/out.off FILE_REGEX "\n${near_fifth} ${near_fifth} ${near_fifth}\n${near_fifth} -${near_fifth} -${near_fifth}\n")
# the limit point does not move under refinement: after 2 levels too
subdiv_cli_test(surface_limit_loop ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 2 --limit
  OUTPUT @WORK@/out.off VERTICES 34 FACES 64 FILE @WORK@/out.off FILE_REGEX "\n${near_fifth} ${near_fifth} ${near_fifth}\n")
# the cube (valence 3): Catmull-Clark's limit mask 9/24, 4/24 per edge neighbour, 1/24 per face neighbour
subdiv_cli_test(surface_limit_catmull_clark ARGS surface ${cube} ${mesh_out} --scheme catmull-clark --levels 1 --limit
  OUTPUT @WORK@/out.off VERTICES 26 FACES 24)
# interpolating: the old vertices stay where they are
subdiv_cli_test(surface_limit_butterfly ARGS surface ${tetra} ${mesh_out} --scheme butterfly --levels 1 --limit
  OUTPUT @WORK@/out.off VERTICES 10 FACES 16 CONTAINS "1 1 1" "1 -1 -1" "-1 1 -1" "-1 -1 1")
# a border: the limit of the border is the cubic B-spline of the border polygon; z stays 0
subdiv_cli_test(surface_limit_border ARGS surface ${SUBDIV_CLI_DIR}/open_square.off ${mesh_out} --scheme loop --levels 1 --limit
  OUTPUT @WORK@/out.off VERTICES 9 FACES 8 CONTAINS "0.16666666666666666 0.16666666666666666 0")
# heights 0.5 (decimal, fraction, padded, a comment and a blank line): every
# vertex goes 0.5 along its normal, (1,1,1) to (1/5 + 1/(2 sqrt 3)) (1,1,1)
set(displaced "0\\.4886751345948[0-9]*")
subdiv_cli_test(surface_displace ARGS surface ${tetra} ${mesh_out} --scheme loop-warren --levels 1
  --displace ${SUBDIV_CLI_DIR}/tetra_heights.txt
  OUTPUT @WORK@/out.off VERTICES 10 FACES 16 STDOUT_REGEX "loop-warren, 1 level, displaced: 4 V, 6 E, 4 F -> 10 V, 24 E, 16 F"
  FILE @WORK@/out.off FILE_REGEX "\n${displaced} ${displaced} ${displaced}\n")
# doo-sabin (dual): a vertex goes to the limit of its vertex face, the average of
# its three corner points (9/16, 3/16, 3/16, 1/16): (0,0,0) of the unit cube to (1/6, 1/6, 1/6)
set(near_sixth "0\\.1666666666666666[0-9]*")
subdiv_cli_test(surface_limit_doo_sabin ARGS surface ${cube} ${mesh_out} --scheme doo-sabin --levels 0 --limit
  OUTPUT @WORK@/out.off VERTICES 8 FACES 6 FILE @WORK@/out.off FILE_REGEX "\n${near_sixth} ${near_sixth} ${near_sixth}\n")
subdiv_cli_test(surface_limit_doo_sabin_levels ARGS surface ${cube} ${mesh_out} --scheme doo-sabin --levels 2 --limit
  OUTPUT @WORK@/out.off VERTICES 96 FACES 98)
# sqrt3 border vertices are analysed too (over a resting and a refining step)
subdiv_cli_test(surface_limit_sqrt3_border ARGS surface ${SUBDIV_CLI_DIR}/open_square.off ${mesh_out} --scheme sqrt3 --levels 1 --limit
  OUTPUT @WORK@/out.off VERTICES 6 FACES 6)
subdiv_surface_error(surface_displace_count 1 "HEIGHTS '[^']*tetra_heights_short.txt' has 3 heights, INPUT has 4 vertices"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --displace ${SUBDIV_CLI_DIR}/tetra_heights_short.txt)
subdiv_surface_error(surface_displace_bad_line 1 "HEIGHTS '[^']*tetra_heights_bad.txt' line 3: cannot read 'abc' as a number"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --displace ${SUBDIV_CLI_DIR}/tetra_heights_bad.txt)
subdiv_surface_error(surface_displace_missing 1 "cannot read HEIGHTS '[^']*no_heights.txt'"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --displace ${SUBDIV_CLI_DIR}/no_heights.txt)
subdiv_surface_error(surface_displace_no_value 2 "option --displace needs a value"
  ARGS surface ${tetra} ${mesh_out} --scheme loop --levels 1 --displace)

endif()

# === cgal-subdiv analyse =======================================================
if(TARGET cgal-subdiv)
find_package(Python3 COMPONENTS Interpreter)

subdiv_cli_test(analyse_help ARGS analyse --help
  STDOUT_REGEX "--scheme.*loop, loop-warren, catmull-clark, doo-sabin, sqrt3.*--valence N.*3 <= N <= 32.*--boundary.*--json.*Exit status")
# the readable table
subdiv_cli_test(analyse_loop_table ARGS analyse --scheme loop --valence 5
  STDOUT_REGEX "^Loop \\(Loop 1987 beta\\) \\(loop\\) at an interior vertex of valence 5\n.*eigenvalues +1, 0.4522542486 \\(x2\\).*subdominant +0.4522542486, multiplicity 2.*characteristic map +regular_injective.*C1 +yes.*limit mask, centre +0.47142")
subdiv_cli_test(analyse_bspline_table ARGS analyse --scheme bspline
  STDOUT_REGEX "eigenvalues +1, 0.5, 0.25\n.*limit mask +1/6, 2/3, 1/6 \\(offsets -1..1\\).*smoothness +C\\^2.*Holder exponent +>= 3")

# --json: one JSON object (python3 -m json.tool), fields and values (test/cli/analyse_checks.py)
function(subdiv_analyse_json name check)
  if(NOT Python3_Interpreter_FOUND)
    return()
  endif()
  list(JOIN ARGN "|" args)
  add_test(NAME cli_analyse_json_${name}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:cgal-subdiv> -DPYTHON=${Python3_EXECUTABLE}
                   -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli/analyse_json_${name} "-DARGS=${args}" -DCASE=${check}
                   -P ${SUBDIV_CLI_DIR}/run_analyse_json.cmake)
  subdiv_timeout(timeout 60)
  set_tests_properties(cli_analyse_json_${name} PROPERTIES TIMEOUT ${timeout} LABELS cli)
endfunction()
subdiv_analyse_json(loop_3 loop3 analyse --scheme loop --valence 3 --json)
subdiv_analyse_json(loop_6 loop6 analyse --scheme loop --valence 6 --json)
subdiv_analyse_json(catmull_clark_5 catmull_clark5 analyse --scheme catmull-clark --valence 5 --json)
subdiv_analyse_json(butterfly_3 butterfly3 analyse --scheme butterfly --valence 3 --json)
subdiv_analyse_json(loop_border_2 loop_border2 analyse --scheme loop --valence 2 --boundary --json)
subdiv_analyse_json(catmull_clark_border_5 catmull_clark_border5 analyse --scheme catmull-clark --valence 5 --boundary --json)
subdiv_analyse_json(doo_sabin_5 doo_sabin5 analyse --scheme doo-sabin --valence 5 --json)
subdiv_analyse_json(doo_sabin_border_4 doo_sabin_border4 analyse --scheme doo-sabin --valence 4 --boundary --json)
subdiv_analyse_json(catmull_clark_crease_1_3 catmull_clark_crease_1_3 analyse --scheme catmull-clark --crease 1,3 --json)
subdiv_analyse_json(loop_dart_5 loop_dart5 analyse --scheme loop --dart 5 --json)
subdiv_analyse_json(loop_corner_6 loop_corner6 analyse --scheme loop --corner 6 --json)
subdiv_analyse_json(bspline_3 bspline3 analyse --scheme bspline --degree 3 --json)
subdiv_analyse_json(four_point_w_1_5 four_point_tense analyse --scheme four-point --w 1/5 --json)
subdiv_analyse_json(bezier_3 bezier analyse --scheme bezier --json)

# errors: one line on stderr, exit 1 (cannot be analysed) or 2 (malformed command line)
subdiv_cli_error(analyse_valence_too_small 1 "the valence of an interior vertex must be between 3 and 32, got 2"
  ARGS analyse --scheme loop --valence 2)
# Catmull-Clark at interior valence 2: two quads laid out as half-planes; the
# closed-form limit 2/7 v + 2/7 (e1 + e2) + 1/14 (f1 + f2), and no C1 (1/4
# twice but -1/4 as large)
subdiv_cli_test(analyse_catmull_clark_valence_2 ARGS analyse --scheme catmull-clark --valence 2
  STDOUT_REGEX "at an interior vertex of valence 2\n.*eigenvalues +1, 0\\.25 \\(1/4\\) \\(x2\\), -0\\.25 \\(-1/4\\), 0\\.125 \\(1/8\\)\n.*\n  C1 +no\n  limit mask, centre +2/7\n  limit mask, others +2/7 1/14 2/7 1/14 ")
subdiv_cli_error(analyse_catmull_clark_valence_too_small 1
  "the valence of an interior vertex must be between 2 and 32, got 1" ARGS analyse --scheme catmull-clark --valence 1)
subdiv_cli_error(analyse_doo_sabin_two_corners 1 "the number of corners of the central face must be between 3 and 32, got 2"
  ARGS analyse --scheme doo-sabin --valence 2)
subdiv_cli_error(analyse_valence_too_large 1 "must be between 2 and 32, got 33" ARGS analyse --scheme catmull-clark --valence 33)
subdiv_cli_error(analyse_border_zero 1 "the number of faces at a border vertex must be between 1 and 32, got 0"
  ARGS analyse --scheme loop --valence 0 --boundary)
subdiv_cli_test(analyse_sqrt3_border ARGS analyse --scheme sqrt3 --valence 4 --boundary
  STDOUT_REGEX "^sqrt3 \\(Kobbelt\\) \\(sqrt3\\) at a border vertex with 4 faces\n.*limit mask, centre")
# doo-sabin at the border face made from a border vertex with N faces
subdiv_cli_test(analyse_doo_sabin_border ARGS analyse --scheme doo-sabin --valence 5 --boundary
  STDOUT_REGEX "^Doo-Sabin \\(doo-sabin\\) at the border face made from a border vertex with 5 faces\n.*C1 +yes")
subdiv_cli_error(analyse_doo_sabin_border_zero 1 "the number of faces at a border vertex must be between 1 and 32, got 0"
  ARGS analyse --scheme doo-sabin --valence 0 --boundary)
subdiv_cli_error(analyse_linear 1 "linear has no smoothness to analyse" ARGS analyse --scheme linear --valence 6)
subdiv_cli_error(analyse_bspline_degree 1 "degree must be between 1 and 64, got 0" ARGS analyse --scheme bspline --degree 0)
subdiv_cli_error(analyse_unknown_scheme 2 "unknown scheme 'loopy' \\(expected loop, " ARGS analyse --scheme loopy --valence 6)
subdiv_cli_error(analyse_missing_scheme 2 "missing --scheme" ARGS analyse --valence 6)
subdiv_cli_error(analyse_missing_valence 2 "missing --valence N" ARGS analyse --scheme loop --json)
subdiv_cli_error(analyse_valence_not_a_number 2 "--valence expects a whole number, got 'six'"
  ARGS analyse --scheme loop --valence six)
subdiv_cli_error(analyse_valence_for_curve 2 "--valence applies to surface schemes only" ARGS analyse --scheme chaikin --valence 6)
subdiv_cli_error(analyse_boundary_for_curve 2 "--boundary applies to surface schemes only" ARGS analyse --scheme chaikin --boundary)
subdiv_cli_error(analyse_degree_for_surface 2 "--degree applies to bspline and bezier only"
  ARGS analyse --scheme loop --valence 6 --degree 3)
subdiv_cli_error(analyse_positional 2 "unexpected argument 'loop'" ARGS analyse loop)
# sharp vertices (infinitely sharp tags): the table of a crease, side by side
subdiv_cli_test(analyse_catmull_clark_crease ARGS analyse --scheme catmull-clark --crease 2,3
  STDOUT_REGEX "^Catmull-Clark \\(catmull-clark\\) at a crease vertex with 2 and 3 faces on its sides\n.*eigenvalues +1, 0.5796823261, 0.5 \\(1/2\\) \\(x2\\), 0.4100970508, 0.25 \\(1/4\\) \\(x3\\).*block triangular +yes.*side 1 +2 faces: .*C1 yes\n  side 2 +3 faces: .*C1 yes\n.*  C1 +yes\n  limit mask, centre +2/3\n  limit mask, others +1/6 0 0 0 1/6 0 0 0 0 0 ")
subdiv_cli_test(analyse_catmull_clark_corner ARGS analyse --scheme catmull-clark --corner 5
  STDOUT_REGEX "at a corner \\(vertex sharpness 10\\) of valence 5\n.*subdominant +0.6545084972, multiplicity 1.*  C1 +no\n  limit mask, centre +1\n  limit mask, others +0 0 0 0 0 0 0 0 0 0 ")
subdiv_cli_error(analyse_crease_side_zero 1 "--crease K1,K2: the faces on each side must be between 1 and 8, got 0"
  ARGS analyse --scheme loop --crease 0,3)
subdiv_cli_error(analyse_crease_side_too_large 1 "--crease K1,K2: the faces on each side must be between 1 and 8, got 9"
  ARGS analyse --scheme catmull-clark --crease 2,9)
subdiv_cli_error(analyse_loop_crease_1_1 1 "--crease 1,1: an interior vertex of valence 2 in a triangle mesh"
  ARGS analyse --scheme loop --crease 1,1)
subdiv_cli_error(analyse_crease_malformed 2 "--crease expects K1,K2 \\(the faces on each side, two whole numbers\\), got '3'"
  ARGS analyse --scheme loop --crease 3)
subdiv_cli_error(analyse_dart_too_large 1 "--dart N: the valence must be between 3 and 16, got 17"
  ARGS analyse --scheme loop --dart 17)
subdiv_cli_error(analyse_corner_too_small 1 "--corner N: the valence must be between 3 and 16, got 2"
  ARGS analyse --scheme catmull-clark --corner 2)
subdiv_cli_error(analyse_dart_not_a_number 2 "--dart expects a whole number, got 'five'"
  ARGS analyse --scheme loop --dart five)
subdiv_cli_error(analyse_dart_for_sqrt3 2 "--dart applies to loop, loop-warren and catmull-clark"
  ARGS analyse --scheme sqrt3 --dart 5)
subdiv_cli_error(analyse_corner_for_curve 2 "--corner applies to surface schemes only" ARGS analyse --scheme chaikin --corner 5)
subdiv_cli_error(analyse_two_configurations 2 "--crease, --dart and --corner each give a configuration: give one"
  ARGS analyse --scheme loop --dart 5 --corner 5)
subdiv_cli_error(analyse_dart_and_valence 2 "no --valence or --boundary with them"
  ARGS analyse --scheme loop --dart 5 --valence 5)

# the demo prints the analysis summary and writes it into index.md
subdiv_cli_test(demo_analysis_summary ARGS demo --output-dir @WORK@/demo TIMEOUT 60
  STDOUT_REGEX "analysis +valences +subdominant.*\nloop +3\\.\\.8 +0\\.2500 0\\.3750 0\\.4523 0\\.5000 [^\n]*C1 at 3\\.\\.8\n.*\nbutterfly +3\\.\\.8 +0\\.2500 [^\n]*C1 at 4\\.\\.7; not at 3, 8\n.*/demo\n$"
  FILE @WORK@/demo/index.md
  FILE_REGEX "## Analysis.*\\| catmull-clark \\| 3\\.\\.8 \\| 0\\.4101, 0\\.5000, [^\n]* \\| C1 at 3\\.\\.8 \\|")
endif()

# === cgal-subdiv evaluate and tessellate (CGAL/Subdiv/limit/) ===================
if(TARGET cgal-subdiv)
set(locations ${SUBDIV_CLI_DIR}/locations)
set(grid ${SUBDIV_CLI_DIR}/grid_4x4.off)

subdiv_cli_test(evaluate_help ARGS evaluate --help
  STDOUT_REGEX "--scheme.*--at LOCATIONS.*FACE U V.*FACE CORNER U V.*--json.*x y z dux duy duz dvx dvy dvz nx ny nz.*Exit status")
subdiv_cli_test(tessellate_help ARGS tessellate --help
  STDOUT_REGEX "--scheme.*--rate N.*V \\+ E \\(N - 1\\) \\+ F \\(N - 1\\)\\^2.*--triangles.*--normals.*Exit status")
subdiv_cli_test(help_lists_limit_commands ARGS --help STDOUT_REGEX "\n  evaluate +[^\n]*\n.*\n  tessellate +")

# a flat grid of quads: face 5 (a regular patch) is the plane (1 + u, 1 + v, 0),
# du = (1, 0, 0), dv = (0, 1, 0) (to rounding: the B-spline's weights in
# double), z and the normal (0, 0, 1) exactly; to stdout or to -o
set(near "-?[0-9.e-]+")
set(grid_face_5 "1.2(5|49999999999999[0-9]*) 1.5 0 ${near} ${near} 0 ${near} ${near} 0 0 0 1")
subdiv_cli_test(evaluate_grid_stdout ARGS evaluate ${grid} --scheme catmull-clark --at ${locations}/grid_face_5.txt
  STDOUT_REGEX "^${grid_face_5}\n$")
subdiv_cli_test(evaluate_grid_output ARGS evaluate ${grid} --scheme catmull-clark --at ${locations}/grid_face_5.txt
  -o @WORK@/out.txt STDOUT_REGEX "^$" OUTPUT @WORK@/out.txt POINTS 1 FILE @WORK@/out.txt FILE_REGEX "^${grid_face_5}\n$")

# Loop with a border: the flat open square's limit lies in its plane, normal +z
subdiv_cli_test(evaluate_loop_with_border ARGS evaluate ${SUBDIV_CLI_DIR}/open_square.off --scheme loop
  --at ${locations}/one_centre.txt STDOUT_REGEX "^${near} ${near} 0 ${near} ${near} 0 ${near} ${near} 0 -?0 -?0 1\n$")

# values against hand-derived ones and `surface --limit` (test/cli/limit_checks.py)
function(subdiv_limit_check name)
  if(NOT Python3_Interpreter_FOUND)
    return()
  endif()
  add_test(NAME cli_limit_${name}
           COMMAND ${Python3_EXECUTABLE} ${SUBDIV_CLI_DIR}/limit_checks.py $<TARGET_FILE:cgal-subdiv> ${SUBDIV_CLI_DIR}
                   ${CMAKE_CURRENT_BINARY_DIR}/cli/limit_${name} ${name})
  subdiv_timeout(timeout 60)
  set_tests_properties(cli_limit_${name} PROPERTIES TIMEOUT ${timeout} LABELS cli)
endfunction()
foreach(check IN ITEMS cc_cube_corners cc_cube_centres cc_grid_plane loop_tetra cc_sub_quads json_layout
                       tessellate_matches_evaluate tessellate_normals)
  subdiv_limit_check(${check})
endforeach()

# bad locations: one line naming LOCATIONS and the line, exit 1, no output
function(subdiv_evaluate_error name mesh scheme file regex)
  subdiv_cli_error(evaluate_${name} 1 "${file}:${regex}"
    ARGS evaluate ${mesh} --scheme ${scheme} --at ${locations}/${file} -o @WORK@/out.txt)
endfunction()
subdiv_evaluate_error(face_out_of_range ${cube} catmull-clark face_out_of_range.txt
  "3: face 12 out of range \\(the mesh has 6 faces\\)\n$")
subdiv_evaluate_error(face_negative ${cube} catmull-clark face_negative.txt
  "2: face -1 out of range \\(the mesh has 6 faces\\)\n$")
subdiv_evaluate_error(face_not_whole ${cube} catmull-clark face_not_whole.txt "2: FACE '1.5' is not a whole number\n$")
subdiv_evaluate_error(u_outside ${cube} catmull-clark u_outside.txt
  "3: u = 1.5 is outside the domain of face 2 \\(\\[0, 1\\]\\^2\\)\n$")
subdiv_evaluate_error(v_negative ${tetra} loop v_negative.txt
  "1: v = -1/8 is outside the domain of face 0 \\(u, v >= 0, u \\+ v <= 1\\)\n$")
subdiv_evaluate_error(outside_triangle ${tetra} loop outside_triangle.txt
  "2: u \\+ v = 1.25 is outside the domain of face 0 \\(u, v >= 0, u \\+ v <= 1\\)\n$")
subdiv_evaluate_error(corner_for_quad ${cube} catmull-clark corner_for_quad.txt
  "1: face 0 is a quad: give FACE U V, without a CORNER\n$")
subdiv_evaluate_error(corner_missing ${tetra} catmull-clark corner_missing.txt
  "2: face 1 has 3 corners: give FACE CORNER U V, its sub-quad at CORNER\n$")
subdiv_evaluate_error(corner_out_of_range ${tetra} catmull-clark corner_out_of_range.txt
  "1: face 0 has no corner 3 \\(its corners are 0 to 2\\)\n$")
subdiv_evaluate_error(corner_for_loop ${tetra} loop corner_for_loop.txt "1: loop takes FACE U V: a CORNER picks")
subdiv_evaluate_error(nan ${cube} catmull-clark nan.txt "1: u is 'nan', not a finite number\n$")
subdiv_evaluate_error(inf ${cube} catmull-clark inf.txt "3: v is '-inf', not a finite number\n$")
subdiv_evaluate_error(too_few_fields ${cube} catmull-clark too_few_fields.txt
  "1: expected FACE U V or FACE CORNER U V, got 2 fields\n$")
subdiv_evaluate_error(too_many_fields ${cube} catmull-clark too_many_fields.txt
  "1: expected FACE U V or FACE CORNER U V, got 5 fields\n$")
subdiv_evaluate_error(not_a_number ${cube} catmull-clark not_a_number.txt "1: v 'abc' is not a number\n$")
subdiv_evaluate_error(not_finite ${SUBDIV_CLI_DIR}/hostile/near_max_cube.off catmull-clark near_max.txt
  "2: the limit there is not finite: the coordinates of '[^']*near_max_cube.off' are too large for the scheme's weights; scale the mesh down\n$")
subdiv_cli_error(evaluate_no_locations 1 "'[^']*no_locations.txt' holds no locations"
  ARGS evaluate ${cube} --scheme catmull-clark --at ${locations}/no_locations.txt -o @WORK@/out.txt)
subdiv_cli_error(evaluate_missing_locations 1 "cannot read '[^']*missing.txt'"
  ARGS evaluate ${cube} --scheme catmull-clark --at missing.txt -o @WORK@/out.txt)
# an error writes nothing on stdout either
subdiv_cli_test(evaluate_error_stdout_empty ARGS evaluate ${cube} --scheme catmull-clark
  --at ${locations}/u_outside.txt RC 1 STDOUT_REGEX "^$" STDERR_LINES 1)

# meshes the evaluator refuses (exit 1) and malformed command lines (exit 2)
subdiv_cli_error(evaluate_loop_on_quads 1 "Limit_surface: face 0 is not a triangle \\(Loop\\)"
  ARGS evaluate ${cube} --scheme loop --at ${locations}/one_centre.txt -o @WORK@/out.txt)
subdiv_cli_error(evaluate_scheme_not_evaluated 2 "--scheme sqrt3: only catmull-clark and loop are evaluated so far\n$"
  ARGS evaluate ${tetra} --scheme sqrt3 --at ${locations}/one_centre.txt -o @WORK@/out.txt)
subdiv_cli_error(evaluate_unknown_scheme 2 "unknown scheme 'cubic'"
  ARGS evaluate ${tetra} --scheme cubic --at ${locations}/one_centre.txt -o @WORK@/out.txt)
subdiv_cli_error(evaluate_missing_at 2 "missing --at LOCATIONS\n$" ARGS evaluate ${cube} --scheme catmull-clark)
subdiv_cli_error(evaluate_missing_scheme 2 "missing --scheme \\(catmull-clark or loop\\)\n$"
  ARGS evaluate ${cube} --at ${locations}/one_centre.txt)
subdiv_cli_error(evaluate_missing_mesh 2 "missing MESH" ARGS evaluate --scheme loop --at ${locations}/one_centre.txt)
subdiv_cli_error(evaluate_mesh_extension 2 "MESH '[^']*one_centre.txt': unknown format '.txt'"
  ARGS evaluate ${locations}/one_centre.txt --scheme loop --at ${locations}/one_centre.txt)

# tessellate: on a mesh of quads V + E (N - 1) + F (N - 1)^2 vertices (every
# mesh vertex and every inner edge point once, shared by the faces around it)
# and F N^2 quads or 2 F N^2 triangles; the cube: V 8, E 12, F 6
subdiv_cli_test(tessellate_cube_rate_2 ARGS tessellate ${cube} ${mesh_out} --scheme catmull-clark --rate 2
  OUTPUT @WORK@/out.off VERTICES 26 FACES 24
  STDOUT_REGEX "^catmull-clark, rate 2: 8 V, 12 E, 6 F -> 26 V, 48 E, 24 F in [0-9.]+ s; wrote [^\n]*out.off\n$")
subdiv_cli_test(tessellate_cube_rate_3 ARGS tessellate ${cube} ${mesh_out} --scheme catmull-clark --rate 3
  OUTPUT @WORK@/out.off VERTICES 56 FACES 54 FILE @WORK@/out.off FILE_REGEX "\n4 +[0-9]+ [0-9]+ [0-9]+ [0-9]+\n")
subdiv_cli_test(tessellate_cube_rate_3_triangles ARGS tessellate ${cube} ${mesh_out} --scheme catmull-clark --rate 3
  --triangles OUTPUT @WORK@/out.off VERTICES 56 FACES 108 FILE @WORK@/out.off FILE_NOT_REGEX "\n4 +[0-9]+ ")
# Loop: a triangle becomes N^2 triangles; V + E (N - 1) + F (N - 1)(N - 2)/2 vertices
subdiv_cli_test(tessellate_tetra_loop_rate_3 ARGS tessellate ${tetra} -o @WORK@/out.obj --scheme loop --rate 3
  OUTPUT @WORK@/out.obj VERTICES 20 FACES 36)
# catmull-clark on triangles: 3 sub-quads of (N/2)^2 quads each; N = 4: V + E (N - 1)
# + F (1 + 3 (N/2 - 1) + 3 (N/2 - 1)^2) vertices (the centre, the spokes to it, the
# sub-quads' inner points) = 4 + 18 + 28, and 12 F faces
subdiv_cli_test(tessellate_tetra_cc_rate_4 ARGS tessellate ${tetra} -o @WORK@/out.ply --scheme catmull-clark --rate 4
  OUTPUT @WORK@/out.ply VERTICES 50 FACES 48)
# normals: one vn per vertex (OBJ), nx ny nz (PLY), NOFF (OFF)
subdiv_cli_test(tessellate_normals_obj ARGS tessellate ${cube} -o @WORK@/out.obj --scheme catmull-clark --rate 2
  --normals OUTPUT @WORK@/out.obj VERTICES 26 FACES 24 NORMALS 26)
subdiv_cli_test(tessellate_normals_ply ARGS tessellate ${cube} -o @WORK@/out.ply --scheme catmull-clark --rate 2
  --normals OUTPUT @WORK@/out.ply VERTICES 26 FACES 24 FILE @WORK@/out.ply FILE_REGEX "property double nx\n")
subdiv_cli_test(tessellate_normals_off ARGS tessellate ${cube} -o @WORK@/out.off --scheme catmull-clark --rate 2
  --normals OUTPUT @WORK@/out.off VERTICES 26 FACES 24 FILE @WORK@/out.off FILE_REGEX "^NOFF\n")
subdiv_cli_test(tessellate_no_normals ARGS tessellate ${cube} -o @WORK@/out.obj --scheme catmull-clark --rate 2
  OUTPUT @WORK@/out.obj VERTICES 26 FACES 24 NORMALS 0)

foreach(rate IN ITEMS 0 -1 1025 2.5 two)
  string(REPLACE "." "_" name "${rate}")
  subdiv_surface_error(tessellate_bad_rate_${name} 2 "--rate is a whole number from 1 to 1024, not '${rate}'\n$"
    ARGS tessellate ${cube} ${mesh_out} --scheme catmull-clark --rate ${rate})
endforeach()
subdiv_surface_error(tessellate_missing_rate 2 "missing --rate N\n$" ARGS tessellate ${cube} ${mesh_out} --scheme loop)
subdiv_surface_error(tessellate_missing_output 2 "missing -o OUTPUT\n$"
  ARGS tessellate ${cube} --scheme catmull-clark --rate 2)
subdiv_surface_error(tessellate_scheme_not_evaluated 2 "--scheme doo-sabin: only catmull-clark and loop are evaluated so far\n$"
  ARGS tessellate ${cube} ${mesh_out} --scheme doo-sabin --rate 2)
subdiv_cli_test(tessellate_normals_stl RC 2 STDERR_LINES 1
  STDERR_REGEX "^cgal-subdiv: error: --normals: OUTPUT '[^']*out.stl' is STL, which holds face normals only"
  ARGS tessellate ${cube} -o @WORK@/out.stl --scheme catmull-clark --rate 2 --normals OUTPUT @WORK@/out.stl)
subdiv_surface_error(tessellate_loop_on_quads 1 "Limit_surface: face 0 is not a triangle \\(Loop\\)"
  ARGS tessellate ${cube} ${mesh_out} --scheme loop --rate 2)
# 64 triangles at rate 1024: 64 x 1025 x 1026 / 2 points, above the library's 2^24
subdiv_surface_error(tessellate_too_large 1 "tessellate: the rates would make up to [0-9.]+ output points, more than"
  ARGS tessellate ${PROJECT_SOURCE_DIR}/doc/data/torus.off ${mesh_out} --scheme loop --rate 1024)
endif()
