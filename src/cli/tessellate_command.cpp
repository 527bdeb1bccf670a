// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv tessellate MESH -o OUTPUT --scheme S --rate N [--triangles] [--normals]
#include "commands.h"
#include "limit_evaluator.h"
#include "surface.h"

#include <chrono>
#include <cmath>
#include <iostream>

namespace cgal_subdiv {
namespace {

// every point is an evaluation (local refinement near extraordinary
// vertices): beyond this the run takes minutes, and the library's bound on
// the output (2^24 points) refuses most meshes anyway
constexpr int max_rate = 1024;

const char* const tessellate_help = R"(usage: cgal-subdiv tessellate MESH -o OUTPUT --scheme SCHEME --rate N
                              [--triangles] [--normals]

Writes a tessellation of the limit surface of the polygon mesh in MESH: every
face cut into a grid of points of the limit surface
(CGAL::Subdiv::tessellate). A point on a vertex or an edge of MESH is
evaluated once and shared by the faces around it, so the output has no crack:
it is closed when MESH is. One line on stdout sums it up: vertices (V), edges
(E) and faces (F) before and after, and the time the tessellation took.

  MESH                  OFF, OBJ, PLY or STL, read as for 'cgal-subdiv
                        surface' (a manifold polygon mesh); the surface is
                        smooth: tags (OBJ t lines) are ignored, with a note
  -o, --output OUTPUT   OFF, OBJ, PLY or STL (from the extension), ASCII, 17
                        significant digits, written under a temporary name and
                        renamed at the end
  --scheme SCHEME       catmull-clark or loop (a triangle mesh), closed or
                        with a border; the other schemes are not evaluated
                        yet
  --rate N              segments per edge of MESH, 1 <= N <= 1024: a quad
                        becomes N x N quads, a triangle (loop) N^2 triangles,
                        a catmull-clark face with n != 4 corners n sub-quads of
                        N/2 x N/2 (N odd: N + 1 on its edges, the quads next to
                        it zipped to it with triangles). On a mesh of quads,
                        the output has V + E (N - 1) + F (N - 1)^2 vertices
                        and F N^2 faces (V, E, F: those of MESH); an output of
                        more than 2^24 points is refused before any work
  --triangles           triangles only: each quad of the grid split in two
  --normals             the unit limit normal at every output vertex: vn lines
                        in OBJ, nx ny nz in PLY, NOFF in OFF (STL holds face
                        normals only and is refused)
  -h, --help            show this help

Exit status: 0 on success; 1 if the input cannot be used (MESH unreadable, a
mesh the scheme does not evaluate, e.g. loop on quads, an output
too large); 2 for a malformed command line (unknown option or scheme, a
scheme not evaluated, missing MESH, -o, --scheme or --rate, a rate that is not
a whole number from 1 to 1024, an extension other than .off, .obj, .ply,
.stl, --normals with STL). Errors are one line on stderr:
"cgal-subdiv: error: ...", and no OUTPUT is written then.
)";

const std::vector<Option_spec> tessellate_options = {{{"-o", "--output"}, true}, {{"--scheme"}, true},
                                                     {{"--rate"}, true},         {{"--triangles"}, false},
                                                     {{"--normals"}, false},     {{"-h", "--help"}, false}};

int rate_of(const Parsed_args& args)
{
  if(!args.has("--rate"))
    throw Usage_error("missing --rate N");
  const auto refuse = [&] {
    return Usage_error("--rate is a whole number from 1 to " + std::to_string(max_rate) + ", not '" +
                       args.value("--rate") + "'");
  };
  int rate = 0;
  try {
    rate = args.integer("--rate", 0);
  } catch(const Usage_error&) {
    throw refuse();
  }
  if(rate < 1 || rate > max_rate)
    throw refuse();
  return rate;
}

// the derivatives of a mesh whose coordinates are near the largest double
// overflow, and so its normals, which no format should receive as nan
void check_finite_normals(const Surface& result, const std::string& step, const std::string& input)
{
  const Normal_map normal = *normals_of(result);
  for(const Surface::Vertex_index v : result.vertices())
    if(!std::isfinite(normal[v].x()) || !std::isfinite(normal[v].y()) || !std::isfinite(normal[v].z()))
      throw Input_error(step + " on '" + input + "' gives a non-finite normal (output vertex " +
                        std::to_string(static_cast<std::size_t>(v)) + "): the coordinates of '" + input +
                        "' are too large for the scheme's weights; scale the mesh down. Nothing was written");
}

} // namespace

int tessellate_command(const std::vector<std::string>& arguments)
{
  const Parsed_args args = scan_args(arguments, tessellate_options, "tessellate");
  if(args.has("-h")) {
    std::cout << tessellate_help;
    return 0;
  }
  const Limit_arguments limit = limit_arguments(args, "tessellate");
  if(!args.has("-o") || args.value("-o").empty())
    throw Usage_error("missing -o OUTPUT");
  const std::string output = args.value("-o");
  const Mesh_format output_format = mesh_format(output, "OUTPUT");
  const int rate = rate_of(args);
  const bool normals = args.has("--normals");
  if(normals && output_format == Mesh_format::stl)
    throw Usage_error("--normals: OUTPUT '" + output +
                      "' is STL, which holds face normals only (write .obj, .ply or .off to keep them)");

  std::vector<std::string> notes;
  std::vector<std::size_t> file_numbers;
  const Surface mesh = read_surface(limit.input, Soup_fix::none, notes, &file_numbers);
  const Limit_evaluator evaluator(mesh, limit.scheme);
  const auto start = std::chrono::steady_clock::now();
  const Surface result = evaluator.tessellate(rate, args.has("--triangles"), normals);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string step = limit.scheme_name + " tessellated at rate " + std::to_string(rate);
  check_finite_result(result, step, limit.input, largest_coordinate(mesh), file_numbers);
  if(normals)
    check_finite_normals(result, step, limit.input);
  write_surface(result, output);

  print_notes(notes);
  std::cout << limit.scheme_name << ", rate " << rate << ": " << describe(counts(mesh)) << " -> "
            << describe(counts(result)) << " in " << seconds_text(seconds) << "; wrote " << output << std::endl;
  return 0;
}

} // namespace cgal_subdiv
