// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-doc-tables OUTPUT_DIR: writes the documentation tables of every
// scheme (rules read from the masks, eigenvalues and verdicts by valence,
// limit and tangent masks, curve smoothness; an overview of all schemes) as
// Markdown for reading and CSV for machines. The output is deterministic (no
// timestamps, fixed number formats); doc/tables/ is this tool's output and a
// test checks that it is up to date.
#include "../cli/analyse_schemes.h"
#include "../cli/numbers.h"
#include "limit_tables.h"
#include "rules.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using cgal_subdiv::Curve_summary;
using cgal_subdiv::Exact;
using cgal_subdiv::Scheme_kind;
using cgal_subdiv::Scheme_spec;
using cgal_subdiv::Surface_scheme_facts;
using cgal_subdiv::Surface_summary;
using subdiv_doc_tables::Rule;
using subdiv_doc_tables::Rule_term;

constexpr int first_valence = 3, last_valence = 16, last_border = 8;
using cgal_subdiv::max_crease_side;

// ------------------------------------------------------------------ numbers

// computed doubles: 10 significant digits (robust to the last bits of the
// eigen-solver), tiny values as 0
std::string num(double x, int digits = 10)
{
  if(std::abs(x) < 1e-12)
    x = 0;
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

std::string complex_text(const std::complex<double>& z)
{
  if(std::abs(z.imag()) < 1e-9)
    return num(z.real());
  return num(z.real()) + (z.imag() < 0 ? "-" : "+") + num(std::abs(z.imag())) + "i";
}

std::string fraction(const Exact& x)
{
  return cgal_subdiv::format_exact(x);
}
double to_double(const Exact& x)
{
  return cgal_subdiv::nearest_double(x);
}

// a weight: the exact fraction, or "≈" and 12 digits for a rounded irrational one
std::string weight_text(const Exact& w, bool rational)
{
  return rational ? fraction(w) : "≈" + num(to_double(w), 12);
}

std::string csv_field(const std::string& text)
{
  if(text.find_first_of(",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for(char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_row(const std::vector<std::string>& fields)
{
  std::string row;
  for(std::size_t i = 0; i < fields.size(); ++i)
    row += (i ? "," : "") + csv_field(fields[i]);
  return row + "\n";
}

std::string yes_no(bool b)
{
  return b ? "yes" : "no";
}

// "3..5, 7, 9..16" from a sorted list
std::string ranges(const std::vector<int>& values)
{
  std::string text;
  for(std::size_t i = 0; i < values.size();) {
    std::size_t j = i;
    while(j + 1 < values.size() && values[j + 1] == values[j] + 1)
      ++j;
    text += (text.empty() ? "" : ", ") + std::to_string(values[i]);
    if(j > i)
      text += (j == i + 1 ? ", " : "..") + std::to_string(values[j]);
    i = j + 1;
  }
  return text;
}

// ------------------------------------------------------------------ files

class Output
{
public:
  explicit Output(const fs::path& dir) : m_dir(dir) {}
  std::ostringstream& file(const std::string& name) { return m_files[name]; }
  void write_all() const
  {
    for(const auto& entry : m_files) {
      const fs::path path = m_dir / entry.first;
      std::ofstream out(path, std::ios::binary);
      out << entry.second.str();
      if(!out)
        throw std::runtime_error("cannot write " + path.string());
    }
  }
  std::vector<std::string> names() const
  {
    std::vector<std::string> result;
    for(const auto& entry : m_files)
      result.push_back(entry.first);
    return result;
  }

private:
  fs::path m_dir;
  std::map<std::string, std::ostringstream> m_files;
};

// ------------------------------------------------------------------ rules

// the terms of one ring: "a (all n)", "(a, b) x k", or "[label] a, [label] b, ..."
std::string ring_text(const std::vector<const Rule_term*>& terms, int ring_size)
{
  std::vector<std::string> values;
  for(const Rule_term* t : terms)
    values.push_back(weight_text(t->weight, t->rational));
  if(static_cast<int>(values.size()) == ring_size && ring_size > 1)
    for(std::size_t period : {std::size_t(1), std::size_t(2)}) {
      if(values.size() % period != 0 || values.size() == period)
        continue;
      bool periodic = true;
      for(std::size_t i = period; i < values.size(); ++i)
        periodic = periodic && values[i] == values[i - period];
      if(!periodic)
        continue;
      if(period == 1)
        return values[0] + " (all " + std::to_string(values.size()) + ")";
      return "(" + values[0] + ", " + values[1] + ") x " + std::to_string(values.size() / 2);
    }
  std::string text;
  for(const Rule_term* t : terms)
    text += (text.empty() ? "" : ", ") + std::string("[") + std::to_string(t->label) + "] " +
            weight_text(t->weight, t->rational);
  return text;
}

std::string rule_text(const Rule& rule, bool face_centred)
{
  std::string text;
  for(std::size_t r = 0; r < rule.ring_sizes.size(); ++r) {
    std::vector<const Rule_term*> terms;
    for(const Rule_term& t : rule.terms)
      if(t.ring == static_cast<int>(r))
        terms.push_back(&t);
    if(terms.empty())
      continue;
    std::string part;
    if(r == 0 && !face_centred)
      part = "centre " + weight_text(terms.front()->weight, terms.front()->rational);
    else
      part =
        (r == 0 ? std::string("corners: ") : "ring " + std::to_string(r) + ": ") + ring_text(terms, rule.ring_sizes[r]);
    text += (text.empty() ? "" : "; ") + part;
  }
  return text;
}

bool all_rational(const std::vector<Rule>& rules)
{
  for(const Rule& rule : rules)
    for(const Rule_term& t : rule.terms)
      if(!t.rational)
        return false;
  return true;
}

// ------------------------------------------------------------------ surface schemes

struct Scheme_tables
{
  const Surface_scheme_facts* facts = nullptr;
  std::string name;
  std::vector<Surface_summary> interior, border;
  std::vector<std::vector<Rule>> interior_rules, border_rules; // by configuration
  // sharp vertices (schemes with sharpness tags): creases by (k1, k2), darts and corners by valence
  std::vector<Surface_summary> crease, dart, corner;
};

int regular_valence(const Scheme_tables& t)
{
  if(t.facts->dual || t.facts->keyword == "catmull-clark")
    return 4;
  return 6;
}

std::string where(const Scheme_tables& t)
{
  return t.facts->dual ? "n (corners of the face)" : "n";
}

std::string eigen_row(const Surface_summary& s)
{
  const double third = s.eigenvalues.size() > 3 ? std::abs(s.eigenvalues[3]) : 0.0;
  std::string map = s.characteristic_map;
  return "| " + std::to_string(s.valence) + " | " + std::to_string(s.ring.size()) + " | " + yes_no(s.exact) + " | " +
         complex_text(s.subdominant) + " | " + std::to_string(s.subdominant_multiplicity) + " | " + num(third) + " | " +
         yes_no(s.c1_necessary) + " | " + (s.extended_spectrum_ok ? "ok" : "no") + " (" +
         num(s.extended_largest_other, 6) + ") | " + map + " | **" + (s.c1 ? "C1" : "not C1") + "** |\n";
}

std::string leading_eigenvalues(const Surface_summary& s, std::size_t count)
{
  std::string text;
  for(std::size_t i = 0; i < s.eigenvalues.size() && i < count; ++i)
    text += (i ? ", " : "") + complex_text(s.eigenvalues[i]);
  if(s.eigenvalues.size() > count)
    text += ", ... (" + std::to_string(s.eigenvalues.size()) + " in all)";
  return text;
}

// the limit mask restricted to rings 0 and 1, as a rule
Rule limit_rule(const Surface_summary& s)
{
  Rule rule;
  for(std::size_t i = 0; i < s.limit_mask.size(); ++i) {
    const int r = s.ring[i];
    if(static_cast<int>(rule.ring_sizes.size()) <= r)
      rule.ring_sizes.resize(static_cast<std::size_t>(r) + 1, 0);
    ++rule.ring_sizes[static_cast<std::size_t>(r)];
    if(s.limit_mask[i] != Exact(0) && r <= 1)
      rule.terms.push_back({static_cast<int>(i), r, s.limit_mask[i], s.exact});
  }
  return rule;
}

std::string tangent_text(const Surface_summary& s, int which)
{
  const std::vector<double>& t = s.tangent_mask[which];
  if(!s.c1_necessary || t.empty())
    return "-";
  std::string text;
  for(std::size_t i = 0; i < t.size(); ++i)
    if(s.ring[i] <= 1)
      text += (text.empty() ? "" : " ") + num(t[i], 6);
  return text;
}

std::string check_text(const Surface_summary& s)
{
  if(s.limit_error < 0)
    return "-";
  return s.limit_error < 1e-12 ? "< 1e-12" : num(s.limit_error, 2);
}

void write_scheme(const Scheme_tables& t, Output& out)
{
  std::ostringstream& md = out.file("surface-" + t.facts->keyword + ".md");
  const bool rational = [&] {
    for(const auto& rules : t.interior_rules)
      if(!all_rational(rules))
        return false;
    for(const auto& rules : t.border_rules)
      if(!all_rational(rules))
        return false;
    return true;
  }();
  md << "# " << t.name << " (`" << t.facts->keyword << "`)\n\n"
     << "Generated by `subdiv-doc-tables` from the scheme's own mask; do not edit.\n\n"
     << "- split: " << t.facts->split << "; " << (t.facts->dual ? "dual (centred at faces)" : "primal") << "; "
     << (t.facts->interpolating ? "interpolating" : "approximating") << "\n"
     << "- weights: "
     << (rational ? "all rational at the configurations below: exact in exact kernels"
                  : "some irrational (marked ≈): exact kernels get the nearest double, converted exactly")
     << "\n- analysis: exact (`Exact_rational`) local subdivision matrices, eigenvalues in double; "
     << "see `analyse_surface_scheme()` for every step\n\n";

  md << "## Rules\n\n"
     << "Each rule is the list of weights a mask reports for one new vertex, read through a `Stencil` "
     << "accumulator on a patch built as a real mesh. Old vertices are given by their label in the "
     << "canonical order of the analysis: "
     << (t.facts->dual ? "labels 0..n-1 are the corners of the central face (at the border: from the first one "
                         "after its border edges), then ring by ring"
                       : "label 0 is the centre, then ring by ring, counter-clockwise, label 1 first")
     << " (`[label] weight`; `w (all k)`: the same weight for the k vertices of the ring; "
     << "`(a, b) x k`: a and b alternating).\n\n";
  const auto rule_tables = [&](const std::vector<std::vector<Rule>>& by_config,
                               const std::vector<Surface_summary>& configs, const std::string& label) {
    if(by_config.empty())
      return;
    for(std::size_t r = 0; r < by_config.front().size(); ++r) {
      md << "### " << by_config.front()[r].name << " rule\n\n"
         << by_config.front()[r].description << ".\n\n"
         << "| " << label << " | weights |\n|---:|---|\n";
      for(std::size_t c = 0; c < by_config.size(); ++c)
        if(r < by_config[c].size())
          md << "| " << configs[c].valence << " | " << rule_text(by_config[c][r], t.facts->dual) << " |\n";
      md << "\n";
    }
  };
  rule_tables(t.interior_rules, t.interior, where(t));
  rule_tables(t.border_rules, t.border, "k (faces)");

  const auto analysis_tables = [&](const std::vector<Surface_summary>& configs, const std::string& title,
                                   const std::string& label) {
    if(configs.empty())
      return;
    md << "## " << title << "\n\n"
       << "| " << label << " | size | exact | lambda1 | mult. | abs(lambda3) | C1 necessary | extended spectrum "
       << "(largest other) | characteristic map | verdict |\n"
       << "|---:|---:|---|---:|---:|---:|---|---|---|---|\n";
    for(const Surface_summary& s : configs)
      md << eigen_row(s);
    md << "\nLeading eigenvalues (by modulus):\n\n| " << label << " | eigenvalues |\n|---:|---|\n";
    for(const Surface_summary& s : configs)
      md << "| " << s.valence << " | " << leading_eigenvalues(s, 8) << " |\n";
    md << "\nLimit mask (rings 0 and 1; " << (configs.front().exact ? "exact" : "≈ where rounded")
       << "), tangent masks (left eigenvectors of the subdominant pair on rings 0 and 1, orthonormal, "
       << "shown when the C1 condition holds), and the check of the limit mask by refinement (distance "
       << "to the predicted limit, relative to the neighbourhood):\n\n"
       << "| " << label << " | limit mask | tangent 1 | tangent 2 | check |\n|---:|---|---|---|---|\n";
    for(const Surface_summary& s : configs)
      md << "| " << s.valence << " | " << rule_text(limit_rule(s), s.face_centred) << " | " << tangent_text(s, 0)
         << " | " << tangent_text(s, 1) << " | " << check_text(s) << " |\n";
    md << "\n";
  };
  analysis_tables(t.interior,
                  t.facts->dual ? "Eigen-analysis at faces with n corners" : "Eigen-analysis at interior vertices",
                  where(t));
  analysis_tables(t.border,
                  t.facts->dual ? "Eigen-analysis at border faces made from border vertices with k faces "
                                  "(k >= 3: the vertex face, a border k-gon; k = 2: a border quad of the "
                                  "regular border; k = 1: the corner face)"
                                : "Eigen-analysis at border vertices with k faces",
                  "k");
  if(t.border.empty())
    md << "Border vertices: not analysed.\n";
  if(t.crease.empty())
    return;
  md << "\n## Sharp vertices (infinitely sharp tags)\n\n"
     << "OpenSubdiv's rules (`Sdc::Crease`), taken from the mask through `Sharpness_tags` as `subdivide()` "
     << "takes them, on a patch whose sharp edges are sharp along their whole ray (so the configuration is the "
     << "same on every level). Semi-sharp values are not analysed: their sharpness decays with the level, so no "
     << "stationary local matrix exists. See doc/sharp_features.md.\n\n"
     << "### Crease vertices with k1 and k2 faces on their sides\n\n"
     << "A crease is judged side by side: its matrix is block triangular (the crease rows read the crease only, "
     << "neither side reads the other), each side's block has the spectrum of the border with as many faces "
     << "(checked), and takes that border analysis's verdicts; the crease is C1 on both sides when both are. "
     << "Verdicts, k1 down, k2 across:\n\n| k1 \\ k2 |";
  for(int k2 = 1; k2 <= max_crease_side; ++k2)
    md << " " << k2 << " |";
  md << "\n|---:|";
  for(int k2 = 1; k2 <= max_crease_side; ++k2)
    md << "---|";
  md << "\n";
  const auto crease_at = [&](int k1, int k2) -> const Surface_summary* {
    for(const Surface_summary& s : t.crease)
      if(s.configuration.first_side == k1 && s.configuration.second_side() == k2)
        return &s;
    return nullptr;
  };
  for(int k1 = 1; k1 <= max_crease_side; ++k1) {
    md << "| " << k1 << " |";
    for(int k2 = 1; k2 <= max_crease_side; ++k2) {
      const Surface_summary* s = crease_at(k1, k2);
      md << " " << (s == nullptr ? "-" : s->c1 ? "C1" : "not C1") << " |";
    }
    md << "\n";
  }
  md << "\n(-: an interior vertex of valence 2 in a triangle mesh, which no patch holds.)\n\n"
     << "| k1, k2 | size | lambda1 | leading eigenvalues | block triangular | sides' spectra = borders' | "
     << "limit mask | check | verdict |\n|---|---:|---:|---|---|---|---|---|---|\n";
  for(const Surface_summary& s : t.crease) {
    bool borders = s.sides.size() == 2;
    for(const Surface_summary::Side& side : s.sides)
      borders = borders && side.same_as_border;
    md << "| " << s.configuration.first_side << ", " << s.configuration.second_side() << " | " << s.ring.size() << " | "
       << complex_text(s.subdominant) << " | " << leading_eigenvalues(s, 6) << " | " << yes_no(s.block_triangular)
       << " | " << yes_no(borders) << " | " << rule_text(limit_rule(s), false) << " | " << check_text(s) << " | **"
       << (s.c1 ? "C1" : "not C1") << "** |\n";
  }
  md << "\n";
  analysis_tables(t.dart, "Eigen-analysis at darts of valence n (a crease ends at the vertex)", "n");
  analysis_tables(t.corner, "Eigen-analysis at corners of valence n (vertex sharpness 10, smooth edges)", "n");
}

// the sharp vertices of every scheme that has them, one row per configuration
void write_sharp_csv(const std::vector<Scheme_tables>& all, Output& out)
{
  std::ostringstream& csv = out.file("surface_sharp.csv");
  csv << csv_row({"scheme", "vertex", "valence", "k1", "k2", "size", "exact", "lambda1_re", "lambda1_im",
                  "multiplicity", "abs_lambda3", "block_triangular", "sides_are_borders", "c1_necessary",
                  "characteristic_map", "c1", "limit_centre"});
  for(const Scheme_tables& t : all)
    for(const auto* configs : {&t.crease, &t.dart, &t.corner})
      for(const Surface_summary& s : *configs) {
        const bool crease = !s.sides.empty();
        bool borders = s.sides.size() == 2;
        for(const Surface_summary::Side& side : s.sides)
          borders = borders && side.same_as_border;
        csv << csv_row({s.scheme,
                        configs == &t.crease ? "crease"
                        : configs == &t.dart ? "dart"
                                             : "corner",
                        std::to_string(s.valence), crease ? std::to_string(s.configuration.first_side) : "",
                        crease ? std::to_string(s.configuration.second_side()) : "", std::to_string(s.ring.size()),
                        s.exact ? "1" : "0", num(s.subdominant.real()), num(s.subdominant.imag()),
                        std::to_string(s.subdominant_multiplicity),
                        num(s.eigenvalues.size() > 3 ? std::abs(s.eigenvalues[3]) : 0.0),
                        crease ? (s.block_triangular ? "1" : "0") : "", crease ? (borders ? "1" : "0") : "",
                        s.c1_necessary ? "1" : "0", s.characteristic_map, s.c1 ? "1" : "0",
                        s.limit_mask.empty() ? "" : num(s.limit_mask_double[0])});
      }
}

void write_surface_csv(const std::vector<Scheme_tables>& all, Output& out)
{
  std::ostringstream& analysis = out.file("surface_analysis.csv");
  std::ostringstream& eigen = out.file("surface_eigenvalues.csv");
  std::ostringstream& masks = out.file("surface_masks.csv");
  std::ostringstream& rules = out.file("surface_rules.csv");
  analysis << csv_row({"scheme", "boundary", "valence", "size", "exact", "lambda1_re", "lambda1_im", "multiplicity",
                       "abs_lambda3", "c1_necessary", "extended_spectrum_ok", "characteristic_map", "c1",
                       "limit_centre"});
  eigen << csv_row({"scheme", "boundary", "valence", "index", "re", "im"});
  masks << csv_row(
    {"scheme", "boundary", "valence", "label", "ring", "limit", "limit_fraction", "tangent1", "tangent2"});
  rules << csv_row({"scheme", "rule", "boundary", "valence", "label", "ring", "weight", "fraction"});
  for(const Scheme_tables& t : all)
    for(const auto* configs : {&t.interior, &t.border})
      for(const Surface_summary& s : *configs) {
        const std::string b = s.boundary ? "1" : "0", n = std::to_string(s.valence);
        analysis << csv_row({s.scheme, b, n, std::to_string(s.ring.size()), s.exact ? "1" : "0",
                             num(s.subdominant.real()), num(s.subdominant.imag()),
                             std::to_string(s.subdominant_multiplicity),
                             num(s.eigenvalues.size() > 3 ? std::abs(s.eigenvalues[3]) : 0.0),
                             s.c1_necessary ? "1" : "0", s.extended_spectrum_ok ? "1" : "0", s.characteristic_map,
                             s.c1 ? "1" : "0", s.limit_mask.empty() ? "" : num(s.limit_mask_double[0])});
        for(std::size_t i = 0; i < s.eigenvalues.size(); ++i)
          eigen << csv_row({s.scheme, b, n, std::to_string(i), num(s.eigenvalues[i].real()),
                            num(std::abs(s.eigenvalues[i].imag()) < 1e-9 ? 0.0 : s.eigenvalues[i].imag())});
        for(std::size_t i = 0; i < s.limit_mask.size(); ++i)
          masks << csv_row({s.scheme, b, n, std::to_string(i), std::to_string(s.ring[i]), num(s.limit_mask_double[i]),
                            s.exact ? fraction(s.limit_mask[i]) : "",
                            s.c1_necessary && !s.tangent_mask[0].empty() ? num(s.tangent_mask[0][i], 6) : "",
                            s.c1_necessary && !s.tangent_mask[1].empty() ? num(s.tangent_mask[1][i], 6) : ""});
      }
  for(const Scheme_tables& t : all)
    for(int side = 0; side < 2; ++side) {
      const auto& by_config = side ? t.border_rules : t.interior_rules;
      const auto& configs = side ? t.border : t.interior;
      for(std::size_t c = 0; c < by_config.size(); ++c)
        for(const Rule& rule : by_config[c])
          for(const Rule_term& term : rule.terms)
            rules << csv_row({t.facts->keyword, rule.name, side ? "1" : "0", std::to_string(configs[c].valence),
                              std::to_string(term.label), std::to_string(term.ring), num(to_double(term.weight), 17),
                              term.rational ? fraction(term.weight) : ""});
    }
}

// ------------------------------------------------------------------ curve schemes

Scheme_spec curve_spec(Scheme_kind kind, int degree = 3, Exact a = Exact(1) / 4, Exact b = Exact(3) / 4,
                       Exact w = Exact(1) / 16)
{
  Scheme_spec spec;
  spec.kind = kind;
  spec.degree = degree;
  spec.a = a;
  spec.b = b;
  spec.w = w;
  return spec;
}

std::string curve_label(const Scheme_spec& spec)
{
  switch(spec.kind) {
    case Scheme_kind::bezier:
      return "bezier, degree " + std::to_string(spec.degree);
    case Scheme_kind::bspline:
      return "bspline, degree " + std::to_string(spec.degree);
    case Scheme_kind::chaikin:
      return "chaikin";
    case Scheme_kind::corner_cutting:
      return "corner-cutting, a = " + fraction(spec.a) + ", b = " + fraction(spec.b);
    case Scheme_kind::four_point:
      return "four-point, w = " + fraction(spec.w);
  }
  return "";
}

std::string rule_terms(const std::vector<std::pair<int, Exact>>& terms)
{
  std::string text;
  for(const auto& term : terms)
    text += (text.empty() ? "" : ", ") + std::string("[") + std::to_string(term.first) + "] " + fraction(term.second);
  return text;
}

std::string curve_eigenvalues(const Curve_summary& s, std::size_t count)
{
  std::string text;
  for(std::size_t i = 0; i < s.eigenvalues.size() && i < count; ++i)
    text += (i ? ", " : "") + complex_text(s.eigenvalues[i]);
  if(s.eigenvalues.size() > count)
    text += ", ...";
  return text;
}

std::string limit_text(const Curve_summary& s)
{
  if(s.limit_mask.empty())
    return "-";
  std::string text;
  for(std::size_t i = 0; i < s.limit_mask.size(); ++i)
    text += (i ? ", " : "") + fraction(s.limit_mask[i]);
  return text + " (offsets " + std::to_string(s.window_first) + ".." + std::to_string(s.window_last) + ")";
}

std::string holder_text(const Curve_summary& s)
{
  if(s.c_infinity)
    return "inf";
  return s.smoothness < 0 ? "-" : num(s.holder_exponent, 4);
}

bool is_interpolating(const Curve_summary& s)
{
  return s.rules.size() == 2 && s.rules[0].size() == 1 && s.rules[0][0].first == 0 && s.rules[0][0].second == Exact(1);
}

// primal: the even rule is symmetric about the old point
bool is_primal(const Curve_summary& s)
{
  if(s.rules.size() != 2)
    return false;
  const auto& even = s.rules[0];
  for(const auto& term : even) {
    bool mirrored = false;
    for(const auto& other : even)
      mirrored = mirrored || (other.first == -term.first && other.second == term.second);
    if(!mirrored)
      return false;
  }
  return true;
}

struct Overview_row
{
  std::vector<std::string> cells;
};

const std::vector<std::string> overview_header = {"scheme",
                                                  "kind",
                                                  "primal or dual",
                                                  "approximating or interpolating",
                                                  "split",
                                                  "regular points (computed)",
                                                  "extraordinary points (computed)",
                                                  "border (computed)",
                                                  "exact kernels"};

void write_curves(Output& out, std::vector<Overview_row>& overview)
{
  std::ostringstream& md = out.file("curves.md");
  std::ostringstream& csv = out.file("curve_schemes.csv");
  md << "# Curve schemes\n\n"
     << "Generated by `subdiv-doc-tables` from the schemes' own masks (`analyse_curve_scheme()`, "
     << "`analyse_bezier()` in `Exact_rational`); do not edit. Rules: `[k] w` means old point i+k "
     << "contributes w to new point 2i (even) or 2i+1 (odd). Limit masks are over the invariant "
     << "window of offsets around an old point. Smoothness and Hölder bounds come from the "
     << "difference-scheme (symbol) method with up to 16 steps: a lower bound, proven.\n\n"
     << "| scheme | even rule | odd rule | eigenvalues | limit mask | smoothness | Hölder >= | "
     << "predicted rate |\n|---|---|---|---|---|---|---:|---:|\n";
  csv << csv_row({"scheme", "degree", "a", "b", "w", "even_rule", "odd_rule", "lambda1", "lambda2", "limit_mask",
                  "smoothness", "holder", "predicted_rate"});
  std::vector<Scheme_spec> specs;
  for(int degree = 1; degree <= 7; ++degree)
    specs.push_back(curve_spec(Scheme_kind::bspline, degree));
  specs.push_back(curve_spec(Scheme_kind::chaikin));
  specs.push_back(curve_spec(Scheme_kind::corner_cutting));
  specs.push_back(curve_spec(Scheme_kind::corner_cutting, 3, Exact(1) / 10, Exact(3) / 5));
  specs.push_back(curve_spec(Scheme_kind::four_point));
  specs.push_back(curve_spec(Scheme_kind::four_point, 3, Exact(1) / 4, Exact(3) / 4, Exact(1) / 5));
  std::vector<Curve_summary> bezier;
  for(const Scheme_spec& spec : specs) {
    const Curve_summary s = analyse_curve(spec);
    md << "| " << curve_label(spec) << " | " << rule_terms(s.rules[0]) << " | " << rule_terms(s.rules[1]) << " | "
       << curve_eigenvalues(s, 6) << " | " << limit_text(s) << " | " << smoothness_text(s) << " | " << holder_text(s)
       << " | " << num(s.predicted_rate, 6) << " |\n";
    std::string mask;
    for(const Exact& w : s.limit_mask)
      mask += (mask.empty() ? "" : " ") + fraction(w);
    csv << csv_row({s.scheme, std::to_string(spec.degree), fraction(spec.a), fraction(spec.b), fraction(spec.w),
                    rule_terms(s.rules[0]), rule_terms(s.rules[1]),
                    s.eigenvalues.size() > 1 ? complex_text(s.eigenvalues[1]) : "",
                    s.eigenvalues.size() > 2 ? complex_text(s.eigenvalues[2]) : "", mask, smoothness_text(s),
                    holder_text(s), num(s.predicted_rate, 6)});
    if(spec.kind != Scheme_kind::bspline || spec.degree <= 5)
      overview.push_back({{curve_label(spec), "curve", is_primal(s) ? "primal" : "dual",
                           is_interpolating(s) ? "interpolating" : "approximating", "binary (doubling)",
                           smoothness_text(s) + (s.smoothness >= 0 ? ", Hölder >= " + holder_text(s) : ""),
                           "- (none on curves)", "open ends: see `End_rule`", "yes (rational weights)"}});
  }
  md
    << "\n## Bezier subdivision (de Casteljau at t = 1/2)\n\n"
    << "The matrix is the left half of the split (row j: new control point j); the limit is the "
    << "polynomial curve, C^inf.\n\n| degree | left-half split rows | eigenvalues | limit mask |\n|---:|---|---|---|\n";
  for(int degree = 1; degree <= 5; ++degree) {
    const Curve_summary s = analyse_curve(curve_spec(Scheme_kind::bezier, degree));
    std::string rows;
    for(const auto& r : s.rules)
      rows += (rows.empty() ? "" : "; ") + rule_terms(r);
    md << "| " << degree << " | " << rows << " | " << curve_eigenvalues(s, 8) << " | " << limit_text(s) << " |\n";
    if(degree == 3)
      overview.push_back({{"bezier, any degree", "curve", "-", "approximating (interpolates the segment ends)",
                           "de Casteljau midpoint split", "C^inf (polynomial)", "- (none on curves)",
                           "segment ends kept", "yes (rational weights)"}});
  }

  // four-point over w
  md << "\n## Four-point scheme over the tension w\n\n"
     << "| w | eigenvalues | limit mask | smoothness | Hölder >= | predicted rate |\n|---:|---|---|---|---:|---:|\n";
  std::ostringstream& fp = out.file("four_point.csv");
  fp << csv_row({"w", "w_double", "lambda1", "lambda2", "lambda3", "smoothness", "holder", "predicted_rate"});
  const std::vector<std::pair<int, int>> ws = {{0, 1}, {1, 64}, {1, 32}, {3, 64}, {1, 16}, {5, 64}, {3, 32}, {1, 10},
                                               {1, 8}, {3, 20}, {4, 25}, {1, 6},  {3, 16}, {1, 5},  {9, 40}, {6, 25}};
  for(const auto& pq : ws) {
    const Exact w = Exact(pq.first) / pq.second;
    const Curve_summary s = analyse_curve(curve_spec(Scheme_kind::four_point, 3, Exact(1) / 4, Exact(3) / 4, w));
    md << "| " << fraction(w) << " | " << curve_eigenvalues(s, 5) << " | " << limit_text(s) << " | "
       << smoothness_text(s) << " | " << holder_text(s) << " | " << num(s.predicted_rate, 6) << " |\n";
    fp << csv_row({fraction(w), num(to_double(w), 17), s.eigenvalues.size() > 1 ? complex_text(s.eigenvalues[1]) : "",
                   s.eigenvalues.size() > 2 ? complex_text(s.eigenvalues[2]) : "",
                   s.eigenvalues.size() > 3 ? complex_text(s.eigenvalues[3]) : "", smoothness_text(s), holder_text(s),
                   num(s.predicted_rate, 6)});
  }

  // corner cutting over (a, b)
  md << "\n## Corner cutting over (a, b)\n\n"
     << "Rules (1-a, a) and (1-b, b). Cell: smoothness and Hölder bound; '-' where a >= b.\n\n| a \\ b |";
  std::ostringstream& cc = out.file("corner_cutting.csv");
  cc << csv_row({"a", "b", "lambda1", "lambda2", "smoothness", "holder", "predicted_rate"});
  std::vector<Exact> grid;
  for(int i = 1; i <= 9; ++i)
    grid.push_back(Exact(i) / 10);
  grid.insert(grid.begin() + 2, Exact(1) / 4);
  grid.insert(grid.begin() + 8, Exact(3) / 4);
  for(const Exact& b : grid)
    md << " " << fraction(b) << " |";
  md << "\n|---:|";
  for(std::size_t i = 0; i < grid.size(); ++i)
    md << "---|";
  md << "\n";
  for(const Exact& a : grid) {
    md << "| " << fraction(a) << " |";
    for(const Exact& b : grid) {
      if(!(a < b)) {
        md << " - |";
        continue;
      }
      const Curve_summary s = analyse_curve(curve_spec(Scheme_kind::corner_cutting, 3, a, b));
      md << " " << smoothness_text(s) << " (" << holder_text(s) << ") |";
      cc << csv_row({fraction(a), fraction(b), s.eigenvalues.size() > 1 ? complex_text(s.eigenvalues[1]) : "",
                     s.eigenvalues.size() > 2 ? complex_text(s.eigenvalues[2]) : "", smoothness_text(s), holder_text(s),
                     num(s.predicted_rate, 6)});
    }
    md << "\n";
  }
}

// ------------------------------------------------------------------ overview

std::string c1_summary(const std::vector<Surface_summary>& configs, int skip, const std::string& letter)
{
  std::vector<int> yes, no;
  for(const Surface_summary& s : configs)
    if(s.valence != skip)
      (s.c1 ? yes : no).push_back(s.valence);
  if(configs.empty())
    return "not analysed";
  if(no.empty())
    return "C1 at " + letter + " = " + ranges(yes);
  if(yes.empty())
    return "not C1 at " + letter + " = " + ranges(no);
  return "C1 at " + letter + " = " + ranges(yes) + "; not at " + ranges(no);
}

void write_overview(const std::vector<Scheme_tables>& all, std::vector<Overview_row> curves, Output& out)
{
  std::vector<Overview_row> rows;
  for(const Scheme_tables& t : all) {
    const int regular = regular_valence(t);
    std::string regular_text = "-";
    for(const Surface_summary& s : t.interior)
      if(s.valence == regular)
        regular_text = std::string(s.c1 ? "C1" : "not C1") + " (" +
                       (t.facts->dual ? "4-gon" : "n = " + std::to_string(regular)) + ")";
    std::vector<int> exact;
    bool border_exact = true;
    for(std::size_t c = 0; c < t.interior_rules.size(); ++c)
      if(all_rational(t.interior_rules[c]))
        exact.push_back(t.interior[c].valence);
    for(const auto& rules : t.border_rules)
      border_exact = border_exact && all_rational(rules);
    std::string exact_text = exact.size() == t.interior_rules.size() && border_exact
                               ? "yes (all weights rational)"
                               : "exact at " + std::string(t.facts->dual ? "n" : "valence") + " " + ranges(exact) +
                                   " only (elsewhere rounded weights)";
    rows.push_back(
      {{"[" + t.facts->keyword + "](surface-" + t.facts->keyword + ".md)", "surface", t.facts->dual ? "dual" : "primal",
        t.facts->interpolating ? "interpolating" : "approximating", t.facts->split, regular_text,
        c1_summary(t.interior, regular, t.facts->dual ? "n (face)" : "n"), c1_summary(t.border, -1, "k"), exact_text}});
  }
  rows.push_back({{"linear", "surface", "primal", "interpolating", "1-to-4 triangle split or quad split",
                   "C0 (the limit is the control mesh; not analysed)", "C0", "C0", "yes (rational weights)"}});
  for(Overview_row& row : curves) {
    row.cells[0] = "[" + row.cells[0] + "](curves.md)";
    rows.push_back(row);
  }

  std::ostringstream& md = out.file("README.md");
  std::ostringstream& csv = out.file("overview.csv");
  md << "# Scheme tables\n\n"
     << "Generated by `subdiv-doc-tables` (`build/src/subdiv-doc-tables doc/tables`); do not edit: the test "
     << "`doc_tables` fails when these files differ from a fresh run.\n\n"
     << "Every weight is read from the schemes' own masks, every verdict is computed by the eigen-analysis "
     << "(`analyse_surface_scheme()`, `analyse_curve_scheme()`) in exact rational arithmetic "
     << "(`Exact_rational`; eigenvalues by Eigen in double). Surface verdicts are the C1 test "
     << "(eigenvalues, extended spectrum, characteristic map) at interior vertices of valence " << first_valence << ".."
     << last_valence << " (Doo-Sabin: faces with that many corners) and at border "
     << "vertices with 1.." << last_border
     << " faces (Doo-Sabin: the border faces made from them); the test decides C1, not higher smoothness (the "
     << "B-spline based schemes are C2 at regular points, which this analysis does not test). Curve "
     << "smoothness is proven by the difference-scheme method (a lower bound). The schemes that take "
     << "OpenSubdiv's sharpness tags (loop, loop-warren, catmull-clark) are also analysed at sharp vertices, "
     << "with infinitely sharp tags: crease vertices with 1.." << max_crease_side << " faces on either side, "
     << "darts and corners of valence " << cgal_subdiv::min_sharp_valence << ".." << cgal_subdiv::max_sharp_valence
     << " (on their pages, and `surface_sharp.csv`).\n\n"
     << "## Overview\n\n|";
  for(const std::string& h : overview_header)
    md << " " << h << " |";
  md << "\n|";
  for(std::size_t i = 0; i < overview_header.size(); ++i)
    md << "---|";
  md << "\n";
  csv << csv_row(overview_header);
  for(const Overview_row& row : rows) {
    md << "|";
    for(const std::string& cell : row.cells)
      md << " " << cell << " |";
    md << "\n";
    std::vector<std::string> plain = row.cells;
    if(!plain[0].empty() && plain[0][0] == '[')
      plain[0] = plain[0].substr(1, plain[0].find(']') - 1);
    csv << csv_row(plain);
  }
  md << "\nPer scheme (rules, eigenvalues and verdicts by valence, limit and tangent masks):";
  for(const Scheme_tables& t : all)
    md << " [" << t.facts->keyword << "](surface-" << t.facts->keyword << ".md),";
  md << " [curve schemes](curves.md) (with the four-point scheme over w and corner cutting over (a, b)).\n\n"
     << "Machine-readable: `overview.csv`, `surface_analysis.csv` (one row per scheme and configuration), "
     << "`surface_eigenvalues.csv`, `surface_masks.csv` (limit and tangent masks by label), "
     << "`surface_rules.csv` (every rule weight by label, with the exact fraction where rational), "
     << "`surface_sharp.csv` (one row per sharp vertex configuration), "
     << "`curve_schemes.csv`, `four_point.csv`, `corner_cutting.csv`, `limit_eigenbasis.csv`.\n\n"
     << "The limit surface evaluator (`Limit_surface`): its Stam eigenbasis by valence, under Catmull-Clark "
     << "and Loop, in [limit-eigenbasis.md](limit-eigenbasis.md).\n";
}

const char* const usage =
  "usage: subdiv-doc-tables OUTPUT_DIR [--figures FIGURES_DIR]\n"
  "writes the scheme tables (Markdown and CSV) into OUTPUT_DIR and, with --figures, the figures\n"
  "drawn from the library (the limit surface's curvature) into FIGURES_DIR (both created if missing)\n";

void write_limit_tables(Output& out)
{
  const subdiv_doc_tables::Limit_tables limit = subdiv_doc_tables::limit_eigenbasis_tables(first_valence, last_valence);
  out.file("limit-eigenbasis.md") << limit.markdown;
  out.file("limit_eigenbasis.csv") << limit.csv;
}

void write_figures(const fs::path& dir)
{
  fs::create_directories(dir);
  const fs::path path = dir / subdiv_doc_tables::curvature_figure_name;
  std::ofstream out(path, std::ios::binary);
  out << subdiv_doc_tables::curvature_figure();
  if(!out)
    throw std::runtime_error("cannot write " + path.string());
  std::cerr << "subdiv-doc-tables: wrote " << path.string() << "\n";
}

} // namespace

int main(int argc, char** argv)
{
  const bool help = argc == 2 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help");
  const bool with_figures = argc == 4 && std::string(argv[2]) == "--figures";
  if(help || !(argc == 2 || with_figures)) {
    (help ? std::cout : std::cerr) << usage;
    return help ? 0 : 2;
  }
  try {
    const fs::path dir = argv[1];
    fs::create_directories(dir);
    Output out(dir);
    std::vector<Scheme_tables> all;
    for(const Surface_scheme_facts& facts : cgal_subdiv::analysable_surface_schemes()) {
      Scheme_tables t;
      t.facts = &facts;
      for(int n = first_valence; n <= last_valence; ++n) {
        t.interior.push_back(cgal_subdiv::analyse_surface(facts.keyword, n, false));
        t.interior_rules.push_back(subdiv_doc_tables::read_rules(facts.keyword, n, false));
      }
      if(facts.border_analysis)
        for(int k = 1; k <= last_border; ++k) {
          t.border.push_back(cgal_subdiv::analyse_surface(facts.keyword, k, true));
          t.border_rules.push_back(subdiv_doc_tables::read_rules(facts.keyword, k, true));
        }
      if(facts.sharp_analysis) {
        for(int k1 = 1; k1 <= max_crease_side; ++k1)
          for(int k2 = 1; k2 <= max_crease_side; ++k2)
            if(k1 + k2 > 2 || facts.split == "quad split") // a triangle mesh has no interior valence 2
              t.crease.push_back(
                cgal_subdiv::analyse_sharp_vertex(facts.keyword, CGAL::Subdiv::Configuration::crease(k1, k2)));
        for(int n = cgal_subdiv::min_sharp_valence; n <= cgal_subdiv::max_sharp_valence; ++n) {
          t.dart.push_back(cgal_subdiv::analyse_sharp_vertex(facts.keyword, CGAL::Subdiv::Configuration::dart(n)));
          t.corner.push_back(cgal_subdiv::analyse_sharp_vertex(facts.keyword, CGAL::Subdiv::Configuration::corner(n)));
        }
      }
      t.name = t.interior.front().name;
      write_scheme(t, out);
      all.push_back(std::move(t));
      std::cerr << "subdiv-doc-tables: " << facts.keyword << " done\n";
    }
    write_surface_csv(all, out);
    write_sharp_csv(all, out);
    std::vector<Overview_row> curves;
    write_curves(out, curves);
    write_overview(all, curves, out);
    write_limit_tables(out);
    out.write_all();
    std::cerr << "subdiv-doc-tables: wrote " << out.names().size() << " files to " << dir.string() << "\n";
    if(with_figures)
      write_figures(argv[3]);
    return 0;
  } catch(const std::exception& e) {
    std::cerr << "subdiv-doc-tables: error: " << e.what() << "\n";
    return 1;
  }
}
