// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "report.h"
#include "analysis_config.h"

#if SUBDIV_CLI_WITH_ANALYSIS

#include "curve_impl.h"
#include "numbers.h"
#include "schemes.h"

#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <type_traits>

namespace cgal_subdiv {
namespace {

namespace S = CGAL::Subdiv;
using Analysis = S::Curve_analysis<Exact>;
using Measurements = std::vector<S::Level_measurement>;

double max_of(const std::vector<double>& values)
{
  double result = 0;
  for(double v : values)
    result = std::max(result, v);
  return result;
}

// Bezier: new control point J sits at index position J/2 of the old control
// polygon (old point i becomes new point 2i), so the sup distance between the
// two polygons is reached at the new points.
template <class Point>
double bezier_level_distance(const std::vector<Point>& old_points, const std::vector<Point>& new_points)
{
  const std::size_t n = old_points.size();
  double result = 0;
  for(std::size_t j = 0; j < new_points.size(); ++j) {
    const Point on_old = CGAL::midpoint(old_points[(j / 2) % n], old_points[((j + 1) / 2) % n]);
    result = std::max(result, std::sqrt(CGAL::squared_distance(on_old, new_points[j])));
  }
  return result;
}

template <class Point>
Measurements measure_bezier(std::vector<Point> current, int degree, const Refine_spec& refine)
{
  Measurements result;
  for(int level = 1; level <= refine.levels; ++level) {
    std::vector<Point> next =
      S::bezier_subdivision(current, degree, S::parameters::number_of_iterations(1).closed(refine.closed));
    S::Level_measurement m;
    m.level = level;
    m.points = next.size();
    m.distance = bezier_level_distance(current, next);
    m.ratio = result.empty() ? std::numeric_limits<double>::quiet_NaN() : m.distance / result.back().distance;
    m.max_curvature = max_of(S::discrete_curvature(next, S::parameters::closed(refine.closed)));
    result.push_back(m);
    current.swap(next);
  }
  return result;
}

template <class Point>
Measurements measure(const Curve_job& job, const Input_polyline& input)
{
  if(job.refine.use_tolerance)
    return {};
  const std::vector<Point> control = curve_impl::make_points<Point>(input);
  return with_scheme<double>(job.scheme, [&](const auto& scheme) {
    if constexpr(Is_bezier<std::decay_t<decltype(scheme)>>::value)
      return measure_bezier(control, scheme.degree(), job.refine);
    else
      return S::measure_levels(
        control, scheme,
        S::parameters::number_of_iterations(job.refine.levels).closed(job.refine.closed).end_rule(job.refine.end_rule));
  });
}

Analysis analyse(const Scheme_spec& spec)
{
  return with_scheme<Exact>(spec, [](const auto& scheme) -> Analysis {
    if constexpr(Is_bezier<std::decay_t<decltype(scheme)>>::value)
      return S::analyse_bezier(scheme);
    else
      return S::analyse_curve_scheme(scheme);
  });
}

std::string printf_number(const char* format, double x)
{
  if(std::isnan(x))
    return "-";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

// "0.25 (1/4)" when x is p/q for a small or power-of-two q
std::string with_fraction(double x)
{
  const std::string decimal = printf_number("%.6g", x);
  for(long q = 1; q <= (1L << 20); q = q < 64 ? q + 1 : 2 * q) {
    const double p = std::round(x * static_cast<double>(q));
    if(std::abs(x - p / static_cast<double>(q)) < 1e-10 * std::max(1.0, std::abs(x)))
      return q == 1 ? decimal : decimal + " (" + printf_number("%.0f", p) + "/" + std::to_string(q) + ")";
  }
  return decimal;
}

std::string eigenvalue_text(const std::complex<double>& z)
{
  if(std::abs(z.imag()) < 1e-12)
    return with_fraction(z.real());
  return printf_number("%.6g", z.real()) + (z.imag() < 0 ? " - " : " + ") + printf_number("%.6g", std::abs(z.imag())) +
         "i";
}

std::string smoothness_text(const Analysis& a)
{
  if(a.smoothness == S::infinite_smoothness)
    return "C^inf";
  if(a.smoothness >= 0)
    return "C^" + std::to_string(a.smoothness);
  return "not proven";
}

std::string join(const std::vector<std::string>& items, const std::string& separator)
{
  std::string result;
  for(std::size_t i = 0; i < items.size(); ++i)
    result += (i ? separator : "") + items[i];
  return result;
}

void write_measurements(const Measurements& levels, std::ostream& out)
{
  out << "### Distance between successive levels\n\n";
  if(levels.empty()) {
    out << "(no levels: adaptive refinement to a tolerance)\n\n";
    return;
  }
  out << "| level | points | distance | ratio | max curvature |\n"
      << "|------:|-------:|---------:|------:|--------------:|\n";
  for(const S::Level_measurement& m : levels)
    out << "| " << m.level << " | " << m.points << " | " << printf_number("%.6g", m.distance) << " | "
        << printf_number("%.4f", m.ratio) << " | " << printf_number("%.6g", m.max_curvature) << " |\n";
  out << "\n";
}

void write_matrix(const Analysis& a, std::ostream& out)
{
  out << "- subdivision matrix S over offsets " << a.window_first << ".." << a.window_last << " (exact):\n\n";
  if(a.matrix.rows() > 10) {
    out << "  (" << a.matrix.rows() << " x " << a.matrix.cols() << ", not shown)\n\n";
    return;
  }
  std::size_t width = 1;
  for(Eigen::Index r = 0; r < a.matrix.rows(); ++r)
    for(Eigen::Index c = 0; c < a.matrix.cols(); ++c)
      width = std::max(width, format_exact(a.matrix(r, c)).size());
  out << "  ```\n";
  for(Eigen::Index r = 0; r < a.matrix.rows(); ++r) {
    out << "  [";
    for(Eigen::Index c = 0; c < a.matrix.cols(); ++c) {
      const std::string entry = format_exact(a.matrix(r, c));
      out << ' ' << std::string(width - entry.size(), ' ') << entry;
    }
    out << " ]\n";
  }
  out << "  ```\n\n";
}

void write_analysis(const Analysis& a, std::ostream& out)
{
  std::vector<std::string> eigenvalues, mask;
  for(const auto& z : a.eigenvalues)
    eigenvalues.push_back(eigenvalue_text(z));
  for(const Exact& x : a.limit_mask)
    mask.push_back(format_exact(x));
  out << "### Eigen-analysis of the scheme\n\n";
  write_matrix(a, out);
  out << "- eigenvalues, largest modulus first: " << (eigenvalues.empty() ? "(Eigen failed)" : join(eigenvalues, ", "))
      << "\n"
      << "- eigenvalue 1 simple and dominant: " << (a.one_is_simple_and_dominant ? "yes" : "no") << "\n"
      << "- necessary condition for C1 (lambda1 = 1/2 > |lambda2|): " << (a.c1_necessary ? "yes" : "no") << "\n"
      << "- limit mask over offsets " << a.window_first << ".." << a.window_last << ": "
      << (mask.empty() ? "(none: 1 is not a simple eigenvalue)" : join(mask, ", ")) << "\n"
      << "- verdict: " << (a.converges ? "converges, " + smoothness_text(a) : "convergence not proven")
      << (a.converges && a.smoothness != S::infinite_smoothness
            ? ", Holder exponent >= " + printf_number("%.3f", a.holder_exponent)
            : "")
      << "\n"
      << "- predicted rate of the distances: " << with_fraction(a.predicted_rate) << "\n\n";
}

void write_comparison(const Measurements& levels, const Analysis& a, std::ostream& out)
{
  if(levels.size() < 2)
    return;
  std::vector<std::string> ratios;
  for(std::size_t i = 1; i < levels.size(); ++i)
    ratios.push_back(printf_number("%.4f", levels[i].ratio));
  out << "Measured ratios (levels 2.." << levels.size() << "): " << join(ratios, ", ")
      << "; predicted rate: " << with_fraction(a.predicted_rate) << ".\n\n";
}

} // namespace

Report_summary write_report(const Curve_job& job, const Input_polyline& input, std::ostream& out)
{
  const Measurements levels =
    input.dimension == 3 ? measure<Double_kernel::Point_3>(job, input) : measure<Double_kernel::Point_2>(job, input);
  const Analysis analysis = analyse(job.scheme);
  out << "## " << describe(job.scheme) << ": " << describe(job.refine) << ", " << input.points.size()
      << " input points\n\n";
  write_measurements(levels, out);
  write_analysis(analysis, out);
  write_comparison(levels, analysis, out);

  Report_summary summary;
  summary.last_ratio = levels.empty() ? std::numeric_limits<double>::quiet_NaN() : levels.back().ratio;
  summary.predicted_rate = analysis.predicted_rate;
  summary.verdict = smoothness_text(analysis);
  return summary;
}

bool report_available()
{
  return true;
}

} // namespace cgal_subdiv

#else // SUBDIV_CLI_WITH_ANALYSIS

namespace cgal_subdiv {

Report_summary write_report(const Curve_job&, const Input_polyline&, std::ostream&)
{
  throw Input_error(
    "this cgal-subdiv was built without the analysis layer "
    "(CGAL/Subdiv/analysis/curve_analysis.h): no --report");
}

bool report_available()
{
  return false;
}

} // namespace cgal_subdiv

#endif // SUBDIV_CLI_WITH_ANALYSIS
