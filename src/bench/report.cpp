// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: formatting and the SVG chart (see report.h).
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

namespace subdiv_bench {

std::string seconds(double s)
{
  if(!std::isfinite(s) || s >= 1e299)
    return "-";
  char text[32];
  if(s >= 10)
    std::snprintf(text, sizeof text, "%.1f", s);
  else if(s >= 1)
    std::snprintf(text, sizeof text, "%.2f", s);
  else if(s >= 0.1)
    std::snprintf(text, sizeof text, "%.3f", s);
  else if(s >= 0.01)
    std::snprintf(text, sizeof text, "%.4f", s);
  else
    std::snprintf(text, sizeof text, "%.5f", s);
  return text;
}

std::string fixed(double x, int decimals)
{
  if(!std::isfinite(x))
    return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, x);
  return text;
}

std::string scientific(double x)
{
  if(!std::isfinite(x))
    return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.1e", x);
  return text;
}

namespace {

std::string escape(const std::string& text)
{
  std::string out;
  for(const char c : text) {
    if(c == '&')
      out += "&amp;";
    else if(c == '<')
      out += "&lt;";
    else if(c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

// a round step for about 5 grid lines up to `top`
double nice_step(double top)
{
  const double raw = top / 5;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for(const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if(m * power >= raw)
      return m * power;
  return 10 * power;
}

} // namespace

std::string bar_chart_svg(const std::string& title, const std::string& axis, const std::vector<std::string>& series,
                          const std::vector<Chart_group>& groups)
{
  const char* colours[] = {"#d62728", "#7f7f7f", "#2ca02c", "#1f77b4", "#9467bd", "#ff7f0e"};
  const int label_width = 320, plot_width = 480, bar = 11, gap = 12, right = 70;
  const int width = label_width + plot_width + right;
  // the legend, wrapped to the width: where each entry goes
  std::vector<std::pair<int, int>> legend;
  int lx = 10, ly = 32;
  for(const std::string& name : series) {
    const int entry = 30 + 7 * static_cast<int>(name.size());
    if(lx > 10 && lx + entry > width) {
      lx = 10;
      ly += 18;
    }
    legend.emplace_back(lx, ly);
    lx += entry;
  }
  const int top = ly + 32;
  const int group_height = static_cast<int>(series.size()) * bar + gap;
  const int height = top + static_cast<int>(groups.size()) * group_height + 40;
  double high = 0;
  for(const Chart_group& g : groups)
    for(const double v : g.values)
      if(std::isfinite(v))
        high = std::max(high, v);
  if(high <= 0)
    high = 1;
  const double step = nice_step(high);
  const double scale_top = std::ceil(high / step) * step;
  const auto x_of = [&](double v) { return label_width + v / scale_top * plot_width; };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"10\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << escape(title) << "</text>\n";
  // legend
  for(std::size_t s = 0; s < series.size(); ++s) {
    const int x = legend[s].first, y = legend[s].second;
    svg << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"12\" height=\"12\" fill=\"" << colours[s % 6] << "\"/>";
    svg << "<text x=\"" << x + 16 << "\" y=\"" << y + 11 << "\" font-size=\"12\">" << escape(series[s]) << "</text>\n";
  }
  // grid and axis
  const int plot_bottom = top + static_cast<int>(groups.size()) * group_height;
  for(double v = 0; v <= scale_top + step / 2; v += step) {
    const double x = x_of(v);
    svg << "<line x1=\"" << x << "\" y1=\"" << top - 4 << "\" x2=\"" << x << "\" y2=\"" << plot_bottom
        << "\" stroke=\"#dddddd\"/>";
    std::ostringstream label;
    label << v;
    svg << "<text x=\"" << x << "\" y=\"" << plot_bottom + 14 << "\" font-size=\"11\" text-anchor=\"middle\">"
        << label.str() << "</text>\n";
  }
  svg << "<text x=\"" << label_width + plot_width / 2 << "\" y=\"" << plot_bottom + 32
      << "\" font-size=\"12\" text-anchor=\"middle\">" << escape(axis) << "</text>\n";
  // bars
  for(std::size_t g = 0; g < groups.size(); ++g) {
    const int y0 = top + static_cast<int>(g) * group_height;
    svg << "<text x=\"" << label_width - 8 << "\" y=\"" << y0 + (group_height - gap) / 2 + 4
        << "\" font-size=\"11\" text-anchor=\"end\">" << escape(groups[g].label) << "</text>\n";
    for(std::size_t s = 0; s < series.size() && s < groups[g].values.size(); ++s) {
      const double v = groups[g].values[s];
      const int y = y0 + static_cast<int>(s) * bar;
      if(!std::isfinite(v)) {
        svg << "<text x=\"" << label_width + 4 << "\" y=\"" << y + bar - 2
            << "\" font-size=\"9\" fill=\"#999999\">n/a</text>\n";
        continue;
      }
      char value[32];
      std::snprintf(value, sizeof value, v >= 10 ? "%.0f" : "%.1f", v);
      svg << "<rect x=\"" << label_width << "\" y=\"" << y << "\" width=\"" << std::max(1.0, x_of(v) - label_width)
          << "\" height=\"" << bar - 1 << "\" fill=\"" << colours[s % 6] << "\"/>";
      svg << "<text x=\"" << x_of(v) + 3 << "\" y=\"" << y + bar - 2 << "\" font-size=\"9\">" << value << "</text>\n";
    }
  }
  svg << "<line x1=\"" << label_width << "\" y1=\"" << top - 4 << "\" x2=\"" << label_width << "\" y2=\"" << plot_bottom
      << "\" stroke=\"black\"/>\n";
  svg << "</svg>\n";
  return svg.str();
}

} // namespace subdiv_bench
