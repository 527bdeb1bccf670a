// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv curve INPUT -o OUTPUT --scheme S --levels N [options]
#include "args.h"
#include "commands.h"
#include "curve.h"
#include "files.h"
#include "numbers.h"
#include "report.h"
#include "svg.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace cgal_subdiv {
namespace {

const char* const curve_help = R"(usage: cgal-subdiv curve INPUT -o OUTPUT --scheme SCHEME (--levels N | --tolerance T)
                         [--closed] [--degree K] [--a A --b B] [--w W]
                         [--end-rule shrink|keep-ends] [--exact] [--svg FILE] [--report]

Refines the polyline in INPUT with a curve subdivision scheme and writes the
new points to OUTPUT.

  INPUT                 plain text, one point per line with 2 or 3 coordinates
                        ("1.5 -2", "17/3 0 1"), '#' starts a comment, blank
                        lines are skipped; or CGAL's polygon format: a count n,
                        then 2n coordinates laid out in any lines. Of a file
                        with holes or several polygons the first polygon is
                        read and what was ignored is said on stderr.
                        Coordinates are decimals (0.1, 2e-3) or fractions
                        (17/3) and are read exactly.
  -o, --output OUTPUT   where the refined points go: one point per line,
                        17 significant digits, or exact fractions with --exact.
                        Written to a temporary file and renamed at the end, so
                        that a failed run leaves no OUTPUT behind.
  --scheme SCHEME       bezier          chain of Bezier segments of degree K,
                                        de Casteljau split at t = 1/2; open: m*K+1
                                        points, closed: m*K points
                        bspline         uniform B-spline of degree K (Lane-Riesenfeld)
                        chaikin         Chaikin's corner cutting (1/4, 3/4)
                        corner-cutting  corner cutting with parameters A < B
                        four-point      interpolating four-point scheme, tension W
  --levels N            number of refinement levels (N >= 0)
  --tolerance T         bezier only, instead of --levels: split each segment until
                        its control points are within T of its chord
  --closed              the polyline is closed (a last point equal to the first
                        is dropped)
  --degree K            degree of bspline and bezier (default 3)
  --a A, --b B          corner-cutting parameters, 0 < A < B < 1 (default 1/4, 3/4)
  --w W                 four-point tension, 0 <= W < 1/4 (default 1/16)
  --end-rule RULE       ends of an open polyline (not bezier):
                        shrink     only new points whose whole stencil lies on the
                                   polyline (default, as in the lecture notes)
                        keep-ends  the end points stay, the limit runs from the
                                   first to the last point
  --exact               compute in Simple_cartesian<Exact_rational>; the output
                        holds exact fractions (default: Simple_cartesian<double>)
  --svg FILE            also write an SVG figure: control polygon, levels, and the
                        discrete curvature of the result against arc length
  --report              print on stdout the distance between successive levels
                        and the eigen-analysis of the scheme (spectrum, limit
                        mask, smoothness verdict, predicted convergence rate)
  -h, --help            show this help

A, B, W and T are decimals or fractions (1/16).

Exit status: 0 on success; 1 if the input or a parameter cannot be used (file
missing or unreadable, a line that does not parse, too few points, a parameter
out of range, an output too large for memory); 2 for a malformed command line
(unknown option or scheme, missing -o, INPUT, --scheme or --levels). Errors are
one line on stderr: "cgal-subdiv: error: ...".
)";

const std::vector<Option_spec> curve_options = {{{"-o", "--output"}, true},
                                                {{"--scheme"}, true},
                                                {{"--levels"}, true},
                                                {{"--tolerance"}, true},
                                                {{"--closed"}, false},
                                                {{"--degree"}, true},
                                                {{"--a"}, true},
                                                {{"--b"}, true},
                                                {{"--w"}, true},
                                                {{"--end-rule"}, true},
                                                {{"--exact"}, false},
                                                {{"--svg"}, true},
                                                {{"--report"}, false},
                                                {{"-h", "--help"}, false}};

struct Curve_command
{
  std::string input;
  std::string output;
  std::string svg;
  bool report = false;
  Curve_job job;
};

Scheme_kind parse_scheme_kind(const std::string& name)
{
  for(Scheme_kind kind : {Scheme_kind::bezier, Scheme_kind::bspline, Scheme_kind::chaikin, Scheme_kind::corner_cutting,
                          Scheme_kind::four_point})
    if(name == scheme_keyword(kind))
      return kind;
  throw Usage_error("unknown scheme '" + name + "' (expected bezier, bspline, chaikin, corner-cutting or four-point)");
}

// an option that the chosen scheme has no use for is a mistake, not a no-op
void require_applicable(const Parsed_args& args, const std::string& key, bool applies, const std::string& which)
{
  if(args.has(key) && !applies)
    throw Usage_error(key + " applies to " + which + " only");
}

Scheme_spec parse_scheme(const Parsed_args& args)
{
  if(!args.has("--scheme"))
    throw Usage_error("missing --scheme (bezier, bspline, chaikin, corner-cutting or four-point)");
  Scheme_spec spec;
  spec.kind = parse_scheme_kind(args.value("--scheme"));
  const bool has_degree = spec.kind == Scheme_kind::bspline || spec.kind == Scheme_kind::bezier;
  require_applicable(args, "--degree", has_degree, "bspline and bezier");
  require_applicable(args, "--a", spec.kind == Scheme_kind::corner_cutting, "corner-cutting");
  require_applicable(args, "--b", spec.kind == Scheme_kind::corner_cutting, "corner-cutting");
  require_applicable(args, "--w", spec.kind == Scheme_kind::four_point, "four-point");
  spec.degree = args.integer("--degree", spec.degree);
  spec.a = args.number("--a", spec.a);
  spec.b = args.number("--b", spec.b);
  spec.w = args.number("--w", spec.w);
  return spec;
}

Refine_spec parse_refine(const Parsed_args& args, Scheme_kind kind)
{
  Refine_spec refine;
  refine.closed = args.has("--closed");
  require_applicable(args, "--tolerance", kind == Scheme_kind::bezier, "bezier");
  require_applicable(args, "--end-rule", kind != Scheme_kind::bezier && !refine.closed,
                     "open polylines of bspline, chaikin, corner-cutting and four-point");
  if(args.has("--tolerance") == args.has("--levels"))
    throw Usage_error(args.has("--levels") ? "give --levels or --tolerance, not both" : "missing --levels N");
  refine.levels = args.integer("--levels", 0);
  refine.use_tolerance = args.has("--tolerance");
  refine.tolerance = args.number("--tolerance", Exact(0));
  if(refine.use_tolerance && !args.has("--exact") && refine.tolerance > 0 && nearest_double(refine.tolerance) == 0)
    throw Input_error("--tolerance " + args.value("--tolerance") +
                      " is below the smallest double: take a larger one, or --exact");
  const std::string rule = args.value("--end-rule", "shrink");
  if(rule != "shrink" && rule != "keep-ends")
    throw Usage_error("unknown end rule '" + rule + "' (expected shrink or keep-ends)");
  refine.end_rule = rule == "shrink" ? CGAL::Subdiv::End_rule::shrink : CGAL::Subdiv::End_rule::keep_ends;
  return refine;
}

Curve_command parse_curve_command(const Parsed_args& args)
{
  Curve_command command;
  if(args.positional.empty())
    throw Usage_error("missing INPUT; see 'cgal-subdiv curve --help'");
  if(args.positional.size() > 1)
    throw Usage_error("unexpected argument '" + args.positional[1] + "' (only one INPUT)");
  if(!args.has("-o") || args.value("-o").empty())
    throw Usage_error("missing -o OUTPUT");
  command.input = args.positional.front();
  command.output = args.value("-o");
  command.svg = args.value("--svg");
  if(command.svg == command.output)
    throw Usage_error("-o and --svg name the same file");
  command.report = args.has("--report");
  command.job.exact = args.has("--exact");
  command.job.scheme = parse_scheme(args);
  command.job.refine = parse_refine(args, command.job.scheme.kind);
  return command;
}

// a closed polygon written with its first point repeated at the end
void drop_closing_point(Input_polyline& input)
{
  if(input.points.size() > 1 && input.points.front() == input.points.back()) {
    input.points.pop_back();
    input.notes.push_back("dropped the last point, equal to the first, of the closed polygon");
  }
}

} // namespace

int curve_command(const std::vector<std::string>& arguments)
{
  const Parsed_args args = scan_args(arguments, curve_options, "curve");
  if(args.has("-h")) {
    std::cout << curve_help;
    return 0;
  }
  const Curve_command command = parse_curve_command(args);
  Input_polyline input = read_polyline(command.input);
  if(command.job.refine.closed)
    drop_closing_point(input);

  Atomic_file output(command.output);
  Figure figure;
  run_curve(command.job, input, output.stream(), command.svg.empty() ? nullptr : &figure);
  std::unique_ptr<Atomic_file> svg;
  if(!command.svg.empty()) {
    svg = std::make_unique<Atomic_file>(command.svg);
    write_svg(figure, svg->stream());
  }
  std::ostringstream report;
  if(command.report)
    write_report(command.job, input, report);

  // everything worked: now the files appear (all written before any is
  // renamed), and the messages
  output.finish();
  if(svg)
    svg->finish();
  output.commit();
  if(svg)
    svg->commit();
  for(const std::string& note : input.notes)
    std::cerr << "cgal-subdiv: note: " << note << '\n';
  std::cout << report.str();
  return 0;
}

} // namespace cgal_subdiv
