// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_ANALYSIS_PATCH_H
#define CGAL_SUBDIV_ANALYSIS_ANALYSIS_PATCH_H

// The neighbourhoods the surface analysis works on, as real meshes: regular
// patches around a vertex or a face, their labels (the one neighbourhood
// walk), and patches cropped out of refined ones.

#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/Neighbourhood_walk.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

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

/*!
 * \ingroup PkgSubdivAnalysis
 * The mesh type on which the analysis builds its neighbourhoods: a
 * `Surface_mesh` of double points. The positions only serve the geometric
 * checks (characteristic map, convergence); the matrices are read from the
 * stencils, whose weights have the mask's own number type.
 */
using Analysis_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

namespace internal {

using Analysis_vertex = Analysis_mesh::Vertex_index;
using Analysis_halfedge = Analysis_mesh::Halfedge_index;
using Analysis_face = Analysis_mesh::Face_index;

/*
 * A regular patch around a centre, and where to start reading it:
 * - vertex centre: `start` runs from the centre to its first neighbour
 *   (interior: any; border: the border neighbour whose edge has its face on
 *   the left of `start`, so that walking counter-clockwise covers the faces);
 * - face centre: `start` is the halfedge of the central face that leaves its
 *   first corner.
 */
struct Patch
{
  Analysis_mesh mesh;
  Analysis_halfedge start;
};

/*
 * Builds the patch of `rings` rings around a centre of valence n (interior)
 * or with n faces (border), all other vertices regular, from n sectors of the
 * regular triangle or square grid (rings in the face metric: ring r + 1 holds
 * the vertices of the faces touching ring r). Dual (face-centred) patches: a
 * central n-gon, each of its corners the corner of a quadrant of the square
 * grid, consecutive quadrants joined by a strip of quads; all vertices of
 * valence 4. The layout puts sector i between the directions
 * 2 pi i / n and 2 pi (i + 1) / n (border: pi i / n); it is planar.
 */
inline Patch build_patch(int face_size, bool face_centred, int n, bool border, int rings)
{
  require(n >= 1, "the valence must be positive, got " + std::to_string(n));
  require(
    !(face_centred && border),
    "build_patch: the border neighbourhoods of face-centred (dual) schemes are made by refinement (analysis_patch)");
  require(face_centred || border || n >= 3 || (n == 2 && face_size == 4),
          "an interior vertex of valence " + std::to_string(n) +
            ": the eigen-analysis of triangle schemes covers valence 3 or more (at valence 2 the two triangles "
            "share all three edges, so no level of refinement has an analysed neighbourhood; doc/limit.md)");
  require(!face_centred || n >= 3, "a face needs 3 or more corners, got " + std::to_string(n));
  const int sectors = n;
  const double angle = (border ? 3.14159265358979323846 : 2 * 3.14159265358979323846) / n;
  const auto direction = [&](int i) -> std::pair<double, double> { return {std::cos(angle * i), std::sin(angle * i)}; };
  // interior valence 2: two sectors of pi, which a linear map of the grid
  // quadrant would flatten onto a line; they are laid out by angle instead
  const bool half_plane_sectors = !border && !face_centred && n == 2;
  Patch patch;
  Analysis_mesh& mesh = patch.mesh;
  std::map<std::tuple<int, int, int>, Analysis_vertex> ids;
  const double offset = face_centred ? 0.5 : 0.0;
  // the vertex of sector i at grid position (a, b)
  const auto vertex = [&](int i, int a, int b) -> Analysis_vertex {
    if(!face_centred) {
      if(a == 0 && b == 0)
        i = 0;
      else if(a == 0) { // on the axis shared with the next sector
        i = i + 1;
        a = b;
        b = 0;
      }
      if(!border)
        i %= sectors;
    }
    const auto key = std::make_tuple(i, a, b);
    const auto found = ids.find(key);
    if(found != ids.end())
      return found->second;
    double x = 0, y = 0;
    if(half_plane_sectors) { // grid polar angle [0, pi/2] stretched to the sector's [pi i, pi (i + 1)]
      const double r = std::hypot(a, b), theta = angle * i + 2 * std::atan2(b, a);
      x = r * std::cos(theta);
      y = r * std::sin(theta);
    } else {
      const auto u = direction(i), w = direction(i + 1);
      x = (a + offset) * u.first + (b + offset) * w.first;
      y = (a + offset) * u.second + (b + offset) * w.second;
    }
    const Analysis_vertex v = mesh.add_vertex(Analysis_mesh::Point(x, y, 0));
    ids.emplace(key, v);
    return v;
  };
  const Analysis_vertex centre = face_centred ? Analysis_vertex() : vertex(0, 0, 0);
  std::vector<std::vector<Analysis_vertex>> faces;
  for(int i = 0; i < sectors; ++i) {
    if(face_size == 3) {
      for(int a = 0; a < rings; ++a)
        for(int b = 0; a + b < rings; ++b) {
          faces.push_back({vertex(i, a, b), vertex(i, a + 1, b), vertex(i, a, b + 1)});
          if(a + b + 2 <= rings)
            faces.push_back({vertex(i, a + 1, b), vertex(i, a + 1, b + 1), vertex(i, a, b + 1)});
        }
    } else {
      const int last = face_centred ? rings : rings - 1; // dual rings start at 0
      for(int a = 0; a <= last - (face_centred ? 1 : 0); ++a)
        for(int b = 0; b <= last - (face_centred ? 1 : 0); ++b)
          faces.push_back({vertex(i, a, b), vertex(i, a + 1, b), vertex(i, a + 1, b + 1), vertex(i, a, b + 1)});
      if(face_centred) // strip towards the next quadrant
        for(int b = 0; b < rings; ++b)
          faces.push_back(
            {vertex(i, 0, b), vertex(i, 0, b + 1), vertex((i + 1) % n, b + 1, 0), vertex((i + 1) % n, b, 0)});
    }
  }
  if(face_centred) {
    std::vector<Analysis_vertex> central;
    for(int i = 0; i < n; ++i)
      central.push_back(vertex(i, 0, 0));
    faces.insert(faces.begin(), central);
  }
  for(const auto& f : faces) {
    const Analysis_face added = CGAL::Euler::add_face(f, mesh);
    CGAL_assertion(added != Analysis_mesh::null_face());
    (void)added;
  }
  if(face_centred) {
    const Analysis_face f = *mesh.faces().begin();
    Analysis_halfedge h = mesh.halfedge(f);
    while(mesh.source(h) != vertex(0, 0, 0))
      h = mesh.next(h);
    patch.start = h;
  } else if(border) {
    // the border neighbour whose edge has its face on the left of centre -> neighbour
    patch.start = Analysis_halfedge();
    for(Analysis_halfedge h : CGAL::halfedges_around_source(centre, mesh))
      if(!mesh.is_border(h) && mesh.is_border(mesh.opposite(h)))
        patch.start = h;
  } else {
    for(Analysis_halfedge h : CGAL::halfedges_around_source(centre, mesh))
      if(mesh.target(h) == vertex(0, 1, 0))
        patch.start = h;
  }
  return patch;
}

/*
 * The labels of the vertices within `rings` rings of the centre given by
 * `start` (see `Neighbourhood_walk`, the one walk of the package), on an
 * analysis mesh.
 */
struct Labelling
{
  std::vector<Analysis_vertex> vertex_of; // by label
  std::vector<int> ring;                  // by label
  std::vector<int> label_by_index;        // by vertex index, -1 for no label

  std::size_t size() const { return vertex_of.size(); }
  int label(Analysis_vertex v) const { return v.idx() < label_by_index.size() ? label_by_index[v.idx()] : -1; }
};

inline Labelling label_neighbourhood(const Analysis_mesh& mesh, Analysis_halfedge start, bool face_centred, int rings)
{
  Neighbourhood_walk<Analysis_mesh> walk(mesh);
  walk.read(start, face_centred, rings);
  Labelling result;
  result.vertex_of = walk.vertices;
  result.ring = walk.ring_of_label;
  result.label_by_index.assign(mesh.number_of_vertices(), -1);
  for(std::size_t i = 0; i < result.vertex_of.size(); ++i)
    result.label_by_index[result.vertex_of[i].idx()] = static_cast<int>(i);
  return result;
}

// the faces with every vertex labelled, as label tuples starting at their smallest label
inline std::set<std::vector<int>> labelled_faces(const Analysis_mesh& mesh, const Labelling& labels)
{
  std::set<std::vector<int>> result;
  for(Analysis_face f : mesh.faces()) {
    std::vector<int> cycle;
    bool complete = true;
    for(Analysis_vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const int l = labels.label(v);
      if(l < 0)
        complete = false;
      cycle.push_back(l);
    }
    if(!complete)
      continue;
    std::size_t smallest = 0;
    for(std::size_t k = 1; k < cycle.size(); ++k)
      if(cycle[k] < cycle[smallest])
        smallest = k;
    std::vector<int> rotated;
    for(std::size_t k = 0; k < cycle.size(); ++k)
      rotated.push_back(cycle[(smallest + k) % cycle.size()]);
    result.insert(rotated);
  }
  return result;
}

template <class FT>
using Vertex_stencil = Stencil<Analysis_vertex, FT>;

/*
 * The start of a central face with border edges (the border faces of a dual
 * scheme): the halfedge of the face that is not on the border and follows
 * one that is, so that the corners are labelled from the first corner after
 * the border edges, around the face, to the last one before them. Returns
 * false if the face has no border edge; throws if its border edges are not
 * one run (then no start is canonical).
 */
inline bool border_face_start(const Analysis_mesh& mesh, Analysis_face f, Analysis_halfedge& start)
{
  int runs = 0;
  for(Analysis_halfedge h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    if(!mesh.is_border(mesh.opposite(h)) && mesh.is_border(mesh.opposite(mesh.prev(h)))) {
      start = h;
      ++runs;
    }
  CGAL_assertion_msg(runs <= 1, "a central face whose border edges are not consecutive");
  return runs == 1;
}

/*
 * The faces of `mesh` whose vertices all lie within `rings` rings of the
 * centre given by `start`, as a new patch: its vertices are those rings, in
 * label order (vertex i has label i), its faces are added by their smallest
 * labels, and its start runs from label 0 to label 1 (for a vertex centre:
 * centre to first neighbour; for a face centre: the start of the central face).
 */
inline Patch crop_patch(const Analysis_mesh& mesh, Analysis_halfedge start, bool face_centred, int rings)
{
  const Labelling labels = label_neighbourhood(mesh, start, face_centred, rings);
  Patch result;
  for(std::size_t i = 0; i < labels.size(); ++i)
    result.mesh.add_vertex(mesh.point(labels.vertex_of[i]));
  std::vector<std::vector<Analysis_vertex>> faces;
  for(Analysis_face f : mesh.faces()) {
    std::vector<Analysis_vertex> cycle;
    for(Analysis_vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const int l = labels.label(v);
      if(l < 0)
        break;
      cycle.push_back(Analysis_vertex(static_cast<Analysis_mesh::size_type>(l)));
    }
    if(cycle.size() == mesh.degree(f))
      faces.push_back(cycle);
  }
  const auto smallest = [](const std::vector<Analysis_vertex>& f) {
    return std::make_pair(*std::min_element(f.begin(), f.end()), *std::max_element(f.begin(), f.end()));
  };
  std::stable_sort(faces.begin(), faces.end(),
                   [&](const std::vector<Analysis_vertex>& a, const std::vector<Analysis_vertex>& b) {
                     return smallest(a) < smallest(b);
                   });
  for(const auto& f : faces) {
    const auto added = CGAL::Euler::add_face(f, result.mesh);
    CGAL_assertion_msg(added != Analysis_mesh::null_face(), "the cropped neighbourhood is not a manifold patch");
    CGAL_USE(added);
  }
  const auto h = CGAL::halfedge(Analysis_vertex(0), Analysis_vertex(1), result.mesh);
  CGAL_assertion_msg(labels.size() >= 2 && h.second, "the cropped neighbourhood lost its start");
  result.start = h.first;
  return result;
}

// labels and faces of the `rings` rings: the connectivity two levels are compared by
inline std::pair<std::vector<int>, std::set<std::vector<int>>> connectivity(const Analysis_mesh& mesh,
                                                                            Analysis_halfedge start, bool face_centred,
                                                                            int rings)
{
  const Labelling labels = label_neighbourhood(mesh, start, face_centred, rings);
  return {labels.ring, labelled_faces(mesh, labels)};
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_ANALYSIS_PATCH_H
