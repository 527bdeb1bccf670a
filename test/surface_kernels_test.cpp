// Every surface scheme in the four kernels of the issue: Simple_cartesian<double>,
// Epick, Epeck and Simple_cartesian<Exact_rational>. Equalities are exact in the
// exact kernels and to 1e-12 in the floating-point ones.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

namespace S = CGAL::Subdiv;

namespace {

template <class FT>
constexpr bool is_exact()
{
  return !std::is_floating_point<FT>::value;
}

template <class P>
::testing::AssertionResult same(const P& a, const P& b)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  if constexpr(is_exact<FT>()) {
    if(a == b)
      return ::testing::AssertionSuccess();
  } else if(CGAL::to_double(CGAL::squared_distance(a, b)) <=
            1e-24 * (1 + CGAL::to_double((a - CGAL::ORIGIN).squared_length()))) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << a << " != " << b;
}

template <class K>
struct Meshes
{
  using P = typename K::Point_3;
  using Mesh = CGAL::Surface_mesh<P>;
  using V = typename Mesh::Vertex_index;

  // a closed bipyramid (apexes of valence n) and an open fan (a border)
  static Mesh bipyramid(int n)
  {
    Mesh mesh;
    const V top = mesh.add_vertex(P(0, 0, 2)), bottom = mesh.add_vertex(P(1, 0, -3));
    std::vector<V> ring;
    for(int i = 0; i < n; ++i)
      ring.push_back(mesh.add_vertex(P(10 * (i % 3) + i, (i * i) % 7 - 3, i % 2)));
    for(int i = 0; i < n; ++i) {
      mesh.add_face(top, ring[i], ring[(i + 1) % n]);
      mesh.add_face(bottom, ring[(i + 1) % n], ring[i]);
    }
    return mesh;
  }
  static Mesh fan(int n)
  {
    Mesh mesh;
    const V centre = mesh.add_vertex(P(0, 0, 0));
    std::vector<V> ring;
    for(int i = 0; i <= n; ++i)
      ring.push_back(mesh.add_vertex(P(i + 1, i * i - 2, i % 3)));
    for(int i = 0; i < n; ++i)
      mesh.add_face(centre, ring[i], ring[i + 1]);
    return mesh;
  }
  // a cube with one face split into a triangle and a pentagon-ish quad: mixed polygons
  static Mesh mixed()
  {
    Mesh mesh;
    V v[8];
    for(int i = 0; i < 8; ++i)
      v[i] = mesh.add_vertex(P(i & 1 ? 2 : -1, i & 2 ? 3 : 0, i & 4 ? 1 : -2));
    mesh.add_face(v[0], v[2], v[3], v[1]);
    mesh.add_face(v[4], v[5], v[7]);
    mesh.add_face(v[4], v[7], v[6]);
    mesh.add_face(v[0], v[1], v[5], v[4]);
    mesh.add_face(v[2], v[6], v[7], v[3]);
    mesh.add_face(v[0], v[4], v[6], v[2]);
    mesh.add_face(v[1], v[3], v[7], v[5]);
    return mesh;
  }
};

template <class K>
class Surface_kernels : public ::testing::Test
{};
using Kernels =
  ::testing::Types<CGAL::Simple_cartesian<double>, CGAL::Exact_predicates_inexact_constructions_kernel,
                   CGAL::Exact_predicates_exact_constructions_kernel, CGAL::Simple_cartesian<CGAL::Exact_rational>>;
TYPED_TEST_SUITE(Surface_kernels, Kernels);

// the checks every scheme must pass on `mesh`
template <class Mask, class Mesh>
void check_scheme(const Mask& mask, const Mesh& mesh, bool interpolating)
{
  using P = typename Mesh::Point;
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  using FT = typename K::FT;
  const std::string name = mask.name();

  // every new vertex's weights sum to 1 (exactly in exact kernels)
  const S::Host_of<Mask> host(mesh);
  S::internal::for_each_new_vertex(host, mask, [&](std::size_t j, const auto& report) {
    S::Stencil<typename Mesh::Vertex_index, FT> stencil;
    report(stencil);
    if constexpr(is_exact<FT>())
      EXPECT_TRUE(stencil.weight_sum() == FT(1)) << name << " new vertex " << j;
    else
      EXPECT_NEAR(CGAL::to_double(stencil.weight_sum()), 1.0, 1e-14) << name << " new vertex " << j;
  });

  // subdividing an affinely transformed mesh is transforming the subdivided mesh
  const typename K::Aff_transformation_3 t(2, 1, 0, 3, 0, 1, 1, -1, 1, 0, 3, 2);
  Mesh moved = mesh, plain = mesh;
  for(auto v : vertices(moved))
    moved.point(v) = t.transform(moved.point(v));
  S::subdivide(moved, mask, CGAL::parameters::number_of_iterations(2));
  S::subdivide(plain, mask, CGAL::parameters::number_of_iterations(2));
  ASSERT_EQ(num_vertices(moved), num_vertices(plain));
  for(auto v : vertices(plain))
    EXPECT_TRUE(same(moved.point(v), t.transform(plain.point(v)))) << name;

  // the Euler characteristic is kept, the mesh stays valid
  const auto euler = [](const Mesh& m) { return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m)); };
  EXPECT_EQ(euler(plain), euler(mesh)) << name;
  EXPECT_TRUE(plain.is_valid(false)) << name;

  // interpolating schemes keep the old vertices (new vertex i is old vertex i)
  if(interpolating) {
    Mesh once = mesh;
    S::subdivide(once, mask);
    for(auto v : vertices(mesh))
      EXPECT_TRUE(same(once.point(v), mesh.point(v))) << name;
  }

  // a planar mesh stays in its plane
  Mesh flat = mesh;
  for(auto v : vertices(flat))
    flat.point(v) = P(flat.point(v).x(), flat.point(v).y(), 0);
  S::subdivide(flat, mask, CGAL::parameters::number_of_iterations(2));
  for(auto v : vertices(flat))
    EXPECT_TRUE(flat.point(v).z() == FT(0)) << name;
}

} // namespace

TYPED_TEST(Surface_kernels, triangle_schemes)
{
  using M = Meshes<TypeParam>;
  using Mesh = typename M::Mesh;
  for(const Mesh& mesh : {M::bipyramid(3), M::bipyramid(7), M::fan(5)}) {
    check_scheme(S::Loop_mask<Mesh>(), mesh, false);
    check_scheme(S::Loop_mask<Mesh, typename TypeParam::FT, S::Warren_beta>(), mesh, false);
    check_scheme(S::Butterfly_mask<Mesh>(), mesh, true);
    check_scheme(S::Modified_butterfly_mask<Mesh>(), mesh, true);
    check_scheme(S::Linear_triangle_mask<Mesh>(), mesh, true);
    check_scheme(S::Sqrt3_mask<Mesh>(), mesh, false);
    check_scheme(S::Interpolating_sqrt3_mask<Mesh>(), mesh, true);
  }
}

TYPED_TEST(Surface_kernels, polygon_schemes)
{
  using M = Meshes<TypeParam>;
  using Mesh = typename M::Mesh;
  for(const Mesh& mesh : {M::mixed(), M::bipyramid(5), M::fan(4)}) {
    check_scheme(S::Catmull_clark_mask<Mesh>(), mesh, false);
    check_scheme(S::Doo_sabin_mask<Mesh>(), mesh, false);
    check_scheme(S::Linear_quad_mask<Mesh>(), mesh, true);
  }
}
