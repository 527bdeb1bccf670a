// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the jobs of CGAL Subdiv and of CGAL's Subdivision_method_3.
#include "inputs.h"
#include "libraries.h"
#include "threads_parameter.h"

#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Subdiv/limit/tessellate.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <cmath>
#include <optional>
#include <thread>
#include <type_traits>

namespace subdiv_bench {
namespace {

std::vector<P3> points_of(const Mesh& mesh)
{
  std::vector<P3> points;
  points.reserve(mesh.number_of_vertices());
  for(const Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    points.push_back({p.x(), p.y(), p.z()});
  }
  return points;
}

// a refinement in place on a copy of the input's Surface_mesh
template <class Refine>
class Mesh_job : public Job
{
public:
  Mesh_job(const Mesh& input, Refine refine) : m_input(input), m_refine(refine) {}
  void prepare() override
  {
    m_mesh = Mesh();
    m_mesh = m_input;
  }
  void run() override { m_refine(m_mesh); }
  std::size_t output_faces() const override { return m_mesh.number_of_faces(); }
  std::vector<P3> output_points() const override { return points_of(m_mesh); }

private:
  const Mesh& m_input;
  Refine m_refine;
  Mesh m_mesh;
};

template <class Refine>
Job_ptr mesh_job(const Mesh& input, Refine refine)
{
  return std::make_unique<Mesh_job<Refine>>(input, refine);
}

class Stencil_build_job : public Job
{
public:
  Stencil_build_job(const Mesh& input, Scheme scheme, int levels, int threads)
    : m_input(input), m_scheme(scheme), m_levels(levels), m_threads(threads)
  {}
  void prepare() override { m_table = Table(); }
  void run() override
  {
    const auto np = ours_parameters(m_levels, m_threads);
    if(m_scheme == Scheme::loop)
      m_table = CGAL::Subdiv::make_stencil_table(m_input, CGAL::Subdiv::Loop_mask<Mesh>(), np);
    else
      m_table = CGAL::Subdiv::make_stencil_table(m_input, CGAL::Subdiv::Catmull_clark_mask<Mesh>(), np);
  }

private:
  using Table = CGAL::Subdiv::Stencil_table<double>;
  const Mesh& m_input;
  Scheme m_scheme;
  int m_levels;
  int m_threads;
  Table m_table;
};

class Ours_apply_job : public Apply_job
{
public:
  Ours_apply_job(const Mesh& input, Scheme scheme, int levels)
  {
    const auto np = ours_parameters(levels, 1);
    if(scheme == Scheme::loop)
      m_table = CGAL::Subdiv::make_stencil_table(input, CGAL::Subdiv::Loop_mask<Mesh>(), np);
    else
      m_table = CGAL::Subdiv::make_stencil_table(input, CGAL::Subdiv::Catmull_clark_mask<Mesh>(), np);
    for(const Mesh::Vertex_index v : input.vertices())
      m_in.push_back(input.point(v));
    m_out.resize(m_table.number_of_stencils());
  }
  void run() override
  {
    if(m_threads <= 1) {
      m_table.apply(m_in, m_out);
      return;
    }
    const std::size_t n = m_table.number_of_stencils(), half = n / 2;
    std::thread other([&] { m_table.apply_range(m_in, m_out, half, n); });
    m_table.apply_range(m_in, m_out, 0, half);
    other.join();
  }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    for(const Point& p : m_out)
      points.push_back({p.x(), p.y(), p.z()});
    return points;
  }
  std::size_t stencils() const override { return m_table.number_of_stencils(); }
  std::size_t terms() const override { return m_table.number_of_terms(); }
  std::size_t sources() const override { return m_table.number_of_sources(); }
  void set_threads(int threads) override { m_threads = threads; }

private:
  CGAL::Subdiv::Stencil_table<double> m_table;
  std::vector<Point> m_in, m_out;
  int m_threads = 1;
};

// The Surface_mesh::resize calls a refinement of the mesh in place must make,
// alone: reserve the last level (several levels), then resize to every
// level's counts. Every new element is value-initialised by std::vector, so
// this is a floor for any refinement into a Surface_mesh through its public
// API (add_vertex, add_edge, add_face initialise their elements too).
class Resize_floor_job : public Job
{
public:
  Resize_floor_job(const Mesh& input, Scheme scheme, int levels) : m_input(input), m_scheme(scheme), m_levels(levels) {}
  void prepare() override
  {
    m_mesh = Mesh();
    m_mesh = m_input;
  }
  void run() override
  {
    struct Counts
    {
      std::size_t vertices, edges, faces, corners;
    };
    Counts c{m_mesh.number_of_vertices(), m_mesh.number_of_edges(), m_mesh.number_of_faces(), 0};
    for(const Mesh::Halfedge_index h : m_mesh.halfedges())
      c.corners += m_mesh.is_border(h) ? 0 : 1;
    std::vector<Counts> levels;
    for(int level = 0; level < m_levels; ++level) {
      if(m_scheme == Scheme::loop) // 1-to-4 split of triangles
        c = Counts{c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces, 12 * c.faces};
      else // quad split
        c = Counts{c.vertices + c.edges + c.faces, 2 * c.edges + c.corners, c.corners, 4 * c.corners};
      levels.push_back(c);
    }
    using size_type = Mesh::size_type;
    if(m_levels >= 2)
      m_mesh.reserve(static_cast<size_type>(c.vertices), static_cast<size_type>(c.edges),
                     static_cast<size_type>(c.faces));
    for(const Counts& level : levels)
      m_mesh.resize(static_cast<size_type>(level.vertices), static_cast<size_type>(level.edges),
                    static_cast<size_type>(level.faces));
  }
  std::size_t output_faces() const override { return m_mesh.number_of_faces(); }

private:
  const Mesh& m_input;
  Scheme m_scheme;
  int m_levels;
  Mesh m_mesh;
};

// --- the limit surface -------------------------------------------------------------

using Cc_limit = CGAL::Subdiv::Limit_surface<Mesh, CGAL::Subdiv::Catmull_clark_mask<Mesh>>;
using Loop_limit = CGAL::Subdiv::Limit_surface<Mesh, CGAL::Subdiv::Loop_mask<Mesh>>;

P3 p3(const CGAL::Subdiv::Limit_sample::Point& p)
{
  return {p.x(), p.y(), p.z()};
}

// the evaluator made, then evaluated once in every face (this builds the
// Stam eigenbases of the valences it meets)
template <class Surface>
class Limit_build_job : public Job
{
public:
  explicit Limit_build_job(const Mesh& input) : m_input(input) {}
  void prepare() override
  {
    m_surface.reset();
    m_points.clear();
    m_points.reserve(m_input.number_of_faces());
  }
  void run() override
  {
    const Surface& surface = m_surface.emplace(m_input);
    for(const Mesh::Face_index f : m_input.faces()) {
      try {
        if constexpr(std::is_same_v<Surface, Cc_limit>)
          if(m_input.degree(f) != 4) {
            m_points.push_back(p3(surface.evaluate(f, 0, 0.25, 0.25).position));
            continue;
          }
        m_points.push_back(p3(surface.evaluate(f, 0.25, 0.25).position));
      } catch(const CGAL::Subdiv::Bad_input&) {
        const double nan = std::nan("");
        m_points.push_back({nan, nan, nan});
      }
    }
  }
  std::vector<P3> output_points() const override { return m_points; }

private:
  const Mesh& m_input;
  std::optional<Surface> m_surface;
  std::vector<P3> m_points;
};

// P, du and dv at every location, the surface made once
template <class Surface>
class Limit_evaluation_job : public Job
{
public:
  Limit_evaluation_job(const Mesh& input, const std::vector<Limit_location>& locations, bool keep,
                       bool second_derivatives)
    : m_surface(input), m_locations(locations), m_points(locations.size()), m_derivatives(2 * locations.size())
  {
    if(!keep) // every evaluation starts from the mesh, as Bfr's per location does
      m_surface.cached_faces = 0;
    m_surface.second_derivatives = second_derivatives;
  }
  void run() override
  {
    for(std::size_t i = 0; i < m_locations.size(); ++i) {
      const Limit_location& at = m_locations[i];
      const CGAL::Subdiv::Limit_sample s =
        m_surface.evaluate(Mesh::Face_index(static_cast<Mesh::size_type>(at.face)), at.u, at.v);
      m_points[i] = p3(s.position);
      m_derivatives[2 * i] = {s.du.x(), s.du.y(), s.du.z()};
      m_derivatives[2 * i + 1] = {s.dv.x(), s.dv.y(), s.dv.z()};
    }
  }
  std::vector<P3> output_points() const override { return m_points; }

private:
  Surface m_surface;
  const std::vector<Limit_location>& m_locations;
  std::vector<P3> m_points, m_derivatives;
};

template <class Surface>
class Tessellation_job : public Job
{
public:
  Tessellation_job(const Mesh& input, int rate) : m_surface(input), m_rate(rate) {}
  void prepare() override { m_out = Output(); }
  void run() override
  {
    try {
      CGAL::Subdiv::tessellate(m_surface, m_out, m_rate, CGAL::Subdiv::parameters::output_normals(true));
    } catch(const CGAL::Subdiv::Bad_input&) {
      m_out = Output();
    }
  }
  std::size_t output_faces() const override { return m_out.number_of_faces(); }
  std::vector<P3> output_points() const override
  {
    std::vector<P3> points;
    points.reserve(m_out.number_of_vertices());
    for(const Output::Vertex_index v : m_out.vertices())
      points.push_back(p3(m_out.point(v)));
    return points;
  }

private:
  using Output = CGAL::Surface_mesh<CGAL::Subdiv::Limit_sample::Point>;
  Surface m_surface;
  int m_rate;
  Output m_out;
};

template <class Surface>
std::string refusals(const Mesh& mesh, const std::vector<Limit_location>& locations, std::vector<bool>& refused)
{
  const Surface surface(mesh);
  std::string first;
  refused.assign(locations.size(), false);
  for(std::size_t i = 0; i < locations.size(); ++i) {
    const Limit_location& at = locations[i];
    try {
      surface.evaluate(Mesh::Face_index(static_cast<Mesh::size_type>(at.face)), at.u, at.v);
    } catch(const CGAL::Subdiv::Bad_input& e) {
      refused[i] = true;
      if(first.empty())
        first = e.what();
    }
  }
  return first;
}

} // namespace

Job_ptr ours_limit_build(const Input& input, Scheme scheme)
{
  if(scheme == Scheme::loop)
    return std::make_unique<Limit_build_job<Loop_limit>>(input.mesh);
  if(scheme == Scheme::catmull_clark)
    return std::make_unique<Limit_build_job<Cc_limit>>(input.mesh);
  return nullptr;
}

std::string ours_limit_refusals(const Input& input, Scheme scheme, const std::vector<Limit_location>& locations,
                                std::vector<bool>& refused)
{
  if(scheme == Scheme::loop)
    return refusals<Loop_limit>(input.mesh, locations, refused);
  return refusals<Cc_limit>(input.mesh, locations, refused);
}

Job_ptr ours_limit_evaluation(const Input& input, Scheme scheme, const std::vector<Limit_location>& locations,
                              bool keep, bool second_derivatives)
{
  if(scheme == Scheme::loop)
    return std::make_unique<Limit_evaluation_job<Loop_limit>>(input.mesh, locations, keep, second_derivatives);
  if(scheme == Scheme::catmull_clark)
    return std::make_unique<Limit_evaluation_job<Cc_limit>>(input.mesh, locations, keep, second_derivatives);
  return nullptr;
}

Job_ptr ours_tessellation(const Input& input, Scheme scheme, int rate)
{
  if(scheme == Scheme::loop)
    return std::make_unique<Tessellation_job<Loop_limit>>(input.mesh, rate);
  if(scheme == Scheme::catmull_clark)
    return std::make_unique<Tessellation_job<Cc_limit>>(input.mesh, rate);
  return nullptr;
}

Job_ptr surface_mesh_resize_floor(const Input& input, Scheme scheme, int levels)
{
  if(scheme != Scheme::loop && scheme != Scheme::catmull_clark)
    return nullptr;
  return std::make_unique<Resize_floor_job>(input.mesh, scheme, levels);
}

bool ours_has_threads()
{
  return has_threads;
}

bool ours_with_tbb()
{
#ifdef CGAL_LINKED_WITH_TBB
  return true;
#else
  return false;
#endif
}

Job_ptr ours_refinement(const Input& input, Scheme scheme, int levels, int threads)
{
  if(threads > 1 && !has_threads)
    return nullptr;
  const auto np = ours_parameters(levels, threads);
  if(input.textured) { // carrying the UVs of the copy with their seams, in corners plus1 (as OSD below)
    if(scheme != Scheme::loop && scheme != Scheme::catmull_clark)
      return nullptr;
    return mesh_job(input.mesh, [np, scheme](Mesh& m) {
      CGAL::Subdiv::Carried_data<Mesh, double> uvs;
      uvs.corner_map(m.property_map<Mesh::Halfedge_index, Kernel::Point_2>(uv_map_name).first,
                     CGAL::Subdiv::Face_varying_interpolation::corners_plus1,
                     m.property_map<Mesh::Halfedge_index, std::size_t>(uv_index_map_name).first);
      if(scheme == Scheme::loop)
        CGAL::Subdiv::loop_subdivision(m, np.carried_data(uvs));
      else
        CGAL::Subdiv::catmull_clark_subdivision(m, np.carried_data(uvs));
    });
  }
  if(input.creased) { // with the input's creases, which refine with the mesh (the copy's map)
    const auto creases = [](Mesh& m) { return m.property_map<Mesh::Edge_index, double>(crease_map_name).first; };
    if(scheme == Scheme::loop)
      return mesh_job(input.mesh,
                      [np, creases](Mesh& m) { CGAL::Subdiv::loop_subdivision(m, np.edge_sharpness_map(creases(m))); });
    if(scheme == Scheme::catmull_clark)
      return mesh_job(input.mesh, [np, creases](Mesh& m) {
        CGAL::Subdiv::catmull_clark_subdivision(m, np.edge_sharpness_map(creases(m)));
      });
    return nullptr;
  }
  switch(scheme) {
    case Scheme::loop:
      return mesh_job(input.mesh, [np](Mesh& m) { CGAL::Subdiv::loop_subdivision(m, np); });
    case Scheme::catmull_clark:
      return mesh_job(input.mesh, [np](Mesh& m) { CGAL::Subdiv::catmull_clark_subdivision(m, np); });
    case Scheme::doo_sabin:
      return mesh_job(input.mesh, [np](Mesh& m) { CGAL::Subdiv::doo_sabin_subdivision(m, np); });
    case Scheme::sqrt3:
      return mesh_job(input.mesh, [np](Mesh& m) { CGAL::Subdiv::sqrt3_subdivision(m, np); });
  }
  return nullptr;
}

Job_ptr cgal_refinement(const Input& input, Scheme scheme, int levels)
{
  namespace SM = CGAL::Subdivision_method_3;
  const auto np = CGAL::parameters::number_of_iterations(levels);
  switch(scheme) {
    case Scheme::loop:
      return mesh_job(input.mesh, [np](Mesh& m) { SM::Loop_subdivision(m, np); });
    case Scheme::catmull_clark:
      return mesh_job(input.mesh, [np](Mesh& m) { SM::CatmullClark_subdivision(m, np); });
    case Scheme::doo_sabin:
      return mesh_job(input.mesh, [np](Mesh& m) { SM::DooSabin_subdivision(m, np); });
    case Scheme::sqrt3:
      return mesh_job(input.mesh, [np](Mesh& m) { SM::Sqrt3_subdivision(m, np); });
  }
  return nullptr;
}

Job_ptr ours_stencil_build(const Input& input, Scheme scheme, int levels, int threads)
{
  if(scheme != Scheme::loop && scheme != Scheme::catmull_clark)
    return nullptr;
  if(threads > 1 && !has_threads)
    return nullptr;
  return std::make_unique<Stencil_build_job>(input.mesh, scheme, levels, threads);
}

Apply_ptr ours_apply(const Input& input, Scheme scheme, int levels)
{
  if(scheme != Scheme::loop && scheme != Scheme::catmull_clark)
    return nullptr;
  return std::make_unique<Ours_apply_job>(input.mesh, scheme, levels);
}

} // namespace subdiv_bench
