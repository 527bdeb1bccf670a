// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Numbers in and out: the one parser of the tool, exact conversions, printing.
#ifndef CGAL_SUBDIV_CLI_NUMBERS_H
#define CGAL_SUBDIV_CLI_NUMBERS_H

#include "common.h"

#include <string>
#include <type_traits>

namespace cgal_subdiv {

/*
 * parses a decimal ("-0.1", "2.5e-3", "7") or a fraction ("17/3", "-1/16")
 * exactly. Throws std::invalid_argument with a short reason (the caller adds
 * where the text came from).
 */
Exact parse_number(const std::string& text);

/// parses a whole number in the range of int ("3", "-1")
int parse_int(const std::string& text);

/// the double nearest to `x` (ties to even); throws Input_error if |x| is too large
double nearest_double(const Exact& x);

/// the value of `x` in the number type FT of a kernel (double or Exact)
template <class FT>
FT to_ft(const Exact& x)
{
  if constexpr(std::is_same<FT, double>::value)
    return nearest_double(x);
  else
    return FT(x);
}

/// "17/3", "-2", "0"
std::string format_exact(const Exact& x);

/// 17 significant digits, enough to read the same double back
std::string format_double(double x);

/// JSON number: as `format_double`, null for NaN and infinities
std::string json_number(double x);
/// JSON string with the escapes JSON needs
std::string json_string(const std::string& text);

/// the number in the form the output uses
inline std::string format_number(const Exact& x)
{
  return format_exact(x);
}
inline std::string format_number(double x)
{
  return format_double(x);
}

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_NUMBERS_H
