// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The limit surface evaluator of `cgal-subdiv evaluate` and `tessellate`
// (CGAL/Subdiv/limit/Limit_surface.h, tessellate.h) behind a non-template
// interface: its instantiations, costly to compile, live in one file
// (limit_evaluator.cpp).
#ifndef CGAL_SUBDIV_CLI_LIMIT_EVALUATOR_H
#define CGAL_SUBDIV_CLI_LIMIT_EVALUATOR_H

#include "args.h"
#include "surface_from_soup.h"

#include <CGAL/Subdiv/limit/Limit_sample.h>

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cgal_subdiv {

/// the schemes whose limit surface is evaluated
enum class Limit_scheme { catmull_clark, loop };

/// MESH and --scheme, as `evaluate` and `tessellate` take them
struct Limit_arguments
{
  std::string input;
  Limit_scheme scheme;
  std::string scheme_name;
};

/// the one positional MESH (its format known from its extension) and the
/// scheme of --scheme (a keyword of `cgal-subdiv surface`) of `command`;
/// \throws Usage_error if one is missing, for a second positional argument,
///         an unknown extension or scheme, or a scheme not evaluated
Limit_arguments limit_arguments(const Parsed_args& args, const std::string& command);

/// the notes of a successful run on stderr, `cgal-subdiv: note: ...`
void print_notes(const std::vector<std::string>& notes);

/// the limit surface at one parameter
using Limit_point = CGAL::Subdiv::Limit_sample;

/// what the evaluator found for one valence's Stam eigenbasis
/// (`Limit_surface::eigenbasis_conditions()`, `eigenbasis_eigenvalues()`)
struct Eigenbasis_facts
{
  double condition;                ///< of the eigenvector matrix; infinite where the basis is not used
  std::vector<double> eigenvalues; ///< in the order of the eigen-solver
};

/// The limit surface of a mesh under one scheme.
class Limit_evaluator
{
public:
  /// keeps `mesh` by reference (it must outlive the evaluator, unchanged);
  /// \throws CGAL::Subdiv::Bad_input for a mesh the evaluator refuses (Loop: a
  ///         face that is not a triangle)
  Limit_evaluator(const Surface& mesh, Limit_scheme scheme);
  ~Limit_evaluator();
  Limit_evaluator(const Limit_evaluator&) = delete;
  Limit_evaluator& operator=(const Limit_evaluator&) = delete;

  /// the limit at (u, v) of face `face` (a quad, or a triangle under Loop) or,
  /// for `corner` >= 0, of the sub-quad at that corner of a Catmull-Clark
  /// face with n != 4 corners (Limit_surface.h: the parameterisation);
  /// the caller checks the parameters first, the library refuses them again
  Limit_point evaluate(std::size_t face, int corner, double u, double v) const;

  /// the tessellation of the limit surface at `rate` segments per mesh edge
  /// (`CGAL::Subdiv::tessellate`), triangles only with `triangles`, the unit
  /// limit normals in the map "v:normal" (`normal_name`) with `normals`;
  /// \throws CGAL::Subdiv::Bad_input if the output would be too large
  Surface tessellate(int rate, bool triangles, bool normals) const;

  /// the Stam eigenbases built so far (by evaluations next to an
  /// extraordinary vertex), by valence
  std::map<std::size_t, Eigenbasis_facts> eigenbases() const;

private:
  struct Model;
  template <class Mask>
  struct Model_of;
  std::unique_ptr<const Model> m_model;
};

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_LIMIT_EVALUATOR_H
