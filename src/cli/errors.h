// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The two kinds of failure of the cgal-subdiv command-line tool; no CGAL
// here, so that the parts of the tool that need none (mesh_soup.h) can use
// them.
#ifndef CGAL_SUBDIV_CLI_ERRORS_H
#define CGAL_SUBDIV_CLI_ERRORS_H

#include <stdexcept>
#include <string>

namespace cgal_subdiv {

/// A mistake on the command line itself (exit code 2).
class Usage_error : public std::runtime_error
{
public:
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

/// A file or its content cannot be used (exit code 1).
class Input_error : public std::runtime_error
{
public:
  explicit Input_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_ERRORS_H
