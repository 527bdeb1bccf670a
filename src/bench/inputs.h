// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the inputs, made in code (each from its own fixed seed, so that
// a child process can remake any one of them alone) or read from files.
#ifndef SUBDIV_BENCH_INPUTS_H
#define SUBDIV_BENCH_INPUTS_H

#include "bench.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

namespace subdiv_bench {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

struct Input
{
  std::string id;   // short name, for the command line of child processes
  std::string name; // what the tables show
  Mesh mesh;
  Soup soup; // the same mesh as arrays (vertex and face order of `mesh`)
  bool triangles = false;
  bool border = false;
  double diagonal = 1;   // of the bounding box, for relative differences
  bool creased = false;  // `mesh` has the map `crease_map_name`, `soup` its creases
  bool textured = false; // `mesh` has the maps `uv_map_name`, `uv_index_map_name`, `soup` its uvs
};

/// the edge sharpness map of the creased inputs (OpenSubdiv's semantics)
constexpr const char* crease_map_name = "e:sharpness";
/// the per-corner texture coordinates of the textured inputs (`Kernel::Point_2`)
/// and their value indices (`std::size_t`): halfedge maps, the value of face(h) at target(h)
constexpr const char* uv_map_name = "h:uv";
constexpr const char* uv_index_map_name = "h:uv_index";

/// the ids of the inputs made in code, then of the files, then of the
/// creased inputs, then of the textured ones (an id ending in "-uv": the
/// input of the id before it, with box-projected texture coordinates), in
/// table order
std::vector<std::string> input_ids();

/// makes the input `id` (`quick`: 10x smaller generated inputs); false with
/// `why` set when it cannot (a file missing or unreadable)
bool make_input(const std::string& id, bool quick, const std::string& mesh_dir, Input& input, std::string& why);

Soup soup_of(const Mesh& mesh);

/// the valence range, "3..9"
std::string valence_range(const Mesh& mesh);

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_INPUTS_H
