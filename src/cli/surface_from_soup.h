// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The checked polygon soup of mesh_soup.h made into a Surface_mesh: the one
// way cgal-subdiv (and its fuzzer) builds a mesh from a file.
#ifndef CGAL_SUBDIV_CLI_SURFACE_FROM_SOUP_H
#define CGAL_SUBDIV_CLI_SURFACE_FROM_SOUP_H

#include "common.h"
#include "mesh_soup.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>

#include <optional>

#include <string>
#include <vector>

namespace cgal_subdiv {

using Surface = CGAL::Surface_mesh<Double_kernel::Point_3>;

/// the maps the tags are kept in, on the mesh: "e:sharpness", "v:sharpness"
/// (double), "f:hole" (bool); the split of a non-manifold soup writes the
/// first two, the OBJ tags (surface_tags.h) all three
inline constexpr const char* edge_sharpness_name = "e:sharpness";
inline constexpr const char* vertex_sharpness_name = "v:sharpness";
inline constexpr const char* face_hole_name = "f:hole";

/// the maps the texture coordinates of an OBJ file (`vt`, referenced by
/// `f v/vt`) are kept in, per corner (the halfedge whose target is the
/// corner's vertex, in its face): the value (u, v) and the index of the
/// `vt` line (from 0). Two corners at a vertex with different indices are
/// a seam; refinement carries both (`CGAL::Subdiv::Carried_data::corner_map`).
using Texture_point = Double_kernel::Point_2;
inline constexpr const char* texture_point_name = "h:uv";
inline constexpr const char* texture_index_name = "h:uv_index";
/// the map the point of the soup that each vertex copies is kept in, beside
/// the texture coordinates of a split soup (`--split-non-manifold`): the
/// copies of a point are one non-manifold vertex for them, as for OpenSubdiv
/// (`CGAL::Subdiv::Carried_data::non_manifold_copies`)
inline constexpr const char* soup_point_name = "v:soup_point";
using Texture_point_map = Surface::Property_map<Surface::Halfedge_index, Texture_point>;
using Texture_index_map = Surface::Property_map<Surface::Halfedge_index, std::size_t>;

/// whether `mesh` has texture coordinates (both maps above)
bool has_texture_points(const Surface& mesh);
/// removes them (for the schemes and options that cannot carry them)
void remove_texture_points(Surface& mesh);

/// the map the vertex colours of a COFF or PLY file are kept in: CGAL's own
/// name, which its PLY writer writes as red, green, blue and alpha
/// (refinement carries it, `CGAL::Subdiv::Carried_data::vertex_map`)
inline constexpr const char* colour_name = "v:color";
using Colour_map = Surface::Property_map<Surface::Vertex_index, CGAL::IO::Color>;
/// the vertex colours of `mesh`, if it has them
std::optional<Colour_map> colours_of(const Surface& mesh);
/// removes them (for the options and outputs that cannot carry them)
void remove_colours(Surface& mesh);

/// the map the normals of an OBJ file (`vn`, referenced by every face:
/// `f v//vn`, `f v/vt/vn`) are kept in, as vertex data: a vertex has the mean
/// of the unit normals its corners reference (the same one, but for split
/// normals), normalised; zero where they cancel out. Refinement carries it
/// with the weights of the points (`CGAL::Subdiv::Carried_data::vertex_map`);
/// `finish_normals` (surface.h) normalises the result.
using Normal = Double_kernel::Vector_3;
inline constexpr const char* normal_name = "v:normal";
using Normal_map = Surface::Property_map<Surface::Vertex_index, Normal>;
/// the vertex normals of `mesh`, if it has them
std::optional<Normal_map> normals_of(const Surface& mesh);
/// removes them (for the options and outputs that cannot carry them)
void remove_normals(Surface& mesh);

/// `v` scaled to length 1, computed on `v` divided by its largest component
/// so that no square overflows: finite for any finite `v`; zero for zero
Normal unit_or_zero(const Normal& v);

/// what is done with a soup that is not a manifold polygon mesh
enum class Soup_fix {
  none,              ///< nothing: it is refused, naming the face, edge or vertex at fault
  repair,            ///< repair_polygon_soup and orient_polygon_soup (--repair)
  split_non_manifold ///< CGAL::Subdiv::split_non_manifold, with OpenSubdiv's sharpness (--split-non-manifold)
};

/*
 * `soup` (read from `path`, in `format`) as a Surface_mesh: its notes are
 * added to `notes`, the vertices that no face uses are dropped (with a note),
 * and the mesh is built with CGAL::Polygon_mesh_processing once the soup is
 * known to be a manifold polygon mesh. A soup that is not one is refused,
 * or (`fix`) repaired and oriented first (repair_polygon_soup,
 * orient_polygon_soup), or split with the sharpness OpenSubdiv gives its
 * non-manifold edges and vertices (in the maps of surface_tags.h), and a
 * note says so. `file_numbers`, if given, receives the number in the file
 * of every vertex of the mesh (OBJ counts from 1; the copies of a split
 * vertex have its number); empty with `repair`, which merges and splits
 * vertices. The texture coordinates of an OBJ file whose every face has
 * them go to the maps `texture_point_name` and `texture_index_name`
 * (not with `repair`, which reorders faces: a note says they were ignored),
 * the vertex colours of a COFF or PLY file to the map `colour_name`
 * and the normals of an OBJ file whose every face has them to the map
 * `normal_name`, with a note when some vertex has split normals (not with
 * `repair` either, which merges vertices).
 * \throws Input_error: no faces, or not a manifold polygon mesh (naming a
 *         face, an edge or a vertex: by its number in the file and its point)
 */
Surface surface_from_soup(const Mesh_soup& soup, const std::string& path, Mesh_format format, Soup_fix fix,
                          std::vector<std::string>& notes, std::vector<std::size_t>* file_numbers = nullptr);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_FROM_SOUP_H
