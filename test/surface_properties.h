// The properties every surface scheme has, written once as a type-parametrised
// suite over scheme x kernel; each test loops over the fixtures (mesh_builders.h
// and bundled meshes) that fit the scheme's split. The *_test.cpp files that
// include this header instantiate it for a group of schemes, so that no
// translation unit instantiates too many schemes in exact kernels.
//
// Exact kernels (Epeck, Simple_cartesian<Exact_rational>) are checked with ==;
// floating-point ones to a relative 1e-11 or so.
#ifndef CGAL_SUBDIV_TEST_SURFACE_PROPERTIES_H
#define CGAL_SUBDIV_TEST_SURFACE_PROPERTIES_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"

#include <algorithm>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace surface_properties {

namespace S = CGAL::Subdiv;
namespace T = testing_utils;

using Double_kernel = CGAL::Simple_cartesian<double>;
using Rational_kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// ------------------------------------------------------------------ schemes
// A scheme gives the mask objects to check for a mesh type: the default and,
// where the mask has options, other values of them (the same type, so no
// further instantiation).

struct Loop
{
  template <class Mesh>
  static std::vector<S::Loop_mask<Mesh>> masks()
  {
    return {S::Loop_mask<Mesh>(), S::Loop_mask<Mesh>(S::Border_corners::sharp)};
  }
};

struct Loop_warren
{
  template <class Mesh>
  static std::vector<S::Loop_mask<Mesh, T::FT_of<Mesh>, S::Warren_beta>> masks()
  {
    using M = S::Loop_mask<Mesh, T::FT_of<Mesh>, S::Warren_beta>;
    return {M(), M(S::Border_corners::sharp)};
  }
};

struct Butterfly
{
  template <class Mesh>
  static std::vector<S::Butterfly_mask<Mesh>> masks()
  {
    using FT = T::FT_of<Mesh>;
    return {S::Butterfly_mask<Mesh>(), S::Butterfly_mask<Mesh>(FT(1) / FT(10))};
  }
};

struct Modified_butterfly
{
  template <class Mesh>
  static std::vector<S::Modified_butterfly_mask<Mesh>> masks()
  {
    using FT = T::FT_of<Mesh>;
    return {S::Modified_butterfly_mask<Mesh>(), S::Modified_butterfly_mask<Mesh>(FT(-1) / FT(32))};
  }
};

struct Linear_triangle
{
  template <class Mesh>
  static std::vector<S::Linear_triangle_mask<Mesh>> masks()
  {
    return {S::Linear_triangle_mask<Mesh>()};
  }
};

struct Sqrt3
{
  template <class Mesh>
  static std::vector<S::Sqrt3_mask<Mesh>> masks()
  {
    return {S::Sqrt3_mask<Mesh>()};
  }
};

struct Interpolating_sqrt3
{
  template <class Mesh>
  static std::vector<S::Interpolating_sqrt3_mask<Mesh>> masks()
  {
    return {S::Interpolating_sqrt3_mask<Mesh>()};
  }
};

struct Catmull_clark
{
  template <class Mesh>
  static std::vector<S::Catmull_clark_mask<Mesh>> masks()
  {
    return {S::Catmull_clark_mask<Mesh>(), S::Catmull_clark_mask<Mesh>(S::Border_corners::sharp)};
  }
};

struct Doo_sabin
{
  template <class Mesh>
  static std::vector<S::Doo_sabin_mask<Mesh>> masks()
  {
    return {S::Doo_sabin_mask<Mesh>()};
  }
};

struct Linear_quad
{
  template <class Mesh>
  static std::vector<S::Linear_quad_mask<Mesh>> masks()
  {
    return {S::Linear_quad_mask<Mesh>()};
  }
};

/// a type parameter of the suites: a scheme in a kernel
template <class SchemeT, class KernelT>
struct Case
{
  using Scheme = SchemeT;
  using Kernel = KernelT;
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  using FT = typename Kernel::FT;
  using Mask = typename decltype(Scheme::template masks<Mesh>())::value_type;
  static constexpr bool exact = !std::is_floating_point<FT>::value;
  static constexpr bool triangles_only =
    Mask::split == S::Split::triangle_quadrisection || Mask::split == S::Split::sqrt3;
};

// ----------------------------------------------------------------- fixtures

template <class Mesh>
using Fixtures = std::vector<std::pair<std::string, Mesh>>;

/// bundled meshes of triangles: closed, with borders, valences 2 to 10
inline const std::vector<std::string>& triangle_files()
{
  static const std::vector<std::string> names = {"cgal/icosahedron.off", "cgal/open_cube.off", "cgal/hedra_open.off",
                                                 "cgal/corner_tris_with_hole.off", "cgal/patch-23.off"};
  return names;
}

/// bundled meshes of any polygons: faces of 3 to 10 corners (mpi.off), genus
/// 3 (3torus.off), borders, a genus-2 mesh with three holes
inline const std::vector<std::string>& polygon_files()
{
  static const std::vector<std::string> names = {"cgal/cube_quad.off",
                                                 "cgal/corner.off",
                                                 "cgal/P.off",
                                                 "cgal/mpi.off",
                                                 "cgal/3torus.off",
                                                 "cgal/corner_poly.off",
                                                 "cgal/corner_with_hole.off",
                                                 "cgal/corner_with_sharp_edge.off",
                                                 "cgal/mesh_with_colors.off",
                                                 "cgal/double-torus-3-holes.off"};
  return names;
}

/// the meshes a scheme is checked on: small built meshes with generic rational
/// points (every valence 3 to 12 inside and on a border), then bundled files
template <class Mesh>
Fixtures<Mesh> fixtures(bool triangles_only)
{
  using P = T::Point_of<Mesh>;
  using FT = T::FT_of<Mesh>;
  using Double_mesh = CGAL::Surface_mesh<Double_kernel::Point_3>;
  Fixtures<Mesh> out;
  T::Rationals r;
  const auto generic = [&](int i) { return P(FT(i) + r.next<FT>(), FT(i * i % 7) + r.next<FT>(), r.next<FT>()); };
  const auto height = [&](int i, int j) { return P(FT(i), FT(j), r.next<FT>()); };
  if(triangles_only) {
    out.emplace_back("tetrahedron", T::tetrahedron<Mesh>());
    for(int n = 3; n <= 12; ++n) {
      out.emplace_back("bipyramid " + std::to_string(n), T::bipyramid<Mesh>(n));
      out.emplace_back("closed fan " + std::to_string(n),
                       T::closed_fan<Mesh>(n, P(r.next<FT>(), r.next<FT>(), 1), generic));
      if(n <= 9)
        out.emplace_back("open fan " + std::to_string(n), T::open_fan<Mesh>(n));
    }
    out.emplace_back("grid", T::grid<Mesh>(6, 5, height, true));
    out.emplace_back("grid of valences 4 and 8", T::grid<Mesh>(4, 4, height, true, T::Diagonal::alternating));
    // interior edges with both ends on the border
    out.emplace_back("strip", T::grid<Mesh>(6, 1, height, true));
    out.emplace_back("triangle", T::grid<Mesh>(1, 1, height, true));
    for(const std::string& name : triangle_files())
      out.emplace_back(name, T::copy_mesh<Mesh>(T::bundled<Double_mesh>(name)));
  } else {
    out.emplace_back("cube", T::cube<Mesh>());
    out.emplace_back("box of quads and triangles", T::mixed_box<Mesh>());
    for(int n = 3; n <= 10; ++n) // caps of n corners: Doo-Sabin's rounded cosines for n = 5, 7, 8, 9, 10
      out.emplace_back("prism " + std::to_string(n), T::prism<Mesh>(n));
    out.emplace_back("bipyramid 5", T::bipyramid<Mesh>(5));
    out.emplace_back("open fan 4", T::open_fan<Mesh>(4));
    out.emplace_back("quad grid", T::grid<Mesh>(4, 3, height, false));
    for(const std::string& name : polygon_files())
      out.emplace_back(name, T::copy_mesh<Mesh>(T::bundled<Double_mesh>(name)));
  }
  return out;
}

// ------------------------------------------------------------------ helpers

template <class P>
::testing::AssertionResult same_point(const P& a, const P& b)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  if constexpr(!std::is_floating_point<FT>::value) {
    if(a == b)
      return ::testing::AssertionSuccess();
  } else if(CGAL::to_double(CGAL::squared_distance(a, b)) <=
            1e-22 * (1 + CGAL::to_double((a - CGAL::ORIGIN).squared_length()))) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << a << " != " << b;
}

template <class FT>
::testing::AssertionResult sums_to_one(const FT& sum)
{
  if constexpr(!std::is_floating_point<FT>::value) {
    if(sum == FT(1))
      return ::testing::AssertionSuccess();
  } else if(std::abs(CGAL::to_double(sum) - 1) <= 1e-14) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "sum " << sum;
}

template <class Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

template <class Mesh>
std::size_t corner_count(const Mesh& mesh)
{
  std::size_t c = 0;
  for(auto h : halfedges(mesh))
    c += CGAL::is_border(h, mesh) ? 0 : 1;
  return c;
}

template <class Mesh>
std::size_t border_edge_count(const Mesh& mesh)
{
  std::size_t b = 0;
  for(auto e : edges(mesh))
    b += CGAL::is_border(e, mesh) ? 1 : 0;
  return b;
}

template <class Mesh>
std::vector<T::Point_of<Mesh>> points_of(const Mesh& mesh)
{
  std::vector<T::Point_of<Mesh>> points;
  for(auto v : vertices(mesh))
    points.push_back(get(CGAL::vertex_point, mesh, v));
  return points;
}

/// levels run by the tests: three for sqrt3 (a border rests, refines, rests), else two
template <class Mask>
constexpr int levels()
{
  return Mask::split == S::Split::sqrt3 ? 3 : 2;
}

// ------------------------------------------------------------------- suites

template <class C>
class Surface_properties : public ::testing::Test
{};
TYPED_TEST_SUITE_P(Surface_properties);

// Every new vertex's weights sum to 1 (exactly in exact kernels), on the
// input and after one level (sqrt3's border rests, then refines); an edge's
// stencil does not depend on the halfedge it is computed from, and an
// interpolating scheme's vertex stencil is the vertex.
TYPED_TEST_P(Surface_properties, every_stencil_sums_to_one)
{
  using Mesh = typename TypeParam::Mesh;
  using Mask = typename TypeParam::Mask;
  using FT = typename TypeParam::FT;
  using Stencil = S::Stencil<typename Mesh::Vertex_index, FT>;
  for(const Mask& mask : TypeParam::Scheme::template masks<Mesh>())
    for(auto [name, mesh] : fixtures<Mesh>(TypeParam::triangles_only))
      for(int level = 0; level < 2; ++level) {
        SCOPED_TRACE(std::string(mask.name()) + " on " + name + ", level " + std::to_string(level));
        const S::Host_of<Mask> host(mesh);
        std::size_t count = 0;
        S::internal::for_each_new_vertex(host, mask, [&](std::size_t j, const auto& report) {
          Stencil stencil;
          report(stencil);
          EXPECT_TRUE(sums_to_one(stencil.weight_sum())) << "new vertex " << j;
          ++count;
        });
        EXPECT_EQ(count, host.number_of_new_vertices());
        if constexpr(Mask::split == S::Split::triangle_quadrisection || Mask::split == S::Split::quad) {
          for(auto e : edges(mesh)) {
            Stencil s, t;
            mask.edge_node(S::edge_view(mask, mesh, halfedge(e, mesh)), s);
            mask.edge_node(S::edge_view(mask, mesh, opposite(halfedge(e, mesh), mesh)), t);
            EXPECT_EQ(s.size(), t.size()) << "edge " << e;
            for(const auto& term : s.terms())
              EXPECT_TRUE(term.second == t.weight(term.first)) << "edge " << e;
          }
          if(mask.is_interpolating())
            for(auto v : vertices(mesh)) {
              Stencil s;
              mask.vertex_node(S::vertex_view(mask, mesh, v), s);
              EXPECT_EQ(s.size(), 1u) << "vertex " << v;
              EXPECT_TRUE(s.weight(v) == FT(1)) << "vertex " << v;
            }
        }
        S::subdivide(mesh, mask);
      }
}

// The counts of the split at every level, the Euler characteristic, validity.
TYPED_TEST_P(Surface_properties, counts_and_euler_characteristic)
{
  using Mesh = typename TypeParam::Mesh;
  using Mask = typename TypeParam::Mask;
  for(const Mask& mask : TypeParam::Scheme::template masks<Mesh>())
    for(auto [name, mesh] : fixtures<Mesh>(TypeParam::triangles_only))
      for(int level = 0; level < levels<Mask>(); ++level) {
        SCOPED_TRACE(std::string(mask.name()) + " on " + name + ", level " + std::to_string(level));
        const Mesh old = mesh;
        const std::size_t v = num_vertices(old), e = num_edges(old), f = num_faces(old), b = border_edge_count(old),
                          corners = corner_count(old);
        bool refines_border = false;
        if constexpr(Mask::split == S::Split::sqrt3)
          refines_border = S::Host_of<Mask>(old).refines_border();
        S::subdivide(mesh, mask);
        EXPECT_TRUE(mesh.is_valid(false));
        EXPECT_EQ(euler_characteristic(mesh), euler_characteristic(old));
        if constexpr(Mask::split == S::Split::triangle_quadrisection) {
          EXPECT_EQ(num_vertices(mesh), v + e);
          EXPECT_EQ(num_edges(mesh), 2 * e + 3 * f);
          EXPECT_EQ(num_faces(mesh), 4 * f);
        } else if constexpr(Mask::split == S::Split::sqrt3) {
          EXPECT_EQ(num_vertices(mesh), v + f + (refines_border ? b : 0));
          EXPECT_EQ(num_faces(mesh), 3 * f);
          EXPECT_EQ(border_edge_count(mesh), refines_border ? 3 * b : b);
        } else if constexpr(Mask::split == S::Split::quad) {
          EXPECT_EQ(num_vertices(mesh), v + e + f);
          EXPECT_EQ(num_faces(mesh), corners);
          for(auto g : faces(mesh))
            EXPECT_EQ(degree(g, mesh), 4u);
        } else { // dual: a face per old face, interior edge, and vertex with 3 or more faces
          EXPECT_EQ(num_vertices(mesh), corners);
          std::size_t interior_edges = 0, vertex_faces = 0;
          for(auto d : edges(old))
            interior_edges += CGAL::is_border(d, old) ? 0 : 1;
          for(auto u : vertices(old))
            vertex_faces += degree(u, old) >= (CGAL::is_border(u, old) ? 4u : 3u) ? 1 : 0;
          EXPECT_EQ(num_faces(mesh), f + interior_edges + vertex_faces);
        }
        if constexpr(Mask::split == S::Split::triangle_quadrisection || Mask::split == S::Split::sqrt3) {
          for(auto g : faces(mesh))
            EXPECT_EQ(degree(g, mesh), 3u);
        }
      }
}

// Subdividing an affine image of a mesh gives the affine image of the
// subdivided mesh (exactly in exact kernels: every rule is affine, rounded
// weights included, since they sum to exactly 1).
TYPED_TEST_P(Surface_properties, commutes_with_affine_maps)
{
  using Mesh = typename TypeParam::Mesh;
  using Mask = typename TypeParam::Mask;
  using FT = typename TypeParam::FT;
  const typename TypeParam::Kernel::Aff_transformation_3 map(FT(2), FT(1) / FT(3), FT(-1), FT(5),         //
                                                             FT(0), FT(3) / FT(2), FT(1) / FT(5), FT(-2), //
                                                             FT(1), FT(1), FT(1) / FT(7), FT(1) / FT(9));
  for(const Mask& mask : TypeParam::Scheme::template masks<Mesh>())
    for(const auto& [name, mesh] : fixtures<Mesh>(TypeParam::triangles_only)) {
      SCOPED_TRACE(std::string(mask.name()) + " on " + name);
      Mesh then_map = mesh, map_then = mesh;
      for(auto v : vertices(map_then))
        map_then.point(v) = map.transform(map_then.point(v));
      S::subdivide(then_map, mask, CGAL::parameters::number_of_iterations(levels<Mask>()));
      S::subdivide(map_then, mask, CGAL::parameters::number_of_iterations(levels<Mask>()));
      ASSERT_EQ(num_vertices(then_map), num_vertices(map_then));
      for(auto v : vertices(then_map))
        EXPECT_TRUE(same_point(map.transform(then_map.point(v)), map_then.point(v))) << "vertex " << v;
    }
}

// A mesh in the plane x + 2y + 3z = 7 (tilted, off the origin, with exact
// rational points) stays in it, checked with the plane's equation.
TYPED_TEST_P(Surface_properties, a_planar_mesh_stays_in_its_tilted_plane)
{
  using Mesh = typename TypeParam::Mesh;
  using Mask = typename TypeParam::Mask;
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Kernel::Point_3;
  const auto residual = [](const P& p) -> FT { return p.x() + FT(2) * p.y() + FT(3) * p.z() - FT(7); };
  for(const Mask& mask : TypeParam::Scheme::template masks<Mesh>())
    for(auto [name, mesh] : fixtures<Mesh>(TypeParam::triangles_only)) {
      SCOPED_TRACE(std::string(mask.name()) + " on " + name);
      for(auto v : vertices(mesh)) {
        const P p = mesh.point(v);
        mesh.point(v) = P(p.x(), p.y(), (FT(7) - p.x() - FT(2) * p.y()) / FT(3));
      }
      S::subdivide(mesh, mask, CGAL::parameters::number_of_iterations(levels<Mask>()));
      for(auto v : vertices(mesh)) {
        const P& p = mesh.point(v);
        if constexpr(TypeParam::exact) {
          EXPECT_TRUE(residual(p) == FT(0)) << "vertex " << v << ": " << p;
        } else {
          const double scale = 7 + std::abs(p.x()) + 2 * std::abs(p.y()) + 3 * std::abs(p.z());
          EXPECT_LE(std::abs(CGAL::to_double(residual(p))), 1e-13 * scale) << "vertex " << v << ": " << p;
        }
      }
    }
}

// Interpolating schemes keep every old point (old vertex i is new vertex i);
// the others move some on every closed fixture.
TYPED_TEST_P(Surface_properties, interpolating_schemes_and_only_they_keep_the_old_points)
{
  using Mesh = typename TypeParam::Mesh;
  using Mask = typename TypeParam::Mask;
  for(const Mask& mask : TypeParam::Scheme::template masks<Mesh>())
    for(const auto& [name, mesh] : fixtures<Mesh>(TypeParam::triangles_only)) {
      SCOPED_TRACE(std::string(mask.name()) + " on " + name);
      Mesh once = mesh;
      S::subdivide(once, mask);
      if(mask.is_interpolating()) {
        for(auto v : vertices(mesh))
          EXPECT_TRUE(same_point(once.point(v), mesh.point(v))) << "vertex " << v;
      } else if(border_edge_count(mesh) == 0) {
        const auto before = points_of(mesh);
        const auto after = points_of(once);
        std::size_t kept = 0;
        for(std::size_t i = 0; i < before.size() && i < after.size(); ++i)
          kept += before[i] == after[i] ? 1 : 0;
        EXPECT_LT(kept, before.size());
      }
    }
}

REGISTER_TYPED_TEST_SUITE_P(Surface_properties, every_stencil_sums_to_one, counts_and_euler_characteristic,
                            commutes_with_affine_maps, a_planar_mesh_stays_in_its_tilted_plane,
                            interpolating_schemes_and_only_they_keep_the_old_points);

// Polyhedron_3 gives the Surface_mesh results: the same counts and the same
// points (exactly in exact kernels; the order of the vertices may differ).
template <class C>
class Surface_mesh_types : public ::testing::Test
{};
TYPED_TEST_SUITE_P(Surface_mesh_types);

TYPED_TEST_P(Surface_mesh_types, polyhedron_3_gives_the_surface_mesh_results)
{
  using Mesh = typename TypeParam::Mesh;
  using Mask = typename TypeParam::Mask;
  using Polyhedron = CGAL::Polyhedron_3<typename TypeParam::Kernel>;
  using Polyhedron_mask = typename decltype(TypeParam::Scheme::template masks<Polyhedron>())::value_type;
  const auto polyhedron_masks = TypeParam::Scheme::template masks<Polyhedron>();
  const auto surface_mesh_masks = TypeParam::Scheme::template masks<Mesh>();
  for(std::size_t i = 0; i < surface_mesh_masks.size(); ++i) {
    const Mask& mask = surface_mesh_masks[i];
    const Polyhedron_mask& polyhedron_mask = polyhedron_masks[i];
    for(auto [name, mesh] : fixtures<Mesh>(TypeParam::triangles_only)) {
      SCOPED_TRACE(std::string(mask.name()) + " on " + name);
      Polyhedron poly;
      CGAL::copy_face_graph(mesh, poly);
      S::subdivide(mesh, mask, CGAL::parameters::number_of_iterations(levels<Mask>()));
      S::subdivide(poly, polyhedron_mask, CGAL::parameters::number_of_iterations(levels<Mask>()));
      EXPECT_TRUE(poly.is_valid());
      ASSERT_EQ(num_vertices(poly), num_vertices(mesh));
      EXPECT_EQ(num_faces(poly), num_faces(mesh));
      EXPECT_EQ(num_edges(poly), num_edges(mesh));
      if constexpr(TypeParam::exact) {
        auto a = points_of(mesh), b = points_of(poly);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        EXPECT_TRUE(a == b);
      } else {
        EXPECT_LT(T::position_mismatch(poly, mesh), 1e-14);
      }
    }
  }
}

REGISTER_TYPED_TEST_SUITE_P(Surface_mesh_types, polyhedron_3_gives_the_surface_mesh_results);

} // namespace surface_properties

#endif // CGAL_SUBDIV_TEST_SURFACE_PROPERTIES_H
