// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv analyse --scheme S [--valence N [--boundary] | --crease K1,K2 | --dart N | --corner N] [--degree K]
//                     [--a A --b B] [--w W] [--json]
#include "analyse_schemes.h"
#include "args.h"
#include "commands.h"
#include "numbers.h"

#include <cmath>
#include <complex>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace cgal_subdiv {
namespace {

const char* const analyse_help = R"(usage: cgal-subdiv analyse --scheme SCHEME [--valence N [--boundary]]
                           [--crease K1,K2 | --dart N | --corner N]
                           [--degree K] [--a A --b B] [--w W] [--json]

Eigen-analysis of a subdivision scheme, from its own masks, in exact rational
arithmetic (Exact_rational): the local subdivision matrix, its eigenvalues,
the smoothness verdict and the limit mask.

  --scheme SCHEME   surface schemes (need --valence):
                      loop, loop-warren, catmull-clark, doo-sabin, sqrt3,
                      butterfly, modified-butterfly, interpolating-sqrt3
                    (linear has no smoothness to analyse and is refused);
                    curve schemes (no --valence):
                      bspline [--degree K], bezier [--degree K], chaikin,
                      corner-cutting [--a A --b B], four-point [--w W]
  --valence N       surfaces: the valence of the interior vertex, 3 <= N <= 32
                    (catmull-clark: 2 <= N; doo-sabin: the number of
                    corners of the central face);
                    with --boundary the number of faces around the border
                    vertex, 1 <= N <= 32 (the exact analysis costs
                    about the cube of the neighbourhood size: seconds at 32)
  --boundary        analyse a border vertex (the sqrt3 schemes over a resting
                    and a refining step; doo-sabin at the border face made
                    from a border vertex with N faces: its vertex face, a
                    border N-gon, for N >= 3, a border quad for N = 2, a
                    corner face for N = 1)
  --crease K1,K2    instead of --valence (loop, loop-warren, catmull-clark):
                    an interior vertex on an infinitely sharp crease, with K1
                    faces on one side and K2 on the other, 1 <= K1, K2 <= 8
                    (loop: not 1,1); judged side by side, each side as a
                    border vertex with as many faces
  --dart N          a dart of valence N, 3 <= N <= 16: a crease ends there
  --corner N        a corner of valence N, 3 <= N <= 16: vertex sharpness 10
  --degree K        bspline and bezier (default 3)
  --a A, --b B      corner-cutting, 0 < A < B < 1 (default 1/4, 3/4)
  --w W             four-point tension, 0 <= W < 1/4 (default 1/16)
  --json            print one JSON object instead of the table (fields in
                    src/cli/README.md)
  -h, --help        show this help

Surfaces: eigenvalues sorted by modulus, the subdominant eigenvalue and its
multiplicity, the necessary C1 condition, the characteristic map test
(regular_injective, not_regular, not_injective, not_applicable), the C1
verdict, the limit mask (centre weight, then the other vertices of the
neighbourhood in the canonical order: ring by ring, counter-clockwise), the
tangent masks, and the limit mask checked by refinement.
Curves: eigenvalues, limit mask over the invariant window, C^k and Holder
bound by the difference-scheme method, predicted convergence rate.

Exit status: 0 on success; 1 if the configuration cannot be analysed (valence,
crease sides, dart or corner valence out of range, border vertex of a scheme
analysed inside only, linear, a parameter out of range); 2 for a malformed
command line (unknown option or scheme, missing --scheme or --valence,
--valence for a curve scheme, a malformed --crease, two configurations,
--crease, --dart or --corner for a scheme whose sharp vertices are not analysed). Errors
are one line on stderr: "cgal-subdiv: error: ...".
)";

const std::vector<Option_spec> analyse_options = {
  {{"--scheme"}, true}, {{"--valence"}, true}, {{"--boundary"}, false}, {{"--crease"}, true},
  {{"--dart"}, true},   {{"--corner"}, true},  {{"--degree"}, true},    {{"--a"}, true},
  {{"--b"}, true},      {{"--w"}, true},       {{"--json"}, false},     {{"-h", "--help"}, false}};

const char* const curve_keywords[] = {"bezier", "bspline", "chaikin", "corner-cutting", "four-point"};

bool is_curve_scheme(const std::string& name)
{
  for(const char* keyword : curve_keywords)
    if(name == keyword)
      return true;
  return false;
}

std::string all_scheme_names()
{
  std::string names;
  for(const Surface_scheme_facts& facts : analysable_surface_schemes())
    names += facts.keyword + ", ";
  for(const char* keyword : curve_keywords)
    names += std::string(keyword) + ", ";
  return names.substr(0, names.size() - 2);
}

void require_applicable(const Parsed_args& args, const std::string& key, bool applies, const std::string& which)
{
  if(args.has(key) && !applies)
    throw Usage_error(key + " applies to " + which + " only");
}

// ------------------------------------------------------------------ text output

std::string number_text(double x)
{
  if(std::abs(x) < 1e-14)
    x = 0;
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}

std::string complex_text(const std::complex<double>& z)
{
  if(std::abs(z.imag()) < 1e-12)
    return number_text(z.real());
  return number_text(z.real()) + (z.imag() < 0 ? " - " : " + ") + number_text(std::abs(z.imag())) + "i";
}

// distinct eigenvalues with their multiplicity, the exact ones as fractions
std::string spectrum_text(const std::vector<std::complex<double>>& values,
                          const std::vector<std::pair<Exact, int>>& exact, std::size_t limit)
{
  std::string text;
  std::size_t shown = 0;
  for(std::size_t i = 0; i < values.size();) {
    std::size_t j = i + 1;
    while(j < values.size() && std::abs(values[j] - values[i]) < 1e-9)
      ++j;
    if(shown == limit) {
      text += ", ... (" + std::to_string(values.size() - i) + " more)";
      break;
    }
    text += (shown ? ", " : "") + complex_text(values[i]);
    for(const auto& e : exact)
      if(std::abs(values[i].imag()) < 1e-12 && nearest_double(e.first) == values[i].real()) {
        const std::string fraction = format_exact(e.first);
        if(fraction != number_text(values[i].real()))
          text += " (" + fraction + ")";
      }
    if(j - i > 1)
      text += " (x" + std::to_string(j - i) + ")";
    i = j;
    ++shown;
  }
  return text;
}

std::string yes_no(bool b)
{
  return b ? "yes" : "no";
}

void row(std::ostream& out, const std::string& key, const std::string& value)
{
  out << "  ";
  out.width(24);
  out << std::left << key << " " << value << "\n";
}

std::string weight_text(const Surface_summary& s, std::size_t label)
{
  return s.exact ? format_exact(s.limit_mask[label]) : number_text(s.limit_mask_double[label]);
}

namespace S = CGAL::Subdiv;

std::string vertex_kind_name(const S::Configuration& where)
{
  switch(where.kind) {
    case S::Vertex_kind::interior:
      return "interior";
    case S::Vertex_kind::border:
      return "border";
    case S::Vertex_kind::crease:
      return "crease";
    case S::Vertex_kind::dart:
      return "dart";
    case S::Vertex_kind::corner:
      return "corner";
  }
  return "unknown";
}

// the rows of a crease's sides (`Surface_summary::sides`)
void print_sides(const Surface_summary& s, std::ostream& out)
{
  row(out, "block triangular", yes_no(s.block_triangular) + " (the crease reads the crease only, no side the other)");
  for(std::size_t i = 0; i < s.sides.size(); ++i) {
    const Surface_summary::Side& side = s.sides[i];
    row(out, "side " + std::to_string(i + 1),
        std::to_string(side.faces) + (side.faces == 1 ? " face" : " faces") + ": the border's spectrum " +
          yes_no(side.same_as_border) + ", C1 necessary " + yes_no(side.c1_necessary) + ", characteristic map " +
          side.characteristic_map + ", C1 " + yes_no(side.c1));
  }
}

void print_surface_table(const Surface_summary& s, std::ostream& out)
{
  const S::Configuration& c = s.configuration;
  const std::string where =
    c.kind == S::Vertex_kind::crease ? "a crease vertex with " + std::to_string(c.first_side) + " and " +
                                         std::to_string(c.second_side()) + " faces on its sides"
    : c.kind == S::Vertex_kind::dart   ? "a dart of valence " + std::to_string(s.valence)
    : c.kind == S::Vertex_kind::corner ? "a corner (vertex sharpness 10) of valence " + std::to_string(s.valence)
    : s.boundary && s.face_centred
      ? "the border face made from a border vertex with " + std::to_string(s.valence) + " faces"
    : s.boundary     ? "a border vertex with " + std::to_string(s.valence) + " faces"
    : s.face_centred ? "an interior face with " + std::to_string(s.valence) + " corners"
                     : "an interior vertex of valence " + std::to_string(s.valence);
  out << s.name << " (" << s.scheme << ") at " << where << "\n";
  row(out, "neighbourhood",
      std::to_string(s.rings) + (s.rings == 1 ? " ring, " : " rings, ") + std::to_string(s.ring.size()) +
        " vertices (local matrix " + std::to_string(s.ring.size()) + " x " + std::to_string(s.ring.size()) + ")");
  row(out, "weights",
      s.exact ? "exact (every weight rational)" : "some weights irrational: their nearest doubles, converted exactly");
  row(out, "rows sum to 1", yes_no(s.rows_sum_to_one));
  row(out, "eigenvalues", spectrum_text(s.eigenvalues, s.exact_eigenvalues, 12));
  row(out, "1 simple and dominant", yes_no(s.one_is_simple_and_dominant));
  row(out, "subdominant", complex_text(s.subdominant) + ", multiplicity " + std::to_string(s.subdominant_multiplicity));
  row(out, "C1 necessary condition",
      yes_no(s.c1_necessary) + (c.kind == S::Vertex_kind::crease     ? " (both sides, below)"
                                : c.kind != S::Vertex_kind::interior ? " (lambda1 >= lambda2 > |lambda3|, both real)"
                                                                     : " (lambda1 = lambda2 real > |lambda3|)"));
  if(c.kind == S::Vertex_kind::crease)
    print_sides(s, out);
  row(
    out, "extended spectrum",
    std::string(s.extended_spectrum_ok ? "ok" : "not ok") +
      (c.kind == S::Vertex_kind::crease ? std::string(" (both sides', as borders)")
                                        : " (" + std::to_string(s.extended_rings) + " rings: largest other |lambda| " +
                                            number_text(s.extended_largest_other) + ")"));
  std::string map = s.characteristic_map;
  if(s.characteristic_map_levels > 0 && s.characteristic_map != "not_applicable")
    map += " (" + std::to_string(s.characteristic_map_levels) + " levels, annulus of rings " +
           std::to_string(s.annulus_inner) + ".." + std::to_string(s.annulus_outer) + ")";
  row(out, "characteristic map", map);
  row(out, "C1", yes_no(s.c1));
  if(!s.limit_mask.empty()) {
    std::string weights;
    for(std::size_t i = 1; i < s.limit_mask.size(); ++i)
      weights += (i > 1 ? " " : "") + weight_text(s, i);
    row(out, s.face_centred ? "limit mask, corner 0" : "limit mask, centre", weight_text(s, 0));
    row(out, "limit mask, others", weights + " (labels 1.." + std::to_string(s.limit_mask.size() - 1) + ")");
  }
  for(int t = 0; t < 2; ++t)
    if(!s.tangent_mask[t].empty()) {
      std::string weights;
      for(std::size_t i = 0; i < s.tangent_mask[t].size(); ++i)
        weights += (i ? " " : "") + number_text(s.tangent_mask[t][i]);
      row(out, "tangent mask " + std::to_string(t + 1), weights);
    }
  if(s.limit_error >= 0)
    row(out, "limit check",
        "refined " + std::to_string(s.host_levels) + " + " + std::to_string(s.cropped_levels) +
          " levels: distance to the predicted limit " + number_text(s.limit_error) +
          " (relative to the neighbourhood)");
}

void print_curve_table(const Curve_summary& s, std::ostream& out)
{
  out << s.name << " (" << s.scheme << ")\n";
  for(std::size_t r = 0; r < s.rules.size(); ++r) {
    std::string terms;
    for(const auto& term : s.rules[r])
      terms += (terms.empty() ? "" : ", ") + format_exact(term.second) + " p[i" +
               (term.first < 0 ? std::to_string(term.first) : "+" + std::to_string(term.first)) + "]";
    row(out, "rule " + s.rule_names[r], terms);
  }
  row(out, "window", "offsets " + std::to_string(s.window_first) + ".." + std::to_string(s.window_last));
  std::string matrix;
  for(const auto& r : s.matrix) {
    matrix += matrix.empty() ? "[" : "; ";
    for(std::size_t c = 0; c < r.size(); ++c)
      matrix += (c ? " " : "") + format_exact(r[c]);
  }
  row(out, "local matrix", matrix + "]");
  row(out, "eigenvalues", spectrum_text(s.eigenvalues, {}, 16));
  row(out, "1 simple and dominant", yes_no(s.one_is_simple_and_dominant));
  row(out, "C1 necessary condition", yes_no(s.c1_necessary) + " (lambda1 = 1/2 simple > |lambda2|)");
  std::string mask;
  for(const Exact& w : s.limit_mask)
    mask += (mask.empty() ? "" : ", ") + format_exact(w);
  row(out, "limit mask",
      mask.empty() ? "none (1 is not a simple eigenvalue)"
                   : mask + " (offsets " + std::to_string(s.window_first) + ".." + std::to_string(s.window_last) + ")");
  row(out, "smoothness", smoothness_text(s));
  row(out, "Holder exponent",
      s.c_infinity       ? "infinite"
      : s.smoothness < 0 ? "-"
                         : ">= " + number_text(s.holder_exponent));
  row(out, "predicted rate", number_text(s.predicted_rate));
}

// ------------------------------------------------------------------ JSON

std::string json_complex(const std::complex<double>& z)
{
  return "[" + json_number(z.real()) + ", " + json_number(z.imag()) + "]";
}

std::string json_eigenvalues(const std::vector<std::complex<double>>& values)
{
  std::string text = "[";
  for(std::size_t i = 0; i < values.size(); ++i)
    text += (i ? ", " : "") + json_complex(values[i]);
  return text + "]";
}

const char* json_bool(bool b)
{
  return b ? "true" : "false";
}

// a crease's sides: [{"faces": k, "same_as_border": ..., "c1_necessary": ..., "characteristic_map": ..., "c1": ...}, ...]
std::string json_sides(const Surface_summary& s)
{
  std::string text = "[";
  for(std::size_t i = 0; i < s.sides.size(); ++i) {
    const Surface_summary::Side& side = s.sides[i];
    text += std::string(i ? ", " : "") + "{\"faces\": " + std::to_string(side.faces) +
            ", \"same_as_border\": " + json_bool(side.same_as_border) +
            ", \"c1_necessary\": " + json_bool(side.c1_necessary) +
            ", \"characteristic_map\": " + json_string(side.characteristic_map) + ", \"c1\": " + json_bool(side.c1) +
            "}";
  }
  return text + "]";
}

void print_surface_json(const Surface_summary& s, std::ostream& out)
{
  std::string weights;
  for(std::size_t i = 1; i < s.limit_mask_double.size(); ++i)
    weights += (i > 1 ? ", " : "") + json_number(s.limit_mask_double[i]);
  out << "{\n"
      << "  \"scheme\": " << json_string(s.scheme) << ",\n"
      << "  \"valence\": " << s.valence << ",\n"
      << "  \"boundary\": " << json_bool(s.boundary) << ",\n"
      << "  \"vertex\": " << json_string(vertex_kind_name(s.configuration)) << ",\n"
      << "  \"sides\": " << json_sides(s) << ",\n"
      << "  \"eigenvalues\": " << json_eigenvalues(s.eigenvalues) << ",\n"
      << "  \"subdominant\": " << json_complex(s.subdominant) << ",\n"
      << "  \"subdominant_multiplicity\": " << s.subdominant_multiplicity << ",\n"
      << "  \"c1_necessary\": " << json_bool(s.c1_necessary) << ",\n"
      << "  \"characteristic_map\": " << json_string(s.characteristic_map) << ",\n"
      << "  \"c1\": " << json_bool(s.c1) << ",\n"
      << "  \"limit_mask\": {\"center\": "
      << (s.limit_mask_double.empty() ? std::string("null") : json_number(s.limit_mask_double.front()))
      << ", \"weights\": [" << weights << "]},\n"
      << "  \"exact\": " << json_bool(s.exact) << "\n"
      << "}\n";
}

void print_curve_json(const Curve_summary& s, const Scheme_spec& spec, std::ostream& out)
{
  std::string parameters;
  switch(spec.kind) {
    case Scheme_kind::bezier:
    case Scheme_kind::bspline:
      parameters = "\"degree\": " + std::to_string(spec.degree);
      break;
    case Scheme_kind::corner_cutting:
      parameters = "\"a\": " + json_number(nearest_double(spec.a)) + ", \"b\": " + json_number(nearest_double(spec.b));
      break;
    case Scheme_kind::four_point:
      parameters = "\"w\": " + json_number(nearest_double(spec.w));
      break;
    case Scheme_kind::chaikin:
      break;
  }
  std::string offsets, weights, fractions;
  for(std::size_t i = 0; i < s.limit_mask.size(); ++i) {
    const std::string separator = i ? ", " : "";
    offsets += separator + std::to_string(s.window_first + static_cast<int>(i));
    weights += separator + json_number(nearest_double(s.limit_mask[i]));
    fractions += separator + json_string(format_exact(s.limit_mask[i]));
  }
  const std::complex<double> subdominant =
    s.eigenvalues.size() > 1 ? s.eigenvalues[1] : std::complex<double>(std::nan(""), std::nan(""));
  const bool proven = !s.c_infinity && s.smoothness >= 0;
  out << "{\n"
      << "  \"scheme\": " << json_string(s.scheme) << ",\n"
      << "  \"parameters\": {" << parameters << "},\n"
      << "  \"window\": [" << s.window_first << ", " << s.window_last << "],\n"
      << "  \"eigenvalues\": " << json_eigenvalues(s.eigenvalues) << ",\n"
      << "  \"subdominant\": " << json_complex(subdominant) << ",\n"
      << "  \"c1_necessary\": " << json_bool(s.c1_necessary) << ",\n"
      << "  \"limit_mask\": {\"offsets\": [" << offsets << "], \"weights\": [" << weights << "], \"fractions\": ["
      << fractions << "]},\n"
      << "  \"converges\": " << json_bool(s.converges) << ",\n"
      << "  \"c_infinity\": " << json_bool(s.c_infinity) << ",\n"
      << "  \"smoothness\": " << (s.c_infinity ? std::string("null") : std::to_string(s.smoothness)) << ",\n"
      << "  \"holder\": "
      << (s.c_infinity ? std::string("null")
          : proven     ? json_number(s.holder_exponent)
                       : "0")
      << ",\n"
      << "  \"c1\": " << json_bool(s.c_infinity || s.smoothness >= 1) << ",\n"
      << "  \"predicted_rate\": " << json_number(s.predicted_rate) << ",\n"
      << "  \"exact\": true\n"
      << "}\n";
}

Scheme_spec parse_curve_spec(const Parsed_args& args, const std::string& name)
{
  Scheme_spec spec;
  for(Scheme_kind kind : {Scheme_kind::bezier, Scheme_kind::bspline, Scheme_kind::chaikin, Scheme_kind::corner_cutting,
                          Scheme_kind::four_point})
    if(name == curve_keywords[static_cast<int>(kind)])
      spec.kind = kind;
  require_applicable(args, "--degree", spec.kind == Scheme_kind::bspline || spec.kind == Scheme_kind::bezier,
                     "bspline and bezier");
  require_applicable(args, "--a", spec.kind == Scheme_kind::corner_cutting, "corner-cutting");
  require_applicable(args, "--b", spec.kind == Scheme_kind::corner_cutting, "corner-cutting");
  require_applicable(args, "--w", spec.kind == Scheme_kind::four_point, "four-point");
  spec.degree = args.integer("--degree", spec.degree);
  spec.a = args.number("--a", spec.a);
  spec.b = args.number("--b", spec.b);
  spec.w = args.number("--w", spec.w);
  return spec;
}

// the sharp configuration of --crease K1,K2, --dart N or --corner N (at most one), if any
std::optional<S::Configuration> sharp_configuration(const Parsed_args& args)
{
  int given = 0;
  for(const char* option : {"--crease", "--dart", "--corner"})
    given += args.has(option) ? 1 : 0;
  if(given > 1)
    throw Usage_error("--crease, --dart and --corner each give a configuration: give one");
  if(args.has("--dart"))
    return S::Configuration::dart(args.integer("--dart", 0));
  if(args.has("--corner"))
    return S::Configuration::corner(args.integer("--corner", 0));
  if(!args.has("--crease"))
    return std::nullopt;
  const std::string value = args.value("--crease");
  const std::size_t comma = value.find(',');
  const auto whole = [&](const std::string& text) {
    if(text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos)
      throw Usage_error("--crease expects K1,K2 (the faces on each side, two whole numbers), got '" + value + "'");
    return std::stoi(text);
  };
  if(comma == std::string::npos)
    whole("");
  return S::Configuration::crease(whole(value.substr(0, comma)), whole(value.substr(comma + 1)));
}

} // namespace

int analyse_command(const std::vector<std::string>& arguments)
{
  const Parsed_args args = scan_args(arguments, analyse_options, "analyse");
  if(args.has("-h")) {
    std::cout << analyse_help;
    return 0;
  }
  if(!args.positional.empty())
    throw Usage_error("unexpected argument '" + args.positional.front() + "'; see 'cgal-subdiv analyse --help'");
  if(!args.has("--scheme"))
    throw Usage_error("missing --scheme (" + all_scheme_names() + ")");
  const std::string name = args.value("--scheme");
  const bool json = args.has("--json");
  std::ostringstream out;
  if(is_curve_scheme(name)) {
    if(args.has("--valence"))
      throw Usage_error("--valence applies to surface schemes only (a curve scheme has no extraordinary points)");
    require_applicable(args, "--boundary", false, "surface schemes");
    for(const char* option : {"--crease", "--dart", "--corner"})
      require_applicable(args, option, false, "surface schemes");
    const Scheme_spec spec = parse_curve_spec(args, name);
    const Curve_summary summary = analyse_curve(spec);
    if(json)
      print_curve_json(summary, spec, out);
    else
      print_curve_table(summary, out);
  } else {
    if(name != "linear" && !find_analysable_surface_scheme(name))
      throw Usage_error("unknown scheme '" + name + "' (expected " + all_scheme_names() + ")");
    require_applicable(args, "--degree", false, "bspline and bezier");
    require_applicable(args, "--a", false, "corner-cutting");
    require_applicable(args, "--b", false, "corner-cutting");
    require_applicable(args, "--w", false, "four-point");
    const Surface_scheme_facts* facts = find_analysable_surface_scheme(name);
    const std::optional<S::Configuration> sharp = sharp_configuration(args);
    if(sharp) {
      if(args.has("--valence") || args.has("--boundary"))
        throw Usage_error("--crease, --dart and --corner give the configuration: no --valence or --boundary with them");
      for(const char* option : {"--crease", "--dart", "--corner"})
        require_applicable(args, option, facts && facts->sharp_analysis,
                           "loop, loop-warren and catmull-clark (the schemes whose sharp vertices are analysed)");
    }
    if(!sharp && !args.has("--valence") && name != "linear")
      throw Usage_error("missing --valence N (the valence of the vertex to analyse)");
    const Surface_summary summary = sharp ? analyse_sharp_vertex(name, *sharp)
                                          : analyse_surface(name, args.integer("--valence", 0), args.has("--boundary"));
    if(json)
      print_surface_json(summary, out);
    else
      print_surface_table(summary, out);
  }
  std::cout << out.str();
  return 0;
}

} // namespace cgal_subdiv
