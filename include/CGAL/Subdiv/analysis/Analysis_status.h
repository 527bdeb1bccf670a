// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_ANALYSIS_STATUS_H
#define CGAL_SUBDIV_ANALYSIS_ANALYSIS_STATUS_H

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * How an analysis ended (Eigen's `info()` habit): its numbers mean something
 * only with `success`.
 */
enum class Analysis_status {
  success,             ///< every step ran
  no_convergence,      ///< an eigen-solver of Eigen did not converge; the spectrum is missing or partial
  not_affine_invariant ///< the rows of the local subdivision matrix do not sum to 1: it has no limit mask
};

inline std::string to_string(Analysis_status status)
{
  switch(status) {
    case Analysis_status::success:
      return "success";
    case Analysis_status::no_convergence:
      return "no convergence";
    case Analysis_status::not_affine_invariant:
      return "not affine invariant";
  }
  return "unknown";
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_ANALYSIS_STATUS_H
