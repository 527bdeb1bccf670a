// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// What `cgal-subdiv evaluate` and `tessellate` share, apart from the
// evaluator (limit_evaluator.cpp, costly to compile).
#include "limit_evaluator.h"
#include "surface.h"

#include <iostream>

namespace cgal_subdiv {

Limit_arguments limit_arguments(const Parsed_args& args, const std::string& command)
{
  if(args.positional.empty())
    throw Usage_error("missing MESH; see 'cgal-subdiv " + command + " --help'");
  if(args.positional.size() > 1)
    throw Usage_error("unexpected argument '" + args.positional[1] + "' (only one MESH)");
  if(!args.has("--scheme"))
    throw Usage_error("missing --scheme (catmull-clark or loop)");
  Limit_arguments result{args.positional.front(), Limit_scheme::catmull_clark, args.value("--scheme")};
  mesh_format(result.input, "MESH");
  find_surface_scheme(result.scheme_name); // an unknown keyword: the error of `surface`
  if(result.scheme_name == "loop")
    result.scheme = Limit_scheme::loop;
  else if(result.scheme_name != "catmull-clark")
    throw Usage_error("--scheme " + result.scheme_name + ": only catmull-clark and loop are evaluated so far");
  return result;
}

void print_notes(const std::vector<std::string>& notes)
{
  for(const std::string& note : notes)
    std::cerr << "cgal-subdiv: note: " << note << '\n';
}

} // namespace cgal_subdiv
