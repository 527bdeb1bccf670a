// Sharp features (semi-sharp creases and corners) with OpenSubdiv's
// semantics: OpenSubdiv's regression shapes refined by this package and by
// OpenSubdiv Far from the same tags, in the same test; refining level by
// level equals refining at once; exact values in a rational kernel.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_soup.h"
#include "mesh_test_utils.h"

#if defined(SUBDIV_TEST_WITH_OSD)
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

#include <string>
#include <vector>

namespace {

namespace Sd = CGAL::Subdiv;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Edge_sharpness = Mesh::Property_map<Mesh::Edge_index, double>;
using Vertex_sharpness = Mesh::Property_map<Mesh::Vertex_index, double>;

enum class Scheme { catmark, loop };

/// an OpenSubdiv shape: its mesh, as the file numbers the vertices, and its tags
struct Tagged_shape
{
  cgal_subdiv::Mesh_soup soup;
  std::vector<int> crease_pairs; // vertex pairs
  std::vector<float> crease_sharpness;
  std::vector<int> corners;
  std::vector<float> corner_sharpness;
  Sd::Border_corners border = Sd::Border_corners::smooth; // OpenSubdiv's shapes: "edges only" unless tagged
  Sd::Crease_method method = Sd::Crease_method::uniform;
};

// OpenSubdiv's `t crease` and `t corner` tags: one sharpness for every pair
// (vertex), or one each
void read_tag_values(const cgal_subdiv::Obj_tag& tag, int per_item, std::vector<int>& items,
                     std::vector<float>& sharpness)
{
  const std::size_t count = tag.ints.size() / per_item;
  for(long long i : tag.ints)
    items.push_back(static_cast<int>(i));
  for(std::size_t k = 0; k < count; ++k)
    sharpness.push_back(static_cast<float>(tag.floats.size() == 1 ? tag.floats[0] : tag.floats[k]));
}

Tagged_shape read_shape(const std::string& name)
{
  Tagged_shape shape;
  shape.soup =
    cgal_subdiv::read_mesh_soup(testing_utils::test_mesh("opensubdiv/" + name + ".obj"), cgal_subdiv::Mesh_format::obj);
  for(const cgal_subdiv::Obj_tag& tag : shape.soup.tags) {
    if(tag.name == "crease")
      read_tag_values(tag, 2, shape.crease_pairs, shape.crease_sharpness);
    else if(tag.name == "corner")
      read_tag_values(tag, 1, shape.corners, shape.corner_sharpness);
    else if(tag.name == "interpolateboundary" && !tag.ints.empty()) // RenderMan: 1 edge and corner, 2 edge only
      shape.border = tag.ints[0] == 1 ? Sd::Border_corners::sharp : Sd::Border_corners::smooth;
    else if(tag.name == "creasemethod" && !tag.strings.empty())
      shape.method = tag.strings[0] == "chaikin" ? Sd::Crease_method::chaikin : Sd::Crease_method::uniform;
  }
  return shape;
}

/// the mesh of the shape, vertex i being the file's vertex i, with its tags
/// in the maps "e:sharpness" and "v:sharpness"
Mesh tagged_mesh(const Tagged_shape& shape)
{
  Mesh mesh;
  for(const auto& p : shape.soup.points)
    mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for(std::size_t f = 0; f < shape.soup.number_of_faces(); ++f) {
    std::vector<Mesh::Vertex_index> face;
    for(std::size_t k = shape.soup.face_starts[f]; k < shape.soup.face_starts[f + 1]; ++k)
      face.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(shape.soup.indices[k])));
    EXPECT_NE(mesh.add_face(face), Mesh::null_face()) << "face " << f;
  }
  Edge_sharpness edges = mesh.add_property_map<Mesh::Edge_index, double>("e:sharpness", 0).first;
  Vertex_sharpness vertices = mesh.add_property_map<Mesh::Vertex_index, double>("v:sharpness", 0).first;
  for(std::size_t k = 0; k < shape.crease_sharpness.size(); ++k) {
    const auto h =
      halfedge(Mesh::Vertex_index(shape.crease_pairs[2 * k]), Mesh::Vertex_index(shape.crease_pairs[2 * k + 1]), mesh);
    EXPECT_TRUE(h.second) << "crease " << k << " is not an edge";
    put(edges, edge(h.first, mesh), shape.crease_sharpness[k]);
  }
  for(std::size_t k = 0; k < shape.corner_sharpness.size(); ++k)
    put(vertices, Mesh::Vertex_index(shape.corners[k]), shape.corner_sharpness[k]);
  return mesh;
}

/// refines the tagged mesh one level with the scheme and the shape's options
void refine_once(Mesh& mesh, Scheme scheme, const Tagged_shape& shape)
{
  const Edge_sharpness edges = mesh.property_map<Mesh::Edge_index, double>("e:sharpness").first;
  const Vertex_sharpness vertices = mesh.property_map<Mesh::Vertex_index, double>("v:sharpness").first;
  const auto np = Sd::parameters::edge_sharpness_map(edges).vertex_sharpness_map(vertices).crease_method(shape.method);
  if(scheme == Scheme::catmark)
    Sd::subdivide(mesh, Sd::Catmull_clark_mask<Mesh>(shape.border), np);
  else
    Sd::subdivide(mesh, Sd::Loop_mask<Mesh>(shape.border), np);
}

#if defined(SUBDIV_TEST_WITH_OSD)
namespace Osd = OpenSubdiv::Far;

struct Osd_vertex
{
  double p[3];
  void Clear() { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Osd_vertex& v, double w)
  {
    for(int i = 0; i < 3; ++i)
      p[i] += w * v.p[i];
  }
};

/// the points of every level up to `levels` of OpenSubdiv Far, from the same tags
std::vector<std::vector<testing_utils::Double_point>> opensubdiv_levels(const Tagged_shape& shape, Scheme scheme,
                                                                        int levels)
{
  std::vector<int> sizes, indices;
  for(std::size_t f = 0; f < shape.soup.number_of_faces(); ++f)
    sizes.push_back(static_cast<int>(shape.soup.face_starts[f + 1] - shape.soup.face_starts[f]));
  for(std::size_t i : shape.soup.indices)
    indices.push_back(static_cast<int>(i));
  Osd::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(shape.soup.points.size());
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numCreases = static_cast<int>(shape.crease_sharpness.size());
  desc.creaseVertexIndexPairs = shape.crease_pairs.data();
  desc.creaseWeights = shape.crease_sharpness.data();
  desc.numCorners = static_cast<int>(shape.corner_sharpness.size());
  desc.cornerVertexIndices = shape.corners.data();
  desc.cornerWeights = shape.corner_sharpness.data();
  OpenSubdiv::Sdc::Options options;
  options.SetVtxBoundaryInterpolation(shape.border == Sd::Border_corners::sharp
                                        ? OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                                        : OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  options.SetCreasingMethod(shape.method == Sd::Crease_method::chaikin ? OpenSubdiv::Sdc::Options::CREASE_CHAIKIN
                                                                       : OpenSubdiv::Sdc::Options::CREASE_UNIFORM);
  using Factory = Osd::TopologyRefinerFactory<Osd::TopologyDescriptor>;
  const auto type = scheme == Scheme::catmark ? OpenSubdiv::Sdc::SCHEME_CATMARK : OpenSubdiv::Sdc::SCHEME_LOOP;
  std::unique_ptr<Osd::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(type, options)));
  EXPECT_TRUE(refiner != nullptr);
  if(refiner == nullptr)
    return {};
  refiner->RefineUniform(Osd::TopologyRefiner::UniformOptions(levels));
  std::vector<std::vector<Osd_vertex>> points(levels + 1);
  for(const auto& p : shape.soup.points)
    points[0].push_back(Osd_vertex{{p[0], p[1], p[2]}});
  Osd::PrimvarRefinerReal<double> primvar(*refiner);
  std::vector<std::vector<testing_utils::Double_point>> result(levels + 1);
  for(int level = 0; level <= levels; ++level) {
    if(level > 0) {
      points[level].resize(refiner->GetLevel(level).GetNumVertices());
      const Osd_vertex* source = points[level - 1].data();
      Osd_vertex* destination = points[level].data();
      primvar.Interpolate(level, source, destination);
    }
    for(const Osd_vertex& v : points[level])
      result[level].emplace_back(v.p[0], v.p[1], v.p[2]);
  }
  return result;
}

struct Conformance_case
{
  std::string shape;
  Scheme scheme;
};

std::ostream& operator<<(std::ostream& out, const Conformance_case& c)
{
  return out << c.shape;
}

class OpenSubdivShapes : public testing::TestWithParam<Conformance_case>
{};

// Levels 1 to 3, every vertex within 1e-12 of the bounding-box diagonal of
// OpenSubdiv's, matched by position both ways, and the same counts.
TEST_P(OpenSubdivShapes, refine_as_opensubdiv_far_does)
{
  const Conformance_case& c = GetParam();
  const Tagged_shape shape = read_shape(c.shape);
  const auto reference = opensubdiv_levels(shape, c.scheme, 3);
  ASSERT_EQ(reference.size(), 4u);
  Mesh mesh = tagged_mesh(shape);
  for(int level = 1; level <= 3; ++level) {
    refine_once(mesh, c.scheme, shape);
    const auto ours = testing_utils::double_points(mesh);
    ASSERT_EQ(ours.size(), reference[level].size()) << "level " << level;
    const double mismatch = (std::max)(testing_utils::position_mismatch(ours, reference[level]),
                                       testing_utils::position_mismatch(reference[level], ours));
    EXPECT_LT(mismatch, 1e-12) << "level " << level;
  }
}

INSTANTIATE_TEST_SUITE_P(
  Tags, OpenSubdivShapes,
  testing::Values(
    Conformance_case{"catmark_cube_creases0", Scheme::catmark},
    Conformance_case{"catmark_cube_creases1", Scheme::catmark},
    Conformance_case{"catmark_cube_creases2", Scheme::catmark}, Conformance_case{"catmark_chaikin0", Scheme::catmark},
    Conformance_case{"catmark_chaikin1", Scheme::catmark}, Conformance_case{"catmark_chaikin2", Scheme::catmark},
    Conformance_case{"catmark_dart_edgeonly", Scheme::catmark},
    Conformance_case{"catmark_dart_edgecorner", Scheme::catmark},
    Conformance_case{"catmark_pyramid_creases0", Scheme::catmark},
    Conformance_case{"catmark_pyramid_creases1", Scheme::catmark},
    Conformance_case{"catmark_tent_creases0", Scheme::catmark},
    Conformance_case{"catmark_tent_creases1", Scheme::catmark},
    Conformance_case{"catmark_torus_creases0", Scheme::catmark},
    Conformance_case{"catmark_torus_creases1", Scheme::catmark},
    Conformance_case{"catmark_inf_crease0", Scheme::catmark}, Conformance_case{"catmark_inf_crease1", Scheme::catmark},
    Conformance_case{"catmark_single_crease", Scheme::catmark}, Conformance_case{"loop_cube_creases0", Scheme::loop},
    Conformance_case{"loop_cube_creases1", Scheme::loop}, Conformance_case{"loop_chaikin0", Scheme::loop},
    Conformance_case{"loop_chaikin1", Scheme::loop}, Conformance_case{"loop_icos_semisharp", Scheme::loop},
    Conformance_case{"loop_icos_infsharp", Scheme::loop}, Conformance_case{"loop_cubes_semisharp", Scheme::loop},
    Conformance_case{"loop_cubes_infsharp", Scheme::loop}),
  [](const testing::TestParamInfo<Conformance_case>& info) { return info.param.shape; });
#else
TEST(OpenSubdivShapes, refine_as_opensubdiv_far_does)
{
  FAIL() << "OpenSubdiv (Debian's libosd-dev) was not found when the tests were configured: the conformance "
            "test needs it (bash src/scripts/quickstart.sh deps --with-peers installs it)";
}
#endif

// The maps hold the children's sharpness: one level and then another is two
// levels, bit for bit, with either creasing method.
TEST(SharpFeatures, one_level_then_another_is_two_levels)
{
  for(const char* name : {"catmark_chaikin1", "catmark_cubes_semisharp"}) {
    const Tagged_shape shape = read_shape(name);
    Mesh stepwise = tagged_mesh(shape);
    refine_once(stepwise, Scheme::catmark, shape);
    refine_once(stepwise, Scheme::catmark, shape);
    Mesh at_once = tagged_mesh(shape);
    const auto np = Sd::parameters::number_of_iterations(2)
                      .edge_sharpness_map(at_once.property_map<Mesh::Edge_index, double>("e:sharpness").first)
                      .vertex_sharpness_map(at_once.property_map<Mesh::Vertex_index, double>("v:sharpness").first)
                      .crease_method(shape.method);
    Sd::subdivide(at_once, Sd::Catmull_clark_mask<Mesh>(shape.border), np);
    ASSERT_EQ(num_vertices(stepwise), num_vertices(at_once)) << name;
    for(auto v : vertices(stepwise))
      ASSERT_EQ(stepwise.point(v), at_once.point(v)) << name << " vertex " << v;
    const auto a = stepwise.property_map<Mesh::Edge_index, double>("e:sharpness").first;
    const auto b = at_once.property_map<Mesh::Edge_index, double>("e:sharpness").first;
    for(auto e : edges(stepwise))
      ASSERT_EQ(a[e], b[e]) << name << " edge " << e;
  }
}

// A cube with every edge of sharpness 1/2, in rational arithmetic: a corner
// blends its corner rule and the smooth rule half and half, an edge its
// midpoint and the smooth edge rule. By hand, for the cube [-1, 1]^3: the
// smooth vertex point of (1, 1, 1) is (5/9, 5/9, 5/9), so the blend is
// (7/9, 7/9, 7/9); the edge from (1, 1, 1) to (1, 1, -1) has the smooth
// point (3/4, 3/4, 0) and the midpoint (1, 1, 0), so (7/8, 7/8, 0). One level
// down the sharpness is 0 everywhere.
TEST(SharpFeatures, semi_sharp_cube_is_exact_in_rationals)
{
  using EK = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  using Exact_mesh = CGAL::Surface_mesh<EK::Point_3>;
  using FT = EK::FT;
  Exact_mesh mesh = testing_utils::cube<Exact_mesh>();
  for(auto v : vertices(mesh)) { // the builder's cube, moved to [-1, 1]^3
    const auto& p = mesh.point(v);
    mesh.point(v) = EK::Point_3(2 * p.x() - 1, 2 * p.y() - 1, 2 * p.z() - 1);
  }
  auto sharpness = mesh.add_property_map<Exact_mesh::Edge_index, FT>("e:sharpness", FT(1) / FT(2)).first;
  Sd::catmull_clark_subdivision(mesh, Sd::parameters::edge_sharpness_map(sharpness));
  bool corner_seen = false, edge_seen = false;
  for(auto v : vertices(mesh)) {
    const EK::Point_3& p = mesh.point(v);
    if(p == EK::Point_3(FT(7) / FT(9), FT(7) / FT(9), FT(7) / FT(9)))
      corner_seen = true;
    if(p == EK::Point_3(FT(7) / FT(8), FT(7) / FT(8), FT(0)))
      edge_seen = true;
  }
  EXPECT_TRUE(corner_seen);
  EXPECT_TRUE(edge_seen);
  for(auto e : edges(mesh))
    ASSERT_EQ(sharpness[e], FT(0)) << "edge " << e;
}

// Loop with Warren's rational beta, in rationals: one infinitely sharp edge of
// a tetrahedron gets its exact midpoint; its two ends, darts (one sharp edge),
// keep the smooth rule, so they are where the untagged refinement puts them.
TEST(SharpFeatures, loop_warren_dart_and_crease_edge_are_exact)
{
  using EK = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  using Exact_mesh = CGAL::Surface_mesh<EK::Point_3>;
  using FT = EK::FT;
  Exact_mesh tagged = testing_utils::tetrahedron<Exact_mesh>();
  Exact_mesh untagged = tagged;
  const auto h = tagged.halfedge(Exact_mesh::Edge_index(0));
  const EK::Point_3 a = tagged.point(tagged.source(h)), b = tagged.point(tagged.target(h));
  auto sharpness = tagged.add_property_map<Exact_mesh::Edge_index, FT>("e:sharpness", FT(0)).first;
  sharpness[Exact_mesh::Edge_index(0)] = FT(10);
  Sd::loop_warren_subdivision(tagged, Sd::parameters::edge_sharpness_map(sharpness));
  Sd::loop_warren_subdivision(untagged);
  ASSERT_EQ(num_vertices(tagged), num_vertices(untagged));
  std::size_t differing = 0;
  for(auto v : vertices(tagged))
    differing += tagged.point(v) == untagged.point(v) ? 0 : 1;
  EXPECT_EQ(differing, 1u); // the edge point of the sharp edge, nothing else
  bool midpoint_seen = false;
  for(auto v : vertices(tagged))
    midpoint_seen = midpoint_seen || tagged.point(v) == CGAL::midpoint(a, b);
  EXPECT_TRUE(midpoint_seen);
  // the two halves are infinitely sharp, every other new edge smooth
  std::size_t sharp_halves = 0;
  for(auto e : edges(tagged))
    sharp_halves += sharpness[e] == FT(10) ? 1 : (sharpness[e] == FT(0) ? 0 : 100);
  EXPECT_EQ(sharp_halves, 2u);
}

// Tagged sharpness is a user's value: a negative one is refused, naming the
// edge, and the mesh is left as it was.
TEST(SharpFeatures, negative_sharpness_is_refused)
{
  Mesh mesh = testing_utils::cube<Mesh>();
  const Mesh before = mesh;
  auto sharpness = mesh.add_property_map<Mesh::Edge_index, double>("e:sharpness", 0).first;
  sharpness[Mesh::Edge_index(3)] = -1;
  const std::string message = testing_utils::bad_input_message(
    [&] { Sd::catmull_clark_subdivision(mesh, Sd::parameters::edge_sharpness_map(sharpness)); });
  EXPECT_NE(message.find("the sharpness of edge 3 is negative or NaN"), std::string::npos) << message;
  EXPECT_EQ(num_vertices(mesh), num_vertices(before));
  EXPECT_EQ(num_faces(mesh), num_faces(before));
}

} // namespace
