// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_SURFACE_NEIGHBOURHOOD_H
#define CGAL_SUBDIV_ANALYSIS_SURFACE_NEIGHBOURHOOD_H

/// \file surface_neighbourhood.h
/// The invariant neighbourhood of a vertex (or, for dual schemes, of a face)
/// of a surface scheme, built as a real mesh, refined by the scheme's own host
/// and mask, and the local subdivision matrix read from the recorded stencils.

#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/Neighbourhood_walk.h>
#include <CGAL/Subdiv/analysis/analysis_patch.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/stencils/Row_builder.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

namespace internal {

/*
 * The sharpness tags of an analysis patch of a sharp configuration
 * (`tag_patch`): edge and vertex property maps of the mesh, which every
 * refinement of the patch carries (`refine_recording`).
 */
constexpr const char* patch_edge_sharpness = "e:analysis_sharpness";
constexpr const char* patch_vertex_sharpness = "v:analysis_sharpness";

/*
 * One host step of the real host and mask on `mesh`: returns the refined
 * mesh, and the stencil of every new vertex over the old vertices. New
 * positions are computed in double from the stencils (weights converted).
 * A patch with sharpness tags (`tag_patch`) is refined as `subdivide()`
 * refines a tagged mesh: through `Sharpness_tags`, which gives the mask the
 * rules of the level and writes the children's sharpness into the refined
 * mesh's maps, so no rule is typed here.
 */
template <class Mask>
Analysis_mesh refine_recording(const Analysis_mesh& mesh, const Mask& mask,
                               std::vector<Vertex_stencil<typename Mask::Number_type>>& stencils)
{
  using Points = std::decay_t<decltype(std::declval<Analysis_mesh&>().points())>;
  using FT = typename Mask::Number_type;
  Analysis_mesh refined = mesh;
  refined.collect_garbage();
  Stencil_recorder<Analysis_mesh, FT> recorder;
  const Row_points<Points, decltype(recorder.rows)> points{refined.points(), &recorder.rows};
  const auto refine_one = [&](const auto& level_mask, auto&... sinks) {
    refine_level(refined, level_mask, points, Parallel_loop(1), recorder, sinks...);
  };
  const auto edges = refined.property_map<Analysis_mesh::Edge_index, double>(patch_edge_sharpness);
  if(!edges.second) {
    refine_one(mask);
  } else if constexpr(Takes_sharpness_tags<Mask>::value) {
    using Edge_map = Analysis_mesh::Property_map<Analysis_mesh::Edge_index, double>;
    using Vertex_map = Analysis_mesh::Property_map<Analysis_mesh::Vertex_index, double>;
    const auto vertices = refined.property_map<Analysis_mesh::Vertex_index, double>(patch_vertex_sharpness);
    CGAL_assertion(vertices.second);
    const Sharpness_tags<Analysis_mesh, FT, Edge_map, Vertex_map> tags(edges.first, vertices.first,
                                                                       Crease_method::uniform);
    tags.refine(refined, mask, refine_one);
  } else {
    throw Bad_input(mask.name() + " does not take sharpness tags: no crease, dart or corner to analyse");
  }
  stencils = std::move(recorder.rows);
  return refined;
}

/*
 * One analysed step (the host's `analysis_steps` host steps), with the
 * stencils composed over the steps, and where the centre went: the new
 * `start` halfedge, found from the stencils alone:
 * - vertex centre: the new centre is the new vertex whose stencil has the
 *   largest weight on the old centre among those of the same origin, found
 *   through `Host::origin()`; interior: of the halfedges leaving it, the one
 *   to the vertex with the largest weight on the target of the old start
 *   (unique for every scheme here: the edge point of the old start edge);
 *   border: the halfedge to the border neighbour with its face on the left;
 * - face centre: the new central face is the one whose vertices' stencils
 *   read only the old central face's corners; its start corner is the one
 *   with the largest weight on the old start corner.
 */
template <class Mask>
struct Analysed_step
{
  using FT = typename Mask::Number_type;
  Analysis_mesh mesh;
  std::vector<Vertex_stencil<FT>> stencils; // over the vertices of the mesh before the step
  Analysis_halfedge start;
};

template <class Mask>
Analysed_step<Mask> analysed_step(const Analysis_mesh& mesh, Analysis_halfedge start, const Mask& mask)
{
  using FT = typename Mask::Number_type;
  using Traits = Host_of<Mask>;
  Analysed_step<Mask> result;
  // the centre and the start neighbour, followed through the host steps
  std::vector<Analysis_vertex> central; // face centre: corners, from the start corner
  Analysis_vertex centre = mesh.source(start), first_neighbour = mesh.target(start);
  const bool border = !Traits::face_centred && mesh.is_border(centre);
  if(Traits::face_centred) {
    Analysis_halfedge h = start;
    do {
      central.push_back(mesh.source(h));
      h = mesh.next(h);
    } while(h != start);
  }
  Analysis_mesh current = mesh;
  std::vector<Vertex_stencil<FT>> composed;
  for(int step = 0; step < Traits::analysis_steps; ++step) {
    std::vector<Vertex_stencil<FT>> stencils;
    Analysis_mesh next = refine_recording(current, mask, stencils);
    if(step == 0) {
      composed = stencils;
    } else { // compose: sources of `stencils` are vertices of `current`, those of `composed` of `mesh`
      std::vector<Vertex_stencil<FT>> total(stencils.size());
      Row_builder<FT> builder;
      const auto index_of = [](Analysis_vertex v) { return v.idx(); };
      for(std::size_t j = 0; j < stencils.size(); ++j) {
        std::size_t room = 0;
        for(const auto& term : stencils[j])
          room += composed[term.first.idx()].size();
        builder.start(mesh.number_of_vertices(), room);
        for(const auto& term : stencils[j])
          builder.add_terms(composed[term.first.idx()], term.second, index_of);
        for(std::size_t k = 0; k < builder.size(); ++k)
          total[j].add(Analysis_vertex(builder.source(k)), builder.weight(k));
      }
      composed.swap(total);
    }
    // where the centre went, in `next`
    if(!Traits::face_centred) {
      const Host_of<Mask> host(current);
      Analysis_vertex new_centre;
      bool found = false;
      for(std::size_t j = 0; j < stencils.size() && !found; ++j) {
        const Vertex_origin o = host.origin(j);
        if(o.kind == Origin_kind::vertex && o.index == centre.idx()) {
          new_centre = Analysis_vertex(static_cast<Analysis_mesh::size_type>(j));
          found = true;
        }
      }
      require(found, "the host does not keep the centre vertex");
      centre = new_centre;
    }
    current = std::move(next);
  }
  // new start, from the composed stencils (over the vertices of `mesh`)
  const auto weight_on = [&](Analysis_vertex v, Analysis_vertex source) -> double {
    return CGAL::to_double(composed[v.idx()].weight(source));
  };
  Analysis_halfedge new_start;
  bool found = false;
  if(Traits::face_centred) {
    std::set<Analysis_vertex> corners(central.begin(), central.end());
    for(Analysis_face f : current.faces()) {
      bool inside = true;
      for(Analysis_vertex v : CGAL::vertices_around_face(current.halfedge(f), current)) {
        for(const auto& term : composed[v.idx()].terms())
          if(corners.count(term.first) == 0)
            inside = false;
      }
      if(!inside)
        continue;
      require(!found, "two faces could be the new central face");
      found = true;
      if(border_face_start(current, f, new_start))
        continue; // a border face: its start is fixed by its border edges
      double best = -1e300;
      for(Analysis_halfedge h : CGAL::halfedges_around_face(current.halfedge(f), current)) {
        const double w = weight_on(current.source(h), central.front());
        if(w > best) {
          best = w;
          new_start = h;
        }
      }
    }
  } else if(border) {
    for(Analysis_halfedge h : CGAL::halfedges_around_source(centre, current))
      if(!current.is_border(h) && current.is_border(current.opposite(h))) {
        new_start = h;
        found = true;
      }
  } else {
    double best = -1e300, second = -1e300;
    for(Analysis_halfedge h : CGAL::halfedges_around_source(centre, current)) {
      const double w = weight_on(current.target(h), first_neighbour);
      if(w > best) {
        second = best;
        best = w;
        new_start = h;
      } else if(w > second) {
        second = w;
      }
    }
    found = best > second + 1e-12;
  }
  require(found, "the refined neighbourhood cannot be matched with the old one");
  result.mesh = std::move(current);
  result.stencils.swap(composed);
  result.start = new_start;
  return result;
}

/*
 * The patch of `rings` rings around the border face of a dual scheme made
 * from a border vertex with k faces: the face that the host makes of the
 * corners at that vertex (k >= 3: its vertex face, a k-gon with a border edge;
 * k = 2: the edge quad of the interior edge at the vertex, a border quad of
 * the regular border; k = 1: the face face of its single face, a corner
 * face), and its descendants (the face faces of the central face, level
 * after level).
 *
 * Its neighbourhood is not one of regular vertices: with the border
 * topology of `Dual_split` the border corners of a border k-gon (k >= 3)
 * have 3 faces, and each makes a border triangle at the next level, whose
 * border corners have 3 faces again. So the patch is made as real meshes
 * have it: a border vertex with k quads (`build_patch`, 2 rings), refined
 * by the real host and mask, the central face followed through the levels
 * (`analysed_step`) and the mesh cropped to `rings` + 3 rings after every
 * level (enough to keep `rings` + 1 rings exact), until the connectivity of
 * `rings` + 1 rings around the central face is the same at three consecutive
 * levels (the self-similar layout: at most 12 levels). Then it is cropped
 * to `rings` rings (`crop_patch`).
 */
template <class Mask>
Patch border_face_patch(const Mask& mask, int k, int rings)
{
  using Traits = Host_of<Mask>;
  require(k >= 1, "a border vertex needs one face or more, got " + std::to_string(k));
  require(rings >= 1, "a patch needs one ring or more");
  const Patch coarse = build_patch(Traits::regular_face_size, false, k, true, 2);
  const Analysis_vertex centre = coarse.mesh.source(coarse.start);
  // level 1: the new vertices are the face corners, numbered face by face
  // from halfedge(f) (`Dual_split`); the corners at the centre make the central face
  std::vector<Vertex_stencil<typename Mask::Number_type>> stencils;
  Analysis_mesh mesh = refine_recording(coarse.mesh, mask, stencils);
  std::set<Analysis_vertex> corners;
  std::size_t corner = 0;
  for(Analysis_face f : coarse.mesh.faces())
    for(Analysis_halfedge h : CGAL::halfedges_around_face(coarse.mesh.halfedge(f), coarse.mesh)) {
      if(coarse.mesh.target(h) == centre)
        corners.insert(Analysis_vertex(static_cast<Analysis_mesh::size_type>(corner)));
      ++corner;
    }
  require(corner == mesh.number_of_vertices() && corners.size() == static_cast<std::size_t>(k),
          "the host does not number the new vertices by face corners");
  Analysis_halfedge start;
  bool found = false;
  for(Analysis_face f : mesh.faces()) {
    std::size_t inside = 0;
    for(Analysis_vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      inside += corners.count(v);
    if(inside < corners.size())
      continue;
    require(!found, "two faces hold the corners at the border vertex");
    found = border_face_start(mesh, f, start);
    require(found, "the face of the corners at the border vertex has no border edge");
  }
  require(found, "no face holds the corners at the border vertex");
  // then level after level, cropped, until the layout repeats
  const int kept = rings + 3;
  Patch current = crop_patch(mesh, start, true, kept);
  auto last = connectivity(current.mesh, current.start, true, rings + 1);
  int same = 0;
  for(int level = 2; level <= 12 && same < 2; ++level) {
    const Analysed_step<Mask> step = analysed_step(current.mesh, current.start, mask);
    current = crop_patch(step.mesh, step.start, true, kept);
    auto now = connectivity(current.mesh, current.start, true, rings + 1);
    same = now == last ? same + 1 : 0;
    last = std::move(now);
  }
  require(same >= 2, "the neighbourhood of the border face does not become self-similar in 12 levels");
  return crop_patch(current.mesh, current.start, true, rings);
}

/*
 * The sharpness tags of a sharp configuration on a patch built around its
 * centre (`build_patch`, interior): every edge of each sharp ray gets 10 (the
 * ray of sector boundary i leaves the centre in the direction 2 pi i / n of
 * the planar layout, and goes on straight through the regular vertices to
 * the patch border), and a corner's centre gets vertex sharpness 10. The
 * tags are property maps of the mesh (`patch_edge_sharpness`,
 * `patch_vertex_sharpness`), so that they follow the patch through copies
 * and refinement.
 */
inline void tag_patch(Patch& patch, const Configuration& where)
{
  Analysis_mesh& mesh = patch.mesh;
  auto edges = mesh.add_property_map<Analysis_mesh::Edge_index, double>(patch_edge_sharpness, 0).first;
  auto vertices = mesh.add_property_map<Analysis_vertex, double>(patch_vertex_sharpness, 0).first;
  const Analysis_vertex centre = mesh.source(patch.start);
  const double infinitely_sharp = 10;
  if(where.kind == Vertex_kind::corner)
    vertices[centre] = infinitely_sharp;
  const auto& origin = mesh.point(centre);
  for(int ray : where.sharp_rays()) {
    const double angle = 2 * 3.14159265358979323846 * ray / where.valence;
    const double dx = std::cos(angle), dy = std::sin(angle);
    Analysis_vertex v = centre;
    do { // the edge from v that goes furthest along the ray
      Analysis_halfedge best;
      double along = 0;
      for(Analysis_halfedge h : CGAL::halfedges_around_source(v, mesh)) {
        const auto& p = mesh.point(mesh.target(h));
        const double x = p.x() - origin.x(), y = p.y() - origin.y();
        const double off = std::abs(x * dy - y * dx), a = x * dx + y * dy;
        if(off < 1e-9 * (1 + std::abs(a)) && a > along) {
          along = a;
          best = h;
        }
      }
      require(best != Analysis_halfedge(), "tag_patch: a sharp ray leaves the patch's layout");
      edges[mesh.edge(best)] = infinitely_sharp;
      v = mesh.target(best);
    } while(!mesh.is_border(v));
  }
}

/*
 * The patch of `rings` rings the analysis uses for `mask` at `where`:
 * `build_patch`, except at the border for face-centred (dual) schemes, whose
 * border neighbourhoods are made by refinement (`border_face_patch`); the
 * sharp configurations are interior patches with their tags (`tag_patch`).
 */
template <class Mask>
Patch analysis_patch(const Mask& mask, const Configuration& where, int rings)
{
  using Traits = Host_of<Mask>;
  const int n = where.valence;
  const bool border = where.on_border();
  if(where.sharp()) {
    require(Takes_sharpness_tags<Mask>::value,
            mask.name() + " does not take sharpness tags: no crease, dart or corner to analyse");
    require(!Traits::face_centred, mask.name() + ": the sharp configurations are vertex-centred");
    // the sqrt3 schemes refine a crease as a border, on every second step
    // only: their sharp configurations would need the two-step patch of
    // their border analysis, which is not built with tags
    require(Mask::split != Split::sqrt3,
            mask.name() + ": the crease, dart and corner configurations of the sqrt3 schemes are not analysed yet");
    if(where.kind == Vertex_kind::crease)
      require(where.first_side >= 1 && where.second_side() >= 1,
              "a crease vertex needs a face or more on each side, got " + std::to_string(where.first_side) + " and " +
                std::to_string(where.second_side()));
    Patch patch = build_patch(Traits::regular_face_size, false, n, false, rings);
    tag_patch(patch, where);
    return patch;
  }
  if(Traits::face_centred && border)
    return border_face_patch(mask, n, rings);
  return build_patch(Traits::regular_face_size, Traits::face_centred, n, border, rings);
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * A local subdivision matrix, with the neighbourhood it acts on.
 */
template <class FT>
struct Local_subdivision_matrix
{
  /// row i: the weights of new neighbourhood vertex i over the old ones,
  /// both in the canonical order (`ring`); new = S * old
  Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic> S;
  /// ring of every neighbourhood vertex, in the canonical order
  std::vector<int> ring;
  /// number of rings (face metric) of the neighbourhood
  int rings = 0;
  /// false if some new neighbourhood vertex reads an old vertex outside the
  /// neighbourhood (then S is not a subdivision matrix)
  bool invariant = false;
};

namespace internal {

// the matrix of the `rings`-ring neighbourhood; `mask` gives the weights
template <class Mask>
Local_subdivision_matrix<typename Mask::Number_type> local_matrix_of_rings(const Mask& mask, const Configuration& where,
                                                                           int rings)
{
  using FT = typename Mask::Number_type;
  using Traits = Host_of<Mask>;
  const Patch patch = analysis_patch(mask, where, rings + 2);
  const Labelling old_labels = label_neighbourhood(patch.mesh, patch.start, Traits::face_centred, rings);
  const Analysed_step<Mask> step = analysed_step(patch.mesh, patch.start, mask);
  const Labelling new_labels = label_neighbourhood(step.mesh, step.start, Traits::face_centred, rings);
  require(old_labels.size() == new_labels.size() && old_labels.ring == new_labels.ring &&
            labelled_faces(patch.mesh, old_labels) == labelled_faces(step.mesh, new_labels),
          "the refined neighbourhood does not have the connectivity of the old one");
  Local_subdivision_matrix<FT> result;
  const Eigen::Index m = static_cast<Eigen::Index>(old_labels.size());
  result.S.resize(m, m);
  for(Eigen::Index r = 0; r < m; ++r)
    for(Eigen::Index c = 0; c < m; ++c)
      result.S(r, c) = FT(0);
  result.ring = old_labels.ring;
  result.rings = rings;
  result.invariant = true;
  for(Eigen::Index i = 0; i < m; ++i)
    for(const auto& term : step.stencils[new_labels.vertex_of[static_cast<std::size_t>(i)].idx()].terms()) {
      const int j = old_labels.label(term.first);
      if(j < 0) {
        if(term.second != FT(0))
          result.invariant = false;
        continue;
      }
      result.S(i, j) += term.second;
    }
  return result;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * The local subdivision matrix of a surface scheme at a vertex of valence
 * `valence` (`border`: a border vertex with `valence` faces) or, for a dual
 * scheme (`Dual_split`), at a face with `valence` corners, all other
 * vertices regular (valence 6 for triangles, 4 for quads; border vertices
 * with 3 triangles or 2 quads). A dual scheme at the border (`border`) is
 * centred at the face the host makes of the corners at a border vertex with
 * `valence` faces (its vertex face for 3 faces or more, see
 * `internal::border_face_patch`), whose neighbourhood is made by refinement.
 *
 * The neighbourhood is built as a real `Analysis_mesh`, one analysed step of
 * the scheme's own host and mask is run on it, recording the stencil of
 * every new vertex, and the vertices of the refined mesh that play the roles
 * of the old neighbourhood vertices are found by reading both meshes in the
 * same canonical order (see `internal::label_neighbourhood`): row i of S is
 * the stencil of new vertex i over the old vertices. Nothing is typed in.
 *
 * `rings` = 0 picks the smallest ring count r >= 1 whose neighbourhood is
 * invariant (Loop, sqrt3, and the modified butterfly at n != 6: 1 ring,
 * n + 1 vertices; Catmull-Clark: 1 ring, 2n + 1; Doo-Sabin: 1 ring around the
 * face, 4n; butterfly, and the modified butterfly at n = 6: 2 rings, 3n + 1;
 * border vertices with k faces: k + 2, 2k + 2, ... vertices; Doo-Sabin
 * border faces: 1 ring, 4k - 2 vertices for k >= 3, 12 for k = 2, 9 for
 * k = 1); a given `rings` is used as is and the result says whether it is invariant.
 *
 * \tparam FT the number type of the weights: `CGAL::Exact_rational` (default)
 *         gives the exact matrix where the weights are rational
 * \param mask the scheme (any mesh and number type: it is rebound to
 *         `Analysis_mesh` and FT with its options)
 * \param where the configuration: `where.valence` is the `valence` above,
 *        `where.on_border()` is `border`
 * \param np named parameters: `rings`
 * \throws Bad_input for a valence the scheme or the patch cannot have, or if
 *         no neighbourhood of up to 8 rings is invariant
 */
template <class FT = CGAL::Exact_rational, class Mask, class NamedParameters = parameters::Default_named_parameters>
Local_subdivision_matrix<FT> local_subdivision_matrix(const Mask& mask, const Configuration& where,
                                                      const NamedParameters& np = parameters::default_values())
{
  const auto analysed = mask.template rebind<Analysis_mesh, FT>();
  const int rings = parameters::choose_parameter(parameters::get_parameter(np, internal::rings_t()), 0);
  if(rings > 0)
    return internal::local_matrix_of_rings(analysed, where, rings);
  for(int r = 1; r <= 8; ++r) {
    Local_subdivision_matrix<FT> result = internal::local_matrix_of_rings(analysed, where, r);
    if(result.invariant)
      return result;
  }
  throw Bad_input("no invariant neighbourhood of up to 8 rings for " + analysed.name());
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_SURFACE_NEIGHBOURHOOD_H
