// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "rules.h"

#include <CGAL/Subdiv/analysis/surface_analysis.h> // has_small_denominator
#include <CGAL/Subdiv/analysis/surface_neighbourhood.h>
#include <CGAL/Subdiv/masks/Butterfly_mask.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Doo_sabin_mask.h>
#include <CGAL/Subdiv/masks/Interpolating_sqrt3_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/masks/Modified_butterfly_mask.h>
#include <CGAL/Subdiv/masks/Sqrt3_mask.h>

#include <algorithm>
#include <stdexcept>

namespace subdiv_doc_tables {
namespace {

namespace S = CGAL::Subdiv;
namespace SI = CGAL::Subdiv::internal;
using Mesh = S::Analysis_mesh;

constexpr int patch_rings = 3;

Rule make_rule(const std::string& name, const std::string& description,
               const S::Stencil<SI::Analysis_vertex, Exact>& stencil, const SI::Labelling& labels)
{
  Rule rule;
  rule.name = name;
  rule.description = description;
  for(const auto& term : stencil.terms()) {
    if(term.second == Exact(0))
      continue;
    const int label = labels.label(term.first);
    if(label < 0)
      throw std::runtime_error("a " + name + " rule reads a vertex outside the patch");
    rule.terms.push_back(
      {label, labels.ring[static_cast<std::size_t>(label)], term.second, SI::has_small_denominator(term.second)});
  }
  std::sort(rule.terms.begin(), rule.terms.end(),
            [](const Rule_term& x, const Rule_term& y) { return x.label < y.label; });
  for(int r : labels.ring) {
    if(static_cast<int>(rule.ring_sizes.size()) <= r)
      rule.ring_sizes.resize(static_cast<std::size_t>(r) + 1, 0);
    ++rule.ring_sizes[static_cast<std::size_t>(r)];
  }
  return rule;
}

template <template <class, class> class MaskTemplate>
std::vector<Rule> rules_of(int n, bool boundary)
{
  using Mask = MaskTemplate<Mesh, Exact>;
  using Traits = S::Host_of<Mask>;
  const Mask mask;
  const SI::Patch patch = SI::analysis_patch(
    mask, S::Configuration(n, boundary ? S::Vertex_kind::border : S::Vertex_kind::interior), patch_rings + 2);
  const SI::Labelling labels = SI::label_neighbourhood(patch.mesh, patch.start, Traits::face_centred, patch_rings);
  const Mesh& mesh = patch.mesh;
  const auto h = patch.start;
  std::vector<Rule> rules;
  const auto record = [&](const std::string& name, const std::string& description, const auto& call) {
    S::Stencil<SI::Analysis_vertex, Exact> stencil;
    call(stencil);
    rules.push_back(make_rule(name, description, stencil, labels));
  };
  if constexpr(Traits::face_centred) { // dual: the new vertex of corner 0 of the central n-gon
    if(!boundary) {
      record("corner", "The new vertex of corner 0 of the central face (labels 0..n-1: its corners)",
             [&](auto& acc) { mask.corner_node(S::Corner_view<Mesh>(mesh, mesh.prev(h)), acc); });
    } else { // the border face made from a border vertex with n faces
      record("border corner",
             "The new vertex of corner 0 of the central border face (labels 0..m-1: its corners, from the first "
             "one after its border edges): on the border",
             [&](auto& acc) { mask.corner_node(S::Corner_view<Mesh>(mesh, mesh.prev(h)), acc); });
      record("interior corner", "The new vertex of corner 1 of the central border face",
             [&](auto& acc) { mask.corner_node(S::Corner_view<Mesh>(mesh, h), acc); });
      if(n == 1)
        record("corner with a single face", "The new vertex of corner 3 of the corner face, the corner of the mesh",
               [&](auto& acc) { mask.corner_node(S::Corner_view<Mesh>(mesh, mesh.prev(mesh.prev(h))), acc); });
    }
  } else if constexpr(Traits::analysis_steps ==
                      2) { // sqrt3 split: vertex and face points; the border on refining steps
    if(boundary) {
      record("border vertex (refining step)",
             "The new position of the centre (label 0) on a step that refines the border",
             [&](auto& acc) { mask.border_vertex_node(S::Vertex_view<Mesh>(mesh, mesh.source(h)), acc); });
      record("border vertex (resting step)", "The new position of the centre on a step that leaves the border alone",
             [&](auto& acc) { mask.resting_border_vertex_node(S::Vertex_view<Mesh>(mesh, mesh.source(h)), acc); });
      record("border edge, first third",
             "The new vertex at 1/3 of the border edge from the centre to label 1 (refining step)",
             [&](auto& acc) { mask.border_edge_node(S::Edge_view<Mesh>(mesh, h), 1, acc); });
      record("border edge, second third",
             "The new vertex at 2/3 of the border edge from the centre to label 1 (refining step)",
             [&](auto& acc) { mask.border_edge_node(S::Edge_view<Mesh>(mesh, h), 2, acc); });
    } else {
      record("vertex", "The new position of the centre (label 0)",
             [&](auto& acc) { mask.vertex_node(S::Vertex_view<Mesh>(mesh, mesh.source(h)), acc); });
    }
    record("face", "The new vertex of the face (0, 1, 2)",
           [&](auto& acc) { mask.face_node(S::Face_view<Mesh>(mesh, mesh.face(h)), acc); });
  } else {
    const std::string prefix = boundary ? "border " : "";
    record(prefix + "vertex", "The new position of the centre (label 0)",
           [&](auto& acc) { mask.vertex_node(S::Vertex_view<Mesh>(mesh, mesh.source(h)), acc); });
    record(prefix + "edge", "The new vertex of the edge from the centre to label 1",
           [&](auto& acc) { mask.edge_node(S::Edge_view<Mesh>(mesh, h), acc); });
    if constexpr(Traits::regular_face_size == 4)
      if(!boundary || !mesh.is_border(h))
        record("face", "The new vertex of the face (0, 1, 2, 3)",
               [&](auto& acc) { mask.face_node(S::Face_view<Mesh>(mesh, mesh.face(h)), acc); });
  }
  return rules;
}

} // namespace

std::vector<Rule> read_rules(const std::string& keyword, int n, bool boundary)
{
  if(keyword == "loop")
    return rules_of<S::Loop_mask>(n, boundary);
  if(keyword == "loop-warren")
    return rules_of<S::Loop_warren_mask>(n, boundary);
  if(keyword == "catmull-clark")
    return rules_of<S::Catmull_clark_mask>(n, boundary);
  if(keyword == "doo-sabin")
    return rules_of<S::Doo_sabin_mask>(n, boundary);
  if(keyword == "sqrt3")
    return rules_of<S::Sqrt3_mask>(n, boundary);
  if(keyword == "butterfly")
    return rules_of<S::Butterfly_mask>(n, boundary);
  if(keyword == "modified-butterfly")
    return rules_of<S::Modified_butterfly_mask>(n, boundary);
  if(keyword == "interpolating-sqrt3")
    return rules_of<S::Interpolating_sqrt3_mask>(n, boundary);
  throw std::invalid_argument("no rules for " + keyword);
}

} // namespace subdiv_doc_tables
