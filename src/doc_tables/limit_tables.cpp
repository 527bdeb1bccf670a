// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "limit_tables.h"

#include "../cli/limit_evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace subdiv_doc_tables {
namespace {

using cgal_subdiv::Eigenbasis_facts;
using cgal_subdiv::Limit_evaluator;
using cgal_subdiv::Limit_scheme;
using cgal_subdiv::Surface;
using Point = Surface::Point;
using Eigenbases = std::map<std::size_t, Eigenbasis_facts>;

constexpr double pi = 3.14159265358979323846;

// ------------------------------------------------------------------ meshes

// a point of the regular n-gon at height z (the matrices depend on the
// topology only, so any embedding will do)
Point polygon_point(int i, int n, double z)
{
  const double angle = 2 * pi * i / n;
  return Point(std::cos(angle), std::sin(angle), z);
}

// a prism over an n-gon: its caps are n-gons, whose face points have valence
// n after one level of Catmull-Clark
Surface prism(int n)
{
  Surface mesh;
  std::vector<Surface::Vertex_index> bottom, top;
  for(int i = 0; i < n; ++i) {
    bottom.push_back(mesh.add_vertex(polygon_point(i, n, 0)));
    top.push_back(mesh.add_vertex(polygon_point(i, n, 1)));
  }
  mesh.add_face(std::vector<Surface::Vertex_index>(bottom.rbegin(), bottom.rend()));
  mesh.add_face(top);
  for(int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.add_face(bottom[i], bottom[j], top[j], top[i]);
  }
  return mesh;
}

// a bipyramid over an n-gon: two apexes of valence n, the others of valence 4
Surface bipyramid(int n)
{
  Surface mesh;
  const auto top = mesh.add_vertex(Point(0, 0, 1)), bottom = mesh.add_vertex(Point(0, 0, -1));
  std::vector<Surface::Vertex_index> ring;
  for(int i = 0; i < n; ++i)
    ring.push_back(mesh.add_vertex(polygon_point(i, n, 0)));
  for(int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.add_face(top, ring[i], ring[j]);
    mesh.add_face(bottom, ring[j], ring[i]);
  }
  return mesh;
}

// ------------------------------------------------------------------ eigenbases

/*
 * The eigenbases the evaluator builds next to every extraordinary vertex of
 * the mesh: a parameter close to a corner of every face (or sub-quad) is
 * evaluated, so the patch with one extraordinary corner is reached after
 * the evaluator's own local refinement, as in any use.
 */
Eigenbases eigenbases_of(const Surface& mesh, Limit_scheme scheme)
{
  const Limit_evaluator evaluator(mesh, scheme);
  const double near = 1.0 / 64, far = 1 - near;
  for(const Surface::Face_index f : mesh.faces()) {
    const std::size_t degree = mesh.degree(f);
    if(scheme == Limit_scheme::loop) {
      for(const auto& [u, v] : {std::make_pair(near, near), {far - near, near}, {near, far - near}})
        evaluator.evaluate(f, -1, u, v);
    } else if(degree == 4) {
      for(const auto& [u, v] : {std::make_pair(near, near), {far, near}, {far, far}, {near, far}})
        evaluator.evaluate(f, -1, u, v);
    } else {
      for(int corner = 0; corner < static_cast<int>(degree); ++corner) // near the face point and the corner
        for(const double t : {near, far})
          evaluator.evaluate(f, corner, t, t);
    }
  }
  return evaluator.eigenbases();
}

// every eigenbasis the evaluator builds on the test meshes of valences first..last
Eigenbases all_eigenbases(Limit_scheme scheme, int first, int last)
{
  Eigenbases all;
  for(int n = first; n <= last; ++n) {
    const Surface mesh = scheme == Limit_scheme::catmull_clark ? prism(n) : bipyramid(n);
    for(auto& [valence, facts] : eigenbases_of(mesh, scheme))
      all.emplace(valence, std::move(facts)); // the same valence gives the same matrix
  }
  return all;
}

// ------------------------------------------------------------------ numbers

std::string significant(double x, int digits)
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

/*
 * The condition number of V to 2 digits: V is orthonormal within each
 * eigenspace (Stam_eigenbasis.h), so it depends on A only. (The basis the
 * eigen-solver picked inside a repeated eigenvalue depended on rounding:
 * g++ -O2 against -O2 -march=native gave 42 against 5900 for Loop at
 * valence 7 before.)
 */
std::string condition_text(double c)
{
  if(!std::isfinite(c))
    return "inf";
  char buffer[40]; // 2 significant digits, written out (170, not 1.7e+02)
  std::snprintf(buffer, sizeof buffer, "%.0f", std::stod(significant(c, 2)));
  return buffer;
}

// a distinct eigenvalue and how many times it occurs
struct Eigenvalue_group
{
  double value = 0;
  int multiplicity = 0;
};

/*
 * The eigenvalues grouped by value, by decreasing modulus. A defective
 * eigenvalue of multiplicity m comes out of the eigen-solver as a cluster
 * of spread about eps^(1/m) (6e-6 for Loop's triple 1/8), so values closer
 * than 1e-4 are one, and a group's value is its mean, which rounding moves
 * by about eps only.
 */
std::vector<Eigenvalue_group> groups_of(std::vector<double> lambda)
{
  std::sort(lambda.begin(), lambda.end(),
            [](double a, double b) { return std::abs(a) != std::abs(b) ? std::abs(a) > std::abs(b) : a > b; });
  std::vector<Eigenvalue_group> groups;
  double sum = 0;
  for(std::size_t i = 0; i < lambda.size(); ++i) {
    if(groups.empty() || std::abs(lambda[i] - lambda[i - 1]) > 1e-4 * std::max(1.0, std::abs(lambda[i]))) {
      groups.push_back({lambda[i], 0});
      sum = 0;
    }
    sum += lambda[i];
    ++groups.back().multiplicity;
    groups.back().value = sum / groups.back().multiplicity;
  }
  return groups;
}

// ------------------------------------------------------------------ rows

struct Scheme_rows
{
  Limit_scheme scheme;
  std::string name, keyword, regular_patch;
  int regular_valence;
  int size(int n) const { return scheme == Limit_scheme::catmull_clark ? 2 * n + 8 : n + 6; }
};

// the cells of one row: scheme, n, K, method, lambda0, lambda1, mult, lambda2, mult, lambda2/lambda1^2, condition
std::vector<std::string> row_cells(const Scheme_rows& s, int n, const Eigenbases& bases)
{
  const int K = s.size(n);
  std::vector<std::string> cells = {s.keyword, std::to_string(n), std::to_string(K)};
  const auto found = bases.find(static_cast<std::size_t>(n));
  if(n == s.regular_valence) {
    if(found != bases.end())
      throw std::runtime_error(s.name + ": an eigenbasis at the regular valence");
    cells.push_back("regular (" + s.regular_patch + ")");
    cells.resize(11, "-");
    return cells;
  }
  if(found == bases.end())
    throw std::runtime_error(s.name + ": no eigenbasis built at valence " + std::to_string(n));
  const Eigenbasis_facts& facts = found->second;
  if(facts.eigenvalues.size() != static_cast<std::size_t>(K))
    throw std::runtime_error(s.name + ": the local matrix at valence " + std::to_string(n) + " has " +
                             std::to_string(facts.eigenvalues.size()) + " eigenvalues, not " + std::to_string(K));
  const std::vector<Eigenvalue_group> g = groups_of(facts.eigenvalues);
  if(g.size() < 3)
    throw std::runtime_error(s.name + ": fewer than 3 distinct eigenvalues at valence " + std::to_string(n));
  cells.push_back(std::isfinite(facts.condition) ? "Stam" : "matrix powers (defective)");
  cells.push_back(significant(g[0].value, 6));
  cells.push_back(significant(g[1].value, 6));
  cells.push_back(std::to_string(g[1].multiplicity));
  cells.push_back(significant(g[2].value, 6));
  cells.push_back(std::to_string(g[2].multiplicity));
  cells.push_back(significant(g[2].value / (g[1].value * g[1].value), 3));
  cells.push_back(condition_text(facts.condition));
  return cells;
}

std::string csv_row(const std::vector<std::string>& cells)
{
  std::string row;
  for(std::size_t i = 0; i < cells.size(); ++i)
    row += (i ? "," : "") + cells[i];
  return row + "\n";
}

std::string markdown_row(const std::vector<std::string>& cells)
{
  std::string row = "|";
  for(std::size_t i = 1; i < cells.size(); ++i) // the scheme is the section's
    row += " " + cells[i] + " |";
  return row + "\n";
}

void write_header(std::ostringstream& md, int first, int last)
{
  md << "# Limit surface: Stam's eigenbasis by valence\n\n"
     << "Generated by `subdiv-doc-tables` from the evaluator itself (`Limit_surface::eigenbasis_conditions()`, "
     << "`eigenbasis_eigenvalues()`, after evaluations next to inner vertices of valence " << first << ".." << last
     << "); do not edit. The method is explained in doc/limit.md.\n\n"
     << "A patch whose one extraordinary corner is an inner vertex of valence n has K control points (its "
     << "1-ring: 2n + 8 under Catmull-Clark, n + 6 under Loop); one level of refinement maps them to the same "
     << "patch at that corner by the K x K local subdivision matrix A, read off the mask's own refinement. "
     << "The evaluator diagonalises A = V diag(lambda) V^-1 once per valence (Eigen, in double) and evaluates "
     << "any parameter near the corner with one product. Columns: `method` is `Stam` where the eigenbasis is "
     << "used, `regular` where the patch is a spline patch and needs none, `matrix powers (defective)` where A "
     << "is not diagonalisable to rounding (the evaluator then takes the child's control points through L "
     << "products with A, no refinement); "
     << "lambda0 > lambda1 > lambda2 are the three largest distinct eigenvalues, each with its multiplicity "
     << "(the values of a defective cluster averaged); `lambda2/lambda1^2` above 1 makes the Gaussian curvature "
     << "grow without bound towards the vertex for generic control points, below 1 tend to zero (it scales as "
     << "(lambda2 / lambda1^2)^(2L) at level L; see the figure in doc/limit.md); `cond(V)` is the condition "
     << "number of the eigenvector matrix (2-norm; its vectors orthonormal within each eigenspace, so that it "
     << "depends on A only), which bounds the digits the evaluation loses (the evaluator refuses the basis at "
     << "1e6 and above).\n\n";
}

} // namespace

Limit_tables limit_eigenbasis_tables(int first_valence, int last_valence)
{
  const std::vector<Scheme_rows> schemes = {
    {Limit_scheme::catmull_clark, "Catmull-Clark", "catmull-clark", "bicubic B-spline", 4},
    {Limit_scheme::loop, "Loop", "loop", "quartic box spline", 6}};
  Limit_tables out;
  std::ostringstream md, csv;
  write_header(md, first_valence, last_valence);
  csv << csv_row({"scheme", "valence", "K", "method", "lambda0", "lambda1", "lambda1_multiplicity", "lambda2",
                  "lambda2_multiplicity", "lambda2_over_lambda1_squared", "condition"});
  for(const Scheme_rows& s : schemes) {
    const Eigenbases bases = all_eigenbases(s.scheme, first_valence, last_valence);
    md << "## " << s.name << " (`" << s.keyword << "`)\n\n"
       << "| n | K | method | lambda0 | lambda1 | mult. | lambda2 | mult. | lambda2/lambda1^2 | cond(V) |\n"
       << "|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for(int n = first_valence; n <= last_valence; ++n) {
      const std::vector<std::string> cells = row_cells(s, n, bases);
      md << markdown_row(cells);
      csv << csv_row(cells);
    }
    md << "\n";
  }
  out.markdown = md.str();
  out.csv = csv.str();
  return out;
}

} // namespace subdiv_doc_tables
