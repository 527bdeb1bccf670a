// Meshes built by the tests, written once: grids, fans, bipyramids, polyhedra.
// Every builder takes the mesh type (any Surface_mesh); points come from
// callbacks where the tests need particular coordinates, so that exact
// kernels get exact rational coordinates.
#ifndef CGAL_SUBDIV_TEST_MESH_BUILDERS_H
#define CGAL_SUBDIV_TEST_MESH_BUILDERS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/iterator.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace testing_utils {

template <class Mesh>
using Point_of = typename Mesh::Point;
template <class Mesh>
using FT_of = typename CGAL::Kernel_traits<Point_of<Mesh>>::Kernel::FT;

/// deterministic small rationals in [-1, 1], denominators 16 (exact in every kernel)
struct Rationals
{
  std::uint32_t state = 12345;
  template <class FT = double>
  FT next()
  {
    state = state * 1103515245u + 12345u;
    const int numerator = static_cast<int>((state >> 16) % 33) - 16;
    return FT(numerator) / FT(16);
  }
};

/// a mesh from points and faces given by indices into the points
template <class Mesh>
Mesh mesh_of(const std::vector<Point_of<Mesh>>& points, const std::vector<std::vector<int>>& faces)
{
  Mesh mesh;
  std::vector<typename Mesh::Vertex_index> v;
  for(const auto& p : points)
    v.push_back(mesh.add_vertex(p));
  for(const auto& f : faces) {
    std::vector<typename Mesh::Vertex_index> corners;
    for(int i : f)
      corners.push_back(v[static_cast<std::size_t>(i)]);
    EXPECT_NE(mesh.add_face(corners), Mesh::null_face());
  }
  return mesh;
}

/// the same mesh in another mesh type (points converted coordinate by
/// coordinate through double, exact for the dyadic coordinates of files), same indices
template <class Out, class In>
Out copy_mesh(const In& in)
{
  using FT = FT_of<Out>;
  Out out;
  for(auto v : vertices(in)) {
    const auto& p = in.point(v);
    out.add_vertex(Point_of<Out>(FT(CGAL::to_double(p.x())), FT(CGAL::to_double(p.y())), FT(CGAL::to_double(p.z()))));
  }
  for(auto f : faces(in)) {
    std::vector<typename Out::Vertex_index> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, in), in))
      corners.push_back(typename Out::Vertex_index(static_cast<typename Out::size_type>(v.idx())));
    out.add_face(corners);
  }
  return out;
}

/// a regular tetrahedron, faces outward
template <class Mesh>
Mesh tetrahedron()
{
  using P = Point_of<Mesh>;
  return mesh_of<Mesh>({P(1, 1, 1), P(1, -1, -1), P(-1, 1, -1), P(-1, -1, 1)},
                       {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}});
}

/// the unit cube [0, 1]^3 of six quads, faces outward
template <class Mesh>
Mesh cube()
{
  using P = Point_of<Mesh>;
  return mesh_of<Mesh>({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0), P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1)},
                       {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}

/// a box with one face split into two triangles: quads and triangles
template <class Mesh>
Mesh mixed_box()
{
  using P = Point_of<Mesh>;
  std::vector<P> points;
  for(int i = 0; i < 8; ++i)
    points.push_back(P(i & 1 ? 2 : -1, i & 2 ? 3 : 0, i & 4 ? 1 : -2));
  return mesh_of<Mesh>(points,
                       {{0, 2, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

/// a prism over an n-gon: two n-gon caps and n quads (faces of every size for
/// the polygon schemes), with generic rational points
template <class Mesh>
Mesh prism(int n)
{
  using P = Point_of<Mesh>;
  using FT = FT_of<Mesh>;
  Rationals r;
  std::vector<P> points;
  for(int level = 0; level < 2; ++level)
    for(int i = 0; i < n; ++i)
      points.push_back(
        P(FT(i * i % (n + 2)) + r.next<FT>(), FT(i % 4) * FT(level + 1) + r.next<FT>(), FT(3 * level) + r.next<FT>()));
  std::vector<std::vector<int>> faces(2);
  for(int i = 0; i < n; ++i) {
    faces[0].push_back(n - 1 - i); // bottom, seen from below
    faces[1].push_back(n + i);
    faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  }
  return mesh_of<Mesh>(points, faces);
}

/// a closed bipyramid: two apexes of valence n (vertices 0 and 1) over a ring
/// of n vertices of valence 4 (vertices 2 .. n+1)
template <class Mesh>
Mesh bipyramid(int n, const Point_of<Mesh>& top, const Point_of<Mesh>& bottom,
               const std::function<Point_of<Mesh>(int)>& ring_point)
{
  Mesh mesh;
  const auto t = mesh.add_vertex(top), b = mesh.add_vertex(bottom);
  std::vector<typename Mesh::Vertex_index> ring;
  for(int i = 0; i < n; ++i)
    ring.push_back(mesh.add_vertex(ring_point(i)));
  for(int i = 0; i < n; ++i) {
    mesh.add_face(t, ring[i], ring[(i + 1) % n]);
    mesh.add_face(b, ring[(i + 1) % n], ring[i]);
  }
  return mesh;
}

/// the bipyramid with integer points near a circle
template <class Mesh>
Mesh bipyramid(int n)
{
  using P = Point_of<Mesh>;
  return bipyramid<Mesh>(n, P(0, 0, 2), P(1, 0, -3), [](int i) { return P(10 * (i % 3) + i, (i * i) % 7 - 3, i % 2); });
}

/// an open fan: a centre vertex (vertex 0) with n triangles around it, the
/// last one missing (the centre is a border vertex with n faces); ring i is vertex i + 1
template <class Mesh>
Mesh open_fan(int n, const Point_of<Mesh>& centre, const std::function<Point_of<Mesh>(int)>& ring_point)
{
  Mesh mesh;
  const auto c = mesh.add_vertex(centre);
  std::vector<typename Mesh::Vertex_index> ring;
  for(int i = 0; i <= n; ++i)
    ring.push_back(mesh.add_vertex(ring_point(i)));
  for(int i = 0; i < n; ++i)
    mesh.add_face(c, ring[i], ring[i + 1]);
  return mesh;
}

template <class Mesh>
Mesh open_fan(int n)
{
  using P = Point_of<Mesh>;
  return open_fan<Mesh>(n, P(0, 0, 0), [](int i) { return P(i + 1, i * i - 2, i % 3); });
}

/// a closed fan: an interior vertex of valence n (vertex 0) and a border loop
/// of n vertices (vertices 1 .. n)
template <class Mesh>
Mesh closed_fan(int n, const Point_of<Mesh>& centre, const std::function<Point_of<Mesh>(int)>& ring_point)
{
  Mesh mesh;
  const auto c = mesh.add_vertex(centre);
  std::vector<typename Mesh::Vertex_index> ring;
  for(int i = 0; i < n; ++i)
    ring.push_back(mesh.add_vertex(ring_point(i)));
  for(int i = 0; i < n; ++i)
    mesh.add_face(c, ring[i], ring[(i + 1) % n]);
  return mesh;
}

/// how the squares of a triangle grid are cut
enum class Diagonal {
  ascending,  // (i, j)-(i+1, j+1): every interior vertex has valence 6
  descending, // (i+1, j)-(i, j+1): every interior vertex has valence 6
  alternating // ascending where i + j is even: valences 4 and 8
};

/// the faces of the n x m cells of a lattice whose vertex (i, j) is number
/// id(i, j) (an id may wrap around, for a torus): the quad (i, j), (i+1, j),
/// (i+1, j+1), (i, j+1), or its two triangles, cut from (i, j) to (i+1, j+1)
/// where ascending(i, j), else from (i+1, j) to (i, j+1); cells by increasing
/// j, then i
inline std::vector<std::vector<int>> lattice_faces(int n, int m, const std::function<int(int, int)>& id, bool triangles,
                                                   const std::function<bool(int, int)>& ascending)
{
  std::vector<std::vector<int>> faces;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if(!triangles)
        faces.push_back({a, b, c, d});
      else if(ascending(i, j)) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, d});
        faces.push_back({b, c, d});
      }
    }
  return faces;
}

/// the lattice (i, j), 0 <= i <= n, 0 <= j <= m: vertex (i, j) is number
/// j (n + 1) + i, with the point point(i, j); quads, or triangles cut where
/// ascending(i, j) from (i, j) to (i+1, j+1) (lattice_faces)
template <class Mesh>
Mesh grid(int n, int m, const std::function<Point_of<Mesh>(int, int)>& point, bool triangles,
          const std::function<bool(int, int)>& ascending)
{
  std::vector<Point_of<Mesh>> points;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= n; ++i)
      points.push_back(point(i, j));
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  return mesh_of<Mesh>(points, lattice_faces(n, m, id, triangles, ascending));
}

/// the same with the diagonals of `diagonal`
template <class Mesh>
Mesh grid(int n, int m, const std::function<Point_of<Mesh>(int, int)>& point, bool triangles,
          Diagonal diagonal = Diagonal::ascending)
{
  return grid<Mesh>(n, m, point, triangles, [diagonal](int i, int j) {
    return diagonal == Diagonal::ascending || (diagonal == Diagonal::alternating && (i + j) % 2 == 0);
  });
}

/// vertex (i, j) of a grid(n, m, ...)
template <class Mesh>
typename Mesh::Vertex_index grid_vertex(int n, int i, int j)
{
  return typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(j * (n + 1) + i));
}

} // namespace testing_utils

#endif // CGAL_SUBDIV_TEST_MESH_BUILDERS_H
