// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the same refinements with CGAL::Epick and CGAL::Epeck points,
// for the rows that say what exact arithmetic costs (no target).
#include "inputs.h"
#include "libraries.h"
#include "threads_parameter.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

namespace subdiv_bench {
namespace {

template <class K>
CGAL::Surface_mesh<typename K::Point_3> mesh_of(const Soup& soup)
{
  using M = CGAL::Surface_mesh<typename K::Point_3>;
  return mesh_from_soup<M, typename K::Point_3, typename M::Vertex_index>(soup);
}

template <class K, class Refine>
class Kernel_job : public Job
{
public:
  using M = CGAL::Surface_mesh<typename K::Point_3>;
  Kernel_job(const Soup& soup, Refine refine) : m_input(mesh_of<K>(soup)), m_refine(refine) {}
  void prepare() override
  {
    m_mesh = M();
    m_mesh = m_input;
  }
  void run() override { m_refine(m_mesh); }
  std::size_t output_faces() const override { return m_mesh.number_of_faces(); }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    for(const auto v : m_mesh.vertices()) {
      const auto& p = m_mesh.point(v);
      points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    return points;
  }

private:
  M m_input;
  Refine m_refine;
  M m_mesh;
};

template <class K, class Refine>
Job_ptr kernel_job(const Soup& soup, Refine refine)
{
  return std::make_unique<Kernel_job<K, Refine>>(soup, refine);
}

template <class K>
Job_ptr ours(const Soup& soup, Scheme scheme, int levels)
{
  using M = CGAL::Surface_mesh<typename K::Point_3>;
  const auto np = subdiv_bench::ours_parameters(levels, 1);
  if(scheme == Scheme::loop)
    return kernel_job<K>(soup, [np](M& m) { CGAL::Subdiv::loop_subdivision(m, np); });
  if(scheme == Scheme::catmull_clark)
    return kernel_job<K>(soup, [np](M& m) { CGAL::Subdiv::catmull_clark_subdivision(m, np); });
  return nullptr;
}

template <class K>
Job_ptr cgal(const Soup& soup, Scheme scheme, int levels)
{
  using M = CGAL::Surface_mesh<typename K::Point_3>;
  namespace SM = CGAL::Subdivision_method_3;
  const auto np = CGAL::parameters::number_of_iterations(levels);
  if(scheme == Scheme::loop)
    return kernel_job<K>(soup, [np](M& m) { SM::Loop_subdivision(m, np); });
  if(scheme == Scheme::catmull_clark)
    return kernel_job<K>(soup, [np](M& m) { SM::CatmullClark_subdivision(m, np); });
  return nullptr;
}

} // namespace

Job_ptr ours_refinement_kernel(const Input& input, Scheme scheme, int levels, bool exact)
{
  return exact ? ours<CGAL::Epeck>(input.soup, scheme, levels) : ours<CGAL::Epick>(input.soup, scheme, levels);
}

Job_ptr cgal_refinement_kernel(const Input& input, Scheme scheme, int levels, bool exact)
{
  return exact ? cgal<CGAL::Epeck>(input.soup, scheme, levels) : cgal<CGAL::Epick>(input.soup, scheme, levels);
}

} // namespace subdiv_bench
