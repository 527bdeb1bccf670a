// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "limit_evaluator.h"

#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Subdiv/limit/tessellate.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>

#include <type_traits>

namespace cgal_subdiv {

namespace SD = CGAL::Subdiv;

// the output of tessellate() is a mesh of the tool's own type, so that the
// tool's writers take it as they are
static_assert(std::is_same_v<Surface, CGAL::Surface_mesh<SD::Limit_sample::Point>>);
static_assert(std::is_same_v<Normal, SD::Limit_sample::Vector>);

struct Limit_evaluator::Model
{
  virtual ~Model() = default;
  virtual Limit_point evaluate(std::size_t face, int corner, double u, double v) const = 0;
  virtual Surface tessellate(int rate, bool triangles, bool normals) const = 0;
  virtual std::map<std::size_t, Eigenbasis_facts> eigenbases() const = 0;
};

template <class Mask>
struct Limit_evaluator::Model_of : Limit_evaluator::Model
{
  explicit Model_of(const Surface& mesh) : surface(mesh) {}

  Limit_point evaluate(std::size_t face, int corner, double u, double v) const override
  {
    const Surface::Face_index f(static_cast<Surface::size_type>(face));
    SD::Limit_sample s;
    if constexpr(std::is_same_v<Mask, SD::Catmull_clark_mask<Surface>>)
      s = corner >= 0 ? surface.evaluate(f, corner, u, v) : surface.evaluate(f, u, v);
    else
      s = surface.evaluate(f, u, v);
    return s;
  }

  Surface tessellate(int rate, bool triangles, bool normals) const override
  {
    Surface out;
    SD::tessellate(surface, out, rate, SD::parameters::triangulate(triangles).output_normals(normals));
    return out;
  }

  std::map<std::size_t, Eigenbasis_facts> eigenbases() const override
  {
    std::map<std::size_t, Eigenbasis_facts> facts;
    const std::map<std::size_t, std::vector<double>> eigenvalues = surface.eigenbasis_eigenvalues();
    for(const auto& [n, condition] : surface.eigenbasis_conditions())
      facts[n] = Eigenbasis_facts{condition, eigenvalues.at(n)};
    return facts;
  }

  SD::Limit_surface<Surface, Mask> surface;
};

Limit_evaluator::Limit_evaluator(const Surface& mesh, Limit_scheme scheme)
{
  if(scheme == Limit_scheme::catmull_clark)
    m_model = std::make_unique<Model_of<SD::Catmull_clark_mask<Surface>>>(mesh);
  else
    m_model = std::make_unique<Model_of<SD::Loop_mask<Surface>>>(mesh);
}

Limit_evaluator::~Limit_evaluator() = default;

Limit_point Limit_evaluator::evaluate(std::size_t face, int corner, double u, double v) const
{
  return m_model->evaluate(face, corner, u, v);
}

Surface Limit_evaluator::tessellate(int rate, bool triangles, bool normals) const
{
  return m_model->tessellate(rate, triangles, normals);
}

std::map<std::size_t, Eigenbasis_facts> Limit_evaluator::eigenbases() const
{
  return m_model->eigenbases();
}

} // namespace cgal_subdiv
