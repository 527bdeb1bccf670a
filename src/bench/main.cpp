// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: CGAL Subdiv against CGAL's Subdivision_method_3, OpenMesh's
// uniform subdividers and OpenSubdiv's Far, in one process, on the same
// inputs (src/bench/README.md):
//
//   build/src/subdiv-bench [--runs N] [--quick] [--write-doc] [--no-memory] [--meshes DIR]
//
// Sections: full refinement, stencil table build, stencil apply (1 and 2
// threads) against a STREAM-like bandwidth baseline, the limit surface (build,
// evaluation, tessellation, against Bfr), peak memory (each run in
// a child process), agreement of the points, exact kernels. Every time is the
// minimum of N runs (default 3) after a warm-up; input construction, copies
// and file reading are outside the timers. Targets of issue 5 are checked and
// a missed one is marked MISSED.
#include "agreement.h"
#include "bench.h"
#include "inputs.h"
#include "libraries.h"
#include "report.h"
#include "stream.h"

#include <CGAL/version.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifndef SUBDIV_BENCH_MESH_DIR
#define SUBDIV_BENCH_MESH_DIR "../shared/data/meshes"
#endif
#ifndef SUBDIV_BENCH_DOC_DIR
#define SUBDIV_BENCH_DOC_DIR "doc"
#endif

namespace subdiv_bench {
namespace {

const double nan_value = std::nan("");

struct Options
{
  int runs = 3;
  bool quick = false;
  bool write_doc = false;
  bool memory = true;
  Heap heap = Heap::warm;
  std::string mesh_dir = SUBDIV_BENCH_MESH_DIR;
  std::string doc_dir = SUBDIV_BENCH_DOC_DIR;
  std::string command;
};

// everything printed also goes into doc/performance.md
std::string document;
void out(const std::string& text)
{
  std::fputs(text.c_str(), stdout);
  std::fflush(stdout);
  document += text;
}

// --- the libraries ------------------------------------------------------------------

enum Peer { ours, cgal, openmesh, osd, number_of_peers };
const char* peer_names[] = {"ours", "CGAL", "OpenMesh", "OSD Far"};

Job_ptr refinement(Peer peer, const Input& input, Scheme scheme, int levels)
{
  if((input.creased || input.textured) && (peer == cgal || peer == openmesh)) // they have no creases, no UVs
    return nullptr;
  switch(peer) {
    case ours:
      return ours_refinement(input, scheme, levels);
    case cgal:
      return cgal_refinement(input, scheme, levels);
    case openmesh:
      return openmesh_refinement(input.soup, scheme, levels);
    case osd:
      return osd_refinement(input.soup, scheme, levels);
    default:
      return nullptr;
  }
}

bool parse_scheme(const std::string& name, Scheme& scheme)
{
  for(const Scheme s : {Scheme::loop, Scheme::catmull_clark, Scheme::doo_sabin, Scheme::sqrt3})
    if(scheme_name(s) == name) {
      scheme = s;
      return true;
    }
  return false;
}

// --- the inputs -------------------------------------------------------------------

std::map<std::string, Input> inputs;
std::vector<std::string> missing_inputs;

const Input* input(const std::string& id)
{
  const auto it = inputs.find(id);
  return it == inputs.end() ? nullptr : &it->second;
}

// --- what runs --------------------------------------------------------------------

struct Case
{
  Scheme scheme;
  std::string input;
  std::vector<int> levels;
};

// one row of a table: a case of a plan at one number of levels
struct Row_case
{
  const Case& c;
  const Input& in;
  int levels;

  // the first cells of the row: "| scheme | input | levels |"
  std::string cells() const
  {
    return "| " + scheme_name(c.scheme) + " | " + in.name + " | " + std::to_string(levels) + " |";
  }
  // the case in the words of the list of missed targets
  std::string where() const
  {
    return scheme_name(c.scheme) + ", " + in.name + ", " + std::to_string(levels) + " levels";
  }
};

// calls `row(Row_case)` for every number of levels of every case of `plan`
// whose input this run has
template <class Row>
void for_each_row(const std::vector<Case>& plan, const Row& row)
{
  for(const Case& c : plan) {
    const Input* in = input(c.input);
    if(in != nullptr)
      for(const int levels : c.levels)
        row(Row_case{c, *in, levels});
  }
}

// "Seconds, minimum of N runs", the first words of a timing table's text
std::string minimum_of_runs(int runs)
{
  return "Seconds, minimum of " + std::to_string(runs) + " runs";
}

const std::vector<Case> refinement_plan = {
  {Scheme::loop, "tri20k", {1, 2, 3}},        {Scheme::loop, "tri200k", {1, 2}},
  {Scheme::loop, "border", {1, 2}},           {Scheme::loop, "fandisk", {1, 2, 3}},
  {Scheme::loop, "mushroom", {2, 3}},         {Scheme::catmull_clark, "tri20k", {1, 2, 3}},
  {Scheme::catmull_clark, "tri200k", {1, 2}}, {Scheme::catmull_clark, "quad200k", {1, 2}},
  {Scheme::catmull_clark, "mixed", {1, 2}},   {Scheme::catmull_clark, "border", {1, 2}},
  {Scheme::catmull_clark, "fandisk", {1, 2}}, {Scheme::catmull_clark, "mushroom", {2, 3}},
  {Scheme::catmull_clark, "spot", {3, 4, 5}}, {Scheme::doo_sabin, "tri20k", {1, 2, 3}},
  {Scheme::doo_sabin, "quad200k", {1, 2}},    {Scheme::sqrt3, "tri20k", {1, 2, 3}},
};

const std::vector<Case> stencil_plan = {
  {Scheme::loop, "tri20k", {1, 3}},
  {Scheme::loop, "tri200k", {1, 2}},
  {Scheme::loop, "border", {2}},
  {Scheme::loop, "fandisk", {3}},
  {Scheme::catmull_clark, "tri20k", {1, 3}},
  {Scheme::catmull_clark, "quad200k", {1, 2}},
  {Scheme::catmull_clark, "mixed", {2}},
  {Scheme::catmull_clark, "spot", {5}},
};

const std::vector<Case> apply_plan = {
  {Scheme::loop, "tri20k", {3}},
  {Scheme::loop, "tri200k", {2}},
  {Scheme::loop, "fandisk", {3}},
  {Scheme::catmull_clark, "tri20k", {3}},
  {Scheme::catmull_clark, "quad200k", {2}},
  {Scheme::catmull_clark, "mixed", {2}},
};

const std::vector<Case> memory_plan = {
  {Scheme::loop, "tri20k", {3}},
  {Scheme::loop, "tri200k", {2}},
  {Scheme::catmull_clark, "quad200k", {2}},
  {Scheme::catmull_clark, "mixed", {2}},
};

// --- targets ----------------------------------------------------------------------

std::vector<std::string> missed, met;

std::string check(bool ok, const std::string& what, const std::string& detail)
{
  (ok ? met : missed).push_back(what + ": " + detail);
  return ok ? "met" : "**MISSED**";
}

// --- full refinement --------------------------------------------------------------

std::vector<Chart_group> chart;

struct Agreement_row
{
  std::string scheme, input;
  int levels;
  std::string versus[number_of_peers];
  bool flagged = false;
  std::string same_with_two_threads = "-";
};
std::vector<Agreement_row> agreements;

// what a peer's differing rule is, where it is known to differ from ours
std::string known_difference(Peer peer, Scheme scheme, const Input& in)
{
  if(peer == openmesh && scheme == Scheme::catmull_clark && in.border)
    return "OpenMesh's border vertex rule is 2/3, 1/6, 1/6, not 6/8, 1/8, 1/8";
  return "";
}

// the input's name without its valence range, directory and file extension (for the chart)
std::string short_name(const Input& in)
{
  std::string name = in.name.substr(0, in.name.find(" (valence"));
  if(name.find('/') != std::string::npos)
    name = name.substr(name.rfind('/') + 1);
  for(const char* extension : {".off", ".obj"}) {
    const std::size_t at = name.find(extension);
    if(at != std::string::npos)
      name.erase(at, 4);
  }
  return name;
}

// every library's refinement of one case, with ours on two threads (when
// there) and the Surface_mesh resize floor, timed together (interleaved)
struct Refinement_times
{
  Job_ptr jobs[number_of_peers];
  Job_ptr ours2, floor;
  std::vector<double> t; // one per peer, then ours 2T, then the floor
  double two() const { return t[number_of_peers]; }
  double resize() const { return t[number_of_peers + 1]; }
  /// " a | b | ... |": the time of every peer but ours, then of the floor; "-" where missing
  std::string peer_and_floor_cells() const
  {
    std::string cells;
    for(int p = 1; p < number_of_peers; ++p)
      cells += " " + (jobs[p] ? seconds(t[static_cast<std::size_t>(p)]) : std::string("-")) + " |";
    return cells + " " + (floor ? seconds(resize()) : std::string("-")) + " |";
  }
};

Refinement_times time_refinement(const Input& in, Scheme scheme, int levels, int runs)
{
  Refinement_times r;
  std::vector<Job*> list;
  for(int p = 0; p < number_of_peers; ++p) {
    r.jobs[p] = refinement(static_cast<Peer>(p), in, scheme, levels);
    list.push_back(r.jobs[p].get());
  }
  r.ours2 = ours_has_threads() && ours_with_tbb() ? ours_refinement(in, scheme, levels, 2) : nullptr;
  r.floor = surface_mesh_resize_floor(in, scheme, levels);
  list.push_back(r.ours2.get());
  list.push_back(r.floor.get());
  r.t = time_jobs(list, runs);
  return r;
}

void refinement_section(const Options& options)
{
  const bool two = ours_has_threads() && ours_with_tbb();
  out("\n## Full refinement (topology + positions)\n\n" + minimum_of_runs(options.runs) +
      " after a warm-up, one thread unless said. Ours and CGAL: `loop_subdivision` / "
      "`catmull_clark_subdivision` / ... and `Subdivision_method_3` on a copy of the input `Surface_mesh`, "
      "refined in place; `ours 2T`: ours with `CGAL::Subdiv::parameters::threads(2)`. OpenMesh: "
      "`Subdivider::Uniform::LoopT` / `CatmullClarkT` on its own mesh (double points). OSD Far: "
      "`TopologyRefinerFactory<TopologyDescriptor>::Create` + `RefineUniform` + "
      "`PrimvarRefinerReal<double>::Interpolate` level by level into arrays: topology and positions, but no "
      "halfedge mesh at the end (the others end with one); it has no multi-threaded refinement. `ours/best` = "
      "our one-thread time / the fastest other library's; `OSD/ours` = how many times faster than OpenSubdiv we "
      "are. Targets: OSD/ours at least 2 with one thread, at least 3 with two.\n\n"
      "`SM resize`: the `Surface_mesh::reserve`/`resize` calls alone that a refinement of the mesh in place must "
      "make (Loop, Catmull-Clark), on the same copy: `std::vector` value-initialises every new element, and "
      "`add_vertex`/`add_edge`/`add_face` do too, so no refinement into a `Surface_mesh` through its public API "
      "can take less. Where the 2x target is missed and `SM resize` alone is more than half of OSD's time, the "
      "cell says `(floor)`: the target is out of reach for a `Surface_mesh` output (doc/profile.md: with g++ 12 "
      "this fill runs at about 3 GB/s).\n\n"
      "| scheme | input | levels | output faces | ours | ours 2T | CGAL | OpenMesh | OSD Far | SM resize | "
      "ours/best | OSD/ours | OSD/ours 2T | target 2x OSD | target 3x OSD (2T) |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n");
  for_each_row(refinement_plan, [&](const Row_case& rc) {
    const Case& c = rc.c;
    const Input* in = &rc.in;
    const int levels = rc.levels;
    const Refinement_times r = time_refinement(*in, c.scheme, levels, options.runs);
    const auto& jobs = r.jobs;
    const Job_ptr &ours2 = r.ours2, &floor = r.floor;
    const std::vector<double>& t = r.t;
    const double t2 = r.two(), t_floor = r.resize();
    double best = 1e300;
    for(int p = 1; p < number_of_peers; ++p)
      if(jobs[p])
        best = std::min(best, t[static_cast<std::size_t>(p)]);
    const std::string where = rc.where();
    std::string row = rc.cells() + " " + std::to_string(jobs[ours]->output_faces()) + " | " + seconds(t[ours]) + " | " +
                      (ours2 ? seconds(t2) : "-") + " |";
    row += r.peer_and_floor_cells() + " " + fixed(t[ours] / best) + " |";
    if(jobs[osd]) {
      const double speedup = t[osd] / t[ours], speedup2 = ours2 ? t[osd] / t2 : nan_value;
      const bool out_of_reach = floor && t_floor > t[osd] / 2;
      const std::string reach = out_of_reach ? " (floor)" : "";
      const std::string note = out_of_reach ? ", SM resize alone " + seconds(t_floor) + " s" : "";
      row += " " + fixed(speedup) + " | " + fixed(speedup2) + " | " +
             check(speedup >= 2, "full refinement >= 2x OSD, " + where, fixed(speedup) + "x" + note) + reach + " | " +
             (ours2 ? check(speedup2 >= 3, "full refinement >= 3x OSD with 2 threads, " + where, fixed(speedup2) + "x")
                    : std::string("**MISSED** (no 2T path)")) +
             " |";
    } else {
      row += " - | - | | |";
    }
    // the face counts must agree
    for(int p = 1; p < number_of_peers; ++p)
      if(jobs[p] && jobs[p]->output_faces() != jobs[ours]->output_faces())
        row += " (" + std::string(peer_names[p]) + ": " + std::to_string(jobs[p]->output_faces()) + " faces)";
    if(ours2 && ours2->output_faces() != jobs[ours]->output_faces())
      row += " (ours 2T: " + std::to_string(ours2->output_faces()) + " faces)";
    out(row + "\n");
    if(levels == c.levels.back()) {
      if(c.scheme == Scheme::loop || c.scheme == Scheme::catmull_clark) {
        Chart_group group{scheme_name(c.scheme) + ", " + short_name(*in) + ", " + std::to_string(levels) + " lv", {}};
        const double faces = static_cast<double>(jobs[ours]->output_faces());
        for(int p = 0; p < number_of_peers; ++p)
          group.values.push_back(jobs[p] ? faces / t[static_cast<std::size_t>(p)] / 1e6 : nan_value);
        if(two)
          group.values.push_back(ours2 ? faces / t2 / 1e6 : nan_value);
        chart.push_back(group);
      }
      // agreement of the points, at the last level of each case
      Agreement_row a{scheme_name(c.scheme), in->name, levels, {}, false};
      const std::vector<P3> mine = jobs[ours]->output_points();
      for(int p = 1; p < number_of_peers; ++p) {
        if(!jobs[p]) {
          a.versus[p] = "-";
          continue;
        }
        const std::vector<P3> theirs = jobs[p]->output_points();
        const Agreement agreement = compare_points(mine, theirs, in->diagonal);
        a.versus[p] = describe(agreement, mine.size(), theirs.size());
        const bool bad = !agreement.same_count || agreement.unmatched > 0 || agreement.max_relative > 1e-12;
        const std::string expected = known_difference(static_cast<Peer>(p), c.scheme, *in);
        if(bad && !expected.empty()) {
          a.versus[p] += " (expected: " + expected + ")";
        } else if(bad) {
          a.versus[p] = "**" + a.versus[p] + " DIFFER**";
          a.flagged = true;
        }
      }
      if(ours2) { // the same points with two threads, bit for bit
        const std::vector<P3> mine2 = ours2->output_points();
        a.same_with_two_threads = mine2 == mine ? "yes" : "**NO**";
        a.flagged = a.flagged || mine2 != mine;
      }
      agreements.push_back(a);
    }
  });
  if(!two) {
    out(
      "\nTarget \"at least 3x faster than OSD Far with 2 threads\": **MISSED** on every row: this build of CGAL "
      "Subdiv has no multi-threaded refinement (" +
      std::string(ours_has_threads() ? "compiled without TBB" : "no `threads` named parameter") + ").\n");
    missed.push_back("full refinement >= 3x OSD with 2 threads: no 2-thread path in this build of CGAL Subdiv");
  }
}

// --- with creases (issue 11) ------------------------------------------------------

const std::vector<Case> crease_plan = {
  {Scheme::loop, "fandisk-creased", {1, 2, 3}},
  {Scheme::catmull_clark, "fandisk-creased", {1, 2}},
  {Scheme::catmull_clark, "rook-creased", {1, 2}},
};

void creased_refinement_section(const Options& options)
{
  out("\n## Refinement with creases\n\n" + minimum_of_runs(options.runs) +
      " after a warm-up. Ours: `loop_subdivision` / `catmull_clark_subdivision` with "
      "`edge_sharpness_map` on a copy of the input `Surface_mesh` (the map refines with the mesh: the children's "
      "sharpness is written back); OSD Far as above, with the same creases as `TopologyDescriptor` crease "
      "pairs and weights. CGAL and OpenMesh have no creases. `fandisk-creased`: infinitely sharp creases from "
      "`mark_sharp_edges` (30 degrees); `rook-creased`: semi-sharp creases of OpenSubdiv's own shape, refined "
      "first. `points`: the largest distance to OSD's nearest point over the bounding-box diagonal. Target "
      "(issue 11): at least as fast as OSD Far.\n\n"
      "| scheme | input | levels | output faces | creases | ours | ours 2T | OSD Far | OSD/ours | OSD/ours 2T | "
      "points vs OSD | target 1x OSD |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n");
  for_each_row(crease_plan, [&](const Row_case& rc) {
    const Refinement_times r = time_refinement(rc.in, rc.c.scheme, rc.levels, options.runs);
    const Job_ptr& mine = r.jobs[ours];
    const Job_ptr& theirs = r.jobs[osd];
    std::string row = rc.cells() + " " + std::to_string(mine->output_faces()) + " | " +
                      std::to_string(rc.in.soup.crease_sharpness.size()) + " | " + seconds(r.t[ours]) + " | " +
                      (r.ours2 ? seconds(r.two()) : "-") + " | ";
    if(!theirs) {
      out(row + "- | - | - | - | |\n");
      return;
    }
    const double speedup = r.t[osd] / r.t[ours], speedup2 = r.ours2 ? r.t[osd] / r.two() : nan_value;
    const std::vector<P3> ours_points = mine->output_points(), osd_points = theirs->output_points();
    const Agreement agreement = compare_points(ours_points, osd_points, rc.in.diagonal);
    std::string points = describe(agreement, ours_points.size(), osd_points.size());
    if(!agreement.same_count || agreement.unmatched > 0 || agreement.max_relative > 1e-12)
      points = "**" + points + " DIFFER**";
    if(r.ours2 && r.ours2->output_points() != ours_points) // two threads: the same bits
      points += " **(ours 2T differs from ours 1T)**";
    row += seconds(r.t[osd]) + " | " + fixed(speedup) + " | " + fixed(speedup2) + " | " + points + " | " +
           check(speedup >= 1, "creased refinement >= 1x OSD, " + rc.where(), fixed(speedup) + "x") + " |";
    out(row + "\n");
  });
}

// --- with UVs (face-varying data, issue 12) ----------------------------------------

const std::vector<Case> uv_plan = {
  {Scheme::loop, "tri200k-uv", {1, 2}},
  {Scheme::catmull_clark, "quad200k-uv", {1, 2}},
};

void uv_refinement_section(const Options& options)
{
  out("\n## Refinement with UVs (face-varying data)\n\n" + minimum_of_runs(options.runs) +
      " after a warm-up, one thread. Each input with box-projected UVs: every face in the chart of the "
      "dominant axis of its normal, so an edge between charts is a seam (a vertex has one UV value per chart "
      "around it). Ours: `loop_subdivision` / `catmull_clark_subdivision` with a `Carried_data` "
      "`corner_map(uv, corners_plus1, uv_index)` on a copy of the input `Surface_mesh`; OSD Far as above, with "
      "the UVs as a face-varying channel in `FVAR_LINEAR_CORNERS_PLUS1`, "
      "`PrimvarRefinerReal<double>::InterpolateFaceVarying` after `Interpolate` at every level. The same "
      "input without UVs is timed in the same run: `UV cost` is the time with UVs minus the time without. "
      "Targets (issue 12): ours with UVs at least as fast as OSD with UVs, and our UV cost no more than "
      "OSD's.\n\n"
      "| scheme | input | levels | output faces | ours | ours, UVs | OSD Far | OSD Far, UVs | OSD/ours, UVs | "
      "UV cost ours | UV cost OSD | targets |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for_each_row(uv_plan, [&](const Row_case& rc) {
    const Input* plain = input(rc.c.input.substr(0, rc.c.input.size() - 3)); // without "-uv"
    if(plain == nullptr)
      return;
    const Scheme scheme = rc.c.scheme;
    Job_ptr jobs[4] = {ours_refinement(*plain, scheme, rc.levels), ours_refinement(rc.in, scheme, rc.levels),
                       osd_refinement(plain->soup, scheme, rc.levels), osd_refinement(rc.in.soup, scheme, rc.levels)};
    const std::vector<double> t = time_jobs({jobs[0].get(), jobs[1].get(), jobs[2].get(), jobs[3].get()}, options.runs);
    std::string row = rc.cells() + " " + std::to_string(jobs[1]->output_faces()) + " | " + seconds(t[0]) + " | " +
                      seconds(t[1]) + " | ";
    if(!jobs[3]) {
      out(row + "- | - | - | " + seconds(t[1] - t[0]) + " | - | |\n");
      return;
    }
    const double speedup = t[3] / t[1], cost_ours = t[1] - t[0], cost_osd = t[3] - t[2];
    row +=
      seconds(t[2]) + " | " + seconds(t[3]) + " | " + fixed(speedup) + " | " + seconds(cost_ours) + " | " +
      seconds(cost_osd) + " | " +
      check(speedup >= 1, "refinement with UVs >= 1x OSD, " + rc.where(), fixed(speedup) + "x") + " " +
      check(cost_ours <= cost_osd, "UV cost <= OSD's, " + rc.where(), seconds(cost_ours) + " vs " + seconds(cost_osd)) +
      " |";
    out(row + "\n");
  });
}

// --- the same refinements, each run in fresh memory -----------------------------

const std::vector<Case> fresh_plan = {
  {Scheme::loop, "tri20k", {3}},          {Scheme::loop, "tri200k", {2}},
  {Scheme::catmull_clark, "tri20k", {3}}, {Scheme::catmull_clark, "quad200k", {2}},
  {Scheme::catmull_clark, "mixed", {2}},
};

void fresh_memory_section(const Options& options)
{
  set_heap(Heap::fresh);
  out(
    "\n## Full refinement in fresh memory\n\n"
    "The largest cases of the next table, run first, with glibc set so that every block of 128 KiB or more is a new "
    "`mmap`, unmapped "
    "when freed: each run pays the page faults and the zeroing of all the memory it writes, as a program that "
    "refines once does (the next table keeps the heap warm, the steady state of a program that refines again "
    "and again, which is what a minimum after a warm-up measures). For information; the targets are checked "
    "in the next table.\n\n"
    "| scheme | input | levels | ours | ours 2T | CGAL | OpenMesh | OSD Far | SM resize | OSD/ours | OSD/ours 2T "
    "|\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for_each_row(fresh_plan, [&](const Row_case& rc) {
    const Refinement_times r = time_refinement(rc.in, rc.c.scheme, rc.levels, options.runs);
    const std::vector<double>& t = r.t;
    std::string row = rc.cells() + " " + seconds(t[ours]) + " | " + (r.ours2 ? seconds(r.two()) : "-") + " |" +
                      r.peer_and_floor_cells() + " " + (r.jobs[osd] ? fixed(t[osd] / t[ours]) : std::string("-")) +
                      " | " + (r.jobs[osd] && r.ours2 ? fixed(t[osd] / r.two()) : std::string("-")) + " |";
    out(row + "\n");
  });
  set_heap(options.heap);
}

// --- stencil tables ---------------------------------------------------------------

void stencil_build_section(const Options& options)
{
  out("\n## Stencil table build\n\n" + minimum_of_runs(options.runs) +
      ". Ours: `make_stencil_table(mesh, mask, parameters::number_of_iterations(levels))` (the refined topology and "
      "one composed table from "
      "the coarse points to the finest ones, input check included). OSD: `StencilTableFactoryReal<double>::Create` "
      "on a uniformly refined `TopologyRefiner` (generateIntermediateLevels = false, "
      "factorizeIntermediateLevels = true, generateOffsets = true), timed with the refiner's creation and "
      "`RefineUniform` (`OSD r+f`, like for like with ours) and alone (`OSD factory`, the refiner made outside "
      "the timer). `ours 2T`: ours with `threads(2)`, for information (OpenSubdiv's factory has one thread). "
      "Target: ours (one thread) at least 5x faster than the factory.\n\n"
      "| scheme | input | levels | ours | ours 2T | OSD r+f | OSD factory | OSD r+f / ours | OSD factory / ours | "
      "target 5x (r+f) | target 5x (factory alone) |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|\n");
  for_each_row(stencil_plan, [&](const Row_case& rc) {
    const Scheme scheme = rc.c.scheme;
    const int levels = rc.levels;
    Job_ptr mine = ours_stencil_build(rc.in, scheme, levels, 1);
    Job_ptr both = osd_stencil_build(rc.in.soup, scheme, levels, false);
    Job_ptr factory = osd_stencil_build(rc.in.soup, scheme, levels, true);
    Job_ptr mine2 = ours_has_threads() && ours_with_tbb() ? ours_stencil_build(rc.in, scheme, levels, 2) : nullptr;
    const std::vector<double> t = time_jobs({mine.get(), both.get(), factory.get(), mine2.get()}, options.runs);
    std::string row = rc.cells() + " " + seconds(t[0]) + " | " + (mine2 ? seconds(t[3]) : "-") + " | " +
                      (both ? seconds(t[1]) : "-") + " | " + (factory ? seconds(t[2]) : "-") + " |";
    if(both && factory) {
      const std::string where = rc.where();
      row +=
        " " + fixed(t[1] / t[0]) + " | " + fixed(t[2] / t[0]) + " | " +
        check(t[1] / t[0] >= 5, "stencil build >= 5x OSD refine+factory, " + where, fixed(t[1] / t[0]) + "x") + " | " +
        check(t[2] / t[0] >= 5, "stencil build >= 5x OSD factory alone, " + where, fixed(t[2] / t[0]) + "x") + " |";
    } else {
      row += " - | - | | |";
    }
    out(row + "\n");
  });
}

// the same Apply_job with a given number of threads
class With_threads : public Job
{
public:
  With_threads(Apply_job* job, int threads) : m_job(job), m_threads(threads) {}
  void prepare() override { m_job->prepare(); }
  void run() override
  {
    m_job->set_threads(m_threads);
    m_job->run();
  }

private:
  Apply_job* m_job;
  int m_threads;
};

void apply_section(const Options& options)
{
  const std::size_t elements = options.quick ? (std::size_t(1) << 22) : (std::size_t(1) << 24);
  const Bandwidth one = measure_bandwidth(1, elements, std::max(5, options.runs));
  const Bandwidth two = measure_bandwidth(2, elements, std::max(5, options.runs));
  const std::size_t cache = last_level_cache_bytes();
  out(
    "\n## Memory bandwidth (STREAM-like, same run)\n\n"
    "Three arrays of " +
    std::to_string(elements) + " doubles (" + std::to_string(elements * 8 >> 20) + " MiB each; last-level cache " +
    std::to_string(cache >> 20) + " MiB), best of " + std::to_string(std::max(5, options.runs)) +
    " passes, threads on contiguous halves; bytes as STREAM counts them (copy 16 B, triad 24 B per element).\n\n"
    "| threads | copy GB/s | triad GB/s |\n|---:|---:|---:|\n| 1 | " +
    fixed(one.copy, 1) + " | " + fixed(one.triad, 1) + " |\n| 2 | " + fixed(two.copy, 1) + " | " + fixed(two.triad, 1) +
    " |\n");

  out(
    "\n## Stencil apply\n\n"
    "Seconds to evaluate every stencil once (coarse points in, finest points out), minimum of " +
    std::to_string(options.runs) +
    " runs. Ours: `Stencil_table<double>::apply` on `std::vector<Point_3>` (1 thread) and `apply_range` on two "
    "halves in two `std::thread`s (2 threads). OSD: `StencilTableReal<double>::UpdateValues`, one thread and "
    "two `std::thread`s on two halves (its `start`, `end` arguments). `OSD omp float`: "
    "`Osd::OmpEvaluator::EvalStencils`, 2 OpenMP threads, on a float table (the only multi-threaded CPU "
    "evaluator of Debian's libosdCPU; floats, so half the bytes; for reference, no target). "
    "`MB`: the bytes one apply must move in our model: per term 8 B weight + 4 B index, per stencil 8 B (where "
    "it ends) + 24 B written, per source point 24 B read once (repeated source reads and the write-allocate "
    "read are not counted). `%BW` = MB / time / triad bandwidth of the same thread count. Targets: ours at most "
    "OSD's time (1 and 2 threads), and 70 % of the 2-thread bandwidth where the output (24 B per stencil) is "
    "larger than the last-level cache.\n\n"
    "| scheme | input | levels | stencils | terms | MB | ours 1T | OSD 1T | ours 2T | OSD 2T | OSD omp float 2T "
    "| ours %BW 1T | ours %BW 2T | OSD %BW 2T | target 1T | target 2T | target 70% BW | ours vs OSD points "
    "|\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|---|\n");
  for_each_row(apply_plan, [&](const Row_case& rc) {
    Apply_ptr mine = ours_apply(rc.in, rc.c.scheme, rc.levels);
    Apply_ptr theirs = osd_apply(rc.in.soup, rc.c.scheme, rc.levels);
    Apply_ptr omp = osd_apply_omp_float(rc.in.soup, rc.c.scheme, rc.levels);
    With_threads mine1(mine.get(), 1), mine2(mine.get(), 2);
    std::unique_ptr<With_threads> theirs1, theirs2, omp2;
    if(theirs) {
      theirs1 = std::make_unique<With_threads>(theirs.get(), 1);
      theirs2 = std::make_unique<With_threads>(theirs.get(), 2);
    }
    if(omp)
      omp2 = std::make_unique<With_threads>(omp.get(), 2);
    const std::vector<double> t =
      time_jobs({&mine1, theirs1.get(), &mine2, theirs2.get(), omp2.get()}, std::max(options.runs, 5));
    const double mb = mine->bytes() / 1e6;
    const double ours_bw1 = mine->bytes() / t[0] / 1e9 / one.triad, ours_bw2 = mine->bytes() / t[2] / 1e9 / two.triad;
    const std::string where = rc.where();
    std::string row =
      rc.cells() + " " + std::to_string(mine->stencils()) + " | " + std::to_string(mine->terms()) +
      (theirs && theirs->terms() != mine->terms() ? " (OSD " + std::to_string(theirs->terms()) + ")" : "") + " | " +
      fixed(mb, 0) + " | " + seconds(t[0]) + " | " + (theirs ? seconds(t[1]) : "-") + " | " + seconds(t[2]) + " | " +
      (theirs ? seconds(t[3]) : "-") + " | " + (omp ? seconds(t[4]) : "-") + " | " + fixed(100 * ours_bw1, 0) + " | " +
      fixed(100 * ours_bw2, 0) + " | " + (theirs ? fixed(100 * theirs->bytes() / t[3] / 1e9 / two.triad, 0) : "-") +
      " |";
    if(theirs) {
      row += " " + check(t[0] <= t[1], "stencil apply 1 thread <= OSD, " + where, fixed(t[0] / t[1]) + "x OSD's time");
      row += " (" + fixed(t[0] / t[1]) + "x) | " +
             check(t[2] <= t[3], "stencil apply 2 threads <= OSD, " + where, fixed(t[2] / t[3]) + "x OSD's time") +
             " (" + fixed(t[2] / t[3]) + "x) |";
    } else {
      row += " | |";
    }
    if(24.0 * static_cast<double>(mine->stencils()) > static_cast<double>(cache))
      row += " " +
             check(ours_bw2 >= 0.7, "stencil apply >= 70% of bandwidth on 2 threads, " + where,
                   fixed(100 * ours_bw2, 0) + "%") +
             " |";
    else
      row += " (fits in cache) |";
    if(theirs) {
      mine->prepare();
      mine->set_threads(1);
      mine->run();
      const std::vector<P3> a = mine->output_points(), b = theirs->output_points();
      const Agreement agreement = compare_points(a, b, rc.in.diagonal);
      const bool bad = !agreement.same_count || agreement.unmatched > 0 || agreement.max_relative > 1e-12;
      row += " " + std::string(bad ? "**" : "") + describe(agreement, a.size(), b.size()) +
             std::string(bad ? " DIFFER**" : "") + " |";
    } else {
      row += " - |";
    }
    out(row + "\n");
  });
}

// --- the limit surface (issue 13) -------------------------------------------------

// the evaluation rows (the levels unused) and the tessellation rows (the
// levels: the rate); the mixed torus is evaluated, not tessellated: ours
// refines locally around each of its n-gons and extraordinary vertices, about
// a minute per tessellation at rate 4
const std::vector<Case> limit_plan = {
  {Scheme::catmull_clark, "mixed", {0}},
  {Scheme::catmull_clark, "quad200k", {0}},
  {Scheme::loop, "tri20k", {0}},
  {Scheme::loop, "fandisk", {0}},
};
const std::vector<Case> tessellation_plan = {
  {Scheme::catmull_clark, "quad200k", {4}},
  {Scheme::catmull_clark, "spot", {4}},
  {Scheme::loop, "tri20k", {4}},
  {Scheme::loop, "fandisk", {4}},
};

std::size_t limit_location_count(const Options& options)
{
  return options.quick ? 2000 : 20000;
}

// whether Limit_surface takes the input: Loop on closed triangle meshes only
bool limit_fits(const Input& in, Scheme scheme)
{
  return scheme == Scheme::catmull_clark || (scheme == Scheme::loop && in.triangles && !in.border);
}

// `count` random locations (fixed seed) in the quads (Catmull-Clark) or the
// triangles (Loop) of the input, u and v uniform (reflected into u + v <= 1 in
// a triangle), less those where ours refuses to evaluate (a defect of the
// library, reported): how many in `refused`, the first message in `refusal`
std::vector<Limit_location> limit_locations(const Input& in, Scheme scheme, std::size_t count, std::size_t& refused,
                                            std::string& refusal)
{
  const int size = scheme == Scheme::loop ? 3 : 4;
  std::vector<int> domains;
  for(std::size_t f = 0; f < in.soup.face_sizes.size(); ++f)
    if(in.soup.face_sizes[f] == size)
      domains.push_back(static_cast<int>(f));
  std::vector<Limit_location> locations;
  refused = 0;
  if(domains.empty())
    return locations;
  std::mt19937 random(20261207u);
  std::uniform_int_distribution<std::size_t> pick(0, domains.size() - 1);
  std::uniform_real_distribution<double> unit(0, 1);
  for(std::size_t i = 0; i < count; ++i) {
    const int face = domains[pick(random)];
    double u = unit(random), v = unit(random);
    if(size == 3 && u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    locations.push_back({face, u, v});
  }
  std::vector<bool> refuses;
  refusal = ours_limit_refusals(in, scheme, locations, refuses);
  std::size_t kept = 0;
  for(std::size_t i = 0; i < locations.size(); ++i)
    if(!refuses[i])
      locations[kept++] = locations[i];
  refused = locations.size() - kept;
  locations.resize(kept);
  return locations;
}

// whether the face is a regular patch: its corners inner, of valence 4 with
// quads only around them (Catmull-Clark) or of valence 6 (Loop); both
// libraries evaluate it as a B-spline or box-spline patch, exactly
bool regular_patch(const Mesh& mesh, Mesh::Face_index f, Scheme scheme)
{
  const unsigned valence = scheme == Scheme::loop ? 6 : 4, size = scheme == Scheme::loop ? 3 : 4;
  for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
    if(mesh.is_border(mesh.target(h)) || mesh.degree(mesh.target(h)) != valence)
      return false;
    for(const Mesh::Halfedge_index g : CGAL::halfedges_around_target(h, mesh))
      if(mesh.degree(mesh.face(g)) != size)
        return false;
  }
  return true;
}

double distance(const P3& a, const P3& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// "scheme, input" of a row of the limit section
std::string limit_where(const Row_case& rc)
{
  return scheme_name(rc.c.scheme) + ", " + rc.in.name;
}

void limit_evaluation_rows(const Options& options)
{
  const std::size_t count = limit_location_count(options);
  std::string refusals;
  for_each_row(limit_plan, [&](const Row_case& rc) {
    const Scheme scheme = rc.c.scheme;
    const Input& in = rc.in;
    if(!limit_fits(in, scheme))
      return;
    std::size_t refused = 0;
    std::string refusal;
    const std::vector<Limit_location> locations = limit_locations(in, scheme, count, refused, refusal);
    const std::string where = limit_where(rc);
    if(refused > 0) {
      refusals += "- " + where + ": ours refuses " + std::to_string(refused) + " of " + std::to_string(count) +
                  " locations (`Bad_input`: \"" + refusal + "\"); they are left out of the row, for both.\n";
      missed.push_back("limit evaluation everywhere, " + where + ": refuses " + std::to_string(refused) + " of " +
                       std::to_string(count) + " locations (" + refusal + ")");
    }
    if(locations.empty())
      return;
    Job_ptr build[2] = {ours_limit_build(in, scheme), osd_limit_build(in.soup, scheme)};
    // ours kept, Bfr per location, Bfr per face, ours from the mesh every time (P, Du, Dv, as Bfr), and
    // ours from the mesh with the second derivatives too
    Job_ptr eval[5] = {
      ours_limit_evaluation(in, scheme, locations, true), osd_limit_evaluation(in.soup, scheme, locations, false),
      osd_limit_evaluation(in.soup, scheme, locations, true), ours_limit_evaluation(in, scheme, locations, false),
      ours_limit_evaluation(in, scheme, locations, false, true)};
    const std::vector<double> tb = time_jobs({build[0].get(), build[1].get()}, options.runs);
    const std::vector<double> te =
      time_jobs({eval[0].get(), eval[1].get(), eval[2].get(), eval[3].get(), eval[4].get()}, options.runs);
    const double n = static_cast<double>(locations.size());
    double ns[5];
    for(int k = 0; k < 5; ++k)
      ns[k] = te[std::size_t(k)] / n * 1e9;
    std::size_t regular = 0;
    std::vector<bool> is_regular;
    for(const Limit_location& at : locations) {
      is_regular.push_back(regular_patch(in.mesh, Mesh::Face_index(static_cast<Mesh::size_type>(at.face)), scheme));
      regular += is_regular.back() ? 1 : 0;
    }
    std::string row = "| " + scheme_name(scheme) + " | " + in.name + " | " + std::to_string(in.mesh.number_of_faces()) +
                      " | " + seconds(tb[0]) + " | " + (build[1] ? seconds(tb[1]) : "-") + " | " +
                      std::to_string(locations.size()) + " | " + fixed(100.0 * static_cast<double>(regular) / n, 0) +
                      " % | " + fixed(ns[0], 0) + " | " + fixed(ns[3], 0) + " | " + fixed(ns[4], 0) + " | ";
    if(!eval[1]) {
      out(row + "- | - | - | - | | - | - |\n");
      return;
    }
    const std::vector<P3> mine = eval[0]->output_points(), theirs = eval[1]->output_points();
    double worst[2] = {0, 0}; // regular, other
    bool complete = true;
    for(std::size_t i = 0; i < locations.size(); ++i) {
      const double d = distance(mine[i], theirs[i]) / in.diagonal;
      complete = complete && std::isfinite(d);
      double& w = worst[is_regular[i] ? 0 : 1];
      w = std::isfinite(d) ? std::max(w, d) : w;
    }
    std::string regular_distance = regular > 0 ? scientific(worst[0]) : "(none)";
    if(!complete || worst[0] > 1e-12) {
      regular_distance = "**" + regular_distance + (complete ? "" : ", a point missing") + " DIFFER**";
      missed.push_back("limit positions agree with Bfr on regular patches to 1e-12, " + where);
    }
    row += fixed(ns[1], 0) + " | " + fixed(ns[2], 0) + " | " + fixed(ns[1] / ns[3]) + " | " + fixed(ns[2] / ns[0]) +
           " | " +
           check(ns[3] < ns[1], "limit evaluation from the mesh faster than Bfr per location, " + where,
                 fixed(ns[3], 0) + " ns vs " + fixed(ns[1], 0) + " ns") +
           " | " + regular_distance + " | " + (regular < locations.size() ? scientific(worst[1]) : "(none)") + " |";
    out(row + "\n");
  });
  if(!refusals.empty())
    out("\n" + refusals);
}

void tessellation_rows(const Options& options)
{
  for_each_row(tessellation_plan, [&](const Row_case& rc) {
    const Scheme scheme = rc.c.scheme;
    const Input& in = rc.in;
    if(!limit_fits(in, scheme))
      return;
    Job_ptr tess[2] = {ours_tessellation(in, scheme, rc.levels), osd_tessellation(in.soup, scheme, rc.levels)};
    const std::vector<double> t = time_jobs({tess[0].get(), tess[1].get()}, options.runs);
    const double points[2] = {static_cast<double>(tess[0]->output_points().size()),
                              tess[1] ? static_cast<double>(tess[1]->output_points().size()) : nan_value};
    const double rate[2] = {points[0] / t[0], points[1] / t[1]};
    std::string row = "| " + scheme_name(scheme) + " | " + in.name + " | " + std::to_string(rc.levels) + " | ";
    if(points[0] == 0) {
      row += "**refused** | - | - | ";
      missed.push_back("tessellation, " + limit_where(rc) + ": `tessellate` throws Bad_input");
    } else {
      row += seconds(t[0]) + " | " + std::to_string(static_cast<std::size_t>(points[0])) + " | " +
             fixed(rate[0] / 1e6) + " | ";
    }
    if(tess[1])
      row += seconds(t[1]) + " | " + std::to_string(static_cast<std::size_t>(points[1])) + " | " +
             fixed(rate[1] / 1e6) + " | " + (points[0] > 0 ? fixed(t[1] / t[0]) : "-") + " | " +
             (points[0] > 0 ? fixed(rate[0] / rate[1]) : "-") + " |\n";
    else
      row += "- | - | - | - | - |\n";
    out(row);
  });
}

void limit_section(const Options& options)
{
  out("\n## Limit surface evaluation (issue 13)\n\n" + minimum_of_runs(options.runs) +
      " after a warm-up, one thread. Ours: `CGAL::Subdiv::Limit_surface<Mesh, Mask>` (Catmull-Clark or Loop "
      "mask); OpenSubdiv: `Bfr::RefinerSurfaceFactory<>` over a `Far::TopologyRefiner` of the same faces (the Sdc "
      "options above, Bfr's default options), `Bfr::Surface<double>`.\n\n"
      "- `build`: ours = constructing the `Limit_surface` and evaluating it once in every face (u = v = 1/4; a "
      "face with n != 4 corners in its sub-quad at corner 0), which builds the Stam eigenbases of the valences it "
      "meets (once per valence) and refines the mesh once if a face needs it; Bfr = creating the refiner (not refined) "
      "and the factory (Bfr does its per-face "
      "work in `InitVertexSurface`, timed with the evaluations).\n"
      "- `eval`: ns per evaluation of the position and its first derivatives at " +
      std::to_string(limit_location_count(options)) +
      " random (face, u, v) locations (fixed seed, the same for both), in quads only under Catmull-Clark (so no "
      "sub-quad and Bfr parameterisation of an n-gon to match) and in triangles under Loop. Ours: "
      "`evaluate(f, u, v)` with `second_derivatives = false` (P, Du, Dv and the normal; `ours cold D2`: with the "
      "second derivatives too, cold); `ours kept`: the surface "
      "keeps each face's tree (its direct patch, or its refined neighbourhood; `cached_faces`, the default), so "
      "after the warm-up every location finds its face kept; `ours cold`: `cached_faces = 0`, every evaluation "
      "starts from the mesh (what scattered points cost; the mesh refined once, which the evaluator keeps for "
      "faces that are not a direct patch, is made by the build); `Bfr loc`: "
      "`InitVertexSurface` + `PreparePatchPoints` + `Evaluate(uv, patchPoints, 3, P, Du, Dv)` for each location "
      "(what scattered points cost); `Bfr face`: the locations sorted by face, one surface per face, then all of "
      "its locations (compare with ours kept). `regular`: the share of the locations in a regular patch (corners of "
      "valence 4 with quads "
      "around, or of valence 6), the rest in a patch at an extraordinary vertex or next to an n-gon. Target "
      "(issue 13): one evaluation faster than Bfr's per location, ours cold against Bfr loc.\n"
      "- `dist`: the largest distance between the positions of ours and Bfr's, over the bounding-box diagonal, at "
      "the locations in regular patches (both exact there: above 1e-12 is marked DIFFER) and at the others, "
      "where Bfr stops refining at its approximation level (2) and puts a Gregory patch at the extraordinary "
      "corner, which only approximates the limit.\n\n"
      "| scheme | input | faces | build ours | build Bfr | locations | regular | eval ours kept ns | ours cold ns "
      "| ours cold D2 ns "
      "| Bfr loc ns | Bfr face ns | Bfr loc/ours cold | Bfr face/ours kept | target faster than Bfr loc | dist "
      "regular | dist other |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|\n");
  limit_evaluation_rows(options);
  out(
    "\nTessellation, seconds for the whole mesh at a uniform rate (every edge cut in `rate`), the surface made "
    "outside the timer. Ours: `tessellate(surface, out, rate, output_normals(true))` into a `Surface_mesh` of "
    "quads (triangles under Loop), every point on a mesh edge or vertex evaluated once and shared; an n-gon as "
    "n sub-quads at half the rate. Bfr: for every face `InitVertexSurface` + `PreparePatchPoints`, "
    "`Bfr::Tessellation` at the same rate (`PreserveQuads` under Catmull-Clark) for its coordinates and "
    "facets, then P, Du, Dv and the unit normal at each coordinate into arrays (no mesh: a point on an edge is "
    "evaluated by both of its faces, a vertex by all of its faces). `points`: the points each evaluates; "
    "`Mpt/s`: millions of them per second; `Bfr time/ours`: the same surface, Bfr's time over ours; `ours/Bfr "
    "pt/s`: the ratio of the point rates. No target. The mixed torus is not tessellated here: ours refines "
    "locally at every n-gon and extraordinary vertex, about a minute at rate 4.\n\n"
    "| scheme | input | rate | ours s | ours points | ours Mpt/s | Bfr s | Bfr points | Bfr Mpt/s | Bfr "
    "time/ours | ours/Bfr pt/s |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  tessellation_rows(options);
}

// --- peak memory ------------------------------------------------------------------

std::string self_path()
{
  char path[4096];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if(n <= 0)
    return "";
  path[n] = 0;
  return path;
}

// runs one refinement in a child process (this program, --memory-child) and
// returns its peak resident memory above the baseline, in MB; NaN if it failed
double child_memory(const Options& options, Peer peer, Scheme scheme, const std::string& id, int levels)
{
  const std::string self = self_path();
  if(self.empty())
    return nan_value;
  std::string command = "'" + self + "' --memory-child " + std::to_string(peer) + " '" + scheme_name(scheme) + "' " +
                        id + " " + std::to_string(levels) + " --meshes '" + options.mesh_dir + "'" +
                        (options.quick ? " --quick" : "");
  FILE* pipe = popen(command.c_str(), "r");
  if(pipe == nullptr)
    return nan_value;
  char line[256];
  double megabytes = nan_value;
  while(std::fgets(line, sizeof line, pipe) != nullptr) {
    double value = 0;
    if(std::sscanf(line, "peak-above-baseline-bytes %lf", &value) == 1)
      megabytes = value / 1e6;
  }
  return pclose(pipe) == 0 ? megabytes : nan_value;
}

int memory_child(int argc, char** argv, int at)
{
  if(at + 4 > argc)
    return 2;
  const Peer peer = static_cast<Peer>(std::atoi(argv[at]));
  Scheme scheme;
  if(!parse_scheme(argv[at + 1], scheme))
    return 2;
  const std::string id = argv[at + 2];
  const int levels = std::atoi(argv[at + 3]);
  bool quick = false;
  std::string mesh_dir = SUBDIV_BENCH_MESH_DIR;
  for(int i = at + 4; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--quick")
      quick = true;
    else if(arg == "--meshes" && i + 1 < argc)
      mesh_dir = argv[++i];
  }
  Input in;
  std::string why;
  if(!make_input(id, quick, mesh_dir, in, why))
    return 1;
  Job_ptr job = refinement(peer, in, scheme, levels);
  if(!job)
    return 1;
  job->prepare();
  if(!reset_peak())
    return 1;
  const std::size_t baseline = resident_bytes();
  job->run();
  const std::size_t peak = peak_resident_bytes();
  std::printf("peak-above-baseline-bytes %zu\n", peak > baseline ? peak - baseline : 0);
  return 0;
}

void memory_section(const Options& options)
{
  out(
    "\n## Peak memory of one refinement\n\n"
    "MB above the baseline: each refinement runs once in a child process of its own (this program again), "
    "which makes the input and the library's copy of it, then restarts the peak count of its resident set "
    "(`/proc/self/clear_refs`), notes its size (`VmRSS`), runs the refinement and reads the peak (`VmHWM`). "
    "Target: ours no higher than CGAL's `Subdivision_method_3`.\n\n"
    "| scheme | input | levels | ours MB | CGAL MB | OpenMesh MB | OSD Far MB | ours/CGAL | target <= CGAL |\n"
    "|---|---|---:|---:|---:|---:|---:|---:|---|\n");
  for_each_row(memory_plan, [&](const Row_case& rc) {
    double mb[number_of_peers];
    for(int p = 0; p < number_of_peers; ++p)
      mb[p] = refinement(static_cast<Peer>(p), rc.in, rc.c.scheme, 1)
                ? child_memory(options, static_cast<Peer>(p), rc.c.scheme, rc.c.input, rc.levels)
                : nan_value;
    std::string row = rc.cells();
    for(int p = 0; p < number_of_peers; ++p)
      row += " " + fixed(mb[p], 0) + " |";
    row += " " + fixed(mb[ours] / mb[cgal]) + " | ";
    if(std::isfinite(mb[ours]) && std::isfinite(mb[cgal]))
      row += check(mb[ours] <= mb[cgal], "peak memory <= CGAL's, " + rc.where(),
                   fixed(mb[ours], 0) + " MB vs " + fixed(mb[cgal], 0) + " MB");
    else
      row += "(not measured)";
    out(row + " |\n");
  });
}

// --- agreement ------------------------------------------------------------------

void agreement_section()
{
  out(
    "\n## Agreement of the points\n\n"
    "Largest distance between our refined points and another library's, over the bounding-box diagonal of the "
    "input, at the last level of each case above (the points paired by position: the libraries number new "
    "vertices differently). Where the rules coincide (OSD with VTX_BOUNDARY_EDGE_ONLY and TRI_SUB_CATMARK; "
    "CGAL; OpenMesh except its Catmull-Clark border rule) anything above 1e-12 is marked DIFFER.\n\n"
    "`ours 2T = 1T`: whether our points with two threads are those of one thread, bit for bit.\n\n"
    "| scheme | input | levels | vs CGAL | vs OpenMesh | vs OSD Far | ours 2T = 1T |\n"
    "|---|---|---:|---|---|---|---|\n");
  for(const Agreement_row& a : agreements)
    out("| " + a.scheme + " | " + a.input + " | " + std::to_string(a.levels) + " | " + a.versus[cgal] + " | " +
        a.versus[openmesh] + " | " + a.versus[osd] + " | " + a.same_with_two_threads + " |\n");
  for(const Agreement_row& a : agreements)
    if(a.flagged)
      missed.push_back("agreement to 1e-12: " + a.scheme + " on " + a.input + " differs from a peer");
}

// --- exact kernels ----------------------------------------------------------------

void exact_section(const Options& options)
{
  Input small;
  std::string why;
  if(!make_input("tri20k", true, options.mesh_dir, small, why))
    return;
  out(
    "\n## Exact kernels\n\n"
    "The same refinement with `CGAL::Epick` and `CGAL::Epeck` points on a small input (" +
    small.name + "), seconds, minimum of " + std::to_string(options.runs) +
    " runs. No target: this says what exact constructions cost (`Epeck` stores every constructed coordinate as "
    "a lazy exact number).\n\n"
    "| scheme | levels | output faces | ours Epick | ours Epeck | Epeck/Epick | CGAL Epick | CGAL Epeck | "
    "Epeck/Epick |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for(const Scheme scheme : {Scheme::loop, Scheme::catmull_clark})
    for(int levels = 1; levels <= 2; ++levels) {
      Job_ptr jobs[4] = {
        ours_refinement_kernel(small, scheme, levels, false), ours_refinement_kernel(small, scheme, levels, true),
        cgal_refinement_kernel(small, scheme, levels, false), cgal_refinement_kernel(small, scheme, levels, true)};
      const std::vector<double> t =
        time_jobs({jobs[0].get(), jobs[1].get(), jobs[2].get(), jobs[3].get()}, options.runs);
      out("| " + scheme_name(scheme) + " | " + std::to_string(levels) + " | " +
          std::to_string(jobs[0]->output_faces()) + " | " + seconds(t[0]) + " | " + seconds(t[1]) + " | " +
          fixed(t[1] / t[0], 1) + " | " + seconds(t[2]) + " | " + seconds(t[3]) + " | " + fixed(t[3] / t[2], 1) +
          " |\n");
    }
}

// --- the conditions ---------------------------------------------------------------

std::string file_line(const std::string& path, const std::string& prefix)
{
  std::ifstream file(path);
  std::string line;
  while(std::getline(file, line))
    if(line.compare(0, prefix.size(), prefix) == 0)
      return line.substr(line.find(':') == std::string::npos ? prefix.size() : line.find(':') + 1);
  return "";
}

std::string load_average()
{
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  file >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// the commit of the source tree, and whether the library's headers differ from it
std::string source_state()
{
#ifdef SUBDIV_BENCH_SOURCE_DIR
  const std::string dir = SUBDIV_BENCH_SOURCE_DIR;
  const auto run = [](const std::string& command) {
    std::string text;
    if(FILE* pipe = popen(command.c_str(), "r")) {
      char buffer[256];
      while(std::fgets(buffer, sizeof buffer, pipe) != nullptr)
        text += buffer;
      pclose(pipe);
    }
    while(!text.empty() && text.back() == '\n')
      text.pop_back();
    return text;
  };
  const std::string commit = run("git -C '" + dir + "' log -1 --format='%h %cs' 2>/dev/null");
  if(commit.empty())
    return "(not a git checkout)";
  const std::string changed = run("git -C '" + dir + "' status --porcelain -- include 2>/dev/null");
  return "commit " + commit + (changed.empty() ? ", headers as committed" : ", **headers changed since that commit**");
#else
  return "(source state unknown)";
#endif
}

std::string trim(std::string s)
{
  s.erase(0, s.find_first_not_of(" \t"));
  return s;
}

// --profile PEER SCHEME INPUT LEVELS [REPEATS]: one job only, for perf
int profile(int argc, char** argv, int at, const Options& options)
{
  if(at + 4 > argc)
    return 2;
  const std::string peer = argv[at], id = argv[at + 2];
  Scheme scheme;
  if(!parse_scheme(argv[at + 1], scheme))
    return 2;
  const int levels = std::atoi(argv[at + 3]);
  const int repeats = at + 4 < argc ? std::max(1, std::atoi(argv[at + 4])) : 10;
  Input in;
  std::string why;
  if(!make_input(id, options.quick, options.mesh_dir, in, why)) {
    std::printf("subdiv-bench: %s\n", why.c_str());
    return 1;
  }
  Job_ptr job;
  std::vector<Limit_location> locations; // the limit section's, for the limit peers
  if(peer.find("-limit") != std::string::npos && limit_fits(in, scheme)) {
    std::size_t refused = 0;
    std::string refusal;
    locations = limit_locations(in, scheme, limit_location_count(options), refused, refusal);
  }
  for(int p = 0; p < number_of_peers; ++p)
    if(peer == peer_names[p] || (p == osd && peer == "OSD"))
      job = refinement(static_cast<Peer>(p), in, scheme, levels);
  if(peer == "ours-stencils")
    job = ours_stencil_build(in, scheme, levels, 1);
  else if(peer == "ours-stencils-2T")
    job = ours_stencil_build(in, scheme, levels, 2);
  else if(peer == "ours-apply")
    job = ours_apply(in, scheme, levels);
  else if(peer == "OSD-apply")
    job = osd_apply(in.soup, scheme, levels);
  else if(peer == "ours-2T")
    job = ours_refinement(in, scheme, levels, 2);
  else if(peer == "OSD-stencils")
    job = osd_stencil_build(in.soup, scheme, levels, false);
  else if(peer == "SM-resize")
    job = surface_mesh_resize_floor(in, scheme, levels);
  else if(peer == "ours-limit")
    job = ours_limit_evaluation(in, scheme, locations, true);
  else if(peer == "ours-limit-cold")
    job = ours_limit_evaluation(in, scheme, locations, false);
  else if(peer == "OSD-limit")
    job = osd_limit_evaluation(in.soup, scheme, locations, false);
  else if(peer == "OSD-limit-per-face")
    job = osd_limit_evaluation(in.soup, scheme, locations, true);
  else if(peer == "ours-tessellate")
    job = ours_tessellation(in, scheme, levels);
  else if(peer == "OSD-tessellate")
    job = osd_tessellation(in.soup, scheme, levels);
  if(!job) {
    std::printf("subdiv-bench: no job '%s' for %s\n", peer.c_str(), scheme_name(scheme).c_str());
    return 1;
  }
  double best = 1e300;
  for(int r = 0; r < repeats; ++r) {
    job->prepare();
    const double start = now();
    job->run();
    best = std::min(best, now() - start);
  }
  std::printf("%s %s on %s, %d levels: best of %d runs %s s\n", peer.c_str(), scheme_name(scheme).c_str(),
              in.name.c_str(), levels, repeats, seconds(best).c_str());
  return 0;
}

} // namespace
} // namespace subdiv_bench

int main(int argc, char** argv)
{
  using namespace subdiv_bench;
  Options options;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--memory-child")
      return memory_child(argc, argv, i + 1);
    if(arg == "--runs" && i + 1 < argc) {
      options.runs = std::max(1, std::atoi(argv[++i]));
    } else if(arg == "--quick") {
      options.quick = true;
    } else if(arg == "--write-doc") {
      options.write_doc = true;
    } else if(arg == "--no-memory") {
      options.memory = false;
    } else if(arg == "--heap" && i + 1 < argc &&
              (std::string(argv[i + 1]) == "warm" || std::string(argv[i + 1]) == "fresh")) {
      options.heap = std::string(argv[++i]) == "warm" ? Heap::warm : Heap::fresh;
    } else if(arg == "--meshes" && i + 1 < argc) {
      options.mesh_dir = argv[++i];
    } else if(arg == "--profile") {
      set_heap(options.heap);
      return profile(argc, argv, i + 1, options);
    } else {
      std::printf(
        "usage: subdiv-bench [--runs N] [--quick] [--write-doc] [--no-memory] [--heap warm|fresh] [--meshes DIR]\n"
        "       subdiv-bench [--quick] [--heap warm|fresh] [--meshes DIR] --profile PEER SCHEME INPUT LEVELS "
        "[REPEATS]\n\n"
        "Times CGAL Subdiv against CGAL's Subdivision_method_3, OpenMesh and OpenSubdiv (when found at build\n"
        "time): full refinement, stencil table build and apply, peak memory, agreement of the points, exact\n"
        "kernels; minimum of N runs (default 3) after a warm-up. --quick: inputs 10x smaller. --write-doc: also\n"
        "write doc/performance.md and doc/figures/performance.svg in the source tree. --no-memory: skip the\n"
        "child processes of the peak memory rows. --heap: how malloc treats large blocks in the timed sections\n"
        "(warm, the default: reused; fresh: a new mmap each time, so every run pays its page faults; given\n"
        "before --profile, it applies there too). --meshes: the shared mesh directory (default %s).\n"
        "--profile: only run one job REPEATS times (default 10), for perf; PEER: ours, CGAL, OpenMesh, OSD,\n"
        "ours-2T, ours-stencils, ours-stencils-2T, OSD-stencils, ours-apply, OSD-apply (1 thread), SM-resize (the "
        "floor),\nours-limit, ours-limit-cold, OSD-limit, OSD-limit-per-face (the limit section's evaluations; LEVELS "
        "ignored),\n"
        "ours-tessellate, OSD-tessellate (LEVELS: the rate); SCHEME: Loop, "
        "Catmull-Clark, Doo-Sabin, sqrt3; INPUT: tri20k, tri200k,\n"
        "quad200k, mixed, border, fandisk, mushroom, spot, fandisk-creased, rook-creased, tri200k-uv, quad200k-uv.\n",
        SUBDIV_BENCH_MESH_DIR);
      return arg == "-h" || arg == "--help" ? 0 : 2;
    }
  }
  options.command = "build/src/subdiv-bench";
  for(int i = 1; i < argc; ++i)
    options.command += std::string(" ") + argv[i];

  // the fresh-memory section runs first: once the heap has grown, glibc
  // serves large blocks from its free chunks whatever the mmap settings
  set_heap(Heap::fresh);
  const double start = now();
  const std::string load_before = load_average();
  char date[64];
  const std::time_t clock = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&clock));

  for(const std::string& id : input_ids()) {
    Input in;
    std::string why;
    if(make_input(id, options.quick, options.mesh_dir, in, why))
      inputs.emplace(id, std::move(in));
    else
      missing_inputs.push_back(id + " (" + why + ")");
  }

  out(
    "# Performance\n\n"
    "Written by `subdiv-bench` (src/bench/README.md) in one run; do not edit by hand. Why the missed targets are "
    "missed: doc/profile.md. Regenerate with\n\n"
    "```\ncmake --build build --target subdiv-bench\nbuild/src/subdiv-bench --write-doc\n```\n\n"
    "Conditions of this run:\n\n- date: " +
    std::string(date) + "\n- command: `" + options.command +
    "`\n- machine: " + trim(file_line("/proc/cpuinfo", "model name")) + ", " +
    std::to_string(std::thread::hardware_concurrency()) + " cores, " + trim(file_line("/proc/meminfo", "MemTotal")) +
    " of memory; load average before the run: " + load_before +
    " (the machine is shared: timings vary by 10-30 % between runs; compare ratios of the same run)\n"
    "- compiler: g++ " +
    __VERSION__ +
    ", `-O2 -DNDEBUG` (no CGAL assertions in either library)\n"
    "- libraries: CGAL " +
    CGAL_VERSION_STR + "; OpenMesh " +
    (openmesh_missing().empty() ? openmesh_version() : "skipped: " + openmesh_missing()) + "; OpenSubdiv " +
    (osd_missing().empty() ? osd_version() : "skipped: " + osd_missing()) + "\n- CGAL Subdiv: " + source_state() +
    "; `threads` named parameter: " + (ours_has_threads() ? "yes" : "no") +
    "; TBB: " + (ours_with_tbb() ? "yes" : "no") + "\n- timing: minimum of " + std::to_string(options.runs) +
    " runs after one warm-up run, the libraries interleaved; inputs made (or read) and copied outside the "
    "timers, results freed outside the timers\n- memory: `--heap " +
    heap_name(options.heap) + "`: " +
    (options.heap == Heap::warm
       ? "glibc's malloc takes every block from the heap and keeps freed memory (`M_MMAP_MAX` 0, "
         "`M_TRIM_THRESHOLD` 1 GiB), the same for every library, so the runs after the warm-up reuse mapped "
         "pages (with glibc's defaults blocks up to 32 MiB are reused and larger ones are mapped afresh every "
         "time, which favours libraries made of many small arrays by chance); the section \"in fresh memory\" "
         "shows the other extreme"
       : "every block of 128 KiB or more is a new mmap (each run pays its page faults)") +
    "\n");
  if(options.quick)
    out("- **--quick: inputs 10x smaller than the documented ones**\n");
  out("\nInputs (identical for every library):\n\n");
  for(const std::string& id : input_ids())
    if(const Input* in = input(id))
      out("- `" + id + "`: " + in->name + ", " + std::to_string(in->mesh.number_of_vertices()) + " vertices" +
          (in->border ? ", with border" : ", closed") + "\n");
  for(const std::string& m : missing_inputs)
    out("- skipped: " + m + "\n");
  if(!openmesh_missing().empty())
    out("\nskipped: OpenMesh: " + openmesh_missing() + "\n");
  if(!osd_missing().empty())
    out("\nskipped: OpenSubdiv: " + osd_missing() + "\n");

  fresh_memory_section(options); // ends with set_heap(options.heap)
  refinement_section(options);
  creased_refinement_section(options);
  uv_refinement_section(options);
  stencil_build_section(options);
  apply_section(options);
  limit_section(options);
  if(options.memory)
    memory_section(options);
  agreement_section();
  exact_section(options);

  out("\n## Targets of issue 5\n\n" + std::to_string(met.size()) + " checks met, " + std::to_string(missed.size()) +
      " missed.\n\n");
  for(const std::string& m : missed)
    out("- MISSED: " + m + "\n");
  out("\nRun time " + fixed(now() - start, 0) + " s; load average after the run: " + load_average() + ".\n");

  const std::string svg =
    bar_chart_svg("Full refinement: output faces per second (millions), one thread unless said",
                  "million output faces per second (longer is faster)",
                  ours_has_threads() && ours_with_tbb()
                    ? std::vector<std::string>{"CGAL Subdiv (ours)", "CGAL Subdivision_method_3", "OpenMesh",
                                               "OpenSubdiv Far (no halfedge mesh)", "ours, 2 threads"}
                    : std::vector<std::string>{"CGAL Subdiv (ours)", "CGAL Subdivision_method_3", "OpenMesh",
                                               "OpenSubdiv Far (no halfedge mesh)"},
                  chart);
  if(options.write_doc) {
    const std::string md_path = options.doc_dir + "/performance.md",
                      svg_path = options.doc_dir + "/figures/performance.svg";
    std::ofstream(svg_path) << svg;
    std::ofstream md(md_path);
    md << document.substr(0, document.find("\n## Full refinement"))
       << "\n![full refinement speed](figures/performance.svg)\n"
       << document.substr(document.find("\n## Full refinement"));
    std::printf("\nwrote %s and %s\n", md_path.c_str(), svg_path.c_str());
  }
  return 0;
}
