// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// OpenSubdiv's OBJ tags (`t crease`, `t corner`, `t hole`,
// `t interpolateboundary`, `t creasemethod`, `t smoothtriangles`) as the
// sharpness and hole maps of a Surface_mesh, checked line by line, and
// written back after a refinement.
#ifndef CGAL_SUBDIV_CLI_SURFACE_TAGS_H
#define CGAL_SUBDIV_CLI_SURFACE_TAGS_H

#include "mesh_soup.h"
#include "surface_from_soup.h"

#include <CGAL/Subdiv/masks/Linear_quad_mask.h>
#include <CGAL/Subdiv/masks/Linear_triangle_mask.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/Face_varying.h>
#include <CGAL/Subdiv/views/Sharpness.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace cgal_subdiv {

/// the options the tags give, besides the maps
struct Sharp_options
{
  /// `t interpolateboundary` (RenderMan's numbering): 0 none, 1 edges and
  /// corners, 2 edges only (the default of OpenSubdiv's shapes)
  CGAL::Subdiv::Boundary_interpolation boundary = CGAL::Subdiv::Boundary_interpolation::edges_only;
  CGAL::Subdiv::Crease_method method = CGAL::Subdiv::Crease_method::uniform;
  /// `t smoothtriangles` (catmark or smooth; Catmull-Clark only)
  CGAL::Subdiv::Triangle_subdivision triangles = CGAL::Subdiv::Triangle_subdivision::catmark;
  /// whether a tag was read (or an option of the command line set one)
  bool present = false;
  /// how texture coordinates (face-varying data) are interpolated:
  /// `t facevaryinginterpolateboundary` (OpenSubdiv's numbering, the order of
  /// `Sdc::Options::FVarLinearInterpolation`: 0 none ... 5 all) and
  /// `t facevaryingpropagatecorners 1` (corners plus1 becomes corners plus2,
  /// as in Hbr), or --fvar; the default is USD's, corners plus1. Not a tag
  /// of the geometry: it does not set `present`.
  CGAL::Subdiv::Face_varying_interpolation face_varying = CGAL::Subdiv::Face_varying_interpolation::corners_plus1;
};

/// "none", "corners-only", "corners-plus1", "corners-plus2", "boundaries" or "all"
/// (--fvar), in the order of OpenSubdiv's tag numbers
const std::vector<std::string>& face_varying_keywords();
/// the mode of a keyword of `face_varying_keywords`
/// \throws Usage_error naming the keywords for any other
CGAL::Subdiv::Face_varying_interpolation face_varying_mode(const std::string& keyword);

/// a `Mask` with the options of `options`: the border corners of its
/// boundary mode and, for Catmull-Clark, its triangle rule (the masks
/// without such options as they are). The default options give the default
/// masks.
template <class Mask>
Mask mask_with_options(const Sharp_options& options)
{
  namespace SD = CGAL::Subdiv;
  const SD::Border_corners corners = SD::internal::border_corners_for(options.boundary);
  if constexpr(SD::internal::Has_triangle_subdivision<Mask>::value)
    return Mask(corners, options.triangles);
  else if constexpr(std::is_constructible_v<Mask, SD::Border_corners>)
    return Mask(corners);
  else {
    (void)corners;
    return Mask();
  }
}

/// whether `Mask` is one of the linear masks (`--scheme linear`), which take
/// the tags and move no point for them
template <class Mask>
constexpr bool is_linear_mask = std::is_same_v<Mask, CGAL::Subdiv::Linear_quad_mask<Surface>> ||
                                std::is_same_v<Mask, CGAL::Subdiv::Linear_triangle_mask<Surface>>;

/// the named parameters of the tags of `mesh` (its sharpness and hole maps,
/// added when missing) and of the options of `options` that `Mask` takes:
/// the one place the command line hands its tags to the library
/// (refinement, --limit, --displace). The linear masks move no point for a
/// boundary mode: edges and corners is taken as edges (none still makes the
/// border faces holes).
template <class Mask>
auto tag_parameters(Surface& mesh, const Sharp_options& options)
{
  namespace SD = CGAL::Subdiv;
  const auto tagged =
    SD::parameters::edge_sharpness_map(mesh.add_property_map<Surface::Edge_index, double>(edge_sharpness_name, 0).first)
      .vertex_sharpness_map(mesh.add_property_map<Surface::Vertex_index, double>(vertex_sharpness_name, 0).first)
      .face_hole_map(mesh.add_property_map<Surface::Face_index, bool>(face_hole_name, false).first)
      .crease_method(options.method);
  if constexpr(SD::internal::Has_triangle_subdivision<Mask>::value)
    return tagged.boundary_interpolation(options.boundary).triangle_subdivision(options.triangles);
  else if constexpr(is_linear_mask<Mask>) {
    using Boundary = SD::Boundary_interpolation;
    return tagged.boundary_interpolation(options.boundary == Boundary::edges_and_corners ? Boundary::edges_only
                                                                                         : options.boundary);
  } else // OpenSubdiv's triangle rule is one of Catmull-Clark: the other schemes ignore it, as OpenSubdiv does
    return tagged.boundary_interpolation(options.boundary);
}

/*
 * Puts the sharpness of the `t crease` and `t corner` tags and the faces of
 * `t hole` in the maps of `mesh` (added when a tag needs them) and returns the
 * options of `t interpolateboundary`, `t creasemethod` and
 * `t smoothtriangles`, and the face-varying mode of
 * `t facevaryinginterpolateboundary` and `t facevaryingpropagatecorners`;
 * other tags are ignored, with a note. `file_numbers[v]` is the number in the file (from 1) of mesh vertex v;
 * tags number vertices from 0, as OpenSubdiv's shapes do.
 * \throws Input_error naming `path` and the line: a malformed tag, a vertex
 *         out of range or in no face, a face out of range, a crease that is
 *         no edge of the mesh, a negative or NaN sharpness, a semi-sharp one
 *         when `semi_sharp_refused_by` names a scheme (that takes infinitely
 *         sharp values only)
 */
Sharp_options apply_obj_tags(const std::vector<Obj_tag>& tags, std::size_t file_vertices, Surface& mesh,
                             const std::vector<std::size_t>& file_numbers, const std::string& path,
                             std::vector<std::string>& notes, const std::string& semi_sharp_refused_by = "");

/// `CGAL::Subdiv::mark_sharp_edges`: every edge of `mesh` whose faces bend
/// by more than `angle_in_degrees` becomes infinitely sharp in the edge
/// sharpness map (made if the file had no creases); returns how many
std::size_t mark_sharp_angle(Surface& mesh, double angle_in_degrees);

/// whether `mesh` has sharpness maps (tags were read)
bool has_sharpness(const Surface& mesh);

/// a copy of `mesh` without its hole faces (for the formats that have no hole
/// tags), or nothing when `mesh` has no hole map
std::optional<Surface> without_holes(const Surface& mesh);

/// `options` and the sharp edges (not on the border), sharp vertices and
/// holes of `mesh` as tag lines (`t interpolateboundary`, `t creasemethod`,
/// `t smoothtriangles`, `t crease`, `t corner`, `t hole`), vertices and faces
/// numbered from 0 in the mesh's order (as the OBJ writer writes them)
void write_obj_tags(std::ostream& out, const Surface& mesh, const Sharp_options& options);

/// the tag line of the face-varying mode (`t facevaryinginterpolateboundary`)
void write_obj_face_varying_tag(std::ostream& out, CGAL::Subdiv::Face_varying_interpolation mode);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_TAGS_H
