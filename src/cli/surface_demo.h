// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The surface part of `cgal-subdiv demo`: every available surface scheme on
// the bundled meshes.
#ifndef CGAL_SUBDIV_CLI_SURFACE_DEMO_H
#define CGAL_SUBDIV_CLI_SURFACE_DEMO_H

#include "surface.h"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace cgal_subdiv {

/// a bundled mesh of the demo
struct Demo_mesh
{
  std::string label; // e.g. "torus"
  std::string path;
  bool triangles = false; // all faces triangles: every scheme applies
};

struct Surface_demo_row
{
  std::string name;   // e.g. "surface-loop-torus", also the file name without .off
  std::string scheme; // the keyword
  std::string mesh;   // the label of the input
  int levels = 0;
  Surface_result result;
  std::string failure;
};

/// runs every scheme of surface_schemes() on every mesh it applies to (the
/// triangle schemes on triangle meshes only) and writes DIR/NAME.off
std::vector<Surface_demo_row> run_surface_demo(const std::vector<Demo_mesh>& meshes, const std::filesystem::path& dir);

/// the Markdown section of index.md
void write_surface_index(const std::vector<Surface_demo_row>& rows, const std::vector<Demo_mesh>& meshes,
                         std::ostream& out);
/// the table on stdout
void print_surface_summary(const std::vector<Surface_demo_row>& rows);

/// the scheme keywords that this build does not offer yet, "" if none
std::string unavailable_surface_schemes();

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SURFACE_DEMO_H
