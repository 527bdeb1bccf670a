// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// OpenSubdiv's OBJ tags (`t crease`, `t corner`, `t interpolateboundary`,
// `t creasemethod`) as the sharpness maps of a Surface_mesh, checked line by
// line, and written back after a refinement.
#ifndef CGAL_SUBDIV_CLI_SURFACE_TAGS_H
#define CGAL_SUBDIV_CLI_SURFACE_TAGS_H

#include "mesh_soup.h"
#include "surface_from_soup.h"

#include <CGAL/Subdiv/views/Sharpness.h>

#include <ostream>
#include <string>
#include <vector>

namespace cgal_subdiv {

/// the maps the tags are kept in, on the mesh: "e:sharpness", "v:sharpness" (double)
extern const char* const edge_sharpness_name;
extern const char* const vertex_sharpness_name;

/// the options the tags give, besides the maps
struct Sharp_options
{
  /// `t interpolateboundary`: 1 (RenderMan's numbering) is "edges and
  /// corners"; 2, the default of OpenSubdiv's shapes, and 0 are "edges only"
  CGAL::Subdiv::Border_corners border = CGAL::Subdiv::Border_corners::smooth;
  CGAL::Subdiv::Crease_method method = CGAL::Subdiv::Crease_method::uniform;
  /// whether one of the four tags was read
  bool present = false;
};

/*
 * Puts the sharpness of the `t crease` and `t corner` tags in the maps of
 * `mesh` (added when a tag needs them) and returns the options of
 * `t interpolateboundary` and `t creasemethod`; other tags are ignored, with a
 * note. `file_numbers[v]` is the number in the file (from 1) of mesh vertex v;
 * tags number vertices from 0, as OpenSubdiv's shapes do.
 * \throws Input_error naming `path` and the line: a malformed tag, a vertex
 *         out of range or in no face, a crease that is no edge of the mesh, a
 *         negative or NaN sharpness
 */
Sharp_options apply_obj_tags(const std::vector<Obj_tag>& tags, std::size_t file_vertices, Surface& mesh,
                             const std::vector<std::size_t>& file_numbers, const std::string& path,
                             std::vector<std::string>& notes);

/// whether `mesh` has sharpness maps (tags were read)
bool has_sharpness(const Surface& mesh);

/// `options` and the sharp edges (not on the border) and sharp vertices of
/// `mesh` as tag lines (`t interpolateboundary`, `t creasemethod`, `t crease`,
/// `t corner`), vertices numbered from 0 in the mesh's order (as the OBJ
/// writer writes them)
void write_obj_tags(std::ostream& out, const Surface& mesh, const Sharp_options& options);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_TAGS_H
