// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_TESSELLATE_H
#define CGAL_SUBDIV_LIMIT_TESSELLATE_H

/// \file tessellate.h
/// A watertight tessellation of the limit surface: a `Surface_mesh` of limit
/// points, each point on a mesh vertex or a mesh edge evaluated once and
/// shared by the faces around it.

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * The tessellation of one mesh, domain by domain: a quad or a triangle
 * (Loop) is one domain, a Catmull-Clark face with n != 4 corners n
 * sub-quads. A domain is given by the points of its sides (side k from its
 * corner k to corner k+1, counterclockwise in (u, v)); a domain whose
 * opposite sides have the same rates is a grid, any other one a grid inside
 * a ring of triangles that zips the sides to it.
 */
template <class PolygonMesh, class Mask>
class Tessellator
{
  static constexpr bool catmull_clark = Patch_scheme<Mask>::catmull_clark;
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;

public:
  using Output = CGAL::Surface_mesh<Limit_sample::Point>;
  using Out_vertex = typename Output::Vertex_index;
  using Normal_map = typename Output::template Property_map<Out_vertex, Limit_sample::Vector>;

  Tessellator(const Limit_surface<PolygonMesh, Mask>& surface, bool triangulate)
    : m_surface(surface), m_mesh(surface.mesh()), m_number(m_mesh), m_triangulate(triangulate),
      m_rates(num_edges(m_mesh)), m_at_vertex(num_vertices(m_mesh), Output::null_vertex()), m_along(num_edges(m_mesh))
  {}

  /// the rate of every edge, checked (>= 1), even on the edges of a
  /// Catmull-Clark face with n != 4 corners (the next even rate)
  template <class EdgeRate>
  void set_rates(const EdgeRate& edge_rate, double max_points)
  {
    for(const edge_descriptor e : edges(m_mesh)) {
      long long rate = static_cast<long long>(edge_rate(e));
      if(rate < 1)
        refuse(Message() << "tessellate: the rate of edge " << m_number(e) << " is " << rate << ", not >= 1");
      if(catmull_clark && rate % 2 == 1)
        for(const halfedge_descriptor h : {halfedge(e, m_mesh), opposite(halfedge(e, m_mesh), m_mesh)})
          if(!is_border(h, m_mesh) && m_surface.corners_of(face(h, m_mesh)) != 4) {
            ++rate;
            break;
          }
      m_rates[m_number(e)] = rate;
    }
    // before allocating: every domain's grid, its ring and its sides at most
    double points = 0;
    for(const face_descriptor f : faces(m_mesh)) {
      const int n = m_surface.corners_of(f);
      double largest = 0;
      for(const halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, m_mesh), m_mesh))
        largest = std::max(largest, static_cast<double>(rate_of(h)));
      points += (n == 3 && !catmull_clark) ? (largest + 1) * (largest + 2) / 2
                : n == 4                   ? (largest + 1) * (largest + 1)
                                           : n * (largest / 2 + 1) * (largest / 2 + 1);
    }
    if(points > max_points)
      refuse(Message() << "tessellate: the rates would make up to " << std::to_string(points)
                       << " output points, more than the max_output_points limit (" << std::to_string(max_points)
                       << ")");
    for(std::size_t e = 0; e < m_rates.size(); ++e)
      m_along[e].assign(static_cast<std::size_t>(m_rates[e] + 1), Output::null_vertex());
    m_points = static_cast<std::size_t>(points);
  }

  /// tessellates every face into `out`, with normals into `normals` if given
  void run(Output& out, Normal_map* normals)
  {
    m_out = &out;
    m_normals = normals;
    // room for every point, and about as many faces (a quad's grid has fewer)
    out.reserve(static_cast<typename Output::size_type>(m_points),
                static_cast<typename Output::size_type>(3 * m_points),
                static_cast<typename Output::size_type>((m_triangulate || !catmull_clark ? 2 : 1) * m_points));
    for(const face_descriptor f : faces(m_mesh)) {
      const int n = m_surface.corners_of(f);
      std::vector<halfedge_descriptor> h; // h[i]: the halfedge into corner i
      for(const halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(f, m_mesh), m_mesh))
        h.push_back(g);
      if(n == 4 || !catmull_clark) {
        Domain d{f, -1, n == 3, {}};
        for(int k = 0; k < n; ++k)
          d.sides.push_back(edge_side(d, k, h[(k + 1) % n], 0, rate_of(h[(k + 1) % n])));
        tessellate_domain(d);
        continue;
      }
      // n sub-quads; the spokes from the middle of each side (halfedge h[j]) to the face point
      int s = 1;
      for(const halfedge_descriptor g : h)
        s = std::max(s, rate_of(g) / 2);
      Out_vertex centre = Output::null_vertex();
      std::vector<std::vector<Out_vertex>> spokes(static_cast<std::size_t>(n),
                                                  std::vector<Out_vertex>(static_cast<std::size_t>(s + 1)));
      for(int c = 0; c < n; ++c) {
        Domain d{f, c, false, {}};
        const halfedge_descriptor before = h[c], after = h[(c + 1) % n];
        d.sides.push_back(edge_side(d, 0, after, 0, rate_of(after) / 2));
        d.sides.push_back(spoke_side(d, 1, spokes[(c + 1) % n], after, centre, false));
        d.sides.push_back(spoke_side(d, 2, spokes[c], before, centre, true));
        d.sides.push_back(edge_side(d, 3, before, rate_of(before) / 2, rate_of(before) / 2));
        tessellate_domain(d);
      }
    }
  }

private:
  // a quad, a triangle or the sub-quad at `corner` (>= 0) of a face, and the points of its sides
  struct Domain
  {
    face_descriptor face;
    int corner;
    bool triangle;
    std::vector<std::vector<Out_vertex>> sides;
  };

  int rate_of(halfedge_descriptor h) const { return static_cast<int>(m_rates[m_number(edge(h, m_mesh))]); }

  // a new output point: the limit at (i / m, j / l) of the domain (integers, so that the
  // parameter is the same double from every side)
  Out_vertex make_point(const Domain& d, int i, int m, int j, int l)
  {
    const double u = static_cast<double>(i) / m, v = static_cast<double>(j) / l;
    Limit_sample s;
    if constexpr(catmull_clark) {
      if(d.corner >= 0)
        s = m_surface.evaluate(d.face, d.corner, u, v);
      else
        s = m_surface.evaluate(d.face, u, v);
    } else
      s = m_surface.evaluate(d.face, u, v);
    const Out_vertex w = m_out->add_vertex(s.position);
    if(m_normals)
      (*m_normals)[w] = s.normal;
    return w;
  }

  // point k of side `side` (p segments), made at its parameter in the domain if new
  void fill(const Domain& d, int side, int k, int p, Out_vertex& slot)
  {
    if(slot != Output::null_vertex())
      return;
    if(d.triangle) // sides (t, 0), (1 - t, t), (0, 1 - t)
      slot = side == 0   ? make_point(d, k, p, 0, 1)
             : side == 1 ? make_point(d, p - k, p, k, p)
                         : make_point(d, 0, 1, p - k, p);
    else // sides (t, 0), (1, t), (1 - t, 1), (0, 1 - t)
      slot = side == 0   ? make_point(d, k, p, 0, 1)
             : side == 1 ? make_point(d, 1, 1, k, p)
             : side == 2 ? make_point(d, p - k, p, 1, 1)
                         : make_point(d, 0, 1, p - k, p);
  }

  // the slot of point i along halfedge h (from its source), shared with the face beyond
  Out_vertex& edge_slot(halfedge_descriptor h, int i)
  {
    const int r = rate_of(h);
    if(i == 0)
      return m_at_vertex[m_number(source(h, m_mesh))];
    if(i == r)
      return m_at_vertex[m_number(target(h, m_mesh))];
    // the points run from the source of the edge's halfedge of even ordinal (the one `edges()` gives;
    // halfedge(edge(h)) may give h back: Surface_mesh)
    const std::size_t e = m_number(edge(h, m_mesh));
    return m_along[e][static_cast<std::size_t>(m_number(h) == 2 * e ? i : r - i)];
  }

  // side `side` of the domain: points first .. first + p along halfedge h
  std::vector<Out_vertex> edge_side(const Domain& d, int side, halfedge_descriptor h, int first, int p)
  {
    std::vector<Out_vertex> points;
    for(int k = 0; k <= p; ++k) {
      Out_vertex& slot = edge_slot(h, first + k);
      fill(d, side, k, p, slot);
      points.push_back(slot);
    }
    return points;
  }

  // side 1 (from the middle of h to the face point) or, reversed, side 2 of a sub-quad
  std::vector<Out_vertex> spoke_side(const Domain& d, int side, std::vector<Out_vertex>& spoke, halfedge_descriptor h,
                                     Out_vertex& centre, bool reversed)
  {
    const int s = static_cast<int>(spoke.size()) - 1;
    std::vector<Out_vertex> points;
    for(int k = 0; k <= s; ++k) {
      const int i = reversed ? s - k : k; // from the middle of h
      Out_vertex& slot = i == 0 ? edge_slot(h, rate_of(h) / 2) : i == s ? centre : spoke[static_cast<std::size_t>(i)];
      fill(d, side, k, s, slot);
      points.push_back(slot);
    }
    return points;
  }

  void add_face(std::initializer_list<Out_vertex> corners)
  {
    if(m_out->add_face(corners) == Output::null_face())
      refuse(Message() << "tessellate: an output face could not be added (a non-manifold input?)");
  }

  // the cells of a grid g[i][j], 0 <= i <= m, 0 <= j <= l
  void add_grid(const std::vector<std::vector<Out_vertex>>& g)
  {
    for(std::size_t i = 0; i + 1 < g.size(); ++i)
      for(std::size_t j = 0; j + 1 < g[i].size(); ++j) {
        const Out_vertex a = g[i][j], b = g[i + 1][j], c = g[i + 1][j + 1], e = g[i][j + 1];
        if(m_triangulate) {
          add_face({a, b, c});
          add_face({a, c, e});
        } else
          add_face({a, b, c, e});
      }
  }

  // the triangles t[i][j] (i + j <= m) of a triangular grid
  void add_triangle_grid(const std::vector<std::vector<Out_vertex>>& t)
  {
    const std::size_t m = t.size() - 1;
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t j = 0; i + j < m; ++j) {
        add_face({t[i][j], t[i + 1][j], t[i][j + 1]});
        if(i + j + 1 < m)
          add_face({t[i + 1][j], t[i + 1][j + 1], t[i][j + 1]});
      }
  }

  // the strip of triangles between outer side o and inner side in, both counterclockwise
  void zip(const std::vector<Out_vertex>& o, const std::vector<Out_vertex>& in)
  {
    const std::size_t p = o.size() - 1, q = in.size() - 1;
    std::size_t a = 0, b = 0;
    while(a < p || b < q) {
      if(b == q || (a < p && (a + 1) * q <= (b + 1) * p)) {
        add_face({o[a], o[a + 1], in[b]});
        ++a;
      } else {
        add_face({o[a], in[b + 1], in[b]});
        ++b;
      }
    }
  }

  void tessellate_domain(const Domain& d)
  {
    const auto rate = [&d](int k) { return static_cast<int>(d.sides[static_cast<std::size_t>(k)].size()) - 1; };
    const auto& side = d.sides;
    if(d.triangle) {
      const int m = std::max({rate(0), rate(1), rate(2)});
      const bool uniform = rate(0) == m && rate(1) == m && rate(2) == m;
      std::vector<std::vector<Out_vertex>> t(static_cast<std::size_t>(m + 1));
      for(int i = 0; i <= m; ++i)
        t[i].assign(static_cast<std::size_t>(m + 1 - i), Output::null_vertex());
      if(uniform)
        for(int k = 0; k <= m; ++k) {
          t[k][0] = side[0][k];
          t[m - k][k] = side[1][k];
          t[0][m - k] = side[2][k];
        }
      for(int i = 1; i < m; ++i)
        for(int j = 1; i + j < m; ++j)
          t[i][j] = make_point(d, i, m, j, m);
      if(uniform)
        return add_triangle_grid(t);
      if(m < 3) // no inner point: a fan around the face point
        return ring(side, std::vector<std::vector<Out_vertex>>(3, {make_point(d, 1, 3, 1, 3)}));
      // the inner grid, its corners (1, 1), (m - 2, 1), (1, m - 2)
      const int q = m - 3;
      std::vector<std::vector<Out_vertex>> inner(static_cast<std::size_t>(q + 1)), sides(3);
      for(int i = 0; i <= q; ++i)
        for(int j = 0; i + j <= q; ++j)
          inner[i].push_back(t[i + 1][j + 1]);
      add_triangle_grid(inner);
      for(int k = 0; k <= q; ++k) {
        sides[0].push_back(inner[k][0]);
        sides[1].push_back(inner[q - k][k]);
        sides[2].push_back(inner[0][q - k]);
      }
      return ring(side, sides);
    }
    const int mu = std::max(rate(0), rate(2)), mv = std::max(rate(1), rate(3));
    const bool uniform = rate(0) == mu && rate(2) == mu && rate(1) == mv && rate(3) == mv;
    std::vector<std::vector<Out_vertex>> g(static_cast<std::size_t>(mu + 1),
                                           std::vector<Out_vertex>(static_cast<std::size_t>(mv + 1)));
    if(uniform) {
      for(int i = 0; i <= mu; ++i) {
        g[i][0] = side[0][i];
        g[mu - i][mv] = side[2][i];
      }
      for(int j = 0; j <= mv; ++j) {
        g[mu][j] = side[1][j];
        g[0][mv - j] = side[3][j];
      }
    }
    for(int i = 1; i < mu; ++i)
      for(int j = 1; j < mv; ++j)
        g[i][j] = make_point(d, i, mu, j, mv);
    if(uniform)
      return add_grid(g);
    if(mu < 2 || mv < 2) // no inner point: a fan around the face point
      return ring(side, std::vector<std::vector<Out_vertex>>(4, {make_point(d, 1, 2, 1, 2)}));
    // the inner grid, from (1, 1) to (mu - 1, mv - 1)
    std::vector<std::vector<Out_vertex>> inner, sides(4);
    for(int i = 1; i < mu; ++i)
      inner.emplace_back(g[i].begin() + 1, g[i].end() - 1);
    add_grid(inner);
    const int a = mu - 2, b = mv - 2;
    for(int i = 0; i <= a; ++i) {
      sides[0].push_back(inner[i][0]);
      sides[2].push_back(inner[a - i][b]);
    }
    for(int j = 0; j <= b; ++j) {
      sides[1].push_back(inner[a][j]);
      sides[3].push_back(inner[0][b - j]);
    }
    ring(side, sides);
  }

  void ring(const std::vector<std::vector<Out_vertex>>& outer, const std::vector<std::vector<Out_vertex>>& inner)
  {
    for(std::size_t k = 0; k < outer.size(); ++k)
      zip(outer[k], inner[k]);
  }

  const Limit_surface<PolygonMesh, Mask>& m_surface;
  const PolygonMesh& m_mesh;
  Mesh_numbering<PolygonMesh> m_number;
  bool m_triangulate;
  // by ordinal: every edge's rate, every vertex's point, the points along every edge (`edge_slot()`)
  std::vector<long long> m_rates;
  std::vector<Out_vertex> m_at_vertex;
  std::vector<std::vector<Out_vertex>> m_along;
  std::size_t m_points = 0; // at most
  Output* m_out = nullptr;
  Normal_map* m_normals = nullptr;
};

template <class PolygonMesh, class Mask, class EdgeRate, class NamedParameters>
void tessellate(const Limit_surface<PolygonMesh, Mask>& surface, CGAL::Surface_mesh<Limit_sample::Point>& out,
                const EdgeRate& edge_rate, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Output = CGAL::Surface_mesh<Limit_sample::Point>;
  const bool triangulate = choose_parameter(get_parameter(np, triangulate_t()), false);
  const bool normals = choose_parameter(get_parameter(np, output_normals_t()), false);
  const double max_points =
    static_cast<double>(choose_parameter(get_parameter(np, max_output_points_t()), std::size_t(1) << 24));
  Tessellator<PolygonMesh, Mask> tessellator(surface, triangulate);
  tessellator.set_rates(edge_rate, max_points);
  Output result;
  typename Tessellator<PolygonMesh, Mask>::Normal_map normal_map;
  if(normals)
    normal_map = result.template add_property_map<Output::Vertex_index, Limit_sample::Vector>("v:normal").first;
  tessellator.run(result, normals ? &normal_map : nullptr);
  out = std::move(result);
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * Makes `out` a tessellation of the limit surface of `surface` (its mesh,
 * every face) at `rate` segments per mesh edge, `rate >= 1`:
 * - a quad is cut into `rate` x `rate` quads (two triangles each with
 *   `triangulate(true)`), its grid point (i, j) the limit at (i / rate,
 *   j / rate);
 * - a triangle (Loop) into `rate`^2 triangles, grid point (i, j) at
 *   (i / rate, j / rate);
 * - a Catmull-Clark face with n != 4 corners into its n sub-quads, each a
 *   grid at rate `rate` / 2, so that each of its edges has `rate` segments
 *   like the quads around it (an odd rate is raised to the next even one on
 *   the edges of such faces, and the quads next to them zip the difference
 *   as `tessellate()` with an edge rate does).
 *
 * Every output point on a mesh vertex or a mesh edge is evaluated once, from
 * the first face that reaches it, and shared by the faces around it: the
 * output has no crack by construction, it is closed when the mesh is, and
 * its faces are oriented as the mesh's.
 *
 * Named parameters (`CGAL::Subdiv::parameters`):
 * - `triangulate(bool)`: triangles only (default false: quads where the
 *   domain is a quad grid);
 * - `output_normals(bool)`: the unit limit normals (`Limit_sample::normal`)
 *   into the vertex property "v:normal" of `out` (`Limit_sample::Vector`);
 * - `max_output_points(n)`: refuse, before allocating, rates that could make
 *   more than n output points (default 2^24, about 2 GB of output).
 *
 * \throws Bad_input if `rate < 1` or the output would be too large; `out`
 * is then unchanged (the output is built apart, then moved into it).
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
void tessellate(const Limit_surface<PolygonMesh, Mask>& surface, CGAL::Surface_mesh<Limit_sample::Point>& out, int rate,
                const NamedParameters& np = parameters::default_values())
{
  internal::tessellate(
    surface, out, [rate](typename boost::graph_traits<PolygonMesh>::edge_descriptor) { return rate; }, np);
}

/*!
 * \ingroup PkgSubdivAnalysis
 * The same with a rate per edge: `edge_rate(e)` (an int >= 1) segments along
 * mesh edge `e`, from both of its faces (raised to the next even rate on the
 * edges of a Catmull-Clark face with n != 4 corners, halved on its
 * sub-quads). Inside a domain (a quad, a triangle or a sub-quad) the rate is
 * the larger of the two opposite sides' along u and along v (a triangle: the
 * largest of its three; a sub-quad: its face's largest half rate, which is
 * also the rate of its spokes to the face point). A domain whose sides all
 * have the inner rates is a grid as above; any other one is its inner grid
 * (the points at (i / mu, j / mv), 1 <= i < mu, 1 <= j < mv), or if that is
 * empty the face point, in a ring of triangles that zips each side's points
 * to the inner grid's side, so the sides of different rates join without a
 * crack (as OpenSubdiv's `Bfr::Tessellation` does).
 */
template <class PolygonMesh, class Mask, class EdgeRate, class NamedParameters = parameters::Default_named_parameters,
          class = std::enable_if_t<
            std::is_invocable_v<const EdgeRate&, typename boost::graph_traits<PolygonMesh>::edge_descriptor>>>
void tessellate(const Limit_surface<PolygonMesh, Mask>& surface, CGAL::Surface_mesh<Limit_sample::Point>& out,
                const EdgeRate& edge_rate, const NamedParameters& np = parameters::default_values())
{
  internal::tessellate(surface, out, edge_rate, np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_TESSELLATE_H
