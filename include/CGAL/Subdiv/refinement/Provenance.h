// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_PROVENANCE_H
#define CGAL_SUBDIV_REFINEMENT_PROVENANCE_H

/// \file Provenance.h
/// Where every element of a refined mesh came from in the mesh that was
/// refined (the base mesh): `Carried_data::face_origin_map` and
/// `Carried_data::base_origin_map` (doc/provenance.md).

#include <CGAL/Bbox_2.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivFunctions
 * Where a face of a refined mesh lies in the base mesh (the mesh given to
 * `subdivide()`), for the schemes that split edges (Catmull-Clark, Loop, the
 * butterflies, linear): the base face and the parameters of the face's
 * corners in that base face's domain, which is
 *   - for a base quad under the quad split: the unit square, corner 0 at
 *     (0,0), corner 1 at (1,0), corner 2 at (1,1), corner 3 at (0,1);
 *   - for a base triangle under the triangle split: corner 0 at (0,0),
 *     corner 1 at (1,0), corner 2 at (0,1);
 *   - for a base face with n != 4 corners under the quad split: the unit
 *     square of its sub-quad at corner c (`sub_quad`), (0,0) at corner c, u
 *     towards the midpoint of the edge from corner c to corner c+1, v towards
 *     the midpoint of the edge from corner c-1 to corner c.
 *
 * Corner i of a base face is the target of the i-th halfedge from
 * `halfedge(f)` around the face (for a `Surface_mesh`, the i-th vertex given
 * to `add_face`, as read from a file); faces are numbered in the order of
 * `faces(mesh)`. The parameters are dyadic rationals, exact in double for
 * fewer than 50 levels.
 */
struct Face_origin
{
  /// the ordinal of the base face, in the order of `faces(base mesh)`
  std::size_t face = 0;
  /// for a base face with n != 4 corners under the quad split: the corner c
  /// whose sub-quad holds the face; -1 otherwise
  int sub_quad = -1;
  /// the number of corners of the face (3 or 4)
  int corners = 0;
  /// the (u, v) of the face's corners, from the target of `halfedge(f)` around the face
  std::array<std::array<double, 2>, 4> uv{};

  /// the box of the corners' parameters
  CGAL::Bbox_2 box() const
  {
    CGAL::Bbox_2 b;
    for(int i = 0; i < corners; ++i)
      b += CGAL::Bbox_2(uv[i][0], uv[i][1], uv[i][0], uv[i][1]);
    return b;
  }
};

namespace internal {

/// a new face of a level: its parent (old face ordinal) and its corners'
/// new vertices (new indices), as the host made them
template <class Mesh>
struct New_face
{
  typename boost::graph_traits<Mesh>::face_descriptor face;
  std::size_t parent = 0;
  int size = 0;
  std::array<std::size_t, 4> vertices{};

  /// the position among `vertices` of the new vertex `v`
  int corner_at(typename boost::graph_traits<Mesh>::vertex_descriptor v,
                const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& new_vertices) const
  {
    int i = 0;
    while(i + 1 < size && new_vertices[vertices[i]] != v)
      ++i;
    return i;
  }
};

/// the new faces of `level` (a `New_level` of `refine_level`), by new index
template <class Mesh, class New_level>
std::vector<New_face<Mesh>> new_faces_of(const New_level& level)
{
  const auto& record = level.faces();
  const auto& elements = level.elements();
  std::vector<New_face<Mesh>> result(record.number_of_faces());
  for(std::size_t b = 0; b < record.number_of_blocks(); ++b)
    record.for_each_face_in_block(b, [&](std::size_t k, const auto* corners, std::size_t size, std::size_t parent) {
      New_face<Mesh>& face = result[k];
      face.face = elements.faces[k];
      face.parent = parent;
      face.size = static_cast<int>(size);
      for(std::size_t i = 0; i < size; ++i)
        face.vertices[i] = corners[i].vertex;
    });
  return result;
}

/*
 * The provenance sink of one level (`Carried_data::Level` holds one): it reads
 * the old faces (their corners' vertex and edge ordinals, and their parameters
 * in their base face) before the level is made, and writes the `Face_origin`
 * of every new face and the base origin of every new vertex after. The base
 * mesh's faces (corner vertices and edges, by ordinal) are kept in `Base_faces`
 * from the first level to the last.
 */
struct Base_faces
{
  struct Face
  {
    std::vector<std::size_t> vertices; ///< corner i's vertex
    std::vector<std::size_t> edges;    ///< the edge from corner i to corner i + 1
  };
  std::vector<Face> faces;
};

template <class Mesh>
class Provenance_level
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using UV = std::array<double, 2>;

  struct Old_face
  {
    std::vector<typename GT::vertex_descriptor> corners; // the corner vertices
    std::vector<std::size_t> vertices;                   // ordinals in the old mesh
    std::vector<std::size_t> edges;
    std::vector<UV> uv; // empty for a base n-gon of the quad split (sub-quads)
    Face_origin origin; // its own origin (face, sub_quad)
  };

public:
  /*
   * `base`: the base faces, filled here when `is_base`; `origin_of(f)` gives
   * the origin of old face f when !is_base. `quad_split`: n-gons other than
   * quads get sub-quads.
   */
  template <class Origin_of>
  void read(const Mesh& mesh, bool is_base, bool quad_split, const Origin_of& origin_of, Base_faces& base)
  {
    const Mesh_numbering<Mesh> number(mesh);
    m_base = &base;
    if(is_base)
      base.faces.clear();
    m_old.clear();
    for(auto f : faces(mesh)) {
      Old_face old;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        old.corners.push_back(target(h, mesh));
        old.vertices.push_back(number(target(h, mesh)));
        old.edges.push_back(number(edge(next(h, mesh), mesh)));
      }
      if(is_base) {
        base.faces.push_back({old.vertices, old.edges});
        old.origin.face = m_old.size();
        old.uv = canonical_domain(old.vertices.size(), quad_split);
      } else {
        old.origin = origin_of(f);
        old.uv.assign(old.origin.uv.begin(), old.origin.uv.begin() + old.origin.corners);
      }
      m_old.push_back(std::move(old));
    }
  }

  /*
   * After the level: put_face(f, origin) for every new face (`new_faces`,
   * with `new_vertices` their descriptors, `origins` of the new vertices and
   * their `linear_rows`, the stencils of the linear scheme of the split),
   * and put_vertex(v, origin in the base mesh) for every vertex if
   * put_vertex is not empty.
   */
  template <class Rows, class Put_face, class Put_vertex>
  void write(const Mesh& mesh, const std::vector<New_face<Mesh>>& new_faces,
             const std::vector<typename GT::vertex_descriptor>& new_vertices, const std::vector<Vertex_origin>& origins,
             const Rows& linear_rows, const Put_face& put_face, const Put_vertex& put_vertex) const
  {
    for(const New_face<Mesh>& face : new_faces) {
      const Old_face& old = m_old[face.parent];
      Face_origin result = old.origin;
      result.corners = face.size;
      std::array<UV, 4> uv_of_corner{};
      if(old.uv.empty())
        result.sub_quad = sub_quad_of(old, face, origins);
      for(int i = 0; i < face.size; ++i) {
        const std::size_t j = face.vertices[i];
        uv_of_corner[i] = old.uv.empty() ? sub_quad_parameter(old, result.sub_quad, origins[j])
                                         : parameter(old, linear_rows[j].terms());
      }
      // in the order of the written face, from halfedge(f)
      int i = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face.face, mesh), mesh)) {
        const UV& uv = uv_of_corner[face.corner_at(target(h, mesh), new_vertices)];
        result.uv[i++] = uv;
        if(put_vertex)
          put_vertex(target(h, mesh), base_origin(result, uv));
      }
      put_face(face.face, result);
    }
  }

private:
  static std::vector<UV> canonical_domain(std::size_t corners, bool quad_split)
  {
    if(corners == 4)
      return {UV{0, 0}, UV{1, 0}, UV{1, 1}, UV{0, 1}};
    if(corners == 3 && !quad_split)
      return {UV{0, 0}, UV{1, 0}, UV{0, 1}};
    return {}; // sub-quads
  }

  static std::size_t position(const std::vector<std::size_t>& ordinals, std::size_t ordinal)
  {
    return static_cast<std::size_t>(std::find(ordinals.begin(), ordinals.end(), ordinal) - ordinals.begin());
  }

  // the corner of the old n-gon at the child quad's one corner made from an old vertex
  static int sub_quad_of(const Old_face& old, const New_face<Mesh>& face, const std::vector<Vertex_origin>& origins)
  {
    for(int i = 0; i < face.size; ++i) {
      const Vertex_origin o = origins[face.vertices[i]];
      if(o.kind == Origin_kind::vertex)
        return static_cast<int>(position(old.vertices, o.index));
    }
    return -1; // not reached: every child of the quad split has one
  }

  // the parameter of a new vertex in the sub-quad at corner `sub_quad` of a base n-gon, from its origin `o`
  static UV sub_quad_parameter(const Old_face& old, int sub_quad, const Vertex_origin& o)
  {
    if(o.kind == Origin_kind::vertex)
      return {0, 0};
    if(o.kind == Origin_kind::face)
      return {1, 1};
    // the edge from corner c (u) or the edge to it (v)
    return position(old.edges, o.index) == static_cast<std::size_t>(sub_quad) ? UV{1, 0} : UV{0, 1};
  }

  // the parameter of a new vertex in the domain of the old face: its linear
  // stencil (over the old face's corner vertices) applied to their parameters
  template <class Terms>
  static UV parameter(const Old_face& old, const Terms& terms)
  {
    UV sum{0, 0};
    for(const auto& [vertex, weight] : terms) {
      const UV& p = old.uv[static_cast<std::size_t>(std::find(old.corners.begin(), old.corners.end(), vertex) -
                                                    old.corners.begin())];
      const double w = CGAL::to_double(weight);
      sum[0] += w * p[0];
      sum[1] += w * p[1];
    }
    return sum;
  }

  // the element of the base mesh where the point of parameter uv of `face` lies
  Vertex_origin base_origin(const Face_origin& face, const UV& uv) const
  {
    const Base_faces::Face& base = m_base->faces[face.face];
    const std::size_t n = base.vertices.size();
    const double u = uv[0], v = uv[1];
    if(face.sub_quad >= 0) {
      const std::size_t c = static_cast<std::size_t>(face.sub_quad);
      if(u == 0 && v == 0)
        return {Origin_kind::vertex, base.vertices[c]};
      if(v == 0)
        return {Origin_kind::edge, base.edges[c]};
      if(u == 0)
        return {Origin_kind::edge, base.edges[(c + n - 1) % n]};
      return {Origin_kind::face, face.face};
    }
    // the corners and the edges of the unit square or triangle, in order
    const std::vector<UV> domain = canonical_domain(n, false);
    for(std::size_t c = 0; c < n; ++c)
      if(uv == domain[c])
        return {Origin_kind::vertex, base.vertices[c]};
    const bool on_edge[4] = {v == 0, n == 4 ? u == 1 : u + v == 1, n == 4 ? v == 1 : u == 0, u == 0};
    for(std::size_t c = 0; c < n; ++c)
      if(on_edge[c])
        return {Origin_kind::edge, base.edges[c]};
    return {Origin_kind::face, face.face};
  }

  const Base_faces* m_base = nullptr;
  std::vector<Old_face> m_old;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_PROVENANCE_H
