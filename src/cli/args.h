// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// A small command-line scanner: `--name value`, `--name=value`, flags,
// positional arguments, `--` to end the options.
#ifndef CGAL_SUBDIV_CLI_ARGS_H
#define CGAL_SUBDIV_CLI_ARGS_H

#include "common.h"

#include <map>
#include <string>
#include <vector>

namespace cgal_subdiv {

struct Option_spec
{
  std::vector<std::string> names; // e.g. {"-o", "--output"}; the first is the key
  bool takes_value;
};

class Parsed_args
{
public:
  bool has(const std::string& key) const { return m_values.count(key) != 0; }
  /// the value of an option that takes one; `fallback` if it was not given
  std::string value(const std::string& key, const std::string& fallback = "") const;
  /// parses the value with parse_number(); Usage_error if it is not a number
  Exact number(const std::string& key, const Exact& fallback) const;
  /// parses the value with parse_int(); Usage_error if it is not a whole number
  int integer(const std::string& key, int fallback) const;
  /// a size in bytes: a number with an optional unit, k/M/G/T (powers of
  /// 1000) or KiB/MiB/GiB/TiB (powers of 1024), a final B optional, e.g. 8G,
  /// 512MB, 1.5GiB; Usage_error if it is not a positive size
  double bytes(const std::string& key, double fallback) const;

  std::vector<std::string> positional;

private:
  friend Parsed_args scan_args(const std::vector<std::string>&, const std::vector<Option_spec>&, const std::string&);
  std::map<std::string, std::string> m_values;
};

/// \throws Usage_error for an unknown option, a missing value or an option given twice;
///         `command` names the subcommand in the message (for its --help)
Parsed_args scan_args(const std::vector<std::string>& args, const std::vector<Option_spec>& specs,
                      const std::string& command);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_ARGS_H
