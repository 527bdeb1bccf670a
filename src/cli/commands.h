// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The subcommands of cgal-subdiv. Each returns the exit code of a successful
// run and throws Usage_error (exit 2) or any other exception (exit 1).
#ifndef CGAL_SUBDIV_CLI_COMMANDS_H
#define CGAL_SUBDIV_CLI_COMMANDS_H

#include <string>
#include <vector>

namespace cgal_subdiv {

int curve_command(const std::vector<std::string>& args);
int surface_command(const std::vector<std::string>& args);
int demo_command(const std::vector<std::string>& args, const std::string& program_path);
int analyse_command(const std::vector<std::string>& args);
int evaluate_command(const std::vector<std::string>& args);
int tessellate_command(const std::vector<std::string>& args);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_COMMANDS_H
