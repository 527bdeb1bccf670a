// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The checked polygon soup of mesh_soup.h made into a Surface_mesh: the one
// way cgal-subdiv (and its fuzzer) builds a mesh from a file.
#ifndef CGAL_SUBDIV_CLI_SURFACE_FROM_SOUP_H
#define CGAL_SUBDIV_CLI_SURFACE_FROM_SOUP_H

#include "common.h"
#include "mesh_soup.h"

#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

namespace cgal_subdiv {

using Surface = CGAL::Surface_mesh<Double_kernel::Point_3>;

/*
 * `soup` (read from `path`, in `format`) as a Surface_mesh: its notes are
 * added to `notes`, the vertices that no face uses are dropped (with a note),
 * and the mesh is built with CGAL::Polygon_mesh_processing once the soup is
 * known to be a manifold polygon mesh. With `repair`, a soup that is not one
 * is repaired and oriented first (repair_polygon_soup, orient_polygon_soup)
 * and a note says so. `file_numbers`, if given, receives the number in the
 * file of every vertex of the mesh (OBJ counts from 1); empty with `repair`,
 * which merges and splits vertices.
 * \throws Input_error: no faces, or not a manifold polygon mesh (naming a
 *         face, an edge or a vertex: by its number in the file and its point)
 */
Surface surface_from_soup(const Mesh_soup& soup, const std::string& path, Mesh_format format, bool repair,
                          std::vector<std::string>& notes, std::vector<std::size_t>* file_numbers = nullptr);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_FROM_SOUP_H
