// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ERRORS_H
#define CGAL_SUBDIV_ERRORS_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivErrors
 * Thrown by every entry point of the package when its input cannot be
 * processed: too few points, a parameter out of its range, a level count whose
 * output would not fit in memory, a mesh the scheme does not apply to.
 * `what()` names the problem (and the offending element where it helps).
 * The caller's data is left unchanged when this is thrown.
 *
 * These checks stay on in release builds: they guard user errors, not
 * internal invariants.
 */
class Bad_input : public std::invalid_argument
{
public:
  explicit Bad_input(const std::string& what) : std::invalid_argument(what) {}
};

namespace internal {

inline void require(bool condition, const std::string& message)
{
  if(!condition)
    throw Bad_input(message);
}

// Refuse before allocating: the output of `levels` levels on n points has at most n 2^levels points.
inline void check_output_size(std::size_t n, int levels, std::size_t limit)
{
  require(levels >= 0, "the number of levels must not be negative, got " + std::to_string(levels));
  double estimate = static_cast<double>(n);
  for(int l = 0; l < levels && estimate <= static_cast<double>(limit); ++l)
    estimate *= 2;
  require(estimate <= static_cast<double>(limit), std::to_string(levels) + " levels on " + std::to_string(n) +
                                                    " points would make more than " + std::to_string(limit) +
                                                    " points (the max_output_points limit)");
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ERRORS_H
