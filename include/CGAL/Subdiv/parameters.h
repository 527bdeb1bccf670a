// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_PARAMETERS_H
#define CGAL_SUBDIV_PARAMETERS_H

/// \file parameters.h
/// The named parameters of CGAL Subdiv: CGAL's own ones that the package
/// reads, and the package's, in one chain in any order:
/// `CGAL::Subdiv::parameters::number_of_iterations(3).carried_data(data).threads(2)`.
/// A chain of CGAL's own (`CGAL::parameters::number_of_iterations(3)`) is
/// accepted everywhere too; only the package's parameters cannot be appended
/// to it (CGAL's list is closed), so start the chain here.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// tags of the package's own named parameters (not in a namespace
/// `internal_np`, which would hide CGAL's from code in CGAL::Subdiv)
// carried_data_t and threads_t are only declared: Carried_data.h and
// internal/parallel.h, which read them, still define them, and a second
// definition here breaks every file that includes both. Define them here
// when those two stop.
struct carried_data_t;
struct threads_t;
struct closed_t
{
};
struct end_rule_t
{
};
struct max_output_points_t
{
};
struct flatness_tolerance_t
{
};

} // namespace internal

namespace parameters {

// CGAL's accessors, so that `parameters::choose_parameter` and the like keep
// working from code in CGAL::Subdiv
using CGAL::parameters::choose_parameter;
using CGAL::parameters::default_values;
using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

/*!
 * \ingroup PkgSubdivFunctions
 * A chain of named parameters: a `CGAL::Named_function_parameters` (so every
 * CGAL function that reads named parameters reads it) whose member functions
 * also append the package's own parameters.
 */
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  using Nfp = CGAL::Named_function_parameters<T, Tag, Base>;
  using self = Named_parameters<T, Tag, Base>;

  Named_parameters() = default;
  Named_parameters(const T& v) : Nfp(v) {}
  Named_parameters(const T& v, const Base& b) : Nfp(v, b) {}

#define CGAL_SUBDIV_NAMED_PARAMETER(NAME, TAG)                                                                        \
  template <class K>                                                                                                   \
  Named_parameters<K, TAG, self> NAME(const K& k) const                                                                \
  {                                                                                                                    \
    return Named_parameters<K, TAG, self>(k, *this);                                                                   \
  }
  // CGAL's own
  CGAL_SUBDIV_NAMED_PARAMETER(number_of_iterations, CGAL::internal_np::number_of_iterations_t)
  CGAL_SUBDIV_NAMED_PARAMETER(vertex_point_map, CGAL::internal_np::vertex_point_t)
  CGAL_SUBDIV_NAMED_PARAMETER(geom_traits, CGAL::internal_np::geom_traits_t)
  CGAL_SUBDIV_NAMED_PARAMETER(vertex_normal_map, CGAL::internal_np::vertex_normal_map_t)
  // the package's
  CGAL_SUBDIV_NAMED_PARAMETER(threads, internal::threads_t)
  CGAL_SUBDIV_NAMED_PARAMETER(closed, internal::closed_t)
  CGAL_SUBDIV_NAMED_PARAMETER(end_rule, internal::end_rule_t)
  CGAL_SUBDIV_NAMED_PARAMETER(max_output_points, internal::max_output_points_t)
  CGAL_SUBDIV_NAMED_PARAMETER(flatness_tolerance, internal::flatness_tolerance_t)
#undef CGAL_SUBDIV_NAMED_PARAMETER

  /// other vertex and face data to carry through the levels (`Carried_data`)
  template <class Data>
  Named_parameters<const Data*, internal::carried_data_t, self> carried_data(const Data& data) const
  {
    return Named_parameters<const Data*, internal::carried_data_t, self>(&data, *this);
  }
};

#define CGAL_SUBDIV_NAMED_PARAMETER(NAME, TAG)                                                                        \
  template <class K>                                                                                                   \
  Named_parameters<K, TAG> NAME(const K& k)                                                                            \
  {                                                                                                                    \
    return Named_parameters<K, TAG>(k);                                                                                \
  }
/// \name CGAL's named parameters that the package reads
/// @{
CGAL_SUBDIV_NAMED_PARAMETER(number_of_iterations, CGAL::internal_np::number_of_iterations_t)
CGAL_SUBDIV_NAMED_PARAMETER(vertex_point_map, CGAL::internal_np::vertex_point_t)
CGAL_SUBDIV_NAMED_PARAMETER(geom_traits, CGAL::internal_np::geom_traits_t)
CGAL_SUBDIV_NAMED_PARAMETER(vertex_normal_map, CGAL::internal_np::vertex_normal_map_t)
/// @}
/// \name The package's own named parameters
/// @{
/// how many threads the fast paths use (see `CGAL::Subdiv::subdivide()`):
/// 1 (the default) the calling thread, 0 TBB's choice, n > 1 at most n; the
/// results do not depend on it, bit for bit
CGAL_SUBDIV_NAMED_PARAMETER(threads, internal::threads_t)
/// curves: whether the polyline is closed (default false)
CGAL_SUBDIV_NAMED_PARAMETER(closed, internal::closed_t)
/// curves: what happens at the ends of an open polyline (`End_rule`)
CGAL_SUBDIV_NAMED_PARAMETER(end_rule, internal::end_rule_t)
/// curves: refuse, before allocating, a call whose output would have more points
CGAL_SUBDIV_NAMED_PARAMETER(max_output_points, internal::max_output_points_t)
/// Bezier curves: refine each segment until it is this flat (instead of a fixed depth)
CGAL_SUBDIV_NAMED_PARAMETER(flatness_tolerance, internal::flatness_tolerance_t)
/// @}
#undef CGAL_SUBDIV_NAMED_PARAMETER

/// other vertex and face data to carry through the levels (`Carried_data`)
template <class Data>
Named_parameters<const Data*, internal::carried_data_t> carried_data(const Data& data)
{
  return Named_parameters<const Data*, internal::carried_data_t>(&data);
}

} // namespace parameters
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_PARAMETERS_H
