// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv surface --limit and --displace: limit positions, limit normals
// and displacement along them (CGAL/Subdiv/limit.h).
#ifndef CGAL_SUBDIV_CLI_SURFACE_LIMIT_H
#define CGAL_SUBDIV_CLI_SURFACE_LIMIT_H

#include "surface.h"

#include <string>
#include <vector>

namespace cgal_subdiv {

/*
 * reads the heights file of --displace: one height per vertex of INPUT, in
 * the order of INPUT's vertices, one per line (a decimal or a fraction, as
 * the curve command reads coordinates: 0.25, -1e-3, 1/3); blank lines and
 * lines starting with # are skipped.
 * \throws Input_error naming the file and the line of a value that is not a
 *         number, or the counts when there are not `vertices` heights
 */
std::vector<double> read_heights(const std::string& path, std::size_t vertices);

/*
 * moves every vertex of `mesh` to its limit position under `scheme`; with
 * `tags`, under the boundary mode and triangle rule of `tags`, and with the
 * sharpness maps of `mesh` (as the refinement left them): a corner stays, a
 * crease goes to the limit of its curve (`CGAL::Subdiv::project_to_limit()`).
 * Tags only for a scheme that takes them (`scheme.run_sharp`): the refinement
 * before refuses the others.
 * \throws CGAL::Subdiv::Bad_input when the analysis does not cover a vertex
 */
void project_surface_to_limit(Surface& mesh, const Surface_scheme& scheme, const Sharp_options* tags = nullptr);

/*
 * refines `mesh` `levels` times carrying `heights` (by vertex, in the mesh's
 * order) with the scheme's stencils, then moves every vertex to its limit
 * position plus its limit height along its unit limit normal. With `tags`,
 * the levels refine the sharpness maps of `mesh` with the options of `tags`,
 * and the limit takes those of the refined mesh.
 * \throws Input_error when there are tags and the scheme does not take them
 */
Surface_result displace_surface(Surface& mesh, const Surface_scheme& scheme, int levels, double max_memory,
                                const std::vector<double>& heights, const Sharp_options* tags = nullptr);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_LIMIT_H
