// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "args.h"
#include "numbers.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include <cctype>
#include <stdexcept>

namespace cgal_subdiv {
namespace {

const Option_spec* find_spec(const std::vector<Option_spec>& specs, const std::string& name)
{
  for(const Option_spec& spec : specs)
    for(const std::string& n : spec.names)
      if(n == name)
        return &spec;
  return nullptr;
}

// "-" alone is a file name; "-1" and "-.5" are values, not options
bool looks_like_option(const std::string& arg)
{
  return arg.size() > 1 && arg[0] == '-' && !(std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
}

} // namespace

std::string Parsed_args::value(const std::string& key, const std::string& fallback) const
{
  const auto it = m_values.find(key);
  return it == m_values.end() ? fallback : it->second;
}

Exact Parsed_args::number(const std::string& key, const Exact& fallback) const
{
  if(!has(key))
    return fallback;
  try {
    return parse_number(value(key));
  } catch(const std::invalid_argument& e) {
    const std::string reason = e.what();
    throw Usage_error(key + " expects a number such as 0.25 or 1/4, got '" + value(key) + "'" +
                      (reason == "not a number" ? "" : " (" + reason + ")"));
  }
}

int Parsed_args::integer(const std::string& key, int fallback) const
{
  if(!has(key))
    return fallback;
  try {
    return parse_int(value(key));
  } catch(const std::invalid_argument& e) {
    const std::string reason = e.what();
    throw Usage_error(key + " expects a whole number, got '" + value(key) + "'" +
                      (reason == "not a whole number" ? "" : " (" + reason + ")"));
  }
}

double Parsed_args::bytes(const std::string& key, double fallback) const
{
  if(!has(key))
    return fallback;
  const std::string text = value(key);
  const auto refuse = [&]() -> double {
    throw Usage_error(key + " expects a size such as 8G, 512MB or 2GiB, got '" + text + "'");
  };
  std::size_t digits = 0;
  while(digits < text.size() && (std::isdigit(static_cast<unsigned char>(text[digits])) || text[digits] == '.'))
    ++digits;
  if(digits == 0)
    return refuse();
  char* end = nullptr;
  const std::string number = text.substr(0, digits);
  const double amount = std::strtod(number.c_str(), &end);
  if(end != number.c_str() + number.size())
    return refuse();
  std::string unit = text.substr(digits);
  for(char& c : unit)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::map<std::string, double> units = {{"", 1},
                                               {"b", 1},
                                               {"k", 1e3},
                                               {"kb", 1e3},
                                               {"m", 1e6},
                                               {"mb", 1e6},
                                               {"g", 1e9},
                                               {"gb", 1e9},
                                               {"t", 1e12},
                                               {"tb", 1e12},
                                               {"kib", 1024.0},
                                               {"mib", 1048576.0},
                                               {"gib", 1073741824.0},
                                               {"tib", 1099511627776.0}};
  const auto found = units.find(unit);
  if(found == units.end())
    return refuse();
  const double result = amount * found->second;
  if(!(result >= 1) || !std::isfinite(result))
    throw Usage_error(key + " must be a positive size, got '" + text + "'");
  return result;
}

Parsed_args scan_args(const std::vector<std::string>& args, const std::vector<Option_spec>& specs,
                      const std::string& command)
{
  Parsed_args parsed;
  bool options_ended = false;
  for(std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if(options_ended || !looks_like_option(arg)) {
      parsed.positional.push_back(arg);
      continue;
    }
    if(arg == "--") {
      options_ended = true;
      continue;
    }
    const std::size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const Option_spec* spec = find_spec(specs, name);
    if(!spec)
      throw Usage_error("unknown option '" + name + "'; see 'cgal-subdiv " + command + " --help'");
    const std::string& key = spec->names.front();
    if(parsed.has(key))
      throw Usage_error("option " + key + " given twice");
    if(!spec->takes_value) {
      if(equals != std::string::npos)
        throw Usage_error("option " + key + " takes no value");
      parsed.m_values[key] = "";
    } else if(equals != std::string::npos) {
      parsed.m_values[key] = arg.substr(equals + 1);
    } else {
      if(i + 1 >= args.size())
        throw Usage_error("option " + key + " needs a value");
      parsed.m_values[key] = args[++i];
    }
  }
  return parsed;
}

} // namespace cgal_subdiv
