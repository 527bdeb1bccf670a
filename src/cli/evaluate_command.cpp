// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv evaluate MESH --scheme S --at LOCATIONS [--json] [-o OUTPUT]
#include "commands.h"
#include "files.h"
#include "limit_evaluator.h"
#include "numbers.h"
#include "surface.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace cgal_subdiv {
namespace {

const char* const evaluate_help = R"(usage: cgal-subdiv evaluate MESH --scheme SCHEME --at LOCATIONS [--json]
                            [-o OUTPUT]

Evaluates the limit surface of the polygon mesh in MESH at the parameters
listed in LOCATIONS: the position, the first and second derivatives along the
face's u and v, and the unit normal (CGAL::Subdiv::Limit_surface: exact on
regular patches, local refinement around extraordinary vertices).

  MESH                  OFF, OBJ, PLY or STL, read as for 'cgal-subdiv
                        surface' (a manifold polygon mesh); the surface is
                        smooth: tags (OBJ t lines) are ignored, with a note
  --scheme SCHEME       catmull-clark or loop (a triangle mesh), closed or
                        with a border; the other schemes are not evaluated
                        yet
  --at LOCATIONS        one location per line, '#' comments and blank lines
                        skipped, numbers separated by blanks or commas:
                          FACE U V          a quad (catmull-clark) or a
                                            triangle (loop)
                          FACE CORNER U V   catmull-clark, a face with n != 4
                                            corners: its sub-quad at CORNER
                        FACE counts the faces of MESH in the file's order, from
                        0. The corners of a face are its vertices in the
                        file's order, from 0. A quad has corner 0 at (0,0), 1
                        at (1,0), 2 at (1,1), 3 at (0,1), with U and V in
                        [0,1]; a triangle corner 0 at (0,0), 1 at (1,0), 2 at
                        (0,1), with U, V >= 0 and U + V <= 1; a sub-quad (0,0)
                        at its corner, U towards the middle of the edge to the
                        next corner, V towards the middle of the edge from the
                        previous one, (1,1) at the face's centre, U and V in
                        [0,1]. U and V are decimals or fractions (1/3)
  --json                one JSON object instead of lines: {"scheme": ...,
                        "locations": [{"line": L, "face": F, "corner": C or
                        null, "u": U, "v": V, "position": [x, y, z], "du",
                        "dv", "duu", "duv", "dvv", "normal": [x, y, z]}, ...]}
  -o, --output OUTPUT   write to OUTPUT (under a temporary name, renamed at the
                        end) instead of stdout
  -h, --help            show this help

Output: one line per location, in the order of LOCATIONS:
  x y z dux duy duz dvx dvy dvz nx ny nz
17 significant digits. At an extraordinary vertex itself the derivatives are
zero (the parameterisation has none there) and the normal is the limit normal
of that vertex.

Exit status: 0 on success; 1 if the input cannot be used (MESH or LOCATIONS
unreadable, a mesh the scheme does not evaluate, e.g. loop on quads, a location that is not one: the error names the line of LOCATIONS);
2 for a malformed command line (unknown option or scheme, a scheme not
evaluated, missing MESH, --scheme or --at). Errors are one line on stderr:
"cgal-subdiv: error: ...", and nothing is written then.
)";

const std::vector<Option_spec> evaluate_options = {
  {{"-o", "--output"}, true}, {{"--scheme"}, true}, {{"--at"}, true}, {{"--json"}, false}, {{"-h", "--help"}, false}};

/// One line of LOCATIONS, checked.
struct Location
{
  int line;
  std::size_t face;
  int corner; // -1: none
  double u, v;
};

// the line of LOCATIONS an error is about
struct Line_of
{
  const std::string& path;
  int number;
  Input_error error(const std::string& message) const
  {
    return Input_error(path + ":" + std::to_string(number) + ": " + message);
  }
};

// FACE or CORNER as written: a whole number, or -1 for one that no index
// reaches (negative, beyond int)
long parse_index(const std::string& token, const std::string& what, const Line_of& where)
{
  try {
    return std::max(parse_int(token), -1);
  } catch(const std::invalid_argument& e) {
    if(std::string(e.what()) == "too large")
      return -1;
    throw where.error(what + " '" + token + "' is not a whole number");
  }
}

bool names_infinity_or_nan(std::string token)
{
  if(!token.empty() && (token[0] == '+' || token[0] == '-'))
    token.erase(0, 1);
  for(char& c : token)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return token == "nan" || token == "inf" || token == "infinity";
}

// U or V, in [0, 1] (checked exactly, before rounding to the nearest double)
double parse_parameter(const std::string& token, const std::string& name, const std::string& domain,
                       const Line_of& where)
{
  Exact x;
  try {
    x = parse_number(token);
  } catch(const std::invalid_argument& e) {
    if(names_infinity_or_nan(token))
      throw where.error(name + " is '" + token + "', not a finite number");
    const std::string reason = e.what();
    throw where.error(name + " '" + token + "' is not a number" +
                      (reason == "not a number" ? "" : " (" + reason + ")"));
  }
  if(x < Exact(0) || x > Exact(1))
    throw where.error(name + " = " + token + " is outside " + domain);
  return nearest_double(x);
}

// FACE, a face of the mesh
Surface::Face_index parse_face(const std::string& token, const Surface& mesh, const Line_of& where)
{
  const long face = parse_index(token, "FACE", where);
  const std::size_t faces = mesh.number_of_faces();
  if(face < 0 || static_cast<std::size_t>(face) >= faces)
    throw where.error("face " + token + " out of range (the mesh has " + std::to_string(faces) +
                      (faces == 1 ? " face)" : " faces)"));
  return Surface::Face_index(static_cast<Surface::size_type>(face));
}

// CORNER, -1 if the line has none: a catmull-clark face with n != 4 corners
// needs one (Limit_surface addresses it as n sub-quads), any other face takes none
int parse_corner(const Data_line& line, int corners, Limit_scheme scheme, const Line_of& where)
{
  const bool given = line.tokens.size() == 4;
  const std::string face = "face " + line.tokens[0];
  if(scheme == Limit_scheme::loop && given)
    throw where.error("loop takes FACE U V: a CORNER picks a sub-quad of a catmull-clark face with n != 4 corners");
  if(scheme == Limit_scheme::catmull_clark && corners == 4 && given)
    throw where.error(face + " is a quad: give FACE U V, without a CORNER");
  if(scheme == Limit_scheme::catmull_clark && corners != 4 && !given)
    throw where.error(face + " has " + std::to_string(corners) +
                      " corners: give FACE CORNER U V, its sub-quad at CORNER");
  if(!given)
    return -1;
  const long corner = parse_index(line.tokens[1], "CORNER", where);
  if(corner < 0 || corner >= corners)
    throw where.error(face + " has no corner " + line.tokens[1] + " (its corners are 0 to " +
                      std::to_string(corners - 1) + ")");
  return static_cast<int>(corner);
}

// FACE [CORNER] U V, checked against the mesh and the scheme's domains
Location parse_location(const Data_line& line, const std::string& path, const Surface& mesh, Limit_scheme scheme)
{
  const Line_of where{path, line.number};
  const std::size_t fields = line.tokens.size();
  if(fields != 3 && fields != 4)
    throw where.error("expected FACE U V or FACE CORNER U V, got " + std::to_string(fields) + " fields");
  const Surface::Face_index face = parse_face(line.tokens[0], mesh, where);
  const int corner = parse_corner(line, static_cast<int>(mesh.degree(face)), scheme, where);
  const bool triangle = scheme == Limit_scheme::loop;
  const std::string domain = "the domain of face " + line.tokens[0] + (corner >= 0 ? "'s sub-quad" : "") +
                             (triangle ? " (u, v >= 0, u + v <= 1)" : " ([0, 1]^2)");
  const double u = parse_parameter(line.tokens[fields - 2], "u", domain, where);
  const double v = parse_parameter(line.tokens[fields - 1], "v", domain, where);
  // in doubles, as the evaluator checks it
  if(triangle && !(u + v <= 1))
    throw where.error("u + v = " + format_double(u + v) + " is outside " + domain);
  return Location{line.number, static_cast<std::size_t>(face), corner, u, v};
}

std::vector<Location> read_locations(const std::string& path, const Surface& mesh, Limit_scheme scheme)
{
  std::vector<Location> locations;
  for(const Data_line& line : read_data_lines(path))
    locations.push_back(parse_location(line, path, mesh, scheme));
  if(locations.empty())
    throw Input_error("'" + path + "' holds no locations (FACE U V or FACE CORNER U V per line)");
  return locations;
}

bool is_finite(const Limit_point& p)
{
  for(const Double_kernel::Vector_3& w : {p.position - CGAL::ORIGIN, p.du, p.dv, p.duu, p.duv, p.dvv, p.normal})
    if(!std::isfinite(w.x()) || !std::isfinite(w.y()) || !std::isfinite(w.z()))
      return false;
  return true;
}

std::vector<Limit_point> evaluate_all(const Limit_evaluator& evaluator, const std::vector<Location>& locations,
                                      const std::string& at, const std::string& input)
{
  std::vector<Limit_point> points;
  for(const Location& l : locations) {
    points.push_back(evaluator.evaluate(l.face, l.corner, l.u, l.v));
    if(!is_finite(points.back()))
      throw Line_of{at, l.line}.error("the limit there is not finite: the coordinates of '" + input +
                                      "' are too large for the scheme's weights; scale the mesh down");
  }
  return points;
}

std::string plain_vector(const Double_kernel::Vector_3& w)
{
  return format_double(w.x()) + " " + format_double(w.y()) + " " + format_double(w.z());
}

std::string json_vector(const Double_kernel::Vector_3& w)
{
  return "[" + json_number(w.x()) + ", " + json_number(w.y()) + ", " + json_number(w.z()) + "]";
}

void write_lines(const std::vector<Limit_point>& points, std::ostream& out)
{
  for(const Limit_point& p : points)
    out << plain_vector(p.position - CGAL::ORIGIN) << ' ' << plain_vector(p.du) << ' ' << plain_vector(p.dv) << ' '
        << plain_vector(p.normal) << '\n';
}

void write_json(const std::string& scheme, const std::vector<Location>& locations,
                const std::vector<Limit_point>& points, std::ostream& out)
{
  out << "{\n  \"scheme\": " << json_string(scheme) << ",\n  \"locations\": [";
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Location& l = locations[i];
    const Limit_point& p = points[i];
    out << (i ? ",\n" : "\n") << "    {\"line\": " << l.line << ", \"face\": " << l.face
        << ", \"corner\": " << (l.corner >= 0 ? std::to_string(l.corner) : "null") << ", \"u\": " << json_number(l.u)
        << ", \"v\": " << json_number(l.v) << ", \"position\": " << json_vector(p.position - CGAL::ORIGIN)
        << ", \"du\": " << json_vector(p.du) << ", \"dv\": " << json_vector(p.dv) << ", \"duu\": " << json_vector(p.duu)
        << ", \"duv\": " << json_vector(p.duv) << ", \"dvv\": " << json_vector(p.dvv)
        << ", \"normal\": " << json_vector(p.normal) << "}";
  }
  out << "\n  ]\n}\n";
}

} // namespace

int evaluate_command(const std::vector<std::string>& arguments)
{
  const Parsed_args args = scan_args(arguments, evaluate_options, "evaluate");
  if(args.has("-h")) {
    std::cout << evaluate_help;
    return 0;
  }
  const Limit_arguments limit = limit_arguments(args, "evaluate");
  if(!args.has("--at") || args.value("--at").empty())
    throw Usage_error("missing --at LOCATIONS");
  if(args.has("-o") && args.value("-o").empty())
    throw Usage_error("-o needs a file name");
  const std::string at = args.value("--at");

  std::vector<std::string> notes;
  const Surface mesh = read_surface(limit.input, Soup_fix::none, notes);
  const Limit_evaluator evaluator(mesh, limit.scheme); // refuses the mesh before the locations are read
  const std::vector<Location> locations = read_locations(at, mesh, limit.scheme);
  const std::vector<Limit_point> points = evaluate_all(evaluator, locations, at, limit.input);

  // everything computed: only now is anything written
  std::ostringstream text;
  if(args.has("--json"))
    write_json(limit.scheme_name, locations, points, text);
  else
    write_lines(points, text);
  if(args.has("-o")) {
    Atomic_file file(args.value("-o"));
    file.stream() << text.str();
    file.commit();
  } else {
    std::cout << text.str() << std::flush;
  }
  print_notes(notes);
  return 0;
}

} // namespace cgal_subdiv
