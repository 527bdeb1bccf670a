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
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/ompEvaluator.h>
#include <opensubdiv/version.h>

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

#else

namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
namespace Osd = OpenSubdiv::Osd;

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

  std::unique_ptr<Far::TopologyRefiner> refine(int levels) const
  {
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(m_descriptor, m_options));
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

#endif

} // namespace subdiv_bench
