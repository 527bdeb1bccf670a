// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: OpenMesh's uniform subdividers, when CMake found OpenMesh
// (SUBDIV_BENCH_WITH_OPENMESH); otherwise every job is missing.
#include "libraries.h"

#ifdef SUBDIV_BENCH_WITH_OPENMESH
#include <OpenMesh/Core/System/config.h>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#endif

namespace subdiv_bench {

#ifndef SUBDIV_BENCH_WITH_OPENMESH

std::string openmesh_missing()
{
  return "OpenMesh not found by CMake (Debian: libopenmesh-dev)";
}
std::string openmesh_version()
{
  return "";
}
Job_ptr openmesh_refinement(const Soup&, Scheme, int)
{
  return nullptr;
}

#else

namespace {

// double points, as in every other library of the benchmark
struct Traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Tri_mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using Poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<Traits>;

template <class OM>
OM mesh_of(const Soup& soup)
{
  return mesh_from_soup<OM, typename OM::Point, typename OM::VertexHandle>(soup);
}

template <class OM, class Subdivider>
class Openmesh_job : public Job
{
public:
  Openmesh_job(const Soup& soup, int levels) : m_input(mesh_of<OM>(soup)), m_levels(levels) {}
  void prepare() override
  {
    m_mesh = OM();
    m_mesh = m_input;
  }
  void run() override
  {
    Subdivider subdivider;
    subdivider(m_mesh, static_cast<std::size_t>(m_levels));
  }
  std::size_t output_faces() const override { return m_mesh.n_faces(); }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    points.reserve(m_mesh.n_vertices());
    for(const auto v : m_mesh.vertices()) {
      const auto& p = m_mesh.point(v);
      points.push_back({p[0], p[1], p[2]});
    }
    return points;
  }

private:
  OM m_input;
  int m_levels;
  OM m_mesh;
};

} // namespace

std::string openmesh_missing()
{
  return "";
}
std::string openmesh_version()
{
  return std::to_string(OM_GET_VER) + "." + std::to_string(OM_GET_MAJ) + "." + std::to_string(OM_GET_MIN);
}

Job_ptr openmesh_refinement(const Soup& input, Scheme scheme, int levels)
{
  bool triangles = true;
  for(const int size : input.face_sizes)
    triangles = triangles && size == 3;
  if(scheme == Scheme::loop && triangles)
    return std::make_unique<Openmesh_job<Tri_mesh, OpenMesh::Subdivider::Uniform::LoopT<Tri_mesh, double>>>(input,
                                                                                                            levels);
  if(scheme == Scheme::catmull_clark)
    return std::make_unique<Openmesh_job<Poly_mesh, OpenMesh::Subdivider::Uniform::CatmullClarkT<Poly_mesh, double>>>(
      input, levels);
  return nullptr;
}

#endif

} // namespace subdiv_bench
