// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "analyse_summary.h"
#include "analyse_schemes.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <ostream>

namespace cgal_subdiv {
namespace {

constexpr int summary_first_valence = 3, summary_last_valence = 8;

std::string lambda_text(const std::complex<double>& z)
{
  char buffer[48];
  if(std::abs(z.imag()) < 1e-9)
    std::snprintf(buffer, sizeof buffer, "%.4f", z.real());
  else
    std::snprintf(buffer, sizeof buffer, "%.4f%+.4fi", z.real(), z.imag());
  return buffer;
}

// "C1 at 3..8", "C1 at 4..7; not at 3, 8"
std::string verdict_text(const Analysis_summary_row& row)
{
  std::vector<int> yes, no;
  for(std::size_t i = 0; i < row.valences.size(); ++i)
    (row.c1[i] ? yes : no).push_back(row.valences[i]);
  const auto list = [](const std::vector<int>& values) {
    std::string text;
    for(std::size_t i = 0; i < values.size();) {
      std::size_t j = i;
      while(j + 1 < values.size() && values[j + 1] == values[j] + 1)
        ++j;
      text += (text.empty() ? "" : ", ") + std::to_string(values[i]) +
              (j > i ? (j == i + 1 ? ", " : "..") + std::to_string(values[j]) : std::string());
      i = j + 1;
    }
    return text;
  };
  if(no.empty())
    return "C1 at " + list(yes);
  if(yes.empty())
    return "not C1 at " + list(no);
  return "C1 at " + list(yes) + "; not at " + list(no);
}

std::string subdominants(const Analysis_summary_row& row, const char* separator)
{
  std::string text;
  for(std::size_t i = 0; i < row.subdominant.size(); ++i)
    text += (i ? separator : "") + lambda_text(row.subdominant[i]);
  return text;
}

} // namespace

std::vector<Analysis_summary_row> analysis_summary()
{
  std::vector<Analysis_summary_row> rows;
  for(const Surface_scheme_facts& facts : analysable_surface_schemes()) {
    Analysis_summary_row row;
    row.scheme = facts.keyword;
    try {
      for(int n = summary_first_valence; n <= summary_last_valence; ++n) {
        const Surface_summary s = analyse_surface(facts.keyword, n, false, true, false);
        row.valences.push_back(n);
        row.subdominant.push_back(s.subdominant);
        row.c1.push_back(s.c1);
      }
    } catch(const std::exception& e) {
      row.failure = e.what();
    }
    rows.push_back(row);
  }
  return rows;
}

void print_analysis_summary(const std::vector<Analysis_summary_row>& rows)
{
  std::printf("%-20s %-9s %-50s %s\n", "analysis", "valences", "subdominant eigenvalue lambda1 by valence", "verdict");
  for(const Analysis_summary_row& r : rows) {
    if(!r.failure.empty()) {
      std::printf("%-20s failed: %s\n", r.scheme.c_str(), r.failure.c_str());
      continue;
    }
    const std::string valences = std::to_string(r.valences.front()) + ".." + std::to_string(r.valences.back());
    std::printf("%-20s %-9s %-50s %s\n", r.scheme.c_str(), valences.c_str(), subdominants(r, " ").c_str(),
                verdict_text(r).c_str());
  }
}

void write_analysis_index(const std::vector<Analysis_summary_row>& rows, std::ostream& out)
{
  out << "## Analysis\n\n"
      << "The eigen-analysis of every surface scheme from its own mask (`cgal-subdiv analyse`), exact, at "
      << "interior vertices of valence " << summary_first_valence << ".." << summary_last_valence
      << " (doo-sabin: faces with that many corners): the subdominant eigenvalue lambda1 and the C1 verdict "
      << "(eigenvalues and characteristic map). All valences and border vertices: `doc/tables/` of the "
      << "source tree.\n\n"
      << "| scheme | valences | lambda1 by valence | verdict |\n|---|---|---|---|\n";
  for(const Analysis_summary_row& r : rows) {
    if(!r.failure.empty()) {
      out << "| " << r.scheme << " | failed: " << r.failure << " | | |\n";
      continue;
    }
    out << "| " << r.scheme << " | " << r.valences.front() << ".." << r.valences.back() << " | "
        << subdominants(r, ", ") << " | " << verdict_text(r) << " |\n";
  }
  out << "\n";
}

} // namespace cgal_subdiv
