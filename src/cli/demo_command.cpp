// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv demo [--output-dir DIR] [--input FILE]: every curve scheme on
// the bundled polygon; points, figures, convergence tables and an index.
#include "analyse_summary.h"
#include "args.h"
#include "commands.h"
#include "curve.h"
#include "files.h"
#include "numbers.h"
#include "report.h"
#include "surface_demo.h"
#include "svg.h"

#include <CGAL/Subdiv/errors.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace cgal_subdiv {
namespace {

namespace fs = std::filesystem;

const char* const demo_help = R"(usage: cgal-subdiv demo [--output-dir DIR] [--input FILE]

Runs every curve scheme on a small closed polygon: B-splines of degree 1 to 5,
Chaikin, corner cutting (1/4, 3/4) and (1/10, 3/5), four-point (w = 1/16 and
1/5), Bezier chains; closed, and open where it shows something (both end
rules). For each run it writes to DIR:
  NAME.txt   the refined points (17 significant digits)
  NAME.svg   the figure: control polygon, levels, curvature against arc length
  NAME.md    the distance table and the eigen-analysis (as `curve --report`)
Then runs every surface scheme, 3 levels, on the bundled meshes torus.off (a
closed triangle torus, 64 faces) and house.off (a closed mesh of 40 quads and 4
triangles; the polygon schemes only) and writes
  surface-SCHEME-MESH.off   the refined mesh
Last, the eigen-analysis of every surface scheme (as `cgal-subdiv analyse`)
at interior valences 3..8: subdominant eigenvalue and C1 verdict.
DIR/index.md lists everything. Summary tables (for surfaces: vertices and
faces in and out, time; the analysis summary) go to stdout.

  --output-dir DIR   where to write (default: out), created if missing
  --input FILE       the polygon (default: the bundled doc/data/polygon.txt,
                     from the source tree or <prefix>/share/cgal-subdiv/; the
                     meshes are found in the same place)
  -h, --help         show this help

Exit status: 0 on success, 1 if a run or a file failed, 2 for a malformed
command line.
)";

const std::vector<Option_spec> demo_options = {
  {{"--output-dir"}, true}, {{"--input"}, true}, {{"-h", "--help"}, false}};

constexpr int demo_levels = 5;
constexpr int demo_bezier_levels = 4;

struct Demo_case
{
  std::string name;
  Curve_job job;
};

Demo_case make_case(const std::string& name, Scheme_kind kind, bool closed)
{
  Demo_case c{name, Curve_job()};
  c.job.scheme.kind = kind;
  c.job.refine.closed = closed;
  c.job.refine.levels = kind == Scheme_kind::bezier ? demo_bezier_levels : demo_levels;
  return c;
}

Demo_case with_degree(Demo_case c, int degree)
{
  c.job.scheme.degree = degree;
  return c;
}

Demo_case keeping_ends(Demo_case c)
{
  c.job.refine.end_rule = CGAL::Subdiv::End_rule::keep_ends;
  return c;
}

std::vector<Demo_case> demo_cases()
{
  std::vector<Demo_case> cases;
  for(int degree = 1; degree <= 5; ++degree)
    cases.push_back(
      with_degree(make_case("bspline-" + std::to_string(degree) + "-closed", Scheme_kind::bspline, true), degree));
  cases.push_back(make_case("bspline-3-open", Scheme_kind::bspline, false));
  cases.push_back(keeping_ends(make_case("bspline-3-open-keep-ends", Scheme_kind::bspline, false)));
  cases.push_back(make_case("chaikin-closed", Scheme_kind::chaikin, true));
  cases.push_back(make_case("chaikin-open", Scheme_kind::chaikin, false));
  cases.push_back(make_case("corner-cutting-1_4-3_4-closed", Scheme_kind::corner_cutting, true));
  Demo_case skewed = make_case("corner-cutting-1_10-3_5-closed", Scheme_kind::corner_cutting, true);
  skewed.job.scheme.a = Exact(1) / Exact(10);
  skewed.job.scheme.b = Exact(3) / Exact(5);
  cases.push_back(skewed);
  cases.push_back(make_case("four-point-closed", Scheme_kind::four_point, true));
  Demo_case tense = make_case("four-point-w1_5-closed", Scheme_kind::four_point, true);
  tense.job.scheme.w = Exact(1) / Exact(5);
  cases.push_back(tense);
  cases.push_back(keeping_ends(make_case("four-point-open-keep-ends", Scheme_kind::four_point, false)));
  cases.push_back(make_case("bezier-3-open", Scheme_kind::bezier, false));
  cases.push_back(with_degree(make_case("bezier-2-closed", Scheme_kind::bezier, true), 2));
  return cases;
}

// Bezier chains need m*K+1 (open) or m*K (closed) points: take the longest prefix that is one
Input_polyline bezier_subset(const Input_polyline& input, const Curve_job& job)
{
  if(job.scheme.kind != Scheme_kind::bezier)
    return input;
  const std::size_t k = static_cast<std::size_t>(job.scheme.degree), n = input.points.size();
  const std::size_t keep = job.refine.closed ? n / k * k : (n >= 1 ? (n - 1) / k * k + 1 : 0);
  Input_polyline subset = input;
  subset.points.resize(keep);
  return subset;
}

// a bundled file: in the source tree (run from the build tree), next to the
// installed binary in ../share/cgal-subdiv/, or in the install prefix
std::string find_bundled(const std::string& name, const std::string& program_path, const std::string& hint)
{
  std::error_code ec;
  fs::path program = fs::canonical("/proc/self/exe", ec);
  if(ec)
    program = fs::absolute(program_path, ec);
  const std::vector<std::string> candidates = {
    (fs::path(SUBDIV_SOURCE_DATA_DIR) / name).string(),
    (program.parent_path().parent_path() / SUBDIV_RELATIVE_SHARE_DIR / name).string(),
    (fs::path(SUBDIV_INSTALL_DATA_DIR) / name).string()};
  for(const std::string& candidate : candidates)
    if(fs::is_regular_file(candidate, ec))
      return candidate;
  throw Input_error("cannot find the bundled " + name + " (looked for " + candidates.front() + " and " +
                    candidates.back() + ")" + hint);
}

std::string find_polygon(const Parsed_args& args, const std::string& program_path)
{
  if(args.has("--input"))
    return args.value("--input");
  return find_bundled("polygon.txt", program_path, "; give one with --input");
}

struct Demo_row
{
  std::string name;
  std::string scheme;
  std::string ends;
  std::size_t points = 0;
  Report_summary summary;
  std::string failure;
};

Demo_row run_case(const Demo_case& c, const Input_polyline& input, const fs::path& dir)
{
  Demo_row row{c.name, describe(c.job.scheme), describe(c.job.refine), 0, Report_summary(), ""};
  row.summary.last_ratio = row.summary.predicted_rate = std::nan("");
  row.summary.verdict = "n/a";
  try {
    const Input_polyline used = bezier_subset(input, c.job);
    Atomic_file points((dir / (c.name + ".txt")).string());
    Atomic_file svg((dir / (c.name + ".svg")).string());
    Atomic_file table((dir / (c.name + ".md")).string());
    Figure figure;
    row.points = run_curve(c.job, used, points.stream(), &figure);
    write_svg(figure, svg.stream());
    table.stream() << "# " << c.name << "\n\n![" << c.name << "](" << c.name << ".svg)\n\n";
    if(report_available())
      row.summary = write_report(c.job, used, table.stream());
    else
      table.stream() << "(no convergence table: cgal-subdiv was built without the analysis layer)\n";
    points.commit();
    svg.commit();
    table.commit();
  } catch(const std::exception& e) {
    row.failure = e.what();
  }
  return row;
}

std::string ratio_text(double x)
{
  if(std::isnan(x))
    return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", x);
  return buffer;
}

void write_index(const std::vector<Demo_row>& rows, const std::string& polygon,
                 const std::vector<Surface_demo_row>& surface_rows, const std::vector<Demo_mesh>& meshes,
                 const std::vector<Analysis_summary_row>& analysis_rows, const fs::path& dir)
{
  Atomic_file index((dir / "index.md").string());
  std::ostream& out = index.stream();
  out << "# cgal-subdiv demo\n\n"
      << "Every curve scheme on `" << polygon << "` (Bezier chains: the longest prefix of the polygon that is one).\n"
      << "Distances are between successive levels; for a smooth limit their ratio tends to the predicted rate.\n\n"
      << "| run | scheme | ends, levels | points | last ratio | predicted | smoothness | files |\n"
      << "|---|---|---|---:|---:|---:|---|---|\n";
  for(const Demo_row& r : rows) {
    out << "| " << r.name << " | " << r.scheme << " | " << r.ends << " | ";
    if(!r.failure.empty()) {
      out << "failed: " << r.failure << " | | | | |\n";
      continue;
    }
    out << r.points << " | " << ratio_text(r.summary.last_ratio) << " | " << ratio_text(r.summary.predicted_rate)
        << " | " << r.summary.verdict << " | [points](" << r.name << ".txt) [figure](" << r.name << ".svg) [table]("
        << r.name << ".md) |\n";
  }
  out << "\n";
  write_surface_index(surface_rows, meshes, out);
  write_analysis_index(analysis_rows, out);
  for(const Demo_row& r : rows)
    if(r.failure.empty())
      out << "## " << r.name << "\n\n![" << r.name << "](" << r.name << ".svg)\n\n";
  index.commit();
}

void print_summary(const std::vector<Demo_row>& rows)
{
  std::printf("%-32s %-30s %7s %10s %9s  %s\n", "run", "scheme", "points", "last ratio", "predicted", "smoothness");
  for(const Demo_row& r : rows) {
    if(!r.failure.empty()) {
      std::printf("%-32s %-30s failed: %s\n", r.name.c_str(), r.scheme.c_str(), r.failure.c_str());
      continue;
    }
    std::printf("%-32s %-30s %7zu %10s %9s  %s\n", r.name.c_str(), r.scheme.c_str(), r.points,
                ratio_text(r.summary.last_ratio).c_str(), ratio_text(r.summary.predicted_rate).c_str(),
                r.summary.verdict.c_str());
  }
}

} // namespace

int demo_command(const std::vector<std::string>& arguments, const std::string& program_path)
{
  const Parsed_args args = scan_args(arguments, demo_options, "demo");
  if(args.has("-h")) {
    std::cout << demo_help;
    return 0;
  }
  if(!args.positional.empty())
    throw Usage_error("unexpected argument '" + args.positional.front() + "'; see 'cgal-subdiv demo --help'");
  const std::string polygon = find_polygon(args, program_path);
  const Input_polyline input = read_polyline(polygon);
  const fs::path dir = fs::absolute(args.value("--output-dir", "out"));
  std::error_code ec;
  fs::create_directories(dir, ec);
  if(ec)
    throw Input_error("cannot create '" + dir.string() + "': " + ec.message());

  std::vector<Demo_row> rows;
  std::size_t failures = 0;
  for(const Demo_case& c : demo_cases()) {
    rows.push_back(run_case(c, input, dir));
    failures += rows.back().failure.empty() ? 0 : 1;
  }
  const std::vector<Demo_mesh> meshes = {Demo_mesh{"torus", find_bundled("torus.off", program_path, ""), true},
                                         Demo_mesh{"house", find_bundled("house.off", program_path, ""), false}};
  const std::vector<Surface_demo_row> surface_rows = run_surface_demo(meshes, dir);
  std::size_t surface_failures = 0;
  for(const Surface_demo_row& r : surface_rows)
    surface_failures += r.failure.empty() ? 0 : 1;

  const std::vector<Analysis_summary_row> analysis_rows = analysis_summary();
  std::size_t analysis_failures = 0;
  for(const Analysis_summary_row& r : analysis_rows)
    analysis_failures += r.failure.empty() ? 0 : 1;

  write_index(rows, polygon, surface_rows, meshes, analysis_rows, dir);
  print_summary(rows);
  std::cout << "\n";
  print_surface_summary(surface_rows);
  std::cout << "\n" << std::flush;
  print_analysis_summary(analysis_rows);
  std::fflush(stdout);
  const std::size_t files = 3 * (rows.size() - failures) + (surface_rows.size() - surface_failures) + 1;
  std::cout << "\nwrote " << files << " files; open " << (dir / "index.md").string() << "\n"
            << fs::canonical(dir).string() << std::endl;
  const std::size_t all_failures = failures + surface_failures + analysis_failures,
                    all_runs = rows.size() + surface_rows.size() + analysis_rows.size();
  if(all_failures)
    throw Input_error(std::to_string(all_failures) + " of " + std::to_string(all_runs) + " demo runs failed");
  return 0;
}

} // namespace cgal_subdiv
