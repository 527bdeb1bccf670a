// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: OpenSubdiv's Far (and Osd::OmpEvaluator), when CMake found
// OpenSubdiv (SUBDIV_BENCH_WITH_OSD); otherwise every job is missing.
//
// Options everywhere: Sdc::Options with VTX_BOUNDARY_EDGE_ONLY (the border
// rules of CGAL Subdiv's default Border_corners::smooth) and TRI_SUB_CATMARK
// (the Catmull-Clark rule on triangles); uniform refinement with Far's default
// UniformOptions (no full topology in the last level); double precision
// (PrimvarRefinerReal<double>, StencilTableFactoryReal<double>) except in the
// OmpEvaluator row, which Debian's libosdCPU offers for floats only.
#include "libraries.h"

#ifdef SUBDIV_BENCH_WITH_OSD
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/ompEvaluator.h>
#include <opensubdiv/version.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <thread>
#endif

namespace subdiv_bench {

#ifndef SUBDIV_BENCH_WITH_OSD

std::string osd_missing()
{
  return "OpenSubdiv not found by CMake (Debian: libosd-dev)";
}
std::string osd_version()
{
  return "";
}
Job_ptr osd_refinement(const Soup&, Scheme, int)
{
  return nullptr;
}
Job_ptr osd_stencil_build(const Soup&, Scheme, int, bool)
{
  return nullptr;
}
Apply_ptr osd_apply(const Soup&, Scheme, int)
{
  return nullptr;
}
Apply_ptr osd_apply_omp_float(const Soup&, Scheme, int)
{
  return nullptr;
}
Job_ptr osd_limit_build(const Soup&, Scheme)
{
  return nullptr;
}
Job_ptr osd_limit_evaluation(const Soup&, Scheme, const std::vector<Limit_location>&, bool)
{
  return nullptr;
}
Job_ptr osd_tessellation(const Soup&, Scheme, int)
{
  return nullptr;
}

#else

namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
namespace Osd = OpenSubdiv::Osd;
namespace Bfr = OpenSubdiv::Bfr;

// the primvar type of Far's templates
struct Vertex
{
  double p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Vertex& source, double weight)
  {
    p[0] += weight * source.p[0];
    p[1] += weight * source.p[1];
    p[2] += weight * source.p[2];
  }
};

// a texture coordinate, the primvar of the face-varying channel
struct Uv
{
  double p[2];
  void Clear(void* = nullptr) { p[0] = p[1] = 0; }
  void AddWithWeight(const Uv& source, double weight)
  {
    p[0] += weight * source.p[0];
    p[1] += weight * source.p[1];
  }
};

// the topology of a Soup as Far sees it (pointing into the Soup), and the
// options; the UVs of a textured Soup are a face-varying channel in corners
// plus1 (USD's default, and CGAL Subdiv's in the bench)
class Topology
{
public:
  Topology(const Soup& soup, Scheme scheme)
  {
    if(!soup.uvs.empty()) {
      m_uv_channel.numValues = static_cast<int>(soup.uvs.size());
      m_uv_channel.valueIndices = soup.uv_indices.data();
      m_descriptor.numFVarChannels = 1;
      m_descriptor.fvarChannels = &m_uv_channel;
      for(const auto& uv : soup.uvs)
        m_coarse_uvs.push_back(Uv{{uv[0], uv[1]}});
    }
    m_descriptor.numVertices = static_cast<int>(soup.points.size());
    m_descriptor.numFaces = static_cast<int>(soup.face_sizes.size());
    m_descriptor.numVertsPerFace = soup.face_sizes.data();
    m_descriptor.vertIndicesPerFace = soup.indices.data();
    m_descriptor.numCreases = static_cast<int>(soup.crease_sharpness.size());
    m_descriptor.creaseVertexIndexPairs = soup.crease_pairs.data();
    m_descriptor.creaseWeights = soup.crease_sharpness.data();
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    options.SetTriangleSubdivision(Sdc::Options::TRI_SUB_CATMARK);
    options.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1);
    m_options = Factory::Options(scheme == Scheme::loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, options);
    for(const P3& p : soup.points)
      m_coarse.push_back(Vertex{{p[0], p[1], p[2]}});
  }

  /// the refiner of the base mesh, not refined
  std::unique_ptr<Far::TopologyRefiner> create() const
  {
    return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(m_descriptor, m_options));
  }

  std::unique_ptr<Far::TopologyRefiner> refine(int levels) const
  {
    std::unique_ptr<Far::TopologyRefiner> refiner = create();
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
    return refiner;
  }

  const std::vector<Vertex>& coarse() const { return m_coarse; }
  /// empty without UVs
  const std::vector<Uv>& coarse_uvs() const { return m_coarse_uvs; }

private:
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Far::TopologyDescriptor m_descriptor;
  Far::TopologyDescriptor::FVarChannel m_uv_channel;
  Factory::Options m_options;
  std::vector<Vertex> m_coarse;
  std::vector<Uv> m_coarse_uvs;
};

template <class Real>
typename Far::StencilTableFactoryReal<Real>::Options stencil_options()
{
  typename Far::StencilTableFactoryReal<Real>::Options options;
  options.generateIntermediateLevels = false;
  options.factorizeIntermediateLevels = true;
  options.generateOffsets = true; // where each stencil starts: what two threads need
  return options;
}

class Refine_job : public Job
{
public:
  Refine_job(const Soup& soup, Scheme scheme, int levels) : m_topology(soup, scheme), m_levels(levels) {}
  void prepare() override
  {
    m_refiner.reset();
    m_points = std::vector<Vertex>();
    m_uvs = std::vector<Uv>();
  }
  void run() override
  {
    m_refiner = m_topology.refine(m_levels);
    m_points.resize(
      static_cast<std::size_t>(m_refiner->GetNumVerticesTotal() - m_refiner->GetLevel(0).GetNumVertices()));
    const Far::PrimvarRefinerReal<double> primvar(*m_refiner);
    const Vertex* source = m_topology.coarse().data();
    Vertex* destination = m_points.data();
    for(int level = 1; level <= m_levels; ++level) {
      primvar.Interpolate(level, source, destination);
      source = destination;
      destination += m_refiner->GetLevel(level).GetNumVertices();
    }
    if(m_topology.coarse_uvs().empty())
      return;
    m_uvs.resize(
      static_cast<std::size_t>(m_refiner->GetNumFVarValuesTotal(0) - m_refiner->GetLevel(0).GetNumFVarValues(0)));
    const Uv* uv_source = m_topology.coarse_uvs().data();
    Uv* uv_destination = m_uvs.data();
    for(int level = 1; level <= m_levels; ++level) {
      primvar.InterpolateFaceVarying(level, uv_source, uv_destination);
      uv_source = uv_destination;
      uv_destination += m_refiner->GetLevel(level).GetNumFVarValues(0);
    }
  }
  std::size_t output_faces() const override
  {
    return m_refiner ? static_cast<std::size_t>(m_refiner->GetLevel(m_levels).GetNumFaces()) : 0;
  }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    const std::size_t n = static_cast<std::size_t>(m_refiner->GetLevel(m_levels).GetNumVertices());
    for(std::size_t i = m_points.size() - n; i < m_points.size(); ++i)
      points.push_back({m_points[i].p[0], m_points[i].p[1], m_points[i].p[2]});
    return points;
  }

private:
  Topology m_topology;
  int m_levels;
  std::unique_ptr<Far::TopologyRefiner> m_refiner;
  std::vector<Vertex> m_points; // levels 1 to m_levels
  std::vector<Uv> m_uvs;        // the same, with UVs
};

class Stencil_build_job : public Job
{
public:
  Stencil_build_job(const Soup& soup, Scheme scheme, int levels, bool factory_only)
    : m_topology(soup, scheme), m_levels(levels), m_factory_only(factory_only)
  {}
  void prepare() override
  {
    m_table.reset();
    m_refiner.reset();
    if(m_factory_only)
      m_refiner = m_topology.refine(m_levels);
  }
  void run() override
  {
    if(!m_factory_only)
      m_refiner = m_topology.refine(m_levels);
    m_table.reset(Far::StencilTableFactoryReal<double>::Create(*m_refiner, stencil_options<double>()));
  }

private:
  Topology m_topology;
  int m_levels;
  bool m_factory_only;
  std::unique_ptr<Far::TopologyRefiner> m_refiner;
  std::unique_ptr<const Far::StencilTableReal<double>> m_table;
};

class Apply_double_job : public Apply_job
{
public:
  Apply_double_job(const Soup& soup, Scheme scheme, int levels) : m_topology(soup, scheme)
  {
    const auto refiner = m_topology.refine(levels);
    m_table.reset(Far::StencilTableFactoryReal<double>::Create(*refiner, stencil_options<double>()));
    m_out.resize(static_cast<std::size_t>(m_table->GetNumStencils()));
  }
  void run() override
  {
    const Vertex* in = m_topology.coarse().data();
    if(m_threads <= 1) {
      m_table->UpdateValues(in, m_out.data());
      return;
    }
    const int n = m_table->GetNumStencils(), half = n / 2;
    std::thread other([&] { m_table->UpdateValues(in, m_out.data(), half, n); });
    m_table->UpdateValues(in, m_out.data(), 0, half);
    other.join();
  }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    for(const Vertex& v : m_out)
      points.push_back({v.p[0], v.p[1], v.p[2]});
    return points;
  }
  std::size_t stencils() const override { return static_cast<std::size_t>(m_table->GetNumStencils()); }
  std::size_t terms() const override { return m_table->GetControlIndices().size(); }
  std::size_t sources() const override { return static_cast<std::size_t>(m_table->GetNumControlVertices()); }
  void set_threads(int threads) override { m_threads = threads; }

private:
  Topology m_topology;
  std::unique_ptr<const Far::StencilTableReal<double>> m_table;
  std::vector<Vertex> m_out;
  int m_threads = 1;
};

class Apply_omp_job : public Apply_job
{
public:
  Apply_omp_job(const Soup& soup, Scheme scheme, int levels)
  {
    const Topology topology(soup, scheme);
    const auto refiner = topology.refine(levels);
    m_table.reset(Far::StencilTableFactoryReal<float>::Create(*refiner, stencil_options<float>()));
    for(const P3& p : soup.points)
      for(const double x : p)
        m_in.push_back(static_cast<float>(x));
    m_out.resize(3 * static_cast<std::size_t>(m_table->GetNumStencils()));
  }
  void run() override
  {
    Osd::OmpEvaluator::SetNumThreads(m_threads);
    const Osd::BufferDescriptor points(0, 3, 3);
    Osd::OmpEvaluator::EvalStencils(m_in.data(), points, m_out.data(), points, m_table->GetSizes().data(),
                                    m_table->GetOffsets().data(), m_table->GetControlIndices().data(),
                                    m_table->GetWeights().data(), 0, m_table->GetNumStencils());
  }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    for(std::size_t i = 0; i + 2 < m_out.size(); i += 3)
      points.push_back({m_out[i], m_out[i + 1], m_out[i + 2]});
    return points;
  }
  std::size_t stencils() const override { return static_cast<std::size_t>(m_table->GetNumStencils()); }
  std::size_t terms() const override { return m_table->GetControlIndices().size(); }
  std::size_t sources() const override { return static_cast<std::size_t>(m_table->GetNumControlVertices()); }
  void set_threads(int threads) override { m_threads = threads; }
  // floats: 4 B weights, 4 B indices, 8 B (size + offset) and 12 B points per stencil, 12 B per source
  double bytes() const override
  {
    return 8.0 * static_cast<double>(terms()) + 20.0 * static_cast<double>(stencils()) +
           12.0 * static_cast<double>(sources());
  }

private:
  std::unique_ptr<const Far::StencilTableReal<float>> m_table;
  std::vector<float> m_in, m_out;
  int m_threads = 1;
};

// --- Bfr: the limit surface ---------------------------------------------------------

P3 nan_point()
{
  const double nan = std::nan("");
  return {nan, nan, nan};
}

class Bfr_build_job : public Job
{
public:
  Bfr_build_job(const Soup& soup, Scheme scheme) : m_topology(soup, scheme) {}
  void prepare() override
  {
    m_factory.reset();
    m_refiner.reset();
  }
  void run() override
  {
    m_refiner = m_topology.create();
    m_factory = std::make_unique<Bfr::RefinerSurfaceFactory<>>(*m_refiner);
  }

private:
  Topology m_topology;
  std::unique_ptr<Far::TopologyRefiner> m_refiner;
  std::unique_ptr<Bfr::RefinerSurfaceFactory<>> m_factory;
};

// the refiner and Bfr's factory of a soup, made outside the timers, and the
// surface of one face at a time with its patch points
class Bfr_mesh
{
public:
  Bfr_mesh(const Soup& soup, Scheme scheme)
    : m_topology(soup, scheme), m_refiner(m_topology.create()), m_factory(*m_refiner)
  {
    m_mesh_points.reserve(3 * soup.points.size());
    for(const P3& p : soup.points)
      m_mesh_points.insert(m_mesh_points.end(), p.begin(), p.end());
  }
  /// the surface of face `face`, its patch points ready; false if Bfr has none
  bool init(int face)
  {
    if(!m_factory.InitVertexSurface(face, &m_surface))
      return false;
    m_patch_points.resize(3 * static_cast<std::size_t>(m_surface.GetNumPatchPoints()));
    m_surface.PreparePatchPoints(m_mesh_points.data(), 3, m_patch_points.data(), 3);
    return true;
  }
  const Bfr::Surface<double>& surface() const { return m_surface; }
  void evaluate(const double uv[2], double* p, double* du, double* dv) const
  {
    m_surface.Evaluate(uv, m_patch_points.data(), 3, p, du, dv);
  }

private:
  Topology m_topology;
  std::unique_ptr<Far::TopologyRefiner> m_refiner;
  Bfr::RefinerSurfaceFactory<> m_factory;
  std::vector<double> m_mesh_points, m_patch_points;
  Bfr::Surface<double> m_surface;
};

class Bfr_evaluation_job : public Job
{
public:
  Bfr_evaluation_job(const Soup& soup, Scheme scheme, const std::vector<Limit_location>& locations, bool per_face)
    : m_mesh(soup, scheme), m_locations(locations), m_order(locations.size()), m_per_face(per_face),
      m_points(locations.size(), nan_point()), m_derivatives(2 * locations.size())
  {
    std::iota(m_order.begin(), m_order.end(), std::size_t(0));
    if(per_face)
      std::stable_sort(m_order.begin(), m_order.end(),
                       [&](std::size_t a, std::size_t b) { return locations[a].face < locations[b].face; });
  }
  void run() override
  {
    int face = -1;
    bool valid = false;
    for(const std::size_t i : m_order) {
      const Limit_location& at = m_locations[i];
      if(!m_per_face || at.face != face) {
        face = at.face;
        valid = m_mesh.init(face);
      }
      if(!valid) // no surface: the point stays NaN, so that the comparison shows it
        continue;
      const double uv[2] = {at.u, at.v};
      m_mesh.evaluate(uv, m_points[i].data(), m_derivatives[2 * i].data(), m_derivatives[2 * i + 1].data());
    }
  }
  std::vector<P3> output_points() const override { return m_points; }

private:
  Bfr_mesh m_mesh;
  const std::vector<Limit_location>& m_locations;
  std::vector<std::size_t> m_order; // the locations by face (per face), or as given
  bool m_per_face;
  std::vector<P3> m_points, m_derivatives;
};

class Bfr_tessellation_job : public Job
{
public:
  Bfr_tessellation_job(const Soup& soup, Scheme scheme, int rate)
    : m_mesh(soup, scheme), m_faces(static_cast<int>(soup.face_sizes.size())), m_rate(rate)
  {
    if(scheme == Scheme::catmull_clark)
      m_options.PreserveQuads(true).SetFacetSize(4);
  }
  void prepare() override
  {
    m_points = std::vector<P3>();
    m_normals = std::vector<P3>();
    m_facets = std::vector<int>();
  }
  void run() override
  {
    const int facet_size = m_options.GetFacetSize();
    for(int f = 0; f < m_faces; ++f) {
      if(!m_mesh.init(f))
        continue;
      const Bfr::Tessellation tessellation(m_mesh.surface().GetParameterization(), m_rate, m_options);
      const std::size_t n = static_cast<std::size_t>(tessellation.GetNumCoords());
      m_coords.resize(2 * n);
      tessellation.GetCoords(m_coords.data());
      // the facets index this face's points, from the first one of the face on
      const std::size_t first_facet = m_facets.size();
      m_facets.resize(first_facet + static_cast<std::size_t>(facet_size * tessellation.GetNumFacets()));
      tessellation.GetFacets(m_facets.data() + first_facet);
      for(std::size_t i = 0; i < n; ++i) {
        P3 p, du, dv;
        m_mesh.evaluate(&m_coords[2 * i], p.data(), du.data(), dv.data());
        const P3 normal = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        const double scale = length > 0 ? 1 / length : 0;
        m_points.push_back(p);
        m_normals.push_back({normal[0] * scale, normal[1] * scale, normal[2] * scale});
      }
    }
  }
  std::size_t output_faces() const override
  {
    return m_facets.size() / static_cast<std::size_t>(m_options.GetFacetSize());
  }
  std::vector<P3> output_points() const override { return m_points; }

private:
  Bfr_mesh m_mesh;
  int m_faces, m_rate;
  Bfr::Tessellation::Options m_options;
  std::vector<double> m_coords;
  std::vector<P3> m_points, m_normals;
  std::vector<int> m_facets;
};

bool has_scheme(Scheme scheme)
{
  return scheme == Scheme::loop || scheme == Scheme::catmull_clark;
}

bool fits(const Soup& soup, Scheme scheme)
{
  if(!has_scheme(scheme))
    return false;
  if(scheme == Scheme::loop)
    for(const int size : soup.face_sizes)
      if(size != 3)
        return false;
  return true;
}

} // namespace

std::string osd_missing()
{
  return "";
}
std::string osd_version()
{
  return std::to_string(OPENSUBDIV_VERSION_MAJOR) + "." + std::to_string(OPENSUBDIV_VERSION_MINOR) + "." +
         std::to_string(OPENSUBDIV_VERSION_PATCH);
}

Job_ptr osd_refinement(const Soup& input, Scheme scheme, int levels)
{
  return fits(input, scheme) ? std::make_unique<Refine_job>(input, scheme, levels) : nullptr;
}

Job_ptr osd_stencil_build(const Soup& input, Scheme scheme, int levels, bool factory_only)
{
  return fits(input, scheme) ? std::make_unique<Stencil_build_job>(input, scheme, levels, factory_only) : nullptr;
}

Apply_ptr osd_apply(const Soup& input, Scheme scheme, int levels)
{
  return fits(input, scheme) ? std::make_unique<Apply_double_job>(input, scheme, levels) : nullptr;
}

Apply_ptr osd_apply_omp_float(const Soup& input, Scheme scheme, int levels)
{
  return fits(input, scheme) ? std::make_unique<Apply_omp_job>(input, scheme, levels) : nullptr;
}

Job_ptr osd_limit_build(const Soup& input, Scheme scheme)
{
  return fits(input, scheme) ? std::make_unique<Bfr_build_job>(input, scheme) : nullptr;
}

Job_ptr osd_limit_evaluation(const Soup& input, Scheme scheme, const std::vector<Limit_location>& locations,
                             bool per_face)
{
  return fits(input, scheme) ? std::make_unique<Bfr_evaluation_job>(input, scheme, locations, per_face) : nullptr;
}

Job_ptr osd_tessellation(const Soup& input, Scheme scheme, int rate)
{
  return fits(input, scheme) ? std::make_unique<Bfr_tessellation_job>(input, scheme, rate) : nullptr;
}

#endif

} // namespace subdiv_bench
