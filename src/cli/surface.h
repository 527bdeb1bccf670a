// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Surface meshes in cgal-subdiv: the table of surface schemes, reading and
// writing OFF, OBJ, PLY and STL through CGAL::IO, and one timed run.
#ifndef CGAL_SUBDIV_CLI_SURFACE_H
#define CGAL_SUBDIV_CLI_SURFACE_H

#include "common.h"
#include "mesh_soup.h"
#include "surface_from_soup.h"
#include "surface_tags.h"

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cgal_subdiv {

/// One surface scheme of `cgal-subdiv surface --scheme NAME`.
struct Surface_scheme
{
  std::string name;        // the keyword, e.g. "catmull-clark"
  std::string description; // one line for --help and the demo
  /// refines `mesh` `levels` times, refusing an output above `max_memory`
  /// bytes (0: this machine's memory); throws CGAL::Subdiv::Bad_input when
  /// the scheme does not apply (the mesh is then unchanged)
  std::function<void(Surface& mesh, int levels, double max_memory)> run;
  /// refines triangle meshes only
  bool triangles_only = true;
  /// whether `run(m, a); run(m, b)` equals `run(m, a + b)`, so that a long run
  /// can report its progress level by level
  bool level_by_level = true;
  /// factor by which the face count grows per level, and the peak memory
  /// per output face (for the size check before any work; the library
  /// checks again): the host's own numbers
  double face_growth = 4;
  double bytes_per_face = 100;
  /// refines with the sharpness maps of the mesh (surface_tags.h) and the
  /// options of the tags; empty for the schemes that do not take tags
  std::function<void(Surface& mesh, int levels, double max_memory, const Sharp_options& options)> run_sharp;
  /// whether it takes semi-sharp values (the butterflies take infinitely
  /// sharp ones only)
  bool semi_sharp = true;
  /// whether --limit and --displace take the tags too (not for doo-sabin:
  /// `internal::Limit_takes_sharpness_tags`)
  bool limit_sharp = true;
  /// whether `run_sharp`, which carries the texture coordinates of the mesh
  /// (surface_from_soup.h) in the mode of the options, carries them with
  /// seams: the schemes that split edges; doo-sabin and the sqrt3 schemes
  /// carry them without seams only (`texture_seam`)
  bool carries_texture_seams = false;
};

/// the first seam of the texture coordinates of `mesh` (two corners of a
/// vertex with different vt indices, as `Carried_data` tells them apart),
/// "vertex 12 has different ones in faces 3 and 5", the vertex by its number
/// in the file (`file_numbers`, by vertex, if not empty) and the faces from 0
/// in the file's order; empty if there is none
std::string texture_seam(const Surface& mesh, const std::vector<std::size_t>& file_numbers);

/// every scheme this build offers, in the order of --help
const std::vector<Surface_scheme>& surface_schemes();
/// every scheme keyword the command knows, offered or not yet
const std::vector<std::string>& surface_scheme_keywords();
/// \throws Usage_error for an unknown keyword, Input_error for one that is not
///         available in this build yet
const Surface_scheme& find_surface_scheme(const std::string& name);

/// "loop, loop-warren, ... or linear"
std::string list_surface_schemes();

/// the format of `path` from its extension (any letter case);
/// \throws Usage_error naming `role` ("INPUT", "OUTPUT") for any other extension
Mesh_format mesh_format(const std::string& path, const std::string& role);

struct Mesh_counts
{
  std::size_t vertices = 0, edges = 0, faces = 0;
};
Mesh_counts counts(const Surface& mesh);
/// "8 V, 18 E, 12 F"
std::string describe(const Mesh_counts& counts);
/// "0.125 s"
std::string seconds_text(double seconds);

/*
 * reads `path` (format from the extension) with the checked reader of
 * mesh_soup.h, drops the vertices that no face uses (with a note), and builds
 * the mesh with CGAL::Polygon_mesh_processing once the soup is known to be a
 * manifold polygon mesh. A soup that is not one is refused, or `fix`ed
 * (surface_from_soup.h: repaired, or split as OpenSubdiv refines it) with a
 * note.
 * What the file holds besides points and faces is ignored, with a note.
 * \throws Input_error saying why the file cannot be used: missing, not
 *         readable, malformed (naming the line or byte), not a manifold
 *         polygon mesh (naming a face, an edge or a vertex), no faces
 */
Surface read_surface(const std::string& path, Soup_fix fix, std::vector<std::string>& notes,
                     std::vector<std::size_t>* file_numbers = nullptr);

/// the tag lines (t) of an OBJ file, and the number of vertices of the file
struct File_tags
{
  std::vector<Obj_tag> tags;
  std::size_t file_vertices = 0;
};

/// `read_surface` that also hands over the tag lines, which are then not
/// noted as ignored
Surface read_surface(const std::string& path, Soup_fix fix, std::vector<std::string>& notes,
                     std::vector<std::size_t>* file_numbers, File_tags& tags);

/// the largest coordinate (in magnitude) of a mesh, and where it is
struct Largest_coordinate
{
  std::size_t vertex = 0; // the vertex index in the mesh
  double value = 0;
};
Largest_coordinate largest_coordinate(const Surface& mesh);

/*
 * refuses a result with a non-finite coordinate: names the input (`input`,
 * its largest coordinate `largest`, at the vertex the file numbers
 * `file_numbers[largest.vertex]` if known) as the likely cause, since every
 * scheme's weights are bounded and only coordinates near the largest double
 * overflow. `what` names the step ("loop, 3 levels").
 * \throws Input_error
 */
void check_finite_result(const Surface& result, const std::string& what, const std::string& input,
                         const Largest_coordinate& largest, const std::vector<std::size_t>& file_numbers);

/// normalises the vertex normals of `mesh`, if it has them (surface_from_soup.h):
/// a vertex whose carried normal is zero (its corners' normals cancelled out,
/// or a `vn 0 0 0`) gets the normal of the surface there, the normalised sum of
/// the unit normals of its corners, or 0 0 0 where that is zero too (a
/// degenerate neighbourhood). Returns how many vertices fell back so.
std::size_t finish_normals(Surface& mesh);

/// writes `mesh` to `path` (format from the extension), ASCII with 17
/// significant digits or, with `binary`, binary PLY or STL (STL's 32-bit
/// floats), under a temporary name renamed at the end;
/// \throws Input_error, or Usage_error for `binary` with OFF or OBJ
/// writes `mesh` (with `tags`, an OBJ file also gets the sharpness maps and
/// the options as OpenSubdiv's tag lines; the texture coordinates of a mesh
/// that has them go to an OBJ file as vt lines with their seams, and
/// `face_varying` as the tag `t facevaryinginterpolateboundary`; its vertex
/// normals as one vn line per vertex, the corners `v/vt/vn` or `v//vn`)
void write_surface(
  const Surface& mesh, const std::string& path, bool binary = false, const Sharp_options* tags = nullptr,
  CGAL::Subdiv::Face_varying_interpolation face_varying = CGAL::Subdiv::Face_varying_interpolation::corners_plus1);

/// one line of progress: level (1-based), mesh after it, seconds since start
using Level_callback = std::function<void(int level, const Mesh_counts& counts, double seconds)>;

struct Surface_result
{
  Mesh_counts in, out;
  double seconds = 0; // subdivision only, not reading or writing
};

/// the faces of `levels` levels of `scheme` on `faces` faces, as a double
/// (inf when too large), in constant time
double predicted_faces(const Surface_scheme& scheme, double faces, int levels);

/// refuses, in constant time, `levels` levels of `scheme` on `mesh` whose
/// output would take more than `max_memory` bytes (0: this machine's memory)
/// \throws CGAL::Subdiv::Bad_input that names the output faces and GB
void check_output_size(const Surface_scheme& scheme, const Surface& mesh, int levels, double max_memory);

/// \throws Input_error when there are `tags` and `scheme` does not take them
void refuse_tags_unless_taken(const Surface_scheme& scheme, const Sharp_options* tags);

/*
 * refines `mesh` `levels` times with `scheme`. Checks first that the output
 * fits in `max_memory` bytes (0: this machine's memory; negative levels and
 * too large outputs are refused before any work). If `on_level` is set and
 * the scheme allows it, runs level by level and calls it after each level.
 * With `tags`, refines with the sharpness maps of the mesh (`run_sharp`).
 * \throws CGAL::Subdiv::Bad_input when the scheme does not apply;
 *         Input_error when there are tags and the scheme does not take them
 */
Surface_result subdivide_surface(Surface& mesh, const Surface_scheme& scheme, int levels, double max_memory,
                                 const Level_callback& on_level = Level_callback(),
                                 const Sharp_options* tags = nullptr);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_H
