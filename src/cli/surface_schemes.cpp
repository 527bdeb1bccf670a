// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The one table of surface schemes of cgal-subdiv: a scheme is one line here.
#include "surface.h"
#include "surface_tags.h"

#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/boost/graph/helpers.h>

#include <optional>
#include <type_traits>

namespace cgal_subdiv {
namespace {

namespace SD = CGAL::Subdiv;

using Run = std::function<void(Surface&, int, double)>;

// the maps of `mesh` that refinement carries: the vertex colours and normals,
// with the weights of the points, and the texture coordinates with their
// seams, in `face_varying` (an empty Carried_data costs nothing: subdivide
// then takes its plain path)
SD::Carried_data<Surface, double> carried_maps(const Surface& mesh, SD::Face_varying_interpolation face_varying)
{
  SD::Carried_data<Surface, double> carried;
  if(const std::optional<Colour_map> colours = colours_of(mesh))
    carried.vertex_map(*colours);
  if(const std::optional<Normal_map> normals = normals_of(mesh))
    carried.vertex_map(*normals);
  if(has_texture_points(mesh)) {
    carried.corner_map(mesh.property_map<Surface::Halfedge_index, Texture_point>(texture_point_name).first,
                       face_varying, mesh.property_map<Surface::Halfedge_index, std::size_t>(texture_index_name).first);
    // (a split soup: the copies of a point are one vertex for the UVs)
    if(const auto point_of = mesh.property_map<Surface::Vertex_index, std::size_t>(soup_point_name); point_of.second)
      carried.non_manifold_copies(point_of.first);
  }
  return carried;
}

// the soup points of the vertices are those of the mesh before the levels
// only: the refined mesh drops them (`carried_maps` read them)
void drop_soup_points(Surface& mesh)
{
  if(auto point_of = mesh.property_map<Surface::Vertex_index, std::size_t>(soup_point_name); point_of.second)
    mesh.remove_property_map(point_of.first);
}

template <class Wrapper>
Run call(Wrapper wrapper)
{
  return [wrapper](Surface& mesh, int levels, double max_memory) {
    // (texture coordinates take the path with tags, `run_sharp`)
    const auto carried = carried_maps(mesh, Sharp_options().face_varying);
    wrapper(mesh, SD::parameters::number_of_iterations(levels).max_memory(max_memory).carried_data(carried));
    drop_soup_points(mesh);
  };
}

#define SUBDIV_CLI_WRAP(function) call([](Surface& m, const auto& np) { SD::function(m, np); })

// linear: a triangle mesh stays one (1-to-4 split), anything else becomes quads
const auto linear = call([](Surface& m, const auto& np) {
  if(CGAL::is_triangle_mesh(m))
    SD::linear_triangle_subdivision(m, np);
  else
    SD::linear_quad_subdivision(m, np);
});

// a row of the table: the growth per level and the peak bytes per face come
// from the host of the scheme's mask (the library's own size check); the
// masks that take sharpness tags refine with the mesh's maps (surface_tags.h)
template <class Mask>
Surface_scheme row(const std::string& name, const std::string& description, const Run& run, bool triangles_only)
{
  using Host = SD::Host_of<Mask>;
  Surface_scheme scheme{name, description, run, triangles_only, true, Host::face_growth(), Host::peak_bytes_per_face(),
                        {}};
  scheme.semi_sharp = SD::internal::Takes_semi_sharp_tags<Mask>::value;
  scheme.limit_sharp = SD::internal::Limit_takes_sharpness_tags<Mask>::value;
  scheme.carries_texture_seams = SD::Carried_data<Surface, double>::carries_seams<Mask>();
  if constexpr(SD::internal::Takes_sharpness_tags<Mask>::value)
    scheme.run_sharp = [](Surface& mesh, int levels, double max_memory, const Sharp_options& options) {
      const auto carried = carried_maps(mesh, options.face_varying);
      const auto np =
        tag_parameters<Mask>(mesh, options).number_of_iterations(levels).max_memory(max_memory).carried_data(carried);
      if constexpr(is_linear_mask<Mask>) // the row of the quad mask, whose call picks the split
        SD::linear_subdivision(mesh, np);
      else
        SD::subdivide(mesh, mask_with_options<Mask>(options), np);
      drop_soup_points(mesh);
    };
  return scheme;
}

} // namespace

std::string texture_seam(const Surface& mesh, const std::vector<std::size_t>& file_numbers)
{
  const auto indices = mesh.property_map<Surface::Halfedge_index, std::size_t>(texture_index_name).first;
  const auto seam = SD::internal::first_seam(
    mesh, [&](Surface::Halfedge_index a, Surface::Halfedge_index b) { return indices[a] == indices[b]; });
  if(!seam)
    return "";
  const std::size_t vertex = seam->vertex < file_numbers.size() ? file_numbers[seam->vertex] : seam->vertex;
  return "vertex " + std::to_string(vertex) + " has different ones in faces " + std::to_string(seam->face) + " and " +
         std::to_string(seam->other_face);
}

const std::vector<std::string>& surface_scheme_keywords()
{
  static const std::vector<std::string> keywords = {"loop",  "loop-warren", "catmull-clark",      "doo-sabin",
                                                    "sqrt3", "butterfly",   "modified-butterfly", "interpolating-sqrt3",
                                                    "linear"};
  return keywords;
}

const std::vector<Surface_scheme>& surface_schemes()
{
  // name, description, mask (for the size check), run, triangles only
  static const std::vector<Surface_scheme> schemes = {
    row<SD::Loop_mask<Surface>>("loop", "Loop, Loop's 1987 beta (as CGAL and OpenSubdiv)",
                                SUBDIV_CLI_WRAP(loop_subdivision), true),
    row<SD::Loop_warren_mask<Surface>>("loop-warren", "Loop with Warren's rational beta",
                                       SUBDIV_CLI_WRAP(loop_warren_subdivision), true),
    row<SD::Catmull_clark_mask<Surface>>("catmull-clark", "Catmull-Clark (quads out)",
                                         SUBDIV_CLI_WRAP(catmull_clark_subdivision), false),
    row<SD::Doo_sabin_mask<Surface>>("doo-sabin", "Doo-Sabin (the dual scheme)", SUBDIV_CLI_WRAP(doo_sabin_subdivision),
                                     false),
    row<SD::Sqrt3_mask<Surface>>("sqrt3", "Kobbelt's sqrt3", SUBDIV_CLI_WRAP(sqrt3_subdivision), true),
    row<SD::Butterfly_mask<Surface>>("butterfly", "butterfly (Dyn, Levin, Gregory), interpolating",
                                     SUBDIV_CLI_WRAP(butterfly_subdivision), true),
    row<SD::Modified_butterfly_mask<Surface>>("modified-butterfly",
                                              "modified butterfly (Zorin, Schroeder, Sweldens), interpolating",
                                              SUBDIV_CLI_WRAP(modified_butterfly_subdivision), true),
    row<SD::Interpolating_sqrt3_mask<Surface>>("interpolating-sqrt3", "Labsik and Greiner's interpolating sqrt3",
                                               SUBDIV_CLI_WRAP(interpolating_sqrt3_subdivision), true),
    // the quad split costs more per face than the 1-to-4 split: the size check takes it
    row<SD::Linear_quad_mask<Surface>>(
      "linear", "midpoints: the 1-to-4 split of a triangle mesh, the quad split of any other", linear, false),
  };
  return schemes;
}

} // namespace cgal_subdiv
