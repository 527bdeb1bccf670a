// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "args.h"
#include "numbers.h"

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
