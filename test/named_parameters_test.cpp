// The wrappers honour the named parameters they are given: the mask's number
// type comes from the kernel of the vertex_point_map that is used, not from
// the mesh's own points.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <vector>

namespace S = CGAL::Subdiv;
using KD = CGAL::Simple_cartesian<double>;
using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Double_mesh = CGAL::Surface_mesh<KD::Point_3>;
using Exact_mesh = CGAL::Surface_mesh<KE::Point_3>;

namespace {

// a cube whose corners (valence 3) have weights such as 1/9 and 1/36 in
// Catmull-Clark's vertex rule, which no double holds
template <class Mesh>
Mesh cube()
{
  using P = typename Mesh::Point;
  Mesh mesh;
  typename Mesh::Vertex_index v[8];
  for(int i = 0; i < 8; ++i)
    v[i] = mesh.add_vertex(P(i & 1 ? 3 : 0, i & 2 ? 5 : 1, i & 4 ? 7 : 2));
  mesh.add_face(v[0], v[2], v[3], v[1]);
  mesh.add_face(v[4], v[5], v[7], v[6]);
  mesh.add_face(v[0], v[1], v[5], v[4]);
  mesh.add_face(v[2], v[6], v[7], v[3]);
  mesh.add_face(v[0], v[4], v[6], v[2]);
  mesh.add_face(v[1], v[3], v[7], v[5]);
  return mesh;
}

// a tetrahedron: valence 3, Loop-Warren's beta 3/16 and edge weights 3/8, 1/8
template <class Mesh>
Mesh tetrahedron()
{
  using P = typename Mesh::Point;
  Mesh mesh;
  const auto a = mesh.add_vertex(P(0, 0, 0)), b = mesh.add_vertex(P(3, 0, 0)), c = mesh.add_vertex(P(0, 5, 0)),
             d = mesh.add_vertex(P(0, 0, 7));
  mesh.add_face(a, c, b);
  mesh.add_face(a, b, d);
  mesh.add_face(b, c, d);
  mesh.add_face(a, d, c);
  return mesh;
}

// the double mesh with an exact copy of its points in a property map
struct With_exact_points
{
  Double_mesh mesh;
  Double_mesh::Property_map<Double_mesh::Vertex_index, KE::Point_3> exact;

  explicit With_exact_points(const Exact_mesh& source)
  {
    std::vector<Double_mesh::Vertex_index> v;
    for(auto s : vertices(source))
      v.push_back(
        mesh.add_vertex(KD::Point_3(CGAL::to_double(source.point(s).x()), CGAL::to_double(source.point(s).y()),
                                    CGAL::to_double(source.point(s).z()))));
    for(auto f : faces(source)) {
      std::vector<Double_mesh::Vertex_index> corners;
      for(auto s : vertices_around_face(halfedge(f, source), source))
        corners.push_back(v[s.idx()]);
      mesh.add_face(corners);
    }
    exact = mesh.add_property_map<Double_mesh::Vertex_index, KE::Point_3>("v:exact").first;
    for(auto s : vertices(source))
      exact[v[s.idx()]] = source.point(s);
  }
};

template <class Refine>
void expect_exact_through_the_point_map(const Exact_mesh& coarse, const Refine& refine)
{
  Exact_mesh reference = coarse;
  refine(reference, CGAL::parameters::number_of_iterations(2));
  With_exact_points subject(coarse);
  refine(subject.mesh, S::parameters::number_of_iterations(2).vertex_point_map(subject.exact));
  ASSERT_EQ(num_vertices(subject.mesh), num_vertices(reference));
  // with double weights (1/9 rounded) these would differ from the exact ones
  for(auto v : vertices(reference))
    EXPECT_EQ(subject.exact[Double_mesh::Vertex_index(v.idx())], reference.point(v)) << "vertex " << v.idx();
}

} // namespace

TEST(Named_parameters, an_exact_vertex_point_map_gets_exact_weights)
{
  expect_exact_through_the_point_map(cube<Exact_mesh>(),
                                     [](auto& mesh, const auto& np) { S::catmull_clark_subdivision(mesh, np); });
  expect_exact_through_the_point_map(tetrahedron<Exact_mesh>(),
                                     [](auto& mesh, const auto& np) { S::loop_warren_subdivision(mesh, np); });
}
