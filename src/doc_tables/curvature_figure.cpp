// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The curvature figure of doc/limit.md: the Gaussian curvature of the
// Catmull-Clark limit surface over the faces around one inner vertex of
// valence 3, 4 and 5, on control points sampled from the same height field,
// computed from the evaluator's first and second derivatives and drawn as
// a top view. The output is deterministic (fixed number formats).
#include "limit_tables.h"

#include "../cli/limit_evaluator.h"

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace subdiv_doc_tables {
namespace {

using cgal_subdiv::Limit_evaluator;
using cgal_subdiv::Limit_point;
using cgal_subdiv::Limit_scheme;
using cgal_subdiv::Surface;
using Point = Surface::Point;
using Vertex = Surface::Vertex_index;

constexpr double pi = 3.14159265358979323846;
constexpr int sector_size = 4; // quads along each side of a sector: the border stays 2 rings away
constexpr int rate = 12;       // grid lines per face side, graded towards the vertex
const std::array<int, 3> valences = {3, 4, 5};

// page layout, in SVG user units
constexpr double panel_size = 250, panel_gap = 20, margin = 20, title_height = 64;
constexpr double legend_width = 150;
constexpr double page_width = margin + 3 * panel_size + 2 * panel_gap + legend_width + margin;
constexpr double chart_top = title_height + panel_size + 90, chart_height = 180, chart_left = 70;
constexpr double chart_width = 3 * panel_size + 2 * panel_gap - chart_left + margin;
constexpr double page_height = chart_top + chart_height + 50;
constexpr double log2_range = 2;  // colours from K0 / 4 to 4 K0
constexpr int deepest_level = 24; // the chart samples the face at 2^-L from the vertex, L = 0..deepest_level
const std::array<const char*, 3> line_colours = {"#1b9e77", "#7570b3", "#d95f02"};

// the height field the control points are sampled from: an elliptic
// paraboloid, whose curvature is positive and not symmetric about the vertex
double height(double x, double y)
{
  return (x * x + 2 * y * y) / 8;
}

/*
 * An open quad mesh around vertex 0 of valence n: n sectors, each a
 * `sector_size` x `sector_size` grid spanned by two unit rays at 2 pi / n,
 * every other inner vertex of valence 4.
 */
Surface disk(int n)
{
  Surface mesh;
  const Vertex centre = mesh.add_vertex(Point(0, 0, 0));
  const auto ray = [&](int j) {
    const double angle = 2 * pi * (j % n) / n;
    return std::array<double, 2>{std::cos(angle), std::sin(angle)};
  };
  // vertices on ray j at distance 1..sector_size, then those inside each sector
  std::vector<std::vector<Vertex>> on_ray(n), inside(n);
  const auto add = [&](double x, double y) { return mesh.add_vertex(Point(x, y, height(x, y))); };
  for(int j = 0; j < n; ++j)
    for(int a = 1; a <= sector_size; ++a)
      on_ray[j].push_back(add(a * ray(j)[0], a * ray(j)[1]));
  for(int j = 0; j < n; ++j)
    for(int a = 1; a <= sector_size; ++a)
      for(int b = 1; b <= sector_size; ++b)
        inside[j].push_back(add(a * ray(j)[0] + b * ray(j + 1)[0], a * ray(j)[1] + b * ray(j + 1)[1]));
  // grid point (a, b) of sector j: a along ray j, b along ray j + 1
  const auto at = [&](int j, int a, int b) {
    if(a == 0 && b == 0)
      return centre;
    if(b == 0)
      return on_ray[j][a - 1];
    if(a == 0)
      return on_ray[(j + 1) % n][b - 1];
    return inside[j][(a - 1) * sector_size + (b - 1)];
  };
  for(int j = 0; j < n; ++j)
    for(int a = 0; a < sector_size; ++a)
      for(int b = 0; b < sector_size; ++b)
        mesh.add_face(at(j, a, b), at(j, a + 1, b), at(j, a + 1, b + 1), at(j, a, b + 1));
  return mesh;
}

// one small quad of the plot: its corners (x, y) on the limit surface and its curvature
struct Cell
{
  std::array<std::array<double, 2>, 4> corners;
  double curvature;
};

// the cells of one valence, and the limit images of the faces' sides
struct Panel
{
  int valence;
  std::vector<Cell> cells;
  std::vector<std::vector<std::array<double, 2>>> sides;
  std::vector<double> by_level; // K at (3/4, 1/2) 2^-L from the vertex in its first face, L = 0..deepest_level
  double lambda_ratio;          // lambda2 / lambda1^2 of the eigenbasis used (0: none)
};

// the parameter (u, v) of a face at (s, t) seen from its corner i: s along
// the side to corner i + 1, t along the side to corner i - 1 (the corners
// of a quad at (0,0), (1,0), (1,1), (0,1))
std::array<double, 2> parameter(int i, double s, double t)
{
  static const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const double* c = corner[i];
  const double* next = corner[(i + 1) % 4];
  const double* previous = corner[(i + 3) % 4];
  return {c[0] + s * (next[0] - c[0]) + t * (previous[0] - c[0]),
          c[1] + s * (next[1] - c[1]) + t * (previous[1] - c[1])};
}

// the corner of face f at `vertex` (corner 0: the target of halfedge(f))
int corner_of(const Surface& mesh, Surface::Face_index f, Vertex vertex)
{
  int i = 0;
  for(const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
    if(mesh.target(h) == vertex)
      return i;
    ++i;
  }
  return -1;
}

// grid line k of `rate`: graded, (k / rate)^2, so that the cells are small where the curvature changes
double grid(int k)
{
  const double x = static_cast<double>(k) / rate;
  return x * x;
}

// the largest distinct eigenvalue below the subdominant one, over its square
double lambda_ratio(const Limit_evaluator& evaluator, int n)
{
  const auto bases = evaluator.eigenbases();
  const auto found = bases.find(static_cast<std::size_t>(n));
  if(found == bases.end())
    return 0;
  std::vector<double> lambda = found->second.eigenvalues;
  std::sort(lambda.begin(), lambda.end(), [](double a, double b) { return std::abs(a) > std::abs(b); });
  std::vector<double> distinct;
  for(double x : lambda)
    if(distinct.empty() || std::abs(x - distinct.back()) > 1e-4)
      distinct.push_back(x);
  return distinct.size() < 3 ? 0 : distinct[2] / (distinct[1] * distinct[1]);
}

Panel panel(int n)
{
  const Surface mesh = disk(n);
  const Limit_evaluator evaluator(mesh, Limit_scheme::catmull_clark);
  const Vertex centre(0);
  Panel result{n, {}, {}, {}, 0};
  for(const auto f : CGAL::faces_around_target(mesh.halfedge(centre), mesh)) {
    const int i = corner_of(mesh, f, centre);
    // towards the vertex: the same point of the child L levels down, so that
    // K changes by a constant factor per level once lambda2 dominates
    if(result.by_level.empty())
      for(int L = 0; L <= deepest_level; ++L) {
        const auto [u, v] = parameter(i, std::ldexp(0.75, -L), std::ldexp(0.5, -L));
        result.by_level.push_back(CGAL::Subdiv::gaussian_curvature(evaluator.evaluate(f, -1, u, v)));
      }
    const auto position = [&](double s, double t) {
      const auto [u, v] = parameter(i, s, t);
      const Point p = evaluator.evaluate(f, -1, u, v).position;
      return std::array<double, 2>{p.x(), p.y()};
    };
    std::vector<std::vector<std::array<double, 2>>> nodes(rate + 1);
    for(int a = 0; a <= rate; ++a)
      for(int b = 0; b <= rate; ++b)
        nodes[a].push_back(position(grid(a), grid(b)));
    for(int a = 0; a < rate; ++a)
      for(int b = 0; b < rate; ++b) {
        const auto [u, v] = parameter(i, (grid(a) + grid(a + 1)) / 2, (grid(b) + grid(b + 1)) / 2);
        result.cells.push_back({{nodes[a][b], nodes[a + 1][b], nodes[a + 1][b + 1], nodes[a][b + 1]},
                                CGAL::Subdiv::gaussian_curvature(evaluator.evaluate(f, -1, u, v))});
      }
    // the two sides away from the vertex (the others are a neighbour's)
    std::vector<std::array<double, 2>> side_s, side_t;
    for(int k = 0; k <= rate; ++k) {
      side_s.push_back(nodes[rate][k]);
      side_t.push_back(nodes[k][rate]);
    }
    result.sides.push_back(side_s);
    result.sides.push_back(side_t);
    result.sides.push_back(std::vector<std::array<double, 2>>(nodes[0].begin(), nodes[0].end()));
  }
  result.lambda_ratio = lambda_ratio(evaluator, n);
  return result;
}

// ------------------------------------------------------------------ drawing

std::string fixed(double x, int decimals = 1)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  return buffer;
}

// a diverging blue - white - red scale over t in [0, 1] (ColorBrewer's RdBu)
std::string colour(double t)
{
  static const double stops[5][3] = {{33, 102, 172}, {103, 169, 207}, {247, 247, 247}, {239, 138, 98}, {178, 24, 43}};
  t = std::clamp(t, 0.0, 1.0) * 4;
  const int k = std::min(3, static_cast<int>(t));
  const double f = t - k;
  char buffer[8];
  int rgb[3];
  for(int c = 0; c < 3; ++c)
    rgb[c] = static_cast<int>(std::lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c])));
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buffer;
}

// the colour of curvature K against the reference K0: log2(K / K0) over
// [-log2_range, log2_range]; grey where K <= 0
std::string curvature_colour(double K, double K0)
{
  if(!(K > 0))
    return "#969696";
  return colour((std::log2(K / K0) + log2_range) / (2 * log2_range));
}

void draw_panel(std::ostringstream& svg, const Panel& p, const char* line_colour, double left, double scale, double K0)
{
  const double cx = left + panel_size / 2, cy = title_height + panel_size / 2;
  const auto xy = [&](const std::array<double, 2>& q) {
    return fixed(cx + scale * q[0]) + "," + fixed(cy - scale * q[1]);
  };
  svg << "<g stroke-width=\"0.4\">\n";
  for(const Cell& c : p.cells) {
    const std::string fill = curvature_colour(c.curvature, K0);
    svg << "<path d=\"M" << xy(c.corners[0]) << "L" << xy(c.corners[1]) << " " << xy(c.corners[2]) << " "
        << xy(c.corners[3]) << "Z\" fill=\"" << fill << "\" stroke=\"" << fill << "\"/>\n";
  }
  svg << "</g>\n<g fill=\"none\" stroke=\"#404040\" stroke-width=\"0.8\">\n";
  for(const auto& side : p.sides) {
    svg << "<path d=\"M" << xy(side.front());
    for(std::size_t k = 1; k < side.size(); ++k)
      svg << (k == 1 ? "L" : " ") << xy(side[k]);
    svg << "\"/>\n";
  }
  svg << "</g>\n<circle cx=\"" << fixed(cx) << "\" cy=\"" << fixed(cy) << "\" r=\"2.5\" fill=\"#000\"/>\n";
  char ratio[32];
  std::snprintf(ratio, sizeof ratio, "%.3g", p.lambda_ratio);
  svg << "<text x=\"" << fixed(cx) << "\" y=\"" << fixed(title_height + panel_size + 22)
      << "\" text-anchor=\"middle\" fill=\"" << line_colour << "\">valence " << p.valence << "</text>\n"
      << "<text x=\"" << fixed(cx) << "\" y=\"" << fixed(title_height + panel_size + 40)
      << "\" text-anchor=\"middle\" font-size=\"11\">"
      << (p.lambda_ratio > 0 ? "lambda2 / lambda1^2 = " + std::string(ratio) : std::string("regular patches"))
      << "</text>\n";
}

void draw_legend(std::ostringstream& svg, double left)
{
  const double top = title_height + 10, height = panel_size - 40, width = 18;
  const int steps = 64;
  for(int k = 0; k < steps; ++k) // top: the largest curvature
    svg << "<rect x=\"" << fixed(left) << "\" y=\"" << fixed(top + height * k / steps, 2) << "\" width=\"" << width
        << "\" height=\"" << fixed(height / steps + 0.3, 2) << "\" fill=\"" << colour(1 - (k + 0.5) / steps)
        << "\"/>\n";
  const char* const labels[] = {"&gt;= 4", "2", "1", "1/2", "&lt;= 1/4"};
  for(int k = 0; k < 5; ++k)
    svg << "<text x=\"" << fixed(left + width + 6) << "\" y=\"" << fixed(top + height * k / 4 + 4)
        << "\" font-size=\"11\">" << labels[k] << "</text>\n";
  svg << "<text x=\"" << fixed(left) << "\" y=\"" << fixed(top - 2 + height + 22) << "\" font-size=\"11\">K / K0"
      << "</text>\n<rect x=\"" << fixed(left) << "\" y=\"" << fixed(top + height + 32) << "\" width=\"" << width
      << "\" height=\"10\" fill=\"#969696\"/>\n<text x=\"" << fixed(left + width + 6) << "\" y=\""
      << fixed(top + height + 41) << "\" font-size=\"11\">K &lt;= 0</text>\n";
}

/*
 * K / K0 against the level L of the sample 2^-L from the vertex, one line
 * per valence. (Stam's second derivatives keep their digits down there:
 * `curvature_next_to_an_extraordinary_vertex_keeps_its_digits` pins the
 * curvature at L = 20 to 1e-6 of the exact evaluator's.)
 */
void draw_chart(std::ostringstream& svg, const std::vector<Panel>& panels, double K0)
{
  double low = 0, high = 1;
  for(const Panel& p : panels)
    for(int L = 0; L <= deepest_level; ++L) {
      low = std::min(low, std::floor(p.by_level[L] / K0));
      high = std::max(high, std::ceil(p.by_level[L] / K0));
    }
  const auto x = [&](double L) { return chart_left + chart_width * L / deepest_level; };
  const auto y = [&](double value) { return chart_top + chart_height * (high - value) / (high - low); };
  const double tick = high - low > 12 ? 2 : 1;
  svg << "<g stroke=\"#d9d9d9\" stroke-width=\"0.6\">\n";
  for(double value = low; value <= high; value += tick)
    svg << "<path d=\"M" << fixed(x(0)) << "," << fixed(y(value)) << "H" << fixed(x(deepest_level)) << "\""
        << (value == 0 ? " stroke=\"#737373\"" : "") << "/>\n";
  svg << "</g>\n<g font-size=\"11\" text-anchor=\"end\">\n";
  for(double value = low; value <= high; value += tick)
    svg << "<text x=\"" << fixed(x(0) - 6) << "\" y=\"" << fixed(y(value) + 4) << "\">" << fixed(value, 0)
        << "</text>\n";
  svg << "</g>\n<g font-size=\"11\" text-anchor=\"middle\">\n";
  for(int L = 0; L <= deepest_level; L += 4)
    svg << "<text x=\"" << fixed(x(L)) << "\" y=\"" << fixed(chart_top + chart_height + 16) << "\">" << L
        << "</text>\n";
  svg << "</g>\n<text x=\"" << fixed(x(deepest_level / 2.0)) << "\" y=\"" << fixed(chart_top + chart_height + 34)
      << "\" text-anchor=\"middle\" font-size=\"11\">level L: the point (3/4, 1/2) 2^-L from the vertex in its "
      << "first face</text>\n<text x=\"" << fixed(margin) << "\" y=\"" << fixed(chart_top - 12)
      << "\" font-size=\"11\">K / K0 towards the vertex</text>\n";
  for(std::size_t i = 0; i < panels.size(); ++i) {
    const Panel& p = panels[i];
    const int last = deepest_level;
    svg << "<path fill=\"none\" stroke=\"" << line_colours[i] << "\" stroke-width=\"1.6\" d=\"M";
    for(int L = 0; L <= last; ++L)
      svg << (L == 1 ? "L" : L ? " " : "") << fixed(x(L)) << "," << fixed(y(p.by_level[L] / K0));
    svg << "\"/>\n<text x=\"" << fixed(x(last) + 6) << "\" y=\"" << fixed(y(p.by_level[last] / K0) + 4)
        << "\" font-size=\"11\" fill=\"" << line_colours[i] << "\">n = " << p.valence << "</text>\n";
  }
}

} // namespace

std::string curvature_figure()
{
  std::vector<Panel> panels;
  for(const int n : valences)
    panels.push_back(panel(n));
  // one scale for all panels, so that their sizes compare
  double extent = 0;
  for(const Panel& p : panels)
    for(const Cell& c : p.cells)
      for(const auto& q : c.corners)
        extent = std::max({extent, std::abs(q[0]), std::abs(q[1])});
  const double scale = (panel_size / 2 - 6) / extent;
  // K0: the regular surface's curvature next to its vertex (the cell at it)
  const double K0 = panels[1].cells.front().curvature;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fixed(page_width, 0) << "\" height=\""
      << fixed(page_height, 0) << "\" viewBox=\"0 0 " << fixed(page_width, 0) << " " << fixed(page_height, 0)
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
      << "<text x=\"" << fixed(margin) << "\" y=\"24\" font-size=\"15\">Gaussian curvature K of the Catmull-Clark "
      << "limit surface next to an inner vertex of valence n</text>\n"
      << "<text x=\"" << fixed(margin) << "\" y=\"44\" font-size=\"11\">the faces around the vertex (dot), seen "
      << "from above; control points on z = (x^2 + 2 y^2) / 8; K from Limit_surface's derivatives; "
      << "K0 = K next to the regular vertex</text>\n";
  for(std::size_t i = 0; i < panels.size(); ++i)
    draw_panel(svg, panels[i], line_colours[i], margin + static_cast<double>(i) * (panel_size + panel_gap), scale, K0);
  draw_legend(svg, margin + 3 * panel_size + 2 * panel_gap + 14);
  draw_chart(svg, panels, K0);
  svg << "</svg>\n";
  return svg.str();
}

} // namespace subdiv_doc_tables
