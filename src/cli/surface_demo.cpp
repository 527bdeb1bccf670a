// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "surface_demo.h"

#include <algorithm>
#include <cstdio>
#include <ostream>

namespace cgal_subdiv {
namespace {

constexpr int surface_demo_levels = 3;

std::string seconds_cell(double s)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", s);
  return buffer;
}

std::string vf(const Mesh_counts& c)
{
  return std::to_string(c.vertices) + " / " + std::to_string(c.faces);
}

} // namespace

std::string unavailable_surface_schemes()
{
  std::string missing;
  for(const std::string& name : surface_scheme_keywords()) {
    const auto& offered = surface_schemes();
    if(std::none_of(offered.begin(), offered.end(), [&](const Surface_scheme& s) { return s.name == name; }))
      missing += (missing.empty() ? "" : ", ") + name;
  }
  return missing;
}

std::vector<Surface_demo_row> run_surface_demo(const std::vector<Demo_mesh>& meshes, const std::filesystem::path& dir)
{
  std::vector<Surface_demo_row> rows;
  for(const Demo_mesh& input : meshes) {
    std::vector<std::string> notes;
    Surface original;
    std::string read_failure;
    try {
      original = read_surface(input.path, Soup_fix::none, notes);
    } catch(const std::exception& e) {
      read_failure = e.what();
    }
    for(const Surface_scheme& scheme : surface_schemes()) {
      if(scheme.triangles_only && !input.triangles)
        continue;
      Surface_demo_row row{"surface-" + scheme.name + "-" + input.label,
                           scheme.name,
                           input.label,
                           surface_demo_levels,
                           Surface_result(),
                           read_failure};
      if(read_failure.empty()) {
        try {
          Surface mesh = original;
          row.result = subdivide_surface(mesh, scheme, row.levels, 0);
          write_surface(mesh, (dir / (row.name + ".off")).string());
        } catch(const std::exception& e) {
          row.failure = e.what();
        }
      }
      rows.push_back(row);
    }
  }
  return rows;
}

void write_surface_index(const std::vector<Surface_demo_row>& rows, const std::vector<Demo_mesh>& meshes,
                         std::ostream& out)
{
  out << "## Surfaces\n\n"
      << "Every surface scheme, " << surface_demo_levels << " levels, on the bundled meshes";
  for(std::size_t i = 0; i < meshes.size(); ++i)
    out << (i == 0 ? " " : ", ") << "`" << meshes[i].path << "` (" << meshes[i].label << ")";
  out << "; the triangle schemes on the triangle mesh only. V / F: vertices / faces; time: the subdivision "
      << "alone, in seconds (`cgal-subdiv surface` does the same from the command line).\n\n";
  const std::string missing = unavailable_surface_schemes();
  if(!missing.empty())
    out << "Not yet available in this build: " << missing << ".\n\n";
  out << "| run | scheme | input | levels | V / F in | V / F out | time (s) | file |\n"
      << "|---|---|---|---:|---:|---:|---:|---|\n";
  for(const Surface_demo_row& r : rows) {
    out << "| " << r.name << " | " << r.scheme << " | " << r.mesh << " | " << r.levels << " | ";
    if(!r.failure.empty()) {
      out << "failed: " << r.failure << " | | | |\n";
      continue;
    }
    out << vf(r.result.in) << " | " << vf(r.result.out) << " | " << seconds_cell(r.result.seconds) << " | [" << r.name
        << ".off](" << r.name << ".off) |\n";
  }
  out << "\n";
}

void print_surface_summary(const std::vector<Surface_demo_row>& rows)
{
  std::printf("%-36s %-20s %-7s %6s %13s %15s %9s\n", "run", "scheme", "input", "levels", "V / F in", "V / F out",
              "time (s)");
  for(const Surface_demo_row& r : rows) {
    if(!r.failure.empty()) {
      std::printf("%-36s %-20s %-7s failed: %s\n", r.name.c_str(), r.scheme.c_str(), r.mesh.c_str(), r.failure.c_str());
      continue;
    }
    std::printf("%-36s %-20s %-7s %6d %13s %15s %9s\n", r.name.c_str(), r.scheme.c_str(), r.mesh.c_str(), r.levels,
                vf(r.result.in).c_str(), vf(r.result.out).c_str(), seconds_cell(r.result.seconds).c_str());
  }
  const std::string missing = unavailable_surface_schemes();
  if(!missing.empty())
    std::printf("not yet available in this build: %s\n", missing.c_str());
}

} // namespace cgal_subdiv
