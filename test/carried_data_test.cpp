// Carried data (Carried_data): vertex maps interpolated smoothly (the
// scheme's rules) or linearly (the linear scheme of the same split), and the
// value types users carry: points (UVs as Point_2), vectors, CGAL's colours.
#include <CGAL/Exact_rational.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/centroid.h>

#include <boost/container_hash/hash.hpp>
#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include "mesh_builders.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace S = CGAL::Subdiv;
using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Exact_mesh = CGAL::Surface_mesh<KE::Point_3>;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

KE::Point_2 uv_of(const KE::Point_3& p)
{
  return KE::Point_2(p.x() + p.z() / 3, p.y() - 2 * p.z());
}

/// a scheme that splits edges on a mesh of its own, and the linear scheme of its split
struct Edge_split_case
{
  Exact_mesh base;
  /// 2 levels of the scheme, carrying `data` if it is not null
  std::function<void(Exact_mesh&, const S::Carried_data<Exact_mesh>*)> refine;
  /// 2 levels of the linear scheme of the split: the same numbering
  std::function<void(Exact_mesh&)> refine_linearly;
  /// 2 levels of the scheme with vertex sharpness tags, carrying `data`
  std::function<void(Exact_mesh&, Exact_mesh::Property_map<Exact_mesh::Vertex_index, double>,
                     const S::Carried_data<Exact_mesh>*)>
    refine_tagged;
};

/// Catmull-Clark on a box of quads and triangles, with the bilinear scheme
Edge_split_case catmull_clark_case()
{
  return {testing_utils::mixed_box<Exact_mesh>(),
          [](Exact_mesh& m, const S::Carried_data<Exact_mesh>* data) {
            if(data != nullptr)
              S::catmull_clark_subdivision(m, S::parameters::number_of_iterations(2).carried_data(*data));
            else
              S::catmull_clark_subdivision(m, S::parameters::number_of_iterations(2));
          },
          [](Exact_mesh& m) { S::linear_quad_subdivision(m, S::parameters::number_of_iterations(2)); },
          [](Exact_mesh& m, auto sharpness, const S::Carried_data<Exact_mesh>* data) {
            S::catmull_clark_subdivision(
              m, S::parameters::number_of_iterations(2).vertex_sharpness_map(sharpness).carried_data(*data));
          }};
}

/// Loop on an open fan of 5 triangles, with the linear triangle scheme
Edge_split_case loop_case()
{
  return {testing_utils::open_fan<Exact_mesh>(5),
          [](Exact_mesh& m, const S::Carried_data<Exact_mesh>* data) {
            if(data != nullptr)
              S::loop_subdivision(m, S::parameters::number_of_iterations(2).carried_data(*data));
            else
              S::loop_subdivision(m, S::parameters::number_of_iterations(2));
          },
          [](Exact_mesh& m) { S::linear_triangle_subdivision(m, S::parameters::number_of_iterations(2)); },
          [](Exact_mesh& m, auto sharpness, const S::Carried_data<Exact_mesh>* data) {
            S::loop_subdivision(
              m, S::parameters::number_of_iterations(2).vertex_sharpness_map(sharpness).carried_data(*data));
          }};
}

/*
 * The case's mesh refined with three carried maps of its points: the point
 * itself smooth and linear, and a UV (a Point_2, an affine function of the
 * point) linear. `smooth_twin` and `linear_twin` are the same mesh refined by
 * the scheme and by the linear scheme of its split: the smooth map must equal
 * the scheme's points, the linear maps the linear scheme's, exactly.
 */
void expect_smooth_and_linear_maps(const Edge_split_case& scheme)
{
  Exact_mesh mesh = scheme.base;
  Exact_mesh smooth_twin = mesh;
  Exact_mesh linear_twin = mesh;
  auto smooth = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Point_3>("v:smooth").first;
  auto linear = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Point_3>("v:linear").first;
  auto uv = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Point_2>("v:uv").first;
  for(auto v : vertices(mesh)) {
    smooth[v] = linear[v] = mesh.point(v);
    uv[v] = uv_of(mesh.point(v));
  }
  S::Carried_data<Exact_mesh> data;
  data.vertex_map(smooth).vertex_map(linear, S::Interpolation::linear).vertex_map(uv, S::Interpolation::linear);
  scheme.refine(mesh, &data);
  scheme.refine(smooth_twin, nullptr);
  scheme.refine_linearly(linear_twin);

  ASSERT_EQ(num_vertices(mesh), num_vertices(linear_twin));
  std::size_t moved = 0; // vertices where the smooth and the linear values differ
  for(auto v : vertices(mesh)) {
    EXPECT_EQ(mesh.point(v), smooth_twin.point(v)) << v;
    EXPECT_EQ(smooth[v], mesh.point(v)) << v;
    EXPECT_EQ(linear[v], linear_twin.point(v)) << v;
    EXPECT_EQ(uv[v], uv_of(linear_twin.point(v))) << v;
    moved += smooth[v] != linear[v] ? 1 : 0;
  }
  EXPECT_GT(moved, num_vertices(mesh) / 2); // the two interpolations are not the same
}

} // namespace

TEST(CarriedData, catmull_clark_carries_linear_maps_with_the_bilinear_weights_exactly)
{
  expect_smooth_and_linear_maps(catmull_clark_case());
}

TEST(CarriedData, loop_carries_linear_maps_with_the_linear_triangle_weights_exactly)
{
  expect_smooth_and_linear_maps(loop_case());
}

/*
 * Colours: each channel combined in double with the mask's weights, then
 * rounded and clamped, at every level (one level here: the next would start
 * from the rounded colours). The butterfly's negative weights overshoot, so the
 * same channel carried as a double map goes beyond [0, 255] somewhere: the
 * colour must be that double, rounded and clamped, at every vertex.
 */
TEST(CarriedData, colours_are_combined_in_double_then_rounded_and_clamped)
{
  Mesh mesh = testing_utils::bipyramid<Mesh>(6);
  auto colour = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:colour").first;
  std::array<Mesh::Property_map<Mesh::Vertex_index, double>, 4> channel;
  for(int c = 0; c < 4; ++c)
    channel[c] = mesh.add_property_map<Mesh::Vertex_index, double>("v:channel" + std::to_string(c)).first;
  for(auto v : vertices(mesh)) {
    const int i = static_cast<int>(v.idx());
    // red: the top apex (vertex 0) and vertices 6 and 7 full, the rest empty;
    // green: the other way round; blue: odd values (ties at 1/2)
    const bool full = i >= 6 || i == 0;
    const std::array<unsigned char, 4> value = {static_cast<unsigned char>(full ? 255 : 0),
                                                static_cast<unsigned char>(full ? 0 : 255),
                                                static_cast<unsigned char>(2 * i + 1), 128};
    colour[v] = CGAL::IO::Color(value[0], value[1], value[2], value[3]);
    for(int c = 0; c < 4; ++c)
      channel[c][v] = value[c];
  }
  S::Carried_data<Mesh> data;
  data.vertex_map(colour);
  for(const auto& map : channel)
    data.vertex_map(map);
  S::butterfly_subdivision(mesh, S::parameters::carried_data(data));

  bool above = false, below = false, halfway = false;
  for(auto v : vertices(mesh)) {
    const std::array<unsigned char, 4> got = {colour[v].red(), colour[v].green(), colour[v].blue(), colour[v].alpha()};
    for(int c = 0; c < 4; ++c) {
      const double exact = channel[c][v];
      above = above || exact > 255.5;
      below = below || exact < -0.5;
      halfway = halfway || exact - std::floor(exact) == 0.5;
      EXPECT_EQ(int(got[c]), int(std::clamp(std::round(exact), 0.0, 255.0))) << v << " channel " << c;
    }
    EXPECT_EQ(int(got[3]), 128) << v; // the weights sum to 1
  }
  EXPECT_TRUE(above && below && halfway) << "the test does not reach clamping or a rounding tie";
}

namespace {

/// the combination of points with exact weights
template <class Point>
Point mix(const std::vector<std::pair<Point, CGAL::Exact_rational>>& terms)
{
  auto sum = terms.front().first - terms.front().first;
  for(const auto& [p, w] : terms)
    sum = sum + w * (p - CGAL::ORIGIN);
  return CGAL::ORIGIN + sum;
}

/// the corners of base face `f` of `base` (corner i: the target of the i-th halfedge from halfedge(f))
template <class Base>
std::vector<KE::Point_3> corners_of(const Base& base, std::size_t f)
{
  std::vector<KE::Point_3> result;
  const auto face = *std::next(faces(base).begin(), static_cast<std::ptrdiff_t>(f));
  for(auto h : CGAL::halfedges_around_face(halfedge(face, base), base))
    result.push_back(get(CGAL::vertex_point, base, target(h, base)));
  return result;
}

/// the value at parameter uv in the domain of `origin` (see Face_origin) of
/// the linear interpolation of `c`, the values at the corners of the base face
template <class Point>
Point linear_in_domain(std::vector<Point> c, const S::Face_origin& origin, const std::array<double, 2>& uv)
{
  const CGAL::Exact_rational u(uv[0]), v(uv[1]), one(1);
  const std::size_t n = c.size();
  if(origin.sub_quad >= 0) { // the sub-quad at corner k: k, the midpoints beside it, the centroid
    const std::size_t k = static_cast<std::size_t>(origin.sub_quad);
    std::vector<std::pair<Point, CGAL::Exact_rational>> centroid;
    for(const auto& p : c)
      centroid.push_back({p, one / int(n)});
    c = {c[k], CGAL::midpoint(c[k], c[(k + 1) % n]), mix(centroid), CGAL::midpoint(c[(k + n - 1) % n], c[k])};
  }
  if(c.size() == 3)
    return mix<Point>({{c[0], one - u - v}, {c[1], u}, {c[2], v}});
  return mix<Point>({{c[0], (one - u) * (one - v)}, {c[1], u * (one - v)}, {c[2], u * v}, {c[3], (one - u) * v}});
}

/*
 * Provenance after 2 levels of `refine` (a scheme that splits edges): the
 * same mesh refined by the linear scheme of the split (`refine_linearly`,
 * the same numbering) has every corner of every face at the point of its
 * parameter on the base face, exactly; every vertex's base origin is a base
 * vertex at its point, a base edge through it, or a base face.
 */
void expect_provenance(const Edge_split_case& scheme)
{
  const Exact_mesh& base = scheme.base;
  Exact_mesh mesh = base;
  Exact_mesh linear_twin = base;
  auto face_origin = mesh.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  auto base_origin = mesh.add_property_map<Exact_mesh::Vertex_index, S::Vertex_origin>("v:origin").first;
  S::Carried_data<Exact_mesh> data;
  data.face_origin_map(face_origin).base_origin_map(base_origin);
  scheme.refine(mesh, &data);
  scheme.refine_linearly(linear_twin);
  ASSERT_EQ(num_faces(mesh), num_faces(linear_twin));

  std::vector<std::size_t> children(num_faces(base), 0);
  for(auto f : faces(mesh)) {
    const S::Face_origin& origin = face_origin[f];
    ASSERT_LT(origin.face, num_faces(base));
    ++children[origin.face];
    ASSERT_EQ(origin.corners, static_cast<int>(degree(f, mesh)));
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      EXPECT_EQ(linear_twin.point(target(h, mesh)),
                linear_in_domain(corners_of(base, origin.face), origin, origin.uv[i++]))
        << f << " corner " << i;
    EXPECT_GT(origin.box().xmax(), origin.box().xmin());
  }
  for(auto f : faces(base)) { // 2 levels: 16 children, in 4 sub-quads for the other sizes under the quad split
    const std::size_t n = degree(f, base);
    EXPECT_EQ(children[f.idx()], n == 3 && num_faces(mesh) == 16 * num_faces(base) ? 16 : 4 * n) << f;
  }

  std::map<S::Origin_kind, std::size_t> kinds;
  for(auto v : vertices(mesh)) {
    const S::Vertex_origin o = base_origin[v];
    ++kinds[o.kind];
    const KE::Point_3& p = linear_twin.point(v);
    if(o.kind == S::Origin_kind::vertex) {
      EXPECT_EQ(p, base.point(Exact_mesh::Vertex_index(static_cast<Exact_mesh::size_type>(o.index)))) << v;
    } else if(o.kind == S::Origin_kind::edge) {
      const auto e = Exact_mesh::Edge_index(static_cast<Exact_mesh::size_type>(o.index));
      const KE::Segment_3 segment(base.point(source(e, base)), base.point(target(e, base)));
      EXPECT_TRUE(segment.has_on(p) && p != segment.source() && p != segment.target()) << v;
    }
  }
  // each base edge has 3 new vertices inside it after 2 levels
  EXPECT_EQ(kinds[S::Origin_kind::vertex], num_vertices(base));
  EXPECT_EQ(kinds[S::Origin_kind::edge], 3 * num_edges(base));
  EXPECT_EQ(kinds[S::Origin_kind::face], num_vertices(mesh) - num_vertices(base) - 3 * num_edges(base));
}

} // namespace

TEST(CarriedData, catmull_clark_face_and_vertex_provenance_are_exact)
{
  expect_provenance(catmull_clark_case());
}

TEST(CarriedData, loop_face_and_vertex_provenance_are_exact)
{
  expect_provenance(loop_case());
}

// a writable non_manifold_copies map is kept through the levels: the child of
// a vertex copies its parent's point, every other new vertex is a point of
// its own, above all the others (face_varying_limit reads it on any level)
TEST(CarriedData, non_manifold_copies_are_kept_through_the_levels)
{
  Mesh mesh = testing_utils::cube<Mesh>();
  const auto point_of = mesh.add_property_map<Mesh::Vertex_index, std::size_t>("v:point", 0).first;
  for(const auto v : mesh.vertices())
    point_of[v] = v.idx() / 2; // vertices 2k and 2k + 1 copy point k
  S::Carried_data<Mesh, double> data;
  data.non_manifold_copies(point_of);
  std::vector<S::Vertex_origin> origins;
  data.origins(origins);
  std::vector<std::size_t> old_points;
  for(int level = 1; level <= 2; ++level) {
    old_points.clear();
    for(const auto v : mesh.vertices())
      old_points.push_back(point_of[v]);
    const std::size_t first_new = *std::max_element(old_points.begin(), old_points.end()) + 1;
    S::catmull_clark_subdivision(mesh, S::parameters::carried_data(data));
    ASSERT_EQ(origins.size(), mesh.number_of_vertices());
    std::set<std::size_t> fresh;
    std::size_t j = 0;
    for(const auto v : mesh.vertices()) {
      const S::Vertex_origin& origin = origins[j++];
      if(origin.kind == S::Origin_kind::vertex)
        EXPECT_EQ(point_of[v], old_points[origin.index]);
      else {
        EXPECT_GE(point_of[v], first_new);
        EXPECT_TRUE(fresh.insert(point_of[v]).second) << "point " << point_of[v] << " given twice";
      }
    }
    EXPECT_EQ(fresh.size(), mesh.number_of_vertices() - old_points.size());
  }
}

namespace {

/*
 * UVs with a seam at every edge (every face has its own values at its
 * corners), carried with Face_varying_interpolation::all through 2 levels of
 * `refine`: every new corner holds the linear interpolation, inside its base
 * face, of that face's corner values, at the corner's parameter
 * (face_origin_map), exactly. A second corner map without seams (the value of
 * the corner's vertex) equals, at every corner, the vertex map carried with
 * Interpolation::linear.
 */
void expect_linear_corner_values(const Edge_split_case& scheme)
{
  Exact_mesh mesh = scheme.base;
  using H = Exact_mesh::Halfedge_index;
  auto uv = mesh.add_property_map<H, KE::Point_2>("h:uv").first;
  auto smooth_uv = mesh.add_property_map<H, KE::Point_2>("h:seamless").first;
  auto vertex_uv = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Point_2>("v:uv").first;
  auto origin = mesh.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  std::vector<std::vector<KE::Point_2>> base_values; // by base face, corner
  for(auto f : faces(mesh)) {
    base_values.emplace_back();
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      uv[h] = KE::Point_2(CGAL::Exact_rational(int(f.idx()) * 7 + i) / 3, i * i - int(f.idx()));
      base_values.back().push_back(uv[h]);
      ++i;
    }
  }
  for(auto v : vertices(mesh))
    vertex_uv[v] = uv_of(mesh.point(v));
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh))
      smooth_uv[h] = vertex_uv[target(h, mesh)];
  S::Carried_data<Exact_mesh> data;
  data.corner_map(uv, S::Face_varying_interpolation::all)
    .corner_map(smooth_uv, S::Face_varying_interpolation::all)
    .vertex_map(vertex_uv, S::Interpolation::linear)
    .face_origin_map(origin);
  scheme.refine(mesh, &data);

  std::size_t seams = 0; // corners whose value differs from another corner at the same vertex
  for(auto f : faces(mesh)) {
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      EXPECT_EQ(uv[h], linear_in_domain(base_values[origin[f].face], origin[f], origin[f].uv[i++])) << h;
      EXPECT_EQ(smooth_uv[h], vertex_uv[target(h, mesh)]) << h;
      const H other = opposite(next(h, mesh), mesh); // the corner of the next face around target(h)
      seams += !is_border(other, mesh) && uv[other] != uv[h] ? 1 : 0;
    }
  }
  EXPECT_GT(seams, 0u);
}

} // namespace

TEST(CarriedData, catmull_clark_carries_corner_maps_linearly_with_their_seams)
{
  expect_linear_corner_values(catmull_clark_case());
}

TEST(CarriedData, loop_carries_corner_maps_linearly_with_their_seams)
{
  expect_linear_corner_values(loop_case());
}

/*
 * Doo-Sabin and sqrt3 make faces across the old edges: the provenance maps
 * are refused, naming what was asked, with the mesh and the map unchanged;
 * the same map carried smoothly is accepted.
 */
TEST(CarriedData, schemes_across_edges_refuse_the_provenance_maps_and_change_nothing)
{
  const std::vector<std::string> requests = {"face_origin_map", "base_origin_map"};
  for(const std::string scheme : {"doo-sabin", "sqrt3"})
    for(const std::string& request : requests) {
      Mesh mesh = testing_utils::bipyramid<Mesh>(5);
      const Mesh before = mesh;
      auto value = mesh.add_property_map<Mesh::Vertex_index, double>("v:value").first;
      for(auto v : vertices(mesh))
        value[v] = static_cast<double>(v.idx());
      auto face_origin = mesh.add_property_map<Mesh::Face_index, S::Face_origin>("f:origin").first;
      auto base_origin = mesh.add_property_map<Mesh::Vertex_index, S::Vertex_origin>("v:origin").first;
      S::Carried_data<Mesh> data;
      if(request == requests[0])
        data.face_origin_map(face_origin);
      else
        data.base_origin_map(base_origin);
      const auto refine = [&](const S::Carried_data<Mesh>& carried) {
        const auto np = S::parameters::number_of_iterations(2).carried_data(carried);
        if(scheme == "doo-sabin")
          S::doo_sabin_subdivision(mesh, np);
        else
          S::sqrt3_subdivision(mesh, np);
      };
      try {
        refine(data);
        ADD_FAILURE() << scheme << " accepted " << request;
      } catch(const S::Bad_input& e) {
        EXPECT_NE(std::string(e.what()).find(request), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("across the old edges"), std::string::npos) << e.what();
      }
      ASSERT_EQ(num_vertices(mesh), num_vertices(before)) << scheme;
      for(auto v : vertices(mesh)) {
        EXPECT_EQ(mesh.point(v), before.point(v)) << scheme;
        EXPECT_EQ(value[v], static_cast<double>(v.idx())) << scheme;
      }
      S::Carried_data<Mesh> smooth;
      smooth.vertex_map(value);
      refine(smooth);
      EXPECT_GT(num_vertices(mesh), num_vertices(before)) << scheme;
    }
}

namespace {

/// a scheme that makes new faces across the old edges, and meshes of its own
struct Across_edges_case
{
  /// the scheme's name, as its messages give it
  std::string name;
  /// `levels` levels carrying `data` (isolated vertices kept)
  std::function<void(Exact_mesh&, int, const S::Carried_data<Exact_mesh>&)> refine;
  /// a closed mesh and an open one
  std::vector<Exact_mesh> meshes;
};

std::vector<Across_edges_case> across_edges_cases()
{
  const auto np = [](int levels, const S::Carried_data<Exact_mesh>& data) {
    return S::parameters::number_of_iterations(levels).isolated_vertices(S::Isolated_vertices::keep).carried_data(data);
  };
  const std::vector<Exact_mesh> triangle_meshes = {testing_utils::bipyramid<Exact_mesh>(5),
                                                   testing_utils::open_fan<Exact_mesh>(5)};
  return {
    {"Doo-Sabin",
     [np](Exact_mesh& m, int levels, const auto& data) { S::doo_sabin_subdivision(m, np(levels, data)); },
     {testing_utils::mixed_box<Exact_mesh>(), testing_utils::open_fan<Exact_mesh>(5)}},
    {"sqrt3 (Kobbelt)",
     [np](Exact_mesh& m, int levels, const auto& data) { S::sqrt3_subdivision(m, np(levels, data)); }, triangle_meshes},
    {"interpolating sqrt3 (Labsik-Greiner)",
     [np](Exact_mesh& m, int levels, const auto& data) { S::interpolating_sqrt3_subdivision(m, np(levels, data)); },
     triangle_meshes}};
}

/*
 * A corner map without seams (every corner holds the value of its vertex),
 * carried by `scheme` in the smooth `mode` through 2 levels, alone and with
 * an index map: every corner holds the value that the same values carried as
 * a vertex map with Interpolation::smooth give its vertex, exactly (the
 * value of the vertex's point, the values being a linear function of the
 * points); the index map numbers the values one to a vertex, from 0.
 */
void expect_seam_free_corners_as_smooth_vertex_maps(const Across_edges_case& scheme, const Exact_mesh& base,
                                                    S::Face_varying_interpolation mode)
{
  using H = Exact_mesh::Halfedge_index;
  using V = Exact_mesh::Vertex_index;
  Exact_mesh mesh = base;
  auto uv = mesh.add_property_map<H, KE::Point_2>("h:uv").first;
  auto indexed_uv = mesh.add_property_map<H, KE::Point_2>("h:indexed_uv").first;
  auto index = mesh.add_property_map<H, std::size_t>("h:index").first;
  auto vertex_uv = mesh.add_property_map<V, KE::Point_2>("v:uv").first;
  for(auto v : vertices(mesh))
    vertex_uv[v] = uv_of(mesh.point(v));
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh)) {
      uv[h] = indexed_uv[h] = vertex_uv[target(h, mesh)];
      index[h] = target(h, mesh).idx();
    }
  S::Carried_data<Exact_mesh> data;
  data.corner_map(uv, mode).corner_map(indexed_uv, mode, index).vertex_map(vertex_uv);
  scheme.refine(mesh, 2, data);

  std::map<std::size_t, V> vertex_of_index;
  for(auto h : halfedges(mesh)) {
    if(is_border(h, mesh))
      continue;
    const V v = target(h, mesh);
    EXPECT_EQ(uv[h], vertex_uv[v]) << h;
    EXPECT_EQ(indexed_uv[h], vertex_uv[v]) << h;
    EXPECT_EQ(vertex_of_index.emplace(index[h], v).first->second, v) << h; // one vertex an index
    EXPECT_EQ(vertex_uv[v], uv_of(mesh.point(v))) << h;                    // the points' weights (uv_of is linear)
  }
  EXPECT_EQ(vertex_of_index.size(), num_vertices(mesh)); // one index a vertex
  EXPECT_EQ(vertex_of_index.rbegin()->first + 1, num_vertices(mesh));
}

} // namespace

TEST(CarriedData, schemes_across_edges_carry_seam_free_corner_maps_as_smooth_vertex_maps_exactly)
{
  for(const Across_edges_case& scheme : across_edges_cases())
    for(const Exact_mesh& mesh : scheme.meshes)
      for(const auto mode : {S::Face_varying_interpolation::none, S::Face_varying_interpolation::corners_plus1}) {
        SCOPED_TRACE(scheme.name + " mode " + std::to_string(int(mode)));
        expect_seam_free_corners_as_smooth_vertex_maps(scheme, mesh, mode);
      }
}

namespace {

/*
 * `base` with a corner map without seams, `uv` of its vertex (by index) at
 * every corner, refined one level by `refine` in Face_varying_interpolation::
 * all: every corner of a new vertex that came from `origin` holds
 * `expected(origin)`, exactly, and so does the vertex map of the same values
 * carried with Interpolation::linear.
 */
void expect_linear_corners(const Exact_mesh& base, const std::vector<KE::Point_2>& uv_of_vertex,
                           const std::function<void(Exact_mesh&, const S::Carried_data<Exact_mesh>&)>& refine,
                           const std::function<KE::Point_2(const S::Vertex_origin&)>& expected)
{
  using H = Exact_mesh::Halfedge_index;
  Exact_mesh mesh = base;
  auto uv = mesh.add_property_map<H, KE::Point_2>("h:uv").first;
  auto vertex_uv = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Point_2>("v:uv").first;
  for(auto v : vertices(mesh))
    vertex_uv[v] = uv_of_vertex[v.idx()];
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh))
      uv[h] = uv_of_vertex[target(h, mesh).idx()];
  std::vector<S::Vertex_origin> origins;
  S::Carried_data<Exact_mesh> data;
  data.corner_map(uv, S::Face_varying_interpolation::all)
    .vertex_map(vertex_uv, S::Interpolation::linear)
    .origins(origins);
  refine(mesh, data);
  ASSERT_EQ(origins.size(), num_vertices(mesh));
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh)) {
      const auto v = target(h, mesh);
      EXPECT_EQ(uv[h], expected(origins[v.idx()])) << h;
      EXPECT_EQ(vertex_uv[v], uv[h]) << h;
    }
}

} // namespace

// Doo-Sabin, linear: corner i of face f gets the centre of its quad in the
// linear quad split of f (on the quad, Doo-Sabin's 9/16, 3/16, 3/16, 1/16)
TEST(CarriedData, doo_sabin_carries_corner_maps_linearly_by_the_quad_centres)
{
  using P = KE::Point_3;
  using Q = CGAL::Exact_rational;
  const Exact_mesh base = testing_utils::mesh_of<Exact_mesh>(
    {P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0), P(2, 0, 0)}, {{0, 1, 2, 3}, {1, 4, 2}});
  const std::vector<KE::Point_2> uv = {{0, 0}, {4, 0}, {4, 4}, {0, 8}, {12, 0}};
  // by (face, vertex) of the corner
  const std::map<std::pair<std::size_t, std::size_t>, KE::Point_2> centre = {
    {{0, 0}, {1, Q(7, 4)}},        {{0, 1}, {3, Q(5, 4)}},        {{0, 2}, {3, Q(15, 4)}},      {{0, 3}, {1, Q(21, 4)}},
    {{1, 1}, {Q(17, 3), Q(5, 6)}}, {{1, 4}, {Q(26, 3), Q(5, 6)}}, {{1, 2}, {Q(17, 3), Q(7, 3)}}};
  std::vector<std::pair<std::size_t, std::size_t>> corners; // by corner ordinal: Dual_split's numbering
  for(auto f : faces(base))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, base), base))
      corners.emplace_back(f.idx(), target(h, base).idx());
  expect_linear_corners(
    base, uv, [](Exact_mesh& m, const auto& data) { S::doo_sabin_subdivision(m, S::parameters::carried_data(data)); },
    [&](const S::Vertex_origin& origin) { return centre.at(corners.at(origin.index)); });
}

// Doo-Sabin, linear, with creases: the corners that the tags make one new
// vertex get one value, on the crease or at the corner as the point is (the
// values being a linear function of the points: uv_of)
TEST(CarriedData, doo_sabin_gives_the_corners_welded_by_creases_one_linear_value)
{
  using H = Exact_mesh::Halfedge_index;
  Exact_mesh mesh = testing_utils::mixed_box<Exact_mesh>();
  auto uv = mesh.add_property_map<H, KE::Point_2>("h:uv").first;
  auto edge_sharpness = mesh.add_property_map<Exact_mesh::Edge_index, double>("e:sharpness", 0.).first;
  auto vertex_sharpness = mesh.add_property_map<Exact_mesh::Vertex_index, double>("v:sharpness", 0.).first;
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh))
      uv[h] = uv_of(mesh.point(target(h, mesh)));
  // a crease 5 - 4 - 6 (no face has both edges: vertex 4 has the crease rule,
  // 5 and 6 are darts) and a corner at vertex 3
  std::vector<std::pair<KE::Point_3, KE::Point_3>> creases;
  const auto vertex = [](int i) { return Exact_mesh::Vertex_index(i); };
  for(const int end : {5, 6}) {
    edge_sharpness[edge(halfedge(vertex(4), vertex(end), mesh).first, mesh)] = 10;
    creases.emplace_back(mesh.point(vertex(4)), mesh.point(vertex(end)));
  }
  const Exact_mesh::Vertex_index corner = vertex(3);
  vertex_sharpness[corner] = 10;
  const KE::Point_3 corner_point = mesh.point(corner);
  S::Carried_data<Exact_mesh> data;
  data.corner_map(uv, S::Face_varying_interpolation::all);
  S::doo_sabin_subdivision(
    mesh, S::parameters::edge_sharpness_map(edge_sharpness).vertex_sharpness_map(vertex_sharpness).carried_data(data));

  const auto on_a_crease = [&](const KE::Point_3& p) {
    return std::any_of(creases.begin(), creases.end(), [&](const auto& c) {
      return CGAL::collinear(c.first, c.second, p) && CGAL::collinear_are_ordered_along_line(c.first, p, c.second);
    });
  };
  std::set<Exact_mesh::Vertex_index> welded; // the new vertices on the creases and at the corner
  for(auto h : halfedges(mesh)) {
    const KE::Point_3& p = mesh.point(target(h, mesh));
    if(is_border(h, mesh) || !(p == corner_point || on_a_crease(p)))
      continue;
    EXPECT_EQ(uv[h], uv_of(p)) << h;
    welded.insert(target(h, mesh));
  }
  EXPECT_EQ(welded.size(), 3u); // Chaikin's point next to vertex 4 on each crease edge, and the corner
}

// the sqrt3 schemes, linear: an old vertex keeps its value, a face point
// gets the mean of the face's corners
TEST(CarriedData, sqrt3_schemes_carry_corner_maps_linearly_by_the_face_means)
{
  const Exact_mesh base = testing_utils::tetrahedron<Exact_mesh>(); // faces {0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}
  const std::vector<KE::Point_2> uv = {{0, 0}, {3, 0}, {0, 3}, {6, 6}};
  const std::vector<KE::Point_2> mean_of_face = {{1, 1}, {2, 3}, {3, 2}, {3, 3}};
  const auto expected = [&](const S::Vertex_origin& origin) {
    return origin.kind == S::Origin_kind::vertex ? uv.at(origin.index) : mean_of_face.at(origin.index);
  };
  expect_linear_corners(
    base, uv, [](Exact_mesh& m, const auto& data) { S::sqrt3_subdivision(m, S::parameters::carried_data(data)); },
    expected);
  expect_linear_corners(
    base, uv,
    [](Exact_mesh& m, const auto& data) { S::interpolating_sqrt3_subdivision(m, S::parameters::carried_data(data)); },
    expected);
}

// the sqrt3 schemes, linear, on a lone triangle after a step that left its
// border alone, so that the next one trisects it: the two new vertices of a
// border edge get the values at its thirds, each the third nearer its point
// (the values being (3x, 6y) of the points), an old vertex keeps its value
TEST(CarriedData, sqrt3_schemes_carry_corner_maps_linearly_to_the_thirds_of_the_border)
{
  using P = KE::Point_3;
  using Point_2 = KE::Point_2;
  Exact_mesh base = testing_utils::mesh_of<Exact_mesh>({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)}, {{0, 1, 2}});
  S::sqrt3_subdivision(base); // the resting step: its three corners and its face point (vertex 3)
  ASSERT_EQ(num_vertices(base), 4u);
  const std::vector<Point_2> uv = {{0, 0}, {3, 0}, {0, 6}, {1, 2}};
  std::vector<std::set<Point_2>> thirds; // by edge ordinal, the values at its two thirds (border edges)
  for(auto e : edges(base)) {
    const Point_2 a = uv[source(halfedge(e, base), base).idx()], b = uv[target(halfedge(e, base), base).idx()];
    thirds.push_back(is_border(e, base) ? std::set<Point_2>{CGAL::barycenter(a, 2, b, 1), CGAL::barycenter(a, 1, b, 2)}
                                        : std::set<Point_2>());
  }
  for(const bool interpolating : {false, true}) {
    SCOPED_TRACE(interpolating ? "interpolating sqrt3" : "sqrt3");
    Exact_mesh mesh = base;
    auto corner_uv = mesh.add_property_map<Exact_mesh::Halfedge_index, Point_2>("h:uv").first;
    for(auto h : halfedges(mesh))
      if(!is_border(h, mesh))
        corner_uv[h] = uv[target(h, mesh).idx()];
    std::vector<S::Vertex_origin> origins;
    S::Carried_data<Exact_mesh> data;
    data.corner_map(corner_uv, S::Face_varying_interpolation::all).origins(origins);
    const auto np = S::parameters::carried_data(data);
    if(interpolating)
      S::interpolating_sqrt3_subdivision(mesh, np);
    else
      S::sqrt3_subdivision(mesh, np);
    // 4 old vertices, 2 on each border edge (every face has one: it gets no face point)
    ASSERT_EQ(num_vertices(mesh), 10u);
    std::vector<std::set<Point_2>> met(thirds.size()); // by edge ordinal, the values of its new vertices
    for(auto h : halfedges(mesh)) {
      if(is_border(h, mesh))
        continue;
      const S::Vertex_origin& origin = origins[target(h, mesh).idx()];
      if(origin.kind == S::Origin_kind::edge) {
        const P& p = mesh.point(target(h, mesh));
        const auto distance = [&](const Point_2& third) {
          return CGAL::squared_distance(Point_2(third.x() / 3, third.y() / 6), Point_2(p.x(), p.y()));
        };
        const auto nearer = [&](const Point_2& a, const Point_2& b) { return distance(a) < distance(b); };
        const std::set<Point_2>& edge_thirds = thirds[origin.index];
        EXPECT_EQ(corner_uv[h], *std::min_element(edge_thirds.begin(), edge_thirds.end(), nearer)) << h;
        met[origin.index].insert(corner_uv[h]);
      } else {
        ASSERT_EQ(origin.kind, S::Origin_kind::vertex) << h;
        EXPECT_EQ(corner_uv[h], uv[origin.index]) << h;
      }
    }
    EXPECT_EQ(met, thirds); // both thirds of every border edge
  }
}

/*
 * A corner map with a seam (one corner at vertex 3 of its own value, or of
 * its own index) is refused by the schemes that make faces across the old
 * edges, naming the scheme and the vertex, before anything is done: the
 * mesh (with an isolated vertex that `Isolated_vertices::keep` would set
 * aside) and the maps are unchanged.
 */
TEST(CarriedData, schemes_across_edges_refuse_a_corner_map_with_a_seam_and_change_nothing)
{
  using H = Exact_mesh::Halfedge_index;
  for(const Across_edges_case& scheme : across_edges_cases())
    for(const bool indexed : {false, true}) {
      SCOPED_TRACE(scheme.name + (indexed ? ", indexed" : ""));
      Exact_mesh mesh = testing_utils::bipyramid<Exact_mesh>(5);
      mesh.add_vertex(KE::Point_3(9, 9, 9));
      auto uv = mesh.add_property_map<H, KE::Point_2>("h:uv").first;
      auto index = mesh.add_property_map<H, int>("h:index").first;
      for(auto h : halfedges(mesh))
        if(!is_border(h, mesh)) {
          uv[h] = uv_of(mesh.point(target(h, mesh)));
          index[h] = int(target(h, mesh).idx());
        }
      const H seam = halfedge(Exact_mesh::Vertex_index(3), mesh); // a corner of vertex 3 (closed mesh)
      uv[seam] = KE::Point_2(100, 100);
      index[seam] = 1000;
      const Exact_mesh before = mesh;
      S::Carried_data<Exact_mesh> data;
      if(indexed)
        data.corner_map(uv, S::Face_varying_interpolation::corners_plus1, index);
      else
        data.corner_map(uv, S::Face_varying_interpolation::all);
      try {
        scheme.refine(mesh, 2, data);
        ADD_FAILURE() << "accepted a seam";
      } catch(const S::Bad_input& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(scheme.name + " carries corner maps without seams only"), std::string::npos) << message;
        EXPECT_NE(message.find("vertex 3 has different values in faces"), std::string::npos) << message;
        EXPECT_NE(message.find("Loop, Catmull-Clark, linear and the butterflies carry seams"), std::string::npos)
          << message;
      }
      ASSERT_EQ(num_vertices(mesh), num_vertices(before));
      ASSERT_EQ(num_faces(mesh), num_faces(before));
      const auto uv_before = before.property_map<H, KE::Point_2>("h:uv").first;
      const auto index_before = before.property_map<H, int>("h:index").first;
      for(auto v : vertices(mesh))
        EXPECT_EQ(mesh.point(v), before.point(v)) << v;
      for(auto h : halfedges(mesh))
        if(!is_border(h, mesh)) {
          EXPECT_EQ(uv[h], uv_before[h]) << h;
          EXPECT_EQ(index[h], index_before[h]) << h;
        }
    }
}

namespace {

/// the mesh of `mesh`'s corner values: one vertex per vertex and value, at
/// (u, v, 0), its faces in the order of `mesh`'s, each from the same corner
Exact_mesh value_mesh(const Exact_mesh& mesh, Exact_mesh::Property_map<Exact_mesh::Halfedge_index, KE::Point_2> uv)
{
  Exact_mesh values;
  std::map<std::pair<Exact_mesh::Vertex_index, KE::Point_2>, Exact_mesh::Vertex_index> vertex_of;
  for(auto f : faces(mesh)) {
    std::vector<Exact_mesh::Vertex_index> corners;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const auto key = std::make_pair(target(h, mesh), uv[h]);
      if(vertex_of.count(key) == 0)
        vertex_of[key] = values.add_vertex(KE::Point_3(uv[h].x(), uv[h].y(), 0));
      corners.push_back(vertex_of[key]);
    }
    EXPECT_NE(values.add_face(corners), Exact_mesh::null_face());
  }
  return values;
}

/// the corners of a refined mesh by base face and parameter (face_origin_map)
using Corner_key = std::tuple<std::size_t, int, double, double>;

template <class Value, class CornerValue>
std::map<Corner_key, Value> corners_by_origin(const Exact_mesh& mesh,
                                              Exact_mesh::Property_map<Exact_mesh::Face_index, S::Face_origin> origin,
                                              const CornerValue& value_at)
{
  std::map<Corner_key, Value> result;
  for(auto f : faces(mesh)) {
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const S::Face_origin& o = origin[f];
      result[Corner_key(o.face, o.sub_quad, o.uv[i][0], o.uv[i][1])] = value_at(h);
      ++i;
    }
  }
  return result;
}

/*
 * A seam is a border of the face-varying topology: UVs with seams (two charts
 * of faces, the UV of a corner an affine function of its point, shifted in
 * the second chart), carried through 2 levels in `mode`, equal exactly the
 * points of the mesh of the values (one vertex per vertex and value, cut at
 * the seams) refined by the scheme, with `kept(vertex of that mesh)` (those
 * that the mode keeps) made infinitely sharp. Corners are matched by their
 * base face and parameter.
 */
template <class Kept>
void expect_seams_refined_as_borders(const Edge_split_case& scheme, S::Face_varying_interpolation mode,
                                     const Kept& kept)
{
  Exact_mesh mesh = scheme.base;
  auto uv = mesh.add_property_map<Exact_mesh::Halfedge_index, KE::Point_2>("h:uv").first;
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      uv[h] = uv_of(mesh.point(target(h, mesh))) + KE::Vector_2(f.idx() < 2 ? 5 : 0, 0);
  Exact_mesh values = value_mesh(mesh, uv);
  ASSERT_GT(num_vertices(values), num_vertices(mesh)); // there are seams
  auto sharpness = values.add_property_map<Exact_mesh::Vertex_index, double>("v:sharpness", 0).first;
  std::size_t kept_count = 0;
  for(auto v : vertices(values))
    if(kept(values, v)) {
      sharpness[v] = 10;
      ++kept_count;
    }

  auto origin = mesh.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  S::Carried_data<Exact_mesh> data;
  data.corner_map(uv, mode).face_origin_map(origin);
  scheme.refine(mesh, &data);
  auto value_origin = values.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  S::Carried_data<Exact_mesh> value_data;
  value_data.face_origin_map(value_origin);
  scheme.refine_tagged(values, sharpness, &value_data);

  const auto carried = corners_by_origin<KE::Point_2>(mesh, origin, [&](auto h) { return uv[h]; });
  const auto expected = corners_by_origin<KE::Point_2>(values, value_origin, [&](auto h) {
    const KE::Point_3& p = values.point(target(h, values));
    return KE::Point_2(p.x(), p.y());
  });
  ASSERT_EQ(carried.size(), expected.size());
  for(const auto& [key, value] : carried)
    EXPECT_EQ(value, expected.at(key)) << "base face " << std::get<0>(key) << " at (" << std::get<2>(key) << ", "
                                       << std::get<3>(key) << ")";
  if(mode != S::Face_varying_interpolation::none) {
    EXPECT_GT(kept_count, 0u);
  }
}

bool is_border_vertex(const Exact_mesh& m, Exact_mesh::Vertex_index v)
{
  return bool(CGAL::is_border(v, m));
}

bool is_corner_vertex(const Exact_mesh& m, Exact_mesh::Vertex_index v)
{
  return is_border_vertex(m, v) && m.degree(v) == 2;
}

void expect_seams_refined_as_borders_in_three_modes(const Edge_split_case& scheme)
{
  {
    SCOPED_TRACE("none");
    expect_seams_refined_as_borders(scheme, S::Face_varying_interpolation::none,
                                    [](const auto&, auto) { return false; });
  }
  {
    SCOPED_TRACE("corners_only");
    expect_seams_refined_as_borders(scheme, S::Face_varying_interpolation::corners_only, is_corner_vertex);
  }
  {
    SCOPED_TRACE("boundaries");
    expect_seams_refined_as_borders(scheme, S::Face_varying_interpolation::boundaries, is_border_vertex);
  }
}

} // namespace

TEST(CarriedData, catmull_clark_refines_seams_as_borders_exactly)
{
  expect_seams_refined_as_borders_in_three_modes(catmull_clark_case());
}

TEST(CarriedData, loop_refines_seams_as_borders_exactly)
{
  expect_seams_refined_as_borders_in_three_modes(loop_case());
}

namespace {

/*
 * `corner_maps(mode, indices, uv, tangent)`: two maps of one face-varying
 * channel (one topology and one set of rows per level) end exactly as each
 * carried alone with the same index map, index for index.
 */
void expect_one_channel_as_maps_alone(const Edge_split_case& scheme)
{
  using H = Exact_mesh::Halfedge_index;
  Exact_mesh mesh = scheme.base;
  auto uv = mesh.add_property_map<H, KE::Point_2>("h:uv").first;
  auto tangent = mesh.add_property_map<H, KE::Vector_2>("h:tangent").first;
  auto index = mesh.add_property_map<H, std::size_t>("h:index").first;
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const bool second_chart = f.idx() < 2; // a seam around faces 0 and 1
      const KE::Point_3& p = mesh.point(target(h, mesh));
      uv[h] = uv_of(p) + KE::Vector_2(second_chart ? 5 : 0, 0);
      tangent[h] = KE::Vector_2(2 * p.z() - p.x(), second_chart ? p.y() : -p.y());
      index[h] = 2 * target(h, mesh).idx() + (second_chart ? 1 : 0);
    }
  const S::Face_varying_interpolation mode = S::Face_varying_interpolation::corners_plus1;
  Exact_mesh alone_uv = mesh, alone_tangent = mesh;
  S::Carried_data<Exact_mesh> both;
  both.corner_maps(mode, index, uv, tangent);
  scheme.refine(mesh, &both);

  S::Carried_data<Exact_mesh> uv_data, tangent_data;
  auto uv_alone = alone_uv.property_map<H, KE::Point_2>("h:uv").first;
  auto index_alone = alone_uv.property_map<H, std::size_t>("h:index").first;
  uv_data.corner_map(uv_alone, mode, index_alone);
  scheme.refine(alone_uv, &uv_data);
  auto tangent_alone = alone_tangent.property_map<H, KE::Vector_2>("h:tangent").first;
  tangent_data.corner_map(tangent_alone, mode, alone_tangent.property_map<H, std::size_t>("h:index").first);
  scheme.refine(alone_tangent, &tangent_data);

  ASSERT_EQ(num_halfedges(mesh), num_halfedges(alone_uv));
  std::size_t seam_corners = 0; // corners whose value differs from the next corner's around their vertex
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      EXPECT_EQ(uv[h], uv_alone[h]) << h;
      EXPECT_EQ(index[h], index_alone[h]) << h;
      EXPECT_EQ(tangent[h], tangent_alone[h]) << h;
      const H across = opposite(next(h, mesh), mesh);
      if(!is_border(across, mesh) && index[across] != index[h])
        ++seam_corners;
    }
  EXPECT_GT(seam_corners, 0u); // the seam was carried
}

} // namespace

TEST(CarriedData, catmull_clark_carries_the_maps_of_one_channel_as_each_alone)
{
  expect_one_channel_as_maps_alone(catmull_clark_case());
}

TEST(CarriedData, loop_carries_the_maps_of_one_channel_as_each_alone)
{
  expect_one_channel_as_maps_alone(loop_case());
}

namespace {

using Exact_polyhedron = CGAL::Polyhedron_3<KE>;

/// a map of any descriptor kept beside the mesh: property maps of a Polyhedron_3
template <class Key, class Value>
struct Beside_map
{
  std::shared_ptr<std::unordered_map<Key, Value, boost::hash<Key>>> values =
    std::make_shared<std::unordered_map<Key, Value, boost::hash<Key>>>();
  auto map() const
  {
    return boost::associative_property_map<std::unordered_map<Key, Value, boost::hash<Key>>>(*values);
  }
};

/// the points of the base element named by `o` (ordinals are the base mesh's own), sorted
template <class Base>
std::vector<KE::Point_3> points_of_base_element(const Base& base, const S::Vertex_origin& o)
{
  std::vector<KE::Point_3> result;
  const auto point = [&](auto v) { return get(CGAL::vertex_point, base, v); };
  const auto at = [](const auto& range, std::size_t i) { return *std::next(range.begin(), std::ptrdiff_t(i)); };
  if(o.kind == S::Origin_kind::vertex)
    result.push_back(point(at(vertices(base), o.index)));
  else if(o.kind == S::Origin_kind::edge) {
    const auto e = at(edges(base), o.index);
    result = {point(source(e, base)), point(target(e, base))};
  } else
    result = corners_of(base, o.index);
  std::sort(result.begin(), result.end());
  return result;
}

/// what the maps of a refined mesh say at a corner (a face and a vertex) found by their points
struct Corner_record
{
  KE::Point_2 vertex_uv, corner_uv;
  S::Origin_kind base_kind;
  std::vector<KE::Point_3> base_element; // the points of the base element the vertex lies on
  std::size_t base_face;
  KE::Point_3 at_parameter; // the point of the corner's parameter on the base face (bilinear)
};

/// the records of every corner of `mesh`, keyed by the centroid of its face and the point of its vertex
template <class Mesh_, class Vpm, class Get>
std::map<std::pair<KE::Point_3, KE::Point_3>, Corner_record> corner_records(const Mesh_& mesh, const Vpm& vpm,
                                                                            const Get& record_of)
{
  std::map<std::pair<KE::Point_3, KE::Point_3>, Corner_record> result;
  for(auto f : faces(mesh)) {
    std::vector<KE::Point_3> points;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      points.push_back(get(vpm, target(h, mesh)));
    const KE::Point_3 centroid = CGAL::centroid(points.begin(), points.end());
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      result.emplace(std::make_pair(centroid, get(vpm, target(h, mesh))), record_of(f, h, i++));
  }
  return result;
}

/*
 * Any FaceGraph: a Polyhedron_3 (the generic writer, maps beside the mesh)
 * carries a linear vertex map, a corner map with seams and the provenance
 * maps through 2 levels of Catmull-Clark exactly as a Surface_mesh does,
 * corner by corner (matched by points: the two number their elements apart).
 */
TEST(CarriedData, a_polyhedron_carries_corner_maps_and_provenance_as_a_surface_mesh)
{
  Exact_mesh mesh = testing_utils::mixed_box<Exact_mesh>();
  Exact_polyhedron polyhedron;
  CGAL::copy_face_graph(mesh, polyhedron);
  ASSERT_EQ(num_faces(polyhedron), num_faces(mesh));
  // (their faces may start at other corners: parameters are compared by the points they give)
  const Exact_mesh mesh_base = mesh;
  const Exact_polyhedron polyhedron_base = polyhedron;

  using SM_H = Exact_mesh::Halfedge_index;
  auto sm_vertex_uv = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Point_2>("v:uv").first;
  auto sm_corner_uv = mesh.add_property_map<SM_H, KE::Point_2>("h:uv").first;
  auto sm_base = mesh.add_property_map<Exact_mesh::Vertex_index, S::Vertex_origin>("v:origin").first;
  auto sm_face = mesh.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  using P_V = boost::graph_traits<Exact_polyhedron>::vertex_descriptor;
  using P_H = boost::graph_traits<Exact_polyhedron>::halfedge_descriptor;
  using P_F = boost::graph_traits<Exact_polyhedron>::face_descriptor;
  Beside_map<P_V, KE::Point_2> p_vertex_uv;
  Beside_map<P_H, KE::Point_2> p_corner_uv;
  Beside_map<P_V, S::Vertex_origin> p_base;
  Beside_map<P_F, S::Face_origin> p_face;
  // the same values on both: the vertex's UV, and at a corner a value of its
  // face's centroid and its vertex (a seam at every edge)
  const auto corner_value = [](const auto& g, auto h) {
    std::vector<KE::Point_3> points;
    for(auto c : CGAL::halfedges_around_face(h, g))
      points.push_back(get(CGAL::vertex_point, g, target(c, g)));
    const KE::Point_3 centre = CGAL::centroid(points.begin(), points.end());
    const KE::Point_3& corner = get(CGAL::vertex_point, g, target(h, g));
    return KE::Point_2(centre.x() + 2 * corner.y(), centre.z() - corner.x() / 3);
  };
  for(auto v : vertices(mesh))
    sm_vertex_uv[v] = uv_of(mesh.point(v));
  for(auto v : vertices(polyhedron))
    put(p_vertex_uv.map(), v, uv_of(v->point()));
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh))
      sm_corner_uv[h] = corner_value(mesh, h);
  for(auto h : halfedges(polyhedron))
    if(!is_border(h, polyhedron))
      put(p_corner_uv.map(), h, corner_value(polyhedron, h));

  S::Carried_data<Exact_mesh> sm_data;
  sm_data.vertex_map(sm_vertex_uv, S::Interpolation::linear)
    .corner_map(sm_corner_uv, S::Face_varying_interpolation::all)
    .base_origin_map(sm_base)
    .face_origin_map(sm_face);
  S::catmull_clark_subdivision(mesh, S::parameters::number_of_iterations(2).carried_data(sm_data));
  S::Carried_data<Exact_polyhedron> p_data;
  p_data.vertex_map(p_vertex_uv.map(), S::Interpolation::linear)
    .corner_map(p_corner_uv.map(), S::Face_varying_interpolation::all)
    .base_origin_map(p_base.map())
    .face_origin_map(p_face.map());
  S::catmull_clark_subdivision(polyhedron, S::parameters::number_of_iterations(2).carried_data(p_data));

  const auto sm_records = corner_records(mesh, mesh.points(), [&](auto f, auto h, int i) {
    const S::Face_origin& o = sm_face[f];
    const S::Vertex_origin b = sm_base[target(h, mesh)];
    return Corner_record{sm_vertex_uv[target(h, mesh)],
                         sm_corner_uv[h],
                         b.kind,
                         points_of_base_element(mesh_base, b),
                         o.face,
                         linear_in_domain(corners_of(mesh_base, o.face), o, o.uv[i])};
  });
  const auto p_records = corner_records(polyhedron, get(CGAL::vertex_point, polyhedron), [&](auto f, auto h, int i) {
    const auto v = target(h, polyhedron);
    const S::Face_origin o = get(p_face.map(), f);
    const S::Vertex_origin b = get(p_base.map(), v);
    return Corner_record{get(p_vertex_uv.map(), v),
                         get(p_corner_uv.map(), h),
                         b.kind,
                         points_of_base_element(polyhedron_base, b),
                         o.face,
                         linear_in_domain(corners_of(polyhedron_base, o.face), o, o.uv[i])};
  });
  ASSERT_EQ(sm_records.size(), p_records.size());
  ASSERT_EQ(sm_records.size(), 4 * num_faces(mesh));
  for(const auto& [key, expected] : sm_records) {
    const auto found = p_records.find(key);
    ASSERT_TRUE(found != p_records.end()) << key.second;
    const Corner_record& got = found->second;
    EXPECT_EQ(got.vertex_uv, expected.vertex_uv) << key.second;
    EXPECT_EQ(got.corner_uv, expected.corner_uv) << key.second;
    EXPECT_EQ(got.base_kind, expected.base_kind) << key.second;
    EXPECT_EQ(got.base_element, expected.base_element) << key.second;
    EXPECT_EQ(got.base_face, expected.base_face) << key.second;
    EXPECT_EQ(got.at_parameter, expected.at_parameter) << key.second;
  }
}

} // namespace

namespace {

/// the corners at the vertex at `p` of `mesh`, in the order of the faces, with their value and index
template <class UvMap, class IndexMap>
std::vector<std::pair<KE::Point_2, std::size_t>> corners_at(const Exact_mesh& mesh, const KE::Point_3& p,
                                                            const UvMap& uv, const IndexMap& index)
{
  std::vector<std::pair<KE::Point_2, std::size_t>> result;
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      if(mesh.point(target(h, mesh)) == p)
        result.emplace_back(uv[h], index[h]);
  return result;
}

} // namespace

// Around the middle vertex of a 2x2 grid of quads, each quad its own UV
// island, the corners hold A B A B (A in faces 0 and 2, B in 1 and 3, by
// index). As on OpenSubdiv's base level (doc/provenance.md, "Face-varying
// data"), A is one value over two sectors, kept where it is with one index;
// B, met again after A, is two values, each refined as a crease of its face
// (3/4 of it and 1/8 of each neighbour in the face). Exact, 2 levels of
// Catmull-Clark in `none`: the second level keeps what the first made.
TEST(CarriedData, values_around_a_vertex_are_told_apart_as_on_opensubdivs_base_level)
{
  Exact_mesh mesh;
  std::vector<Exact_mesh::Vertex_index> v;
  for(int y = 0; y < 3; ++y)
    for(int x = 0; x < 3; ++x)
      v.push_back(mesh.add_vertex(KE::Point_3(x, y, 0)));
  const int quads[4][4] = {{0, 1, 4, 3}, {1, 2, 5, 4}, {4, 5, 8, 7}, {3, 4, 7, 6}};
  for(const auto& q : quads)
    mesh.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  auto uv = mesh.add_property_map<Exact_mesh::Halfedge_index, KE::Point_2>("h:uv").first;
  auto index = mesh.add_property_map<Exact_mesh::Halfedge_index, std::size_t>("h:uv_index").first;
  const KE::Point_2 a(100, 0), b(200, 0);
  std::size_t next_index = 2; // 0: A, 1: B
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const KE::Point_3& p = mesh.point(target(h, mesh));
      if(target(h, mesh) == v[4]) {
        uv[h] = f.idx() % 2 == 0 ? a : b;
        index[h] = f.idx() % 2;
      } else {
        uv[h] = KE::Point_2(p.x() + 10 * int(f.idx()), p.y());
        index[h] = next_index++;
      }
    }
  // B's crease in face 1: 3/4 B and 1/8 of (2, 1) + 10 and (1, 0) + 10; in face 3, of (1, 2) + 30 and (0, 1) + 30
  const KE::Point_2 b_in_face_1(KE::FT(150) + KE::FT(23, 8), KE::FT(1, 8)),
    b_in_face_3(KE::FT(150) + KE::FT(61, 8), KE::FT(3, 8));
  S::Carried_data<Exact_mesh> data;
  data.corner_map(uv, S::Face_varying_interpolation::none, index);
  for(int level = 1; level <= 2; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    S::catmull_clark_subdivision(mesh, S::parameters::carried_data(data));
    // the middle vertex stays where it is (a symmetric grid)
    const auto corners = corners_at(mesh, KE::Point_3(1, 1, 0), uv, index);
    ASSERT_EQ(corners.size(), 4u);
    std::map<std::size_t, std::vector<KE::Point_2>> by_index;
    for(const auto& [value, i] : corners)
      by_index[i].push_back(value);
    ASSERT_EQ(by_index.size(), 3u); // A once, B twice
    std::vector<KE::Point_2> singles;
    for(const auto& [i, values] : by_index)
      if(values.size() == 2) {
        EXPECT_EQ(values[0], a);
        EXPECT_EQ(values[1], a);
      } else {
        singles.push_back(values.front());
      }
    ASSERT_EQ(singles.size(), 2u);
    std::sort(singles.begin(), singles.end());
    if(level == 1) {
      EXPECT_EQ(singles[0], b_in_face_1);
      EXPECT_EQ(singles[1], b_in_face_3);
    }
  }
}

namespace {

/*
 * `base` with a UV channel: a seam around faces 0 and 1 (their corners have
 * values of their own), the values numbered densely in "h:index" and held in
 * "h:uv", a semi-sharp edge (sharpness 1.5) inside the first chart in
 * "e:sharpness" if `tagged` (0 everywhere else).
 */
template <class Mesh_>
Mesh_ seamed_channel(const Mesh_& base, bool tagged)
{
  using H = typename Mesh_::Halfedge_index;
  using Point_2 = typename CGAL::Kernel_traits<typename Mesh_::Point>::Kernel::Point_2;
  Mesh_ mesh = base;
  auto uv = mesh.template add_property_map<H, Point_2>("h:uv").first;
  auto index = mesh.template add_property_map<H, int>("h:index").first;
  auto sharpness = mesh.template add_property_map<typename Mesh_::Edge_index, double>("e:sharpness", 0.).first;
  std::map<std::pair<std::size_t, bool>, int> value_of; // (vertex, second chart)
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const bool second_chart = f.idx() < 2;
      const auto& p = mesh.point(target(h, mesh));
      const auto inserted = value_of.emplace(std::make_pair(target(h, mesh).idx(), second_chart), int(value_of.size()));
      index[h] = inserted.first->second;
      uv[h] = Point_2(p.x() / 4 + (second_chart ? 5 : 0), p.y() - p.z() / 8);
    }
  // the edge, off the seam, between the first two faces of the first chart
  for(auto e : edges(mesh))
    if(tagged && !is_border(e, mesh) && face(halfedge(e, mesh), mesh).idx() >= 2 &&
       face(opposite(halfedge(e, mesh), mesh), mesh).idx() >= 2) {
      sharpness[e] = 1.5;
      break;
    }
  return mesh;
}

/*
 * The table of `levels` levels of the seamed channel of `base`, applied to
 * its base values, gives every corner of the refined mesh (the same mesh as
 * `subdivide()` makes, corner for corner) the value that `subdivide()`
 * carries with the same index map, exactly (==), through the index that
 * `subdivide()` writes; one source per base value, one stencil per refined
 * value.
 */
template <class Mesh_, class Mask>
void expect_table_gives_carried_values(const Mesh_& base, const Mask& mask, S::Face_varying_interpolation mode,
                                       int levels, bool tagged)
{
  using H = typename Mesh_::Halfedge_index;
  using E = typename Mesh_::Edge_index;
  using Point_2 = typename CGAL::Kernel_traits<typename Mesh_::Point>::Kernel::Point_2;
  using FT = typename Mask::Number_type;
  const Mesh_ coarse = seamed_channel(base, tagged);
  const auto params = [&](const Mesh_& m) {
    return S::parameters::number_of_iterations(levels).edge_sharpness_map(
      m.template property_map<E, double>("e:sharpness").first);
  };
  Mesh_ carried = coarse;
  auto uv = carried.template property_map<H, Point_2>("h:uv").first;
  auto index = carried.template property_map<H, int>("h:index").first;
  S::Carried_data<Mesh_, FT> data;
  data.corner_map(uv, mode, index);
  S::subdivide(carried, mask, params(carried).carried_data(data));

  const auto coarse_index = coarse.template property_map<H, int>("h:index").first;
  const auto coarse_uv = coarse.template property_map<H, Point_2>("h:uv").first;
  std::vector<Point_2> values(coarse.number_of_vertices() + 16);
  std::set<int> base_values;
  for(auto h : halfedges(coarse))
    if(!is_border(h, coarse)) {
      values[std::size_t(coarse_index[h])] = coarse_uv[h];
      base_values.insert(coarse_index[h]);
    }
  values.resize(base_values.size());
  Mesh_ refined;
  std::vector<std::size_t> refined_index;
  const auto table = S::make_face_varying_stencil_table(
    coarse, mask, coarse_index, mode, params(coarse).refined_mesh(refined).refined_corner_indices(refined_index));
  EXPECT_EQ(table.number_of_sources(), base_values.size());
  std::vector<Point_2> refined_values;
  table.apply(values, refined_values);

  ASSERT_EQ(num_halfedges(refined), num_halfedges(carried));
  ASSERT_EQ(refined_index.size(), num_halfedges(carried));
  for(auto v : vertices(carried))
    EXPECT_EQ(refined.point(v), carried.point(v)) << v;
  std::set<std::size_t> refined_values_used;
  std::size_t seam_corners = 0; // corners whose index differs from the next corner's around their vertex
  for(auto h : halfedges(carried)) {
    if(is_border(h, carried))
      continue;
    ASSERT_EQ(refined_index[h.idx()], std::size_t(index[h])) << h;
    EXPECT_EQ(refined_values[refined_index[h.idx()]], uv[h]) << h;
    refined_values_used.insert(refined_index[h.idx()]);
    const H across = opposite(next(h, carried), carried);
    seam_corners += !is_border(across, carried) && index[across] != index[h] ? 1 : 0;
  }
  EXPECT_EQ(table.number_of_stencils(), refined_values_used.size());
  EXPECT_GT(seam_corners, 0u);
}

const S::Face_varying_interpolation face_varying_modes[] = {S::Face_varying_interpolation::none,
                                                            S::Face_varying_interpolation::corners_plus1,
                                                            S::Face_varying_interpolation::all};

} // namespace

TEST(FaceVaryingStencilTable, catmull_clark_table_gives_the_carried_values_exactly)
{
  for(const S::Face_varying_interpolation mode : face_varying_modes) {
    SCOPED_TRACE(int(mode));
    expect_table_gives_carried_values(testing_utils::mixed_box<Exact_mesh>(), S::Catmull_clark_mask<Exact_mesh>(), mode,
                                      2, false);
    expect_table_gives_carried_values(testing_utils::mixed_box<Exact_mesh>(), S::Catmull_clark_mask<Exact_mesh>(), mode,
                                      2, true);
  }
}

TEST(FaceVaryingStencilTable, loop_table_gives_the_carried_values_exactly)
{
  for(const S::Face_varying_interpolation mode : face_varying_modes) {
    SCOPED_TRACE(int(mode));
    expect_table_gives_carried_values(testing_utils::open_fan<Exact_mesh>(5), S::Loop_mask<Exact_mesh>(), mode, 2,
                                      false);
    expect_table_gives_carried_values(testing_utils::open_fan<Exact_mesh>(5), S::Loop_mask<Exact_mesh>(), mode, 2,
                                      true);
  }
}

// in double, a level's values are those of subdivide() bit for bit (the same
// weights, summed in the same order)
TEST(FaceVaryingStencilTable, a_semi_sharp_level_in_double_gives_the_carried_values_bit_for_bit)
{
  for(const S::Face_varying_interpolation mode : face_varying_modes) {
    SCOPED_TRACE(int(mode));
    expect_table_gives_carried_values(testing_utils::mixed_box<Mesh>(), S::Catmull_clark_mask<Mesh>(), mode, 1, true);
    expect_table_gives_carried_values(testing_utils::bipyramid<Mesh>(5), S::Loop_mask<Mesh>(), mode, 1, true);
  }
}

TEST(FaceVaryingStencilTable, refuses_bad_corner_indices_and_schemes_without_corner_maps)
{
  using H = Exact_mesh::Halfedge_index;
  Exact_mesh mesh = seamed_channel(testing_utils::mixed_box<Exact_mesh>(), false);
  auto index = mesh.property_map<H, int>("h:index").first;
  const auto message_of = [&](const auto& mask) {
    try {
      S::make_face_varying_stencil_table(mesh, mask, index, S::Face_varying_interpolation::corners_plus1);
    } catch(const S::Bad_input& e) {
      return std::string(e.what());
    }
    return std::string("no Bad_input");
  };
  const H corner = halfedge(*faces(mesh).begin(), mesh);
  index[corner] = -1;
  EXPECT_NE(message_of(S::Catmull_clark_mask<Exact_mesh>()).find("has the value index -1"), std::string::npos)
    << message_of(S::Catmull_clark_mask<Exact_mesh>());
  auto wide = mesh.add_property_map<H, long long>("h:wide", 0).first;
  for(auto h : halfedges(mesh))
    wide[h] = index[h] < 0 ? 0 : index[h];
  wide[corner] = (1ll << 32) + 3;
  EXPECT_THROW(
    {
      try {
        S::make_face_varying_stencil_table(mesh, S::Catmull_clark_mask<Exact_mesh>(), wide,
                                           S::Face_varying_interpolation::none);
      } catch(const S::Bad_input& e) {
        EXPECT_NE(std::string(e.what()).find("less than 2^32 - 1"), std::string::npos) << e.what();
        throw;
      }
    },
    S::Bad_input);
  index[corner] = 0;
  EXPECT_NE(message_of(S::Doo_sabin_mask<Exact_mesh>()).find("carries corner maps without seams only"),
            std::string::npos)
    << message_of(S::Doo_sabin_mask<Exact_mesh>());
}
