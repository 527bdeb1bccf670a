// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_VERIFY_LIMIT_H
#define CGAL_SUBDIV_ANALYSIS_VERIFY_LIMIT_H

// The check of a limit mask by refinement: a random neighbourhood refined
// until its centre converges, against the mask applied to its control points.

#include <CGAL/Subdiv/analysis/characteristic_map.h> // Surface_analysis_options, the patches

namespace CGAL {
namespace Subdiv {

namespace internal {

inline Analysis_mesh::Point tracked_point(const Analysis_mesh& mesh, Analysis_halfedge start)
{
  return mesh.point(mesh.source(start));
}

inline double distance(const Analysis_mesh::Point& p, const Analysis_mesh::Point& q)
{
  return std::sqrt(CGAL::squared_distance(p, q));
}

template <class DoubleMask, class Result>
void verify_limit(const DoubleMask& mask, Result& result, const std::vector<double>& limit_mask,
                  const internal::Surface_analysis_options& options)
{
  using Traits = Host_of<DoubleMask>;
  const int rings = result.rings + 2;
  const Patch shape = analysis_patch(mask, result.configuration, rings);
  Patch patch = shape;
  std::mt19937 random(options.seed + static_cast<unsigned>(result.valence) + (result.boundary ? 1000u : 0u));
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for(Analysis_vertex v : patch.mesh.vertices())
    patch.mesh.point(v) = Analysis_mesh::Point(coordinate(random), coordinate(random), coordinate(random));
  const Labelling labels = label_neighbourhood(patch.mesh, patch.start, Traits::face_centred, result.rings);
  double predicted[3] = {0, 0, 0}, diameter = 0;
  for(std::size_t i = 0; i < labels.size(); ++i) {
    const auto& p = patch.mesh.point(labels.vertex_of[i]);
    predicted[0] += limit_mask[i] * p.x();
    predicted[1] += limit_mask[i] * p.y();
    predicted[2] += limit_mask[i] * p.z();
    for(std::size_t j = 0; j < i; ++j)
      diameter = (std::max)(diameter, distance(p, patch.mesh.point(labels.vertex_of[j])));
  }
  const Analysis_mesh::Point limit(predicted[0], predicted[1], predicted[2]);
  // the real host on the whole patch, as long as it fits
  Analysis_mesh mesh = patch.mesh;
  Analysis_halfedge start = patch.start;
  const double growth = Traits::analysis_steps == 2 ? 9 : 4;
  int level = 0;
  while(level < 3 || static_cast<double>(mesh.number_of_faces()) * growth <= static_cast<double>(options.max_faces)) {
    auto step = analysed_step(mesh, start, mask);
    mesh = std::move(step.mesh);
    start = step.start;
    ++level;
  }
  result.host_levels = level;
  result.host_error = distance(tracked_point(mesh, start), limit) / diameter;
  result.host_lambda_power = std::pow(std::abs(result.subdominant), level);
  // then the real host on the cropped patch, until the point stops moving
  const Labelling to = label_neighbourhood(shape.mesh, shape.start, Traits::face_centred, rings);
  for(int more = 0; more < 400; ++more) {
    Patch fresh = shape;
    const Labelling from = label_neighbourhood(mesh, start, Traits::face_centred, rings);
    CGAL_assertion_msg(to.size() == from.size(), "the cropped neighbourhood does not match");
    for(std::size_t i = 0; i < to.size(); ++i)
      fresh.mesh.point(to.vertex_of[i]) = mesh.point(from.vertex_of[i]);
    const Analysis_mesh::Point before = tracked_point(fresh.mesh, fresh.start);
    auto step = analysed_step(fresh.mesh, fresh.start, mask);
    mesh = std::move(step.mesh);
    start = step.start;
    result.cropped_levels = more + 1;
    if(distance(before, tracked_point(mesh, start)) <= 1e-15 * diameter)
      break;
  }
  result.limit_error = distance(tracked_point(mesh, start), limit) / diameter;
}

} // namespace internal

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_VERIFY_LIMIT_H
