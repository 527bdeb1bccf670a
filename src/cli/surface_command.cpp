// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv surface INPUT -o OUTPUT --scheme S --levels N [--repair] [--verbose]
#include "args.h"
#include "commands.h"
#include "surface.h"
#include "surface_limit.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <sstream>

namespace cgal_subdiv {
namespace {

// --boundary, --crease-method and --smooth-triangles: over the file's tags
void apply_sharp_options(const Parsed_args& args, Sharp_options& options)
{
  if(args.has("--boundary")) {
    const std::string mode = args.value("--boundary");
    if(mode == "none")
      options.boundary = CGAL::Subdiv::Boundary_interpolation::none;
    else if(mode == "edges")
      options.boundary = CGAL::Subdiv::Boundary_interpolation::edges_only;
    else if(mode == "edges-and-corners")
      options.boundary = CGAL::Subdiv::Boundary_interpolation::edges_and_corners;
    else
      throw Usage_error("--boundary is none, edges or edges-and-corners, not '" + mode + "'");
    options.present = true;
  }
  if(args.has("--crease-method")) {
    const std::string method = args.value("--crease-method");
    if(method != "uniform" && method != "chaikin")
      throw Usage_error("--crease-method is uniform or chaikin, not '" + method + "'");
    options.method = method == "chaikin" ? CGAL::Subdiv::Crease_method::chaikin : CGAL::Subdiv::Crease_method::uniform;
    options.present = true;
  }
  if(args.has("--smooth-triangles")) {
    options.triangles = CGAL::Subdiv::Triangle_subdivision::smooth;
    options.present = true;
  }
}

// --sharp-angle: the edges where the surface bends more become infinitely
// sharp, with the file's creases
void apply_sharp_angle(const Parsed_args& args, Surface& mesh, Sharp_options& options, std::vector<std::string>& notes)
{
  if(!args.has("--sharp-angle"))
    return;
  const double angle = CGAL::to_double(args.number("--sharp-angle", Exact(0)));
  if(!(angle >= 0 && angle <= 180))
    throw Usage_error("--sharp-angle is an angle in degrees, from 0 to 180, not '" + args.value("--sharp-angle") + "'");
  const std::size_t marked = mark_sharp_angle(mesh, angle);
  notes.push_back("--sharp-angle " + args.value("--sharp-angle") + " made " + std::to_string(marked) +
                  (marked == 1 ? " edge" : " edges") + " infinitely sharp");
  options.present = true;
}

// whether the texture coordinates of `mesh` (an OBJ file's vt) are carried
// to OUTPUT: they are removed, with a note, where they cannot be (a seam
// that the scheme does not carry is named by the file's numbers)
bool keep_texture_points(Surface& mesh, const Surface_scheme& scheme, const Parsed_args& args,
                         Mesh_format output_format, const std::string& input,
                         const std::vector<std::size_t>& file_numbers, std::vector<std::string>& notes)
{
  if(!has_texture_points(mesh)) {
    if(args.has("--fvar"))
      notes.push_back("--fvar: '" + input + "' has no texture coordinates (vt referenced by every face) to carry");
    return false;
  }
  std::string why;
  if(!scheme.run_sharp)
    why = "--scheme " + scheme.name + " does not carry them";
  else if(args.has("--displace"))
    why = "--displace does not carry them yet";
  else if(output_format != Mesh_format::obj)
    why = "OUTPUT '" + args.value("-o") + "' is " + mesh_format_name(output_format) +
          ", which holds none (write .obj to keep them)";
  else if(!scheme.carries_texture_seams)
    if(const std::string seam = texture_seam(mesh, file_numbers); !seam.empty())
      why = "--scheme " + scheme.name +
            " carries them without seams only (it makes faces across the old edges; loop, loop-warren, "
            "catmull-clark, linear and the butterflies carry seams), and " +
            seam;
  if(why.empty())
    return true;
  notes.push_back("left the texture coordinates (vt) of '" + input + "' out: " + why);
  remove_texture_points(mesh);
  return false;
}

// why vertex data of INPUT cannot reach OUTPUT, empty if it can: --displace
// does not carry it, and OUTPUT's format may hold none (`holds`; `formats`
// names those that do)
std::string why_vertex_data_left_out(const Parsed_args& args, Mesh_format output_format, bool holds,
                                     const char* formats)
{
  if(args.has("--displace"))
    return "--displace does not carry them yet";
  if(!holds)
    return "OUTPUT '" + args.value("-o") + "' is " + mesh_format_name(output_format) + ", which holds none (write " +
           formats + " to keep them)";
  return "";
}

// whether the vertex colours of `mesh` (a COFF or PLY file's) are carried to
// OUTPUT: they are removed, with a note, where they cannot be
void keep_colours(Surface& mesh, const Parsed_args& args, Mesh_format output_format, const std::string& input,
                  std::vector<std::string>& notes)
{
  if(!colours_of(mesh))
    return;
  const std::string why = why_vertex_data_left_out(
    args, output_format, output_format == Mesh_format::off || output_format == Mesh_format::ply, ".off or .ply");
  if(why.empty())
    return;
  notes.push_back("left the vertex colours of '" + input + "' out: " + why);
  remove_colours(mesh);
}

// whether the vertex normals of `mesh` (an OBJ file's vn) are carried to
// OUTPUT: they are removed, with a note, where they cannot be
void keep_normals(Surface& mesh, const Parsed_args& args, Mesh_format output_format, const std::string& input,
                  std::vector<std::string>& notes)
{
  if(!normals_of(mesh))
    return;
  const std::string why = why_vertex_data_left_out(args, output_format, output_format == Mesh_format::obj, ".obj");
  if(why.empty())
    return;
  notes.push_back("left the normals (vn) of '" + input + "' out: " + why);
  remove_normals(mesh);
}

// the carried normals of `mesh`, if any, made unit length before writing
void finish_carried_normals(Surface& mesh, const std::string& output, std::vector<std::string>& notes)
{
  const std::size_t fallbacks = finish_normals(mesh);
  if(fallbacks > 0)
    notes.push_back(std::to_string(fallbacks) + (fallbacks == 1 ? " vertex" : " vertices") + " of '" + output +
                    "' got the normal of the surface there: the normals (vn) carried to " +
                    (fallbacks == 1 ? "it" : "them") + " summed to zero");
}

const char* const surface_help_head = R"(usage: cgal-subdiv surface INPUT -o OUTPUT --scheme SCHEME --levels N [--limit]
                           [--displace HEIGHTS] [--repair] [--split-non-manifold]
                           [--max-memory SIZE]
                           [--boundary MODE] [--crease-method METHOD]
                           [--smooth-triangles] [--sharp-angle DEGREES]
                           [--fvar MODE] [--binary] [--verbose]

Refines the polygon mesh in INPUT with a surface subdivision scheme and writes
the result to OUTPUT. One line on stdout sums it up: vertices (V), edges (E)
and faces (F) before and after, and the time the subdivision took (reading and
writing not included).

  INPUT                 OFF, OBJ, PLY or STL (from the extension, any letter
                        case), read with CGAL::IO::read_polygon_mesh into a
                        Surface_mesh<Simple_cartesian<double>::Point_3>. It must
                        be a manifold polygon mesh (borders allowed); if it is
                        not, the error names the edge or vertex at fault.
                        The vertex colours of an ASCII COFF file and of a
                        PLY file (red, green, blue, alpha: integers from 0
                        to 255, or reals from 0 to 1) are carried with the
                        weights of the points to an OFF or PLY OUTPUT; the
                        texture coordinates of an OBJ file (vt, when every
                        face references them: f v/vt) with their seams (see
                        --fvar) to an OBJ OUTPUT; its normals (vn, when
                        every face references them) as vertex data: a
                        vertex gets the mean of its corners' normals,
                        refined with the weights of the points, written
                        normalised, one vn per vertex, to an OBJ OUTPUT.
                        Other properties are ignored.
                        OpenSubdiv's OBJ tags are read: t crease, t corner
                        (vertices from 0), t hole (faces from 0),
                        t interpolateboundary (RenderMan's numbers: 0 none,
                        1 edges and corners, 2 edges only), t creasemethod
                        (normal or chaikin) and t smoothtriangles (catmark or
                        smooth), for loop, loop-warren, catmull-clark,
                        linear (where they move no point), the butterflies,
                        the sqrt3 schemes and doo-sabin (infinitely sharp
                        ones; doo-sabin without --limit, --displace); an
                        OBJ OUTPUT gets the children's tags (holes included),
                        OFF, PLY and STL leave the holes out. Other tags are
                        ignored, with a note.
  -o, --output OUTPUT   OFF, OBJ, PLY or STL (from the extension), ASCII, 17
                        significant digits; STL holds triangles, so other faces
                        are split into triangles there. Written to a temporary
                        file and renamed at the end: a failed run leaves no
                        OUTPUT behind.
  --binary              write binary PLY or STL (for big outputs; STL's
                        32-bit floats round the coordinates)
  --scheme SCHEME       the scheme:
)";

const char* const surface_help_tail = R"(  --levels N            number of refinement levels (N >= 0)
  --limit               then move every vertex to its limit position (the
                        limit masks of the scheme's eigen-analysis; doo-sabin,
                        a dual scheme: the limit of the face the next step
                        makes of the corners at the vertex). With creases and
                        corners, a corner stays and a crease vertex goes to
                        the limit of its crease curve
  --displace HEIGHTS    displacement: HEIGHTS holds one height per vertex of
                        INPUT, in INPUT's vertex order, one per line (a decimal
                        or a fraction; blank lines and # comments skipped).
                        The heights are refined with the points; every vertex
                        then goes to its limit position plus its limit height
                        along its unit limit normal
  --repair              read INPUT as a polygon soup, repair and orient it
                        (CGAL::Polygon_mesh_processing::IO::read_polygon_mesh):
                        for files that are not manifold meshes as they stand
  --split-non-manifold  read a non-manifold INPUT as OpenSubdiv refines it: split
                        into a manifold mesh (CGAL's orient_polygon_soup) whose
                        split edges are sharp and whose non-manifold vertices
                        are corners, unless on a non-manifold crease (loop,
                        loop-warren, catmull-clark; the tags of INPUT apply to
                        every copy of a vertex)
  --boundary MODE       none, edges or edges-and-corners: OpenSubdiv's boundary
                        interpolation (default edges, or INPUT's tag); none
                        refines as edges and makes the faces at the border
                        holes, left out of the OUTPUT
  --crease-method METHOD
                        uniform or chaikin: how semi-sharp creases decay
                        (default uniform, or INPUT's tag)
  --smooth-triangles    catmull-clark: OpenSubdiv's TRI_SUB_SMOOTH edge rule
                        next to triangles (or INPUT's tag)
  --sharp-angle DEGREES loop, loop-warren, catmull-clark, linear, the
                        butterflies, the sqrt3 schemes and doo-sabin: every
                        edge whose two faces' normals make more than DEGREES
                        (0 to 180) becomes infinitely sharp (CGAL's
                        detect_sharp_edges), with the creases of INPUT
  --fvar MODE           how the texture coordinates of an OBJ INPUT are
                        refined, OpenSubdiv's face-varying modes: none (smooth
                        everywhere, a seam refined as a border), corners-only,
                        corners-plus1 (the default, as in USD), corners-plus2,
                        boundaries, all (linear in every face). Default: the
                        tags t facevaryinginterpolateboundary (0 to 5, in this
                        order) and t facevaryingpropagatecorners of INPUT.
                        loop, loop-warren, catmull-clark, linear and the
                        butterflies carry them; with --limit they are those of
                        the last level
  --max-memory SIZE     refuse, before any work, a run whose output would take
                        more memory than SIZE (default: this machine's memory),
                        e.g. 8G, 512MB, 2GiB; the estimate is the output faces
                        times the measured bytes per face (doc/memory.md)
  -v, --verbose         a line on stderr per level (V, E, F, time); without it,
                        such lines appear on runs whose output exceeds a
                        million faces, once the run has taken a second
  -h, --help            show this help

Exit status: 0 on success; 1 if the input cannot be used (file missing,
unreadable or not parsable, not a manifold polygon mesh, a mesh the scheme does
not apply to, e.g. a quad for loop, negative levels, an output that would not
fit in memory); 2 for a malformed command line (unknown option or scheme, an
extension other than .off, .obj, .ply, .stl, missing -o, INPUT, --scheme or
--levels). Errors are one line on stderr: "cgal-subdiv: error: ...".
)";

const std::vector<Option_spec> surface_options = {{{"-o", "--output"}, true},
                                                  {{"--scheme"}, true},
                                                  {{"--levels"}, true},
                                                  {{"--repair"}, false},
                                                  {{"--limit"}, false},
                                                  {{"--displace"}, true},
                                                  {{"-v", "--verbose"}, false},
                                                  {{"-h", "--help"}, false},
                                                  {{"--max-memory"}, true},
                                                  {{"--binary"}, false},
                                                  {{"--boundary"}, true},
                                                  {{"--crease-method"}, true},
                                                  {{"--smooth-triangles"}, false},
                                                  {{"--sharp-angle"}, true},
                                                  {{"--split-non-manifold"}, false},
                                                  {{"--fvar"}, true}};

// "  name   description" with the description wrapped at 80 columns
std::string scheme_help_line(const std::string& name, const std::string& description)
{
  const std::size_t indent = 47, width = 80;
  std::string text = std::string(26, ' ') + name;
  text.resize(std::max(text.size() + 1, indent), ' ');
  std::size_t column = text.size();
  std::istringstream words(description);
  bool first = true;
  for(std::string word; words >> word; first = false) {
    if(!first && column + 1 + word.size() > width) {
      text += "\n" + std::string(indent, ' ');
      column = indent;
    } else if(!first) {
      text += ' ';
      ++column;
    }
    text += word;
    column += word.size();
  }
  return text + "\n";
}

std::string surface_help()
{
  std::string help = surface_help_head;
  for(const bool triangles : {true, false}) {
    help +=
      triangles ? "                        triangle meshes only:\n" : "                        any polygon mesh:\n";
    for(const std::string& name : surface_scheme_keywords()) {
      const Surface_scheme* scheme = nullptr;
      for(const Surface_scheme& s : surface_schemes())
        if(s.name == name)
          scheme = &s;
      if(scheme ? scheme->triangles_only == triangles : triangles)
        help += scheme_help_line(name, scheme ? scheme->description : "(not yet available in this build)");
    }
  }
  return help + surface_help_tail;
}

} // namespace

int surface_command(const std::vector<std::string>& arguments)
{
  const Parsed_args args = scan_args(arguments, surface_options, "surface");
  if(args.has("-h")) {
    std::cout << surface_help();
    return 0;
  }
  if(args.positional.empty())
    throw Usage_error("missing INPUT; see 'cgal-subdiv surface --help'");
  if(args.positional.size() > 1)
    throw Usage_error("unexpected argument '" + args.positional[1] + "' (only one INPUT)");
  if(!args.has("-o") || args.value("-o").empty())
    throw Usage_error("missing -o OUTPUT");
  if(!args.has("--scheme"))
    throw Usage_error("missing --scheme (" + list_surface_schemes() + ")");
  if(!args.has("--levels"))
    throw Usage_error("missing --levels N");
  const std::string input = args.positional.front();
  const std::string output = args.value("-o");
  mesh_format(input, "INPUT");
  const Mesh_format output_format = mesh_format(output, "OUTPUT");
  if(args.has("--binary") && output_format != Mesh_format::ply && output_format != Mesh_format::stl)
    throw Usage_error("--binary writes PLY and STL only; OUTPUT '" + output + "' is " +
                      mesh_format_name(output_format));
  const int levels = args.integer("--levels", 0);
  if(levels < 0)
    throw Input_error("the number of levels must not be negative, got " + std::to_string(levels));
  const Surface_scheme& scheme = find_surface_scheme(args.value("--scheme"));
  const double max_memory = args.bytes("--max-memory", 0);
  const bool verbose = args.has("-v");
  const bool displace = args.has("--displace");

  std::vector<std::string> notes;
  std::vector<std::size_t> file_numbers;
  File_tags file_tags;
  if(args.has("--repair") && args.has("--split-non-manifold"))
    throw Usage_error("--repair and --split-non-manifold are two ways to read a non-manifold INPUT: one at a time");
  const Soup_fix fix = args.has("--repair")               ? Soup_fix::repair
                       : args.has("--split-non-manifold") ? Soup_fix::split_non_manifold
                                                          : Soup_fix::none;
  Surface mesh = read_surface(input, fix, notes, &file_numbers, file_tags);
  // OpenSubdiv's tags (OBJ): the sharpness maps of the mesh and the options
  Sharp_options sharp_options;
  if(!file_tags.tags.empty() && args.has("--repair"))
    notes.push_back("ignored the " + std::to_string(file_tags.tags.size()) + " tag lines (t) of '" + input +
                    "': --repair renumbers the vertices they name");
  else if(!file_tags.tags.empty())
    sharp_options = apply_obj_tags(file_tags.tags, file_tags.file_vertices, mesh, file_numbers, input, notes,
                                   scheme.semi_sharp ? std::string() : scheme.name);
  apply_sharp_options(args, sharp_options);
  apply_sharp_angle(args, mesh, sharp_options, notes);
  sharp_options.present = sharp_options.present || has_sharpness(mesh); // the split's corners and creases
  const bool tagged = sharp_options.present;
  if(args.has("--fvar"))
    sharp_options.face_varying = face_varying_mode(args.value("--fvar"));
  // the texture coordinates are carried by the refinement with tags (which
  // takes the plain path when they are all zero, as they are then)
  const bool textured = keep_texture_points(mesh, scheme, args, output_format, input, file_numbers, notes);
  keep_colours(mesh, args, output_format, input, notes);
  keep_normals(mesh, args, output_format, input, notes);
  const Sharp_options* refine_options = tagged || textured ? &sharp_options : nullptr;
  if(tagged && !scheme.limit_sharp && (displace || args.has("--limit")))
    throw Input_error("--scheme " + scheme.name +
                      " refines with crease and corner tags, but its limit (--limit, --displace) does not take "
                      "them: the limit of its creases is not derived");
  const Largest_coordinate largest = largest_coordinate(mesh);
  const std::vector<double> heights =
    displace ? read_heights(args.value("--displace"), mesh.number_of_vertices()) : std::vector<double>();
  // progress: every level with --verbose, otherwise once the run is long
  bool talking = verbose;
  const Level_callback progress = [&](int level, const Mesh_counts& c, double seconds) {
    talking = talking || seconds >= 1.0;
    if(talking)
      std::cerr << "cgal-subdiv: " << scheme.name << " level " << level << " of " << levels << ": " << describe(c)
                << " (" << seconds_text(seconds) << ")" << std::endl;
  };
  // level by level (a library call each, each checking its input) only when
  // asked or when the run is long enough for progress to matter
  check_output_size(scheme, mesh, levels, max_memory);
  const bool by_level = verbose || predicted_faces(scheme, static_cast<double>(mesh.number_of_faces()), levels) >= 1e6;
  Surface_result result;
  if(displace) {
    result = displace_surface(mesh, scheme, levels, max_memory, heights, tagged ? &sharp_options : nullptr);
  } else {
    result =
      subdivide_surface(mesh, scheme, levels, max_memory, by_level ? progress : Level_callback(), refine_options);
    if(args.has("--limit")) {
      const auto start = std::chrono::steady_clock::now();
      project_surface_to_limit(mesh, scheme, tagged ? &sharp_options : nullptr);
      result.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  }
  const std::string step = scheme.name + ", " + std::to_string(levels) + (levels == 1 ? " level" : " levels") +
                           (displace              ? " and --displace"
                            : args.has("--limit") ? " and --limit"
                                                  : "");
  check_finite_result(mesh, step, input, largest, file_numbers);
  if(talking)
    std::cerr << "cgal-subdiv: writing " << output << std::endl;
  finish_carried_normals(mesh, output, notes);
  write_surface(mesh, output, args.has("--binary"), tagged ? &sharp_options : nullptr, sharp_options.face_varying);

  for(const std::string& note : notes)
    std::cerr << "cgal-subdiv: note: " << note << '\n';
  std::cout << scheme.name << ", " << levels << (levels == 1 ? " level" : " levels")
            << (displace              ? ", displaced: "
                : args.has("--limit") ? ", limit: "
                                      : ": ")
            << describe(result.in) << " -> " << describe(result.out) << " in " << seconds_text(result.seconds)
            << "; wrote " << output << std::endl;
  return 0;
}

} // namespace cgal_subdiv
