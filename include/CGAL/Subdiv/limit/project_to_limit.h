// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_PROJECT_TO_LIMIT_H
#define CGAL_SUBDIV_LIMIT_PROJECT_TO_LIMIT_H

/// \file project_to_limit.h
/// The limit functions: `project_to_limit()`, `limit_normals()` and
/// `displace()`, each a call of a `Limit_evaluator` made for the call.

#include <CGAL/Subdiv/limit/Limit_evaluator.h>
#include <CGAL/Subdiv/parameters.h>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * moves every vertex of `mesh` to its limit position under the scheme of
 * `mask`, e.g. `project_to_limit(mesh, Loop_mask<Mesh>())`; see
 * `Limit_evaluator::project_to_limit()`. Interpolating schemes leave the
 * points where they are (their limit masks are the unit vector of the centre).
 * \throws Bad_input for a mesh the scheme does not apply to, a vertex whose
 * configuration the analysis does not cover (Doo-Sabin: an interior vertex of
 * valence 2).
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
void project_to_limit(PolygonMesh& mesh, const Mask& mask, const NamedParameters& np = parameters::default_values())
{
  Limit_evaluator<Mask>(mask).project_to_limit(mesh, np);
}

/*!
 * \ingroup PkgSubdivAnalysis
 * writes the unit limit normal of every vertex into `normals`, e.g.
 * `limit_normals(mesh, Catmull_clark_mask<Mesh>(), normal_map)`; see
 * `Limit_evaluator::limit_normals()` (tangent masks, fallback to face normals).
 */
template <class PolygonMesh, class Mask, class NormalMap, class NamedParameters = parameters::Default_named_parameters>
void limit_normals(const PolygonMesh& mesh, const Mask& mask, NormalMap normals,
                   const NamedParameters& np = parameters::default_values())
{
  Limit_evaluator<Mask>(mask).limit_normals(mesh, normals, np);
}

/*!
 * \ingroup PkgSubdivAnalysis
 * displacement mapping with the scheme of `mask`; see `Limit_evaluator::displace()`.
 */
template <class PolygonMesh, class Mask, class Height, class NamedParameters = parameters::Default_named_parameters>
void displace(PolygonMesh& mesh, const Mask& mask, const Height& height,
              const NamedParameters& np = parameters::default_values())
{
  Limit_evaluator<Mask>(mask).displace(mesh, height, np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_PROJECT_TO_LIMIT_H
