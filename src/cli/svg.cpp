// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "svg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace cgal_subdiv {
namespace {

using Point = std::array<double, 2>;

// page layout, in SVG user units
constexpr double page_width = 820;
constexpr double margin = 20;
constexpr double curve_top = 78, curve_height = 520;
constexpr double plot_top = curve_top + curve_height + 58, plot_height = 190, plot_left = 70;
constexpr double page_height = plot_top + plot_height + 44;
constexpr std::size_t max_drawn_points = 4000; // longer polylines are thinned for drawing

const char* const control_colour = "#8c8c8c";
const char* const final_colour = "#08306b";

std::string fixed(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

std::string short_number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", x);
  return buffer;
}

std::string escape(const std::string& text)
{
  std::string result;
  for(char c : text) {
    switch(c) {
      case '<':
        result += "&lt;";
        break;
      case '>':
        result += "&gt;";
        break;
      case '&':
        result += "&amp;";
        break;
      default:
        result += c;
    }
  }
  return result;
}

// intermediate level k of 1..count: from light orange through red to purple
std::string level_colour(std::size_t k, std::size_t count)
{
  static const double stops[3][3] = {{253, 174, 97}, {215, 25, 28}, {123, 50, 148}};
  const double t = count <= 1 ? 0.5 : static_cast<double>(k - 1) / static_cast<double>(count - 1);
  const double u = t * 2;
  const int i = u >= 1 ? 1 : 0;
  const double s = u - i;
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x",
                static_cast<int>(stops[i][0] + s * (stops[i + 1][0] - stops[i][0])),
                static_cast<int>(stops[i][1] + s * (stops[i + 1][1] - stops[i][1])),
                static_cast<int>(stops[i][2] + s * (stops[i + 1][2] - stops[i][2])));
  return buffer;
}

// Maps curve coordinates into the curve panel, same scale on both axes.
class Curve_view
{
public:
  explicit Curve_view(const Figure& figure)
  {
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for(const auto& level : figure.levels)
      for(const Point& p : level)
        for(int d = 0; d < 2; ++d) {
          lo[d] = std::min(lo[d], p[d]);
          hi[d] = std::max(hi[d], p[d]);
        }
    const double inner = 24;
    const double dx = std::max(hi[0] - lo[0], 1e-300), dy = std::max(hi[1] - lo[1], 1e-300);
    m_scale = std::min((page_width - 2 * margin - 2 * inner) / dx, (curve_height - 2 * inner) / dy);
    m_centre = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
  }

  Point operator()(const Point& p) const
  {
    return {page_width / 2 + (p[0] - m_centre[0]) * m_scale,
            curve_top + curve_height / 2 - (p[1] - m_centre[1]) * m_scale};
  }

private:
  double m_scale = 1;
  Point m_centre = {0, 0};
};

// "x,y x,y ..." of at most max_drawn_points points (always the first and the last)
template <class Map>
std::string point_list(const std::vector<Point>& points, const Map& map)
{
  const std::size_t stride = points.size() / max_drawn_points + 1;
  std::string list;
  for(std::size_t i = 0; i < points.size(); i += stride) {
    const Point q = map(points[i]);
    list += fixed(q[0]) + "," + fixed(q[1]) + " ";
  }
  if((points.size() - 1) % stride != 0) {
    const Point q = map(points.back());
    list += fixed(q[0]) + "," + fixed(q[1]);
  }
  return list;
}

void polyline(std::ostream& out, const std::vector<Point>& points, bool closed, const Curve_view& view,
              const std::string& style)
{
  out << "  <" << (closed ? "polygon" : "polyline") << " points=\"" << point_list(points, view) << "\" " << style
      << "/>\n";
}

void legend_line(std::ostream& out, double x, const std::string& colour, double width, const std::string& dash,
                 const std::string& label)
{
  out << "  <line x1=\"" << x << "\" y1=\"56\" x2=\"" << x + 26 << "\" y2=\"56\" stroke=\"" << colour
      << "\" stroke-width=\"" << width << "\"" << dash << "/>\n"
      << "  <text x=\"" << x + 32 << "\" y=\"60\" class=\"small\">" << escape(label) << "</text>\n";
}

void write_header_and_legend(const Figure& figure, std::ostream& out)
{
  const std::size_t levels = figure.levels.size() - 1;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << page_width << "\" height=\"" << page_height
      << "\" viewBox=\"0 0 " << page_width << " " << page_height
      << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      << "  <style>.small{font-size:12px;fill:#333}.title{font-size:17px;fill:#111}</style>\n"
      << "  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "  <text x=\"" << margin << "\" y=\"30\" class=\"title\">" << escape(figure.title) << "</text>\n";
  legend_line(out, margin, control_colour, 1.5, " stroke-dasharray=\"5 3\"",
              "control polygon (" + std::to_string(figure.levels.front().size()) + " points)");
  if(levels >= 2) {
    for(std::size_t k = 1; k < levels; ++k)
      out << "  <line x1=\"" << 260 + 26.0 * static_cast<double>(k - 1) / static_cast<double>(levels - 1)
          << "\" y1=\"56\" x2=\"" << 260 + 26.0 * static_cast<double>(k) / static_cast<double>(levels - 1)
          << "\" y2=\"56\" stroke=\"" << level_colour(k, levels - 1) << "\" stroke-width=\"3\"/>\n";
    out << "  <text x=\"292\" y=\"60\" class=\"small\">levels 1.." << levels - 1 << "</text>\n";
  }
  if(levels >= 1)
    legend_line(out, 420, final_colour, 2.5, "",
                "level " + std::to_string(levels) + " (" + std::to_string(figure.levels.back().size()) + " points)");
}

void write_curves(const Figure& figure, std::ostream& out)
{
  const Curve_view view(figure);
  const std::size_t levels = figure.levels.size() - 1;
  out << "  <rect x=\"" << margin << "\" y=\"" << curve_top << "\" width=\"" << page_width - 2 * margin
      << "\" height=\"" << curve_height << "\" fill=\"#fcfcfc\" stroke=\"#e3e3e3\"/>\n";
  polyline(
    out, figure.levels.front(), figure.closed, view,
    std::string("fill=\"none\" stroke=\"") + control_colour + "\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"");
  for(std::size_t k = 1; k < levels; ++k)
    polyline(out, figure.levels[k], figure.closed, view,
             "fill=\"none\" stroke=\"" + level_colour(k, levels - 1) + "\" stroke-width=\"1\" stroke-opacity=\"0.9\"");
  if(levels >= 1)
    polyline(
      out, figure.levels.back(), figure.closed, view,
      std::string("fill=\"none\" stroke=\"") + final_colour + "\" stroke-width=\"2.5\" stroke-linejoin=\"round\"");
  for(const Point& p : figure.levels.front()) {
    const Point q = view(p);
    out << "  <circle cx=\"" << fixed(q[0]) << "\" cy=\"" << fixed(q[1]) << "\" r=\"3.5\" fill=\"" << control_colour
        << "\"/>\n";
  }
  // where the arc length of the curvature plot starts
  const Point start = view(figure.levels.back().front());
  out << "  <circle cx=\"" << fixed(start[0]) << "\" cy=\"" << fixed(start[1]) << "\" r=\"6\" fill=\"none\" stroke=\""
      << final_colour << "\" stroke-width=\"1.5\"/>\n"
      << "  <text x=\"" << fixed(start[0] + 9) << "\" y=\"" << fixed(start[1] - 9)
      << "\" class=\"small\">start</text>\n";
}

void write_curvature_plot(const Figure& figure, std::ostream& out)
{
  const double right = page_width - margin, bottom = plot_top + plot_height;
  out << "  <text x=\"" << margin << "\" y=\"" << plot_top - 14 << "\" class=\"title\" style=\"font-size:14px\">"
      << "discrete curvature of the last level against arc length</text>\n"
      << "  <rect x=\"" << plot_left << "\" y=\"" << plot_top << "\" width=\"" << right - plot_left << "\" height=\""
      << plot_height << "\" fill=\"#fcfcfc\" stroke=\"#bbb\"/>\n";
  if(!figure.has_curvature || figure.curvature.size() < 3) {
    out << "  <text x=\"" << plot_left + 12 << "\" y=\"" << plot_top + 24 << "\" class=\"small\">"
        << "(no curvature: too few points, or built without the analysis layer)</text>\n";
    return;
  }
  const double length = std::max(figure.arc_length.back(), 1e-300);
  const double top = std::max(*std::max_element(figure.curvature.begin(), figure.curvature.end()), 1e-300);
  const auto map = [&](const Point& p) {
    return Point{plot_left + (right - plot_left) * p[0] / length, bottom - (plot_height - 8) * p[1] / top};
  };
  std::vector<Point> graph;
  graph.push_back({0, 0});
  for(std::size_t i = 0; i < figure.curvature.size(); ++i)
    graph.push_back({figure.arc_length[i], figure.curvature[i]});
  graph.push_back({figure.arc_length.back(), 0});
  out << "  <polygon points=\"" << point_list(graph, map) << "\" fill=\"" << final_colour
      << "\" fill-opacity=\"0.12\" stroke=\"" << final_colour
      << "\" stroke-width=\"1.2\" stroke-linejoin=\"round\"/>\n";
  const auto label = [&](double x, double y, const std::string& anchor, const std::string& text) {
    out << "  <text x=\"" << fixed(x) << "\" y=\"" << fixed(y) << "\" class=\"small\" text-anchor=\"" << anchor << "\">"
        << text << "</text>\n";
  };
  label(plot_left - 6, bottom, "end", "0");
  label(plot_left - 6, plot_top + 12, "end", short_number(top));
  label(plot_left, bottom + 16, "middle", "0");
  label(right, bottom + 16, "end", short_number(figure.arc_length.back()));
  label((plot_left + right) / 2, bottom + 30, "middle", "arc length");
  out << "  <text transform=\"translate(" << margin + 6 << "," << plot_top + plot_height / 2
      << ") rotate(-90)\" class=\"small\" text-anchor=\"middle\">curvature</text>\n";
}

} // namespace

void write_svg(const Figure& figure, std::ostream& out)
{
  write_header_and_legend(figure, out);
  write_curves(figure, out);
  write_curvature_plot(figure, out);
  out << "</svg>\n";
}

} // namespace cgal_subdiv
