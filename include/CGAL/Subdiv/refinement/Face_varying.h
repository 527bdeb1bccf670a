// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_FACE_VARYING_H
#define CGAL_SUBDIV_REFINEMENT_FACE_VARYING_H

/// \file Face_varying.h
/// The face-varying topology of one level: the mesh cut along the seams of
/// a corner map, so that a seam is a border, refined with the level's mask
/// and sharpness as any mesh is. The interpolation mode sharpens vertices of
/// the cut mesh (OpenSubdiv's `FVarLinearInterpolation`). `Carried_data`
/// combines the corner values with the rows this makes.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/views/Sharp_level.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivFunctions
 * How `Carried_data` interpolates a corner map (face-varying data, such as
 * UVs with seams): OpenSubdiv's `Sdc::Options::FVarLinearInterpolation`,
 * value for value. A seam (an edge whose two faces disagree at one of its
 * ends) is refined as a border; the modes say which vertices of the
 * face-varying topology are kept where they are (doc/provenance.md,
 * "Face-varying data").
 */
enum class Face_varying_interpolation {
  none,          ///< smooth everywhere, seams refined as borders (`FVAR_LINEAR_NONE`)
  corners_only,  ///< as `none`, with the corners (a value in one face) kept (`FVAR_LINEAR_CORNERS_ONLY`)
  corners_plus1, ///< also the junctions of three regions or more: OpenSubdiv's and USD's usual choice
  corners_plus2, ///< also the darts (a seam that ends inside) (`FVAR_LINEAR_CORNERS_PLUS2`)
  boundaries,    ///< every value on a seam or a border kept, seams linear (`FVAR_LINEAR_BOUNDARIES`)
  all            ///< linear in every face (`FVAR_LINEAR_ALL`): the linear scheme of the split, face by face
};

namespace internal {

/// the mesh that a face-varying topology is cut into: its points are never read
using Face_varying_cut_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

/// the row of a new vertex of the cut mesh over its old vertices (one per value)
template <class FT>
using Face_varying_row = Stencil<typename Face_varying_cut_mesh::Vertex_index, FT>;

/// called with the row of every new vertex of the cut mesh, in order: the
/// rows are combined with the values as they come, never stored (a level
/// makes millions of them)
template <class FT>
using Face_varying_row_visitor = std::function<void(const Face_varying_row<FT>&)>;

/*
 * Where the value of every corner of every new face of one level of a corner
 * map comes from: the row of a new vertex of the cut mesh, numbered in the
 * order of the `Face_varying_row_visitor` calls.
 */
template <class Mesh, class FT>
struct Face_varying_rows
{
  /// the row of the new vertex of an old element (ordinal) of a face
  struct Entry
  {
    std::uint32_t element;
    std::uint32_t row;
  };
  /// the entries of old face `face` (ordinal) are [face_starts[face],
  /// face_starts[face + 1]): one for the vertex of each of its n corners,
  /// then one for the edge of each corner, then one for the face if the
  /// split makes a face point (so a face with n corners has 2n or 2n + 1)
  std::vector<std::size_t> face_starts{0};
  std::vector<Entry> entries;

  /// the row of the new vertex that `origin` (of the old mesh) makes in old face `face`
  std::size_t row_of(std::size_t face, const Vertex_origin& origin) const
  {
    const Entry* first = entries.data() + face_starts[face];
    const std::size_t size = face_starts[face + 1] - face_starts[face], corners = size / 2;
    const auto find = [&](const Entry* from, const Entry* to) {
      for(const Entry* e = from; e != to; ++e)
        if(e->element == origin.index)
          return std::size_t(e->row);
      return no_row();
    };
    const std::size_t row = origin.kind == Origin_kind::vertex ? find(first, first + corners)
                            : origin.kind == Origin_kind::edge ? find(first + corners, first + 2 * corners)
                            : size % 2 == 1                    ? std::size_t(first[size - 1].row)
                                                               : no_row();
    if(row == no_row())
      refuse(Message() << "Carried_data: a new corner has no face-varying value (an internal error: please report it)");
    return row;
  }

private:
  static constexpr std::size_t no_row() { return static_cast<std::size_t>(-1); }
};

/*
 * The face-varying topology of a corner map on one level of `mesh`: the
 * corners at a vertex that meet across edges where the values agree at both
 * ends form one value (a vertex of the cut mesh); an edge where they do not
 * is a seam, a border of the cut mesh.
 */
template <class Mesh>
class Face_varying_topology
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using Cut = Face_varying_cut_mesh;

public:
  /// `same(h, g)`: whether corners h and g (halfedges, into their vertex)
  /// hold equal values. On the `base_level` of a channel (the mesh it is
  /// first carried from), the values of a vertex are told apart as OpenSubdiv
  /// tells them apart on its base level (`join_values_as_opensubdiv`); on
  /// the levels it refines, equal values are one value
  Face_varying_topology(const Mesh& mesh, const std::function<bool(halfedge_descriptor, halfedge_descriptor)>& same,
                        bool base_level = false, std::vector<bool> pinned = {})
    : m_mesh(&mesh), m_number(mesh), m_pinned(std::move(pinned))
  {
    join_corners(same);
    make_values();
    group_values_by_vertex();
    for(std::size_t vertex = 0; vertex < num_vertices(mesh); ++vertex)
      if(m_value_starts[vertex + 1] - m_value_starts[vertex] > 1 &&
         !(base_level && join_values_as_opensubdiv(vertex, same)))
        join_equal_values(vertex, same);
    make_cut_mesh();
  }

  const Cut& cut() const { return m_cut; }
  const Mesh& mesh() const { return *m_mesh; }
  const Mesh_numbering<Mesh>& numbering() const { return m_number; }
  /// the vertex of the cut mesh at corner h (a halfedge with a face)
  typename Cut::Vertex_index value_at(halfedge_descriptor h) const { return m_value_of[m_number(h)]; }
  halfedge_descriptor corner_of(typename Cut::Vertex_index v) const { return m_corner_of[v]; }
  /// the vertex of the old mesh (ordinal) of a cut vertex
  std::size_t vertex_of(typename Cut::Vertex_index v) const { return m_vertex_of[v]; }
  /// the edge of the old mesh (ordinal) of a cut edge
  std::size_t edge_of(typename Cut::Edge_index e) const { return m_edge_of[e]; }
  /// the number of values at the vertex of cut vertex v
  int values_at_vertex(typename Cut::Vertex_index v) const { return m_values_at[m_vertex_of[v]]; }
  /// the number of corners (faces) of cut vertex v
  int faces_at(typename Cut::Vertex_index v) const { return m_faces_at[v]; }
  /// whether cut vertex v is on a border of the cut mesh (a seam, or a border of the mesh)
  bool is_on_cut_border(typename Cut::Vertex_index v) const { return m_cut.is_border(m_cut.halfedge(v)); }
  /// whether every value of the vertex of cut vertex v is kept where it is
  /// (a copy of a non-manifold vertex: `non_manifold_corners`)
  bool is_pinned(typename Cut::Vertex_index v) const { return !m_pinned.empty() && m_pinned[m_vertex_of[v]]; }
  /// whether the vertex of cut vertex v is on a border of the old mesh
  bool is_on_mesh_border(typename Cut::Vertex_index v) const
  {
    return bool(CGAL::is_border(target(m_corner_of[v], *m_mesh), *m_mesh));
  }
  /// whether another value of v's vertex is equal to v's, across seams on both sides
  bool is_disjoint(typename Cut::Vertex_index v) const
  {
    const auto [first, last] = values_of_vertex(v);
    return std::count_if(first, last, [&](std::size_t w) { return m_first_equal[w] == m_first_equal[v]; }) > 1;
  }
  /// the first cut vertex of v's vertex whose value is equal to v's (v, if
  /// v is not disjoint): OpenSubdiv's one value of the vertex, over sectors
  /// that seams separate
  typename Cut::Vertex_index first_equal(typename Cut::Vertex_index v) const
  {
    return typename Cut::Vertex_index(static_cast<typename Cut::size_type>(m_first_equal[v]));
  }
  /// the cut vertices of the vertex of cut vertex v (v among them)
  std::pair<const std::size_t*, const std::size_t*> values_of_vertex(typename Cut::Vertex_index v) const
  {
    const std::size_t vertex = m_vertex_of[v];
    const std::size_t* first = m_values_of_vertex.data();
    return {first + m_value_starts[vertex], first + m_value_starts[vertex + 1]};
  }
  /// the cut halfedge of corner h (the same edge and face)
  typename Cut::Halfedge_index cut_halfedge(halfedge_descriptor h) const { return m_cut_halfedge[m_number(h)]; }

private:
  std::size_t root(std::size_t h)
  {
    while(m_parent[h] != h)
      h = m_parent[h] = m_parent[m_parent[h]];
    return h;
  }

  // corners h (in face f1, into v) and o (across the edge leaving v in f1)
  // are one value when the values agree at v and at the edge's other end
  void join_corners(const std::function<bool(halfedge_descriptor, halfedge_descriptor)>& same)
  {
    const Mesh& mesh = *m_mesh;
    m_parent.resize(2 * num_edges(mesh));
    std::iota(m_parent.begin(), m_parent.end(), std::size_t(0));
    for(auto f : faces(mesh))
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor leaving = next(h, mesh), o = opposite(leaving, mesh);
        if(!CGAL::is_border(o, mesh) && same(h, o) && same(leaving, prev(o, mesh)))
          m_parent[root(m_number(h))] = root(m_number(o));
      }
  }

  // a value (a vertex of the cut mesh) for every group of joined corners
  void make_values()
  {
    const Mesh& mesh = *m_mesh;
    const std::size_t none = static_cast<std::size_t>(-1);
    std::vector<std::size_t> value_of_root(m_parent.size(), none);
    m_value_of.assign(m_parent.size(), Cut::Vertex_index());
    m_values_at.assign(num_vertices(mesh), 0);
    for(auto f : faces(mesh))
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        std::size_t& value = value_of_root[root(m_number(h))];
        if(value == none) {
          value = m_corner_of.size();
          m_corner_of.push_back(h);
          m_vertex_of.push_back(m_number(target(h, mesh)));
          m_faces_at.push_back(0);
          ++m_values_at[m_vertex_of.back()];
        }
        ++m_faces_at[value];
        m_value_of[m_number(h)] = Cut::Vertex_index(static_cast<Cut::size_type>(value));
      }
    m_first_equal.resize(m_corner_of.size());
    std::iota(m_first_equal.begin(), m_first_equal.end(), std::size_t(0));
  }

  // the values of every vertex, in order (a counting sort)
  void group_values_by_vertex()
  {
    std::vector<std::size_t>& starts = m_value_starts;
    starts.assign(num_vertices(*m_mesh) + 1, 0);
    for(std::size_t v = 0; v < m_corner_of.size(); ++v)
      ++starts[m_vertex_of[v] + 1];
    std::partial_sum(starts.begin(), starts.end(), starts.begin());
    m_values_of_vertex.resize(m_corner_of.size());
    std::vector<std::size_t> filled(starts.begin(), starts.end() - 1);
    for(std::size_t v = 0; v < m_corner_of.size(); ++v)
      m_values_of_vertex[filled[m_vertex_of[v]]++] = v;
  }

  // values a and b of `vertex` (cut vertices) are one value: the first of
  // them stands for both
  void join_values(std::size_t vertex, std::size_t a, std::size_t b)
  {
    std::size_t first = m_first_equal[a], other = m_first_equal[b];
    if(first == other)
      return;
    if(other < first)
      std::swap(first, other);
    for(std::size_t k = m_value_starts[vertex]; k < m_value_starts[vertex + 1]; ++k)
      if(m_first_equal[m_values_of_vertex[k]] == other)
        m_first_equal[m_values_of_vertex[k]] = first;
    --m_values_at[vertex]; // one value, as OpenSubdiv counts them
  }

  // equal values in sectors that seams separate on both sides are one value
  void join_equal_values(std::size_t vertex, const std::function<bool(halfedge_descriptor, halfedge_descriptor)>& same)
  {
    for(std::size_t a = m_value_starts[vertex]; a < m_value_starts[vertex + 1]; ++a)
      for(std::size_t b = a + 1; b < m_value_starts[vertex + 1]; ++b)
        if(same(m_corner_of[m_values_of_vertex[a]], m_corner_of[m_values_of_vertex[b]]))
          join_values(vertex, m_values_of_vertex[a], m_values_of_vertex[b]);
  }

  /*
   * The values of `vertex` as OpenSubdiv's base level numbers them
   * (`Vtr::internal::FVarLevel::completeTopologyFromFaceValues`): walking
   * around the vertex from its first face (the one after the border, or the
   * lowest face index inside), a corner whose value differs from the
   * previous corner's is a new value unless found among those met before;
   * but while only two are met, it is compared with the first one only. So
   * with values A B A B around a vertex, Far has A once (in two sectors: kept)
   * and B twice (two creases), which this follows. False (nothing done)
   * where the walk does not meet every corner.
   */
  bool join_values_as_opensubdiv(std::size_t vertex,
                                 const std::function<bool(halfedge_descriptor, halfedge_descriptor)>& same)
  {
    const Mesh& mesh = *m_mesh;
    const halfedge_descriptor any = m_corner_of[m_values_of_vertex[m_value_starts[vertex]]];
    // the first corner: the one after the border, else the one in the lowest face
    const auto after_border = [&](halfedge_descriptor h) {
      return CGAL::is_border(opposite(next(h, mesh), mesh), mesh);
    };
    halfedge_descriptor first = any;
    std::size_t corner_count = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(any, mesh))
      if(!CGAL::is_border(h, mesh)) {
        ++corner_count;
        if(after_border(h) || (!after_border(first) && m_number(face(h, mesh)) < m_number(face(first, mesh))))
          first = h;
      }
    // the corners in Far's order: across the edge into the vertex
    std::vector<halfedge_descriptor>& corners = m_walk;
    corners.assign(1, first);
    for(halfedge_descriptor h = first; corners.size() <= corner_count;) {
      const halfedge_descriptor across = opposite(h, mesh);
      if(CGAL::is_border(across, mesh) || prev(across, mesh) == first)
        break;
      h = prev(across, mesh);
      corners.push_back(h);
    }
    if(corners.size() != corner_count)
      return false;
    std::vector<halfedge_descriptor>& met = m_met; // a corner of every value met
    met.assign(1, first);
    std::vector<std::size_t>& value_of_sibling = m_value_of_sibling;
    value_of_sibling.assign(1, value_at(first));
    std::size_t sibling = 0;
    for(std::size_t i = 1; i < corners.size(); ++i) {
      if(!same(corners[i], corners[i - 1])) {
        sibling = met.size();
        if(met.size() > 2 || (met.size() == 2 && same(met[0], corners[i])))
          sibling = static_cast<std::size_t>(
            std::find_if(met.begin(), met.end(), [&](halfedge_descriptor m) { return same(m, corners[i]); }) -
            met.begin());
        if(sibling == met.size()) {
          met.push_back(corners[i]);
          value_of_sibling.push_back(value_at(corners[i]));
        }
      }
      join_values(vertex, value_of_sibling[sibling], value_at(corners[i]));
    }
    return true;
  }

  // whether the faces of corner h and of its opposite o have the same
  // values at both ends of their edge: the edge is not a seam
  bool same_values_across(halfedge_descriptor h, halfedge_descriptor o) const
  {
    const Mesh& mesh = *m_mesh;
    return value_at(h) == value_at(prev(o, mesh)) && value_at(prev(h, mesh)) == value_at(o);
  }

  /*
   * The cut mesh, wired directly (Euler::add_face searches every edge, and a
   * level has millions): face k of the cut is the face of ordinal k, the cut
   * halfedge of corner h runs from the value at prev(h) to the value at h,
   * an edge whose faces have the same values at both ends is one cut edge and
   * a seam is two, each with a border halfedge.
   */
  void make_cut_mesh()
  {
    const Mesh& mesh = *m_mesh;
    using Cut_halfedge = typename Cut::Halfedge_index;
    std::size_t cut_edges = 0;
    for(auto e : edges(mesh)) {
      const halfedge_descriptor h = halfedge(e, mesh), o = opposite(h, mesh);
      cut_edges += CGAL::is_border(h, mesh) || CGAL::is_border(o, mesh) || same_values_across(h, o) ? 1 : 2;
    }
    m_cut.resize(static_cast<typename Cut::size_type>(m_corner_of.size()),
                 static_cast<typename Cut::size_type>(cut_edges),
                 static_cast<typename Cut::size_type>(num_faces(mesh)));
    m_cut_halfedge.assign(m_parent.size(), Cut_halfedge());
    m_edge_of.assign(cut_edges, 0);
    std::size_t next_edge = 0;
    for(auto f : faces(mesh)) {
      const typename Cut::Face_index cut_face(static_cast<typename Cut::size_type>(m_number(f)));
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor o = opposite(h, mesh);
        Cut_halfedge c;
        if(!CGAL::is_border(o, mesh) && m_cut_halfedge[m_number(o)].is_valid() && same_values_across(h, o))
          c = m_cut.opposite(m_cut_halfedge[m_number(o)]);
        else {
          m_edge_of[next_edge] = m_number(h) >> 1;
          c = Cut_halfedge(static_cast<typename Cut::size_type>(2 * next_edge++));
          m_cut.set_target(m_cut.opposite(c), value_at(prev(h, mesh)));
        }
        m_cut.set_target(c, value_at(h));
        m_cut.set_face(c, cut_face);
        m_cut.set_halfedge(value_at(h), c);
        m_cut_halfedge[m_number(h)] = c;
      }
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        m_cut.set_next(cut_halfedge(h), cut_halfedge(next(h, mesh)));
      m_cut.set_halfedge(cut_face, cut_halfedge(halfedge(f, mesh)));
    }
    wire_cut_borders();
  }

  // the border halfedges of the cut: the next of border halfedge b (into
  // vertex s) is the border halfedge out of s, found by turning around s
  // from b's opposite through the faces; a border vertex keeps a border
  // halfedge, as Surface_mesh expects
  void wire_cut_borders()
  {
    using Cut_halfedge = typename Cut::Halfedge_index;
    const std::size_t turns = m_parent.size(); // more would be a loop: not a manifold fan
    for(const Cut_halfedge b : m_cut.halfedges()) {
      if(!m_cut.is_border(b))
        continue;
      Cut_halfedge out = m_cut.opposite(b);
      for(std::size_t turn = 0; !m_cut.is_border(out); ++turn) {
        if(turn == turns)
          refuse(Message() << "Carried_data: the corner values around vertex " << m_vertex_of[m_cut.target(b)]
                           << " do not make a manifold face-varying topology");
        out = m_cut.opposite(m_cut.prev(out));
      }
      m_cut.set_next(b, out);
      m_cut.set_halfedge(m_cut.target(b), b);
    }
  }

  const Mesh* m_mesh;
  Mesh_numbering<Mesh> m_number;
  std::vector<bool> m_pinned;                         // by old vertex ordinal; empty if none is
  std::vector<std::size_t> m_parent;                  // union-find over the corners, by halfedge ordinal
  std::vector<typename Cut::Vertex_index> m_value_of; // by halfedge ordinal (corners only)
  std::vector<halfedge_descriptor> m_corner_of;       // by cut vertex
  std::vector<std::size_t> m_vertex_of;               // by cut vertex
  std::vector<int> m_faces_at;                        // by cut vertex
  std::vector<int> m_values_at;                       // by old vertex ordinal
  std::vector<std::size_t> m_first_equal;             // by cut vertex
  std::vector<std::size_t> m_value_starts;            // by old vertex ordinal, into m_values_of_vertex
  std::vector<std::size_t> m_values_of_vertex;        // cut vertices, grouped by old vertex
  // the scratch of join_values_as_opensubdiv, reused from vertex to vertex
  std::vector<halfedge_descriptor> m_walk, m_met;
  std::vector<std::size_t> m_value_of_sibling;
  std::vector<std::size_t> m_edge_of;                       // by cut edge
  std::vector<typename Cut::Halfedge_index> m_cut_halfedge; // by halfedge ordinal (corners only)
  Cut m_cut;
};

/*
 * The vertices of `mesh` (by ordinal) whose values OpenSubdiv keeps where
 * they are as the values of a non-manifold vertex: the copies of one point
 * (`point_of(v)`, two copies or more) whose corners do not all hold one value
 * (`same`), as `Vtr::internal::FVarLevel::completeTopologyFromFaceValues`
 * sharpens every value of a non-manifold vertex with mismatched values.
 * Empty if there is none.
 */
template <class Mesh, class PointOf, class Same>
std::vector<bool> non_manifold_corners(const Mesh& mesh, const PointOf& point_of, const Same& same)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  const Mesh_numbering<Mesh> number(mesh);
  std::vector<std::pair<std::size_t, std::size_t>> copies; // (point, vertex ordinal)
  for(auto v : vertices(mesh))
    copies.emplace_back(point_of(v), number(v));
  std::sort(copies.begin(), copies.end());
  std::vector<bool> pinned;
  std::vector<halfedge_descriptor> corners;
  for(std::size_t first = 0, last = 0; first < copies.size(); first = last) {
    while(last < copies.size() && copies[last].first == copies[first].first)
      ++last;
    if(last - first < 2)
      continue;
    corners.clear();
    for(std::size_t k = first; k < last; ++k) {
      const auto v = number.vertex(copies[k].second);
      if(halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge())
        for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh))
          if(!CGAL::is_border(h, mesh))
            corners.push_back(h);
    }
    if(std::all_of(corners.begin(), corners.end(), [&](halfedge_descriptor h) { return same(h, corners.front()); }))
      continue;
    pinned.resize(num_vertices(mesh), false);
    for(std::size_t k = first; k < last; ++k)
      pinned[copies[k].second] = true;
  }
  return pinned;
}

/// whether an edge inside the sector of cut vertex v (not a seam) has a
/// sharpness in `tags` that passes `test`
template <class Mesh, class Tags, class Test>
bool has_inner_edge(const Face_varying_topology<Mesh>& topology, const Tags& tags,
                    typename Face_varying_cut_mesh::Vertex_index v, const Test& test)
{
  const Face_varying_cut_mesh& cut = topology.cut();
  for(auto h : CGAL::halfedges_around_target(v, cut))
    if(!CGAL::is_border(cut.edge(h), cut) && test(tags.edge_sharpness(topology.edge_of(cut.edge(h)))))
      return true;
  return false;
}

/// whether the sector of cut vertex v is "disjoint" as OpenSubdiv says: its
/// value is also another sector's, or an edge inside it is infinitely sharp
template <class Mesh, class Tags>
bool is_disjoint_sector(const Face_varying_topology<Mesh>& topology, const Tags& tags,
                        typename Face_varying_cut_mesh::Vertex_index v)
{
  return topology.is_disjoint(v) ||
         has_inner_edge(topology, tags, v, [](const typename Tags::S& s) { return Tags::Rules::is_infinite(s); });
}

/// whether `mode` keeps cut vertex v of `topology` (with the level's
/// sharpness `tags`) where it is (infinitely sharp); OpenSubdiv's
/// `FVarLevel::completeTopologyFromFaceValues` rules
template <class Mesh, class Tags>
bool is_kept_by(Face_varying_interpolation mode, const Face_varying_topology<Mesh>& topology, const Tags& tags,
                typename Face_varying_cut_mesh::Vertex_index v)
{
  if(topology.is_disjoint(v) || topology.is_pinned(v))
    return true;
  if(!topology.is_on_cut_border(v))
    return false;
  const bool corner = topology.faces_at(v) == 1;
  const int values = topology.values_at_vertex(v);
  // plus1 and plus2: a value's sharpness depends on the other's, when there
  // are two: both are kept if either is disjoint, or (plus2) a corner
  const auto other_value_keeps_both = [&](bool corners_too) {
    if(values != 2)
      return false;
    const auto [first, last] = topology.values_of_vertex(v);
    for(const std::size_t* w = first; w != last; ++w) {
      const typename Face_varying_cut_mesh::Vertex_index value(static_cast<std::uint32_t>(*w));
      if((corners_too && topology.faces_at(value) == 1) || is_disjoint_sector(topology, tags, value))
        return true;
    }
    return false;
  };
  switch(mode) {
    case Face_varying_interpolation::none:
      return false;
    case Face_varying_interpolation::corners_only:
      return corner;
    case Face_varying_interpolation::corners_plus1:
      return corner || values > 2 || other_value_keeps_both(false);
    case Face_varying_interpolation::corners_plus2: // a dart: the one value of an inner vertex, on a seam
      return corner || values > 2 || (values == 1 && !topology.is_on_mesh_border(v)) || other_value_keeps_both(true);
    default: // boundaries, all
      return true;
  }
}

/// the rows of `topology`'s cut mesh refined by `cut_mask` (a mask of the
/// cut mesh), given to `visit`, and where each new corner takes its row from
template <class Mesh, class FT, class CutMask>
Face_varying_rows<Mesh, FT> rows_of_cut(const Face_varying_topology<Mesh>& topology, const CutMask& cut_mask,
                                        const Face_varying_row_visitor<FT>& visit)
{
  using Cut = Face_varying_cut_mesh;
  const Cut& cut = topology.cut();
  const Mesh_numbering<Mesh>& number = topology.numbering();
  const Mesh& mesh = topology.mesh();
  Face_varying_rows<Mesh, FT> result;
  const auto host = make_host(cut, cut_mask);
  // one row after the other (one thread, in order), through one stencil that
  // merges the sources
  Face_varying_row<FT> row;
  row.reserve(16);
  for_each_new_vertex(
    host, cut_mask,
    [&](std::size_t, const auto& report) {
      row.clear();
      report(row);
      visit(row);
    },
    Parallel_loop(1));

  // the new vertex of every old element of the cut mesh
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> row_of_vertex(cut.number_of_vertices(), none), row_of_edge(cut.number_of_edges(), none),
    row_of_face(cut.number_of_faces(), none);
  for(std::size_t j = 0; j < host.number_of_new_vertices(); ++j) {
    const Vertex_origin origin = host.origin(j);
    (origin.kind == Origin_kind::vertex ? row_of_vertex
     : origin.kind == Origin_kind::edge ? row_of_edge
                                        : row_of_face)[origin.index] = j;
  }
  const Mesh_numbering<Cut> cut_number(cut);
  using Entry = typename Face_varying_rows<Mesh, FT>::Entry;
  // (a Surface_mesh numbers its elements in 32 bits: so do the entries)
  const auto entry = [](std::size_t element, std::size_t row) {
    return Entry{static_cast<std::uint32_t>(element), static_cast<std::uint32_t>(row)};
  };
  // two entries a corner, one a face: room for all of them at once
  result.entries.reserve(2 * cut.number_of_halfedges() + cut.number_of_faces());
  result.face_starts.reserve(cut.number_of_faces() + 1);
  for(auto f : faces(mesh)) {
    const std::size_t face = number(f);
    // equal values in sectors that seams separate are one value (kept where
    // it is), as in OpenSubdiv: one row, so one index
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      result.entries.push_back(
        entry(number(target(h, mesh)), row_of_vertex[topology.first_equal(topology.value_at(h))]));
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      result.entries.push_back(entry(number(h) >> 1, row_of_edge[cut_number(cut.edge(topology.cut_halfedge(h)))]));
    if(row_of_face[face] != none)
      result.entries.push_back(entry(face, row_of_face[face]));
    result.face_starts.push_back(result.entries.size());
  }
  return result;
}

/*
 * OpenSubdiv's "dependent sharpness" (`corners_plus1`, `corners_plus2`): of
 * the two values of a vertex (not itself sharp), when an edge inside the
 * sector of one (the leader) is semi-sharp and none inside the other's, the
 * other follows the leader. It is kept while the leader is a corner, and
 * when the leader turns into a crease, it is blended with the leader's
 * weight: its vertex sharpness in `sharpness` is that weight (at most 1, so
 * that it too turns into a crease).
 */
template <class Mesh, class FT, class Tags>
void sharpen_dependent_values(const Face_varying_topology<Mesh>& topology, const Tags& tags,
                              Sharpness_by_ordinal<FT>& sharpness)
{
  using Cut = Face_varying_cut_mesh;
  using Rules = typename Sharp_level<Cut, FT>::Rules;
  using S = typename Sharp_level<Cut, FT>::S;
  const auto semi_sharp = [](const S& s) { return Rules::is_semi_sharp(s); };
  // (a level without semi-sharp edges has none: the usual case, in one pass)
  if(std::none_of(sharpness.edges.begin(), sharpness.edges.end(), semi_sharp))
    return;
  const Cut& cut = topology.cut();
  std::vector<std::pair<typename Cut::Vertex_index, typename Cut::Vertex_index>> followers; // (follower, leader)
  for(const typename Cut::Vertex_index v : cut.vertices()) {
    if(topology.values_at_vertex(v) != 2 || Rules::is_sharp(sharpness.vertices[v.idx()]) ||
       has_inner_edge(topology, tags, v, semi_sharp))
      continue;
    const auto [first, last] = topology.values_of_vertex(v);
    for(const std::size_t* w = first; w != last; ++w) {
      const typename Cut::Vertex_index leader(static_cast<std::uint32_t>(*w));
      if(topology.first_equal(leader) != topology.first_equal(v) && has_inner_edge(topology, tags, leader, semi_sharp))
        followers.emplace_back(v, leader);
    }
  }
  if(followers.empty())
    return;
  const Sharp_level<Cut, FT> level(
    cut, [&](typename Cut::Edge_index e) { return sharpness.edges[e.idx()]; },
    [&](typename Cut::Vertex_index v) { return sharpness.vertices[v.idx()]; }, tags.method(), Border_corners::smooth);
  for(const auto& [follower, leader] : followers) {
    const Sharp_vertex<Cut>& rules = level.record(leader.idx());
    if(rules.rule == Vertex_rule::corner)
      sharpness.vertices[follower.idx()] =
        rules.child_rule == Vertex_rule::corner ? Rules::infinite() : S(level.vertex_weight(leader.idx()));
  }
}

/*
 * The sharpness of every edge and vertex of `topology`'s cut mesh, by ordinal:
 * the sharpness `tags` of the mesh's level, and the vertices that `mode` keeps
 * made infinitely sharp (a seam, a border of the cut mesh, is sharp by being
 * one). The refinement of a level and the face-varying limit both take it.
 */
template <class Mesh, class Tags, class FT = typename Tags::Field>
Sharpness_by_ordinal<FT> cut_sharpness(const Face_varying_topology<Mesh>& topology, const Tags& tags,
                                       Face_varying_interpolation mode)
{
  using Cut = Face_varying_cut_mesh;
  using S = typename Sharp_level<Cut, FT>::S;
  const Cut& cut = topology.cut();
  Sharpness_by_ordinal<FT> result;
  result.edges.reserve(cut.number_of_edges());
  for(const typename Cut::Edge_index e : cut.edges())
    result.edges.push_back(S(tags.edge_sharpness(topology.edge_of(e))));
  result.vertices.reserve(cut.number_of_vertices());
  for(const typename Cut::Vertex_index v : cut.vertices())
    result.vertices.push_back(is_kept_by(mode, topology, tags, v) ? Sharp_level<Cut, FT>::Rules::infinite()
                                                                  : S(tags.vertex_sharpness(topology.vertex_of(v))));
  if(mode == Face_varying_interpolation::corners_plus1 || mode == Face_varying_interpolation::corners_plus2)
    sharpen_dependent_values(topology, tags, result);
  return result;
}

/*
 * The sharpness of a level without tags, as `cut_sharpness` reads a
 * `Sharp_level`'s: none, but at the border corners that `corners` pins. It
 * is read at the vertices of the cut mesh only, so it reads no vertex of the
 * mesh in advance, as a `Sharp_level` would (a level has millions).
 */
template <class Mesh, class FT>
class Untagged_level
{
public:
  using Field = FT;
  using S = typename Sharp_level<Mesh, FT>::S;
  using Rules = typename Sharp_level<Mesh, FT>::Rules;

  Untagged_level(const Mesh& mesh, Border_corners corners) : m_mesh(&mesh), m_number(mesh), m_corners(corners) {}

  S edge_sharpness(std::size_t) const { return S(0); }
  S vertex_sharpness(std::size_t i) const
  {
    return is_pinned_border_corner(*m_mesh, m_number.vertex(i), m_corners) ? Rules::infinite() : S(0);
  }
  Crease_method method() const { return Crease_method::uniform; }

private:
  const Mesh* m_mesh;
  Mesh_numbering<Mesh> m_number;
  Border_corners m_corners;
};

/// `make_rows(tags)` with the sharpness tags of `mask`'s level, or an
/// `Untagged_level` of `mesh` if it has none
template <class Mesh, class FT, class Mask, class MakeRows>
auto with_level_tags(const Mesh& mesh, const Mask& mask, const MakeRows& make_rows)
{
  if(mask.sharp_level() != nullptr)
    return make_rows(*mask.sharp_level());
  return make_rows(Untagged_level<Mesh, FT>(mesh, border_corners_of(mask)));
}

/*
 * The rows of one level of a corner map whose topology is `topology`,
 * refined by `mask` (a mask that takes sharpness tags, with the tags of the
 * level or none) in a smooth `mode`: the cut mesh takes the level's
 * sharpness, seams being borders, and the vertices that `mode` keeps are
 * infinitely sharp.
 */
template <class Mesh, class FT, class Mask>
Face_varying_rows<Mesh, FT> smooth_face_varying_rows(const Face_varying_topology<Mesh>& topology, const Mask& mask,
                                                     Face_varying_interpolation mode,
                                                     const Face_varying_row_visitor<FT>& visit)
{
  using Cut = Face_varying_cut_mesh;
  return with_level_tags<Mesh, FT>(topology.mesh(), mask, [&](const auto& tags) {
    const Sharpness_by_ordinal<FT> sharpness = cut_sharpness(topology, tags, mode);
    const Sharp_level<Cut, FT> cut_level(
      topology.cut(), [&](typename Cut::Edge_index e) { return sharpness.edges[e.idx()]; },
      [&](typename Cut::Vertex_index v) { return sharpness.vertices[v.idx()]; }, tags.method(), Border_corners::smooth);
    return rows_of_cut<Mesh, FT>(topology, mask.template rebind<Cut, FT>().with_sharp_level(&cut_level), visit);
  });
}

/// the rows of one level of a corner map whose topology is `topology`,
/// refined by `linear_mask` (the linear scheme of the split), face by face
template <class Mesh, class FT, class LinearMask>
Face_varying_rows<Mesh, FT> linear_face_varying_rows(const Face_varying_topology<Mesh>& topology,
                                                     const LinearMask& linear_mask,
                                                     const Face_varying_row_visitor<FT>& visit)
{
  return rows_of_cut<Mesh, FT>(topology, linear_mask.template rebind<Face_varying_cut_mesh, FT>(), visit);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_FACE_VARYING_H
