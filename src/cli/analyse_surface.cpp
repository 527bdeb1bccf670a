// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The surface schemes' eigen-analysis in Exact_rational, one instantiation
// of analyse_surface_scheme() per mask (the costly translation unit).
#include "analyse_schemes.h"
#include "numbers.h"

#include <CGAL/Subdiv/analysis/surface_analysis.h>
#include <CGAL/Subdiv/masks/Butterfly_mask.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Doo_sabin_mask.h>
#include <CGAL/Subdiv/masks/Interpolating_sqrt3_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/masks/Modified_butterfly_mask.h>
#include <CGAL/Subdiv/masks/Sqrt3_mask.h>

namespace cgal_subdiv {
namespace {

namespace S = CGAL::Subdiv;

template <class Mask>
Surface_summary run(const std::string& keyword, const Mask& mask, const S::Configuration& where,
                    bool characteristic_map, bool verify_limit)
{
  const S::Surface_analysis<Exact> a = S::analyse_surface_scheme<Exact>(
    mask, where, S::parameters::characteristic_map(characteristic_map).verify_limit(verify_limit));
  Surface_summary s;
  s.scheme = keyword;
  s.name = a.scheme;
  s.valence = a.valence;
  s.boundary = a.boundary;
  s.configuration = a.configuration;
  s.face_centred = a.face_centred;
  s.rings = a.rings;
  s.ring = a.ring;
  s.exact = a.exact;
  s.rows_sum_to_one = a.rows_sum_to_one;
  s.eigenvalues = a.eigenvalues;
  s.exact_eigenvalues = a.exact_eigenvalues;
  s.one_is_simple_and_dominant = a.one_is_simple_and_dominant;
  s.subdominant = a.subdominant;
  s.second_subdominant = a.second_subdominant;
  s.subdominant_multiplicity = a.subdominant_multiplicity;
  s.c1_necessary = a.c1_necessary;
  s.extended_rings = a.extended_rings;
  s.extended_largest_other = a.extended_largest_other;
  s.extended_spectrum_ok = a.extended_spectrum_ok;
  s.characteristic_map = S::to_string(a.characteristic_map);
  s.characteristic_map_levels = a.characteristic_map_levels;
  s.annulus_inner = a.annulus_inner;
  s.annulus_outer = a.annulus_outer;
  s.c1 = a.c1;
  s.limit_mask = a.limit_mask;
  for(const Exact& w : a.limit_mask)
    s.limit_mask_double.push_back(nearest_double(w)); // CGAL::to_double truncates
  s.tangent_mask[0] = a.tangent_mask[0];
  s.tangent_mask[1] = a.tangent_mask[1];
  s.host_levels = a.host_levels;
  s.cropped_levels = a.cropped_levels;
  s.host_error = a.host_error;
  s.limit_error = a.limit_error;
  s.block_triangular = a.block_triangular;
  for(const auto& side : a.sides)
    s.sides.push_back(
      {side.faces, side.same_as_border, side.c1_necessary, side.c1, S::to_string(side.characteristic_map)});
  return s;
}

// the analysis of the scheme `keyword` (checked) at `where`
Surface_summary analyse_at(const std::string& keyword, const S::Configuration& where, bool characteristic_map,
                           bool verify_limit)
{
  using M = S::Analysis_mesh;
  const auto analyse = [&](const auto& mask) { return run(keyword, mask, where, characteristic_map, verify_limit); };
  if(keyword == "loop")
    return analyse(S::Loop_mask<M, Exact>());
  if(keyword == "loop-warren")
    return analyse(S::Loop_warren_mask<M, Exact>());
  if(keyword == "catmull-clark")
    return analyse(S::Catmull_clark_mask<M, Exact>());
  if(keyword == "doo-sabin")
    return analyse(S::Doo_sabin_mask<M, Exact>());
  if(keyword == "sqrt3")
    return analyse(S::Sqrt3_mask<M, Exact>());
  if(keyword == "butterfly")
    return analyse(S::Butterfly_mask<M, Exact>());
  if(keyword == "modified-butterfly")
    return analyse(S::Modified_butterfly_mask<M, Exact>());
  return analyse(S::Interpolating_sqrt3_mask<M, Exact>());
}

} // namespace

const std::vector<Surface_scheme_facts>& analysable_surface_schemes()
{
  // keyword, split, dual, interpolating, border analysed, sharp vertices analysed
  static const std::vector<Surface_scheme_facts> schemes = {
    {"loop", "1-to-4 triangle split", false, false, true, true},
    {"loop-warren", "1-to-4 triangle split", false, false, true, true},
    {"catmull-clark", "quad split", false, false, true, true},
    {"doo-sabin", "dual quad split", true, false, true},
    {"sqrt3", "sqrt3 split", false, false, true},
    {"butterfly", "1-to-4 triangle split", false, true, true},
    {"modified-butterfly", "1-to-4 triangle split", false, true, true},
    {"interpolating-sqrt3", "sqrt3 split", false, true, true},
  };
  return schemes;
}

const Surface_scheme_facts* find_analysable_surface_scheme(const std::string& keyword)
{
  for(const Surface_scheme_facts& facts : analysable_surface_schemes())
    if(facts.keyword == keyword)
      return &facts;
  return nullptr;
}

Surface_summary analyse_surface(const std::string& keyword, int valence, bool boundary, bool characteristic_map,
                                bool verify_limit)
{
  if(keyword == "linear")
    throw Input_error(
      "linear has no smoothness to analyse: its limit is the control mesh itself (C0); "
      "analyse one of the other surface schemes");
  const Surface_scheme_facts* facts = find_analysable_surface_scheme(keyword);
  if(!facts)
    throw Usage_error("unknown scheme '" + keyword + "'");
  if(boundary && !facts->border_analysis)
    throw Input_error("border vertices of " + keyword + " are not analysed");
  // interior valence 2: quad faces only (doc/limit.md); a triangle scheme
  // or a face of two corners cannot be laid out
  const bool quad_primal = facts->split == "quad split";
  const int low = boundary ? 1 : (quad_primal ? 2 : 3);
  if(valence < low || valence > max_analysed_valence) {
    const std::string what = boundary      ? "the number of faces at a border vertex"
                             : facts->dual ? "the number of corners of the central face"
                                           : "the valence of an interior vertex";
    throw Input_error(what + " must be between " + std::to_string(low) + " and " +
                      std::to_string(max_analysed_valence) + ", got " + std::to_string(valence));
  }
  return analyse_at(keyword, S::Configuration(valence, boundary ? S::Vertex_kind::border : S::Vertex_kind::interior),
                    characteristic_map, verify_limit);
}

Surface_summary analyse_sharp_vertex(const std::string& keyword, const S::Configuration& where, bool characteristic_map,
                                     bool verify_limit)
{
  const Surface_scheme_facts* facts = find_analysable_surface_scheme(keyword);
  if(!facts)
    throw Usage_error("unknown scheme '" + keyword + "'");
  const std::string option = where.kind == S::Vertex_kind::crease ? "--crease"
                             : where.kind == S::Vertex_kind::dart ? "--dart"
                                                                  : "--corner";
  if(!facts->sharp_analysis)
    throw Input_error(option + ": " + keyword +
                      " takes no sharpness tags; crease, dart and corner vertices are analysed for loop, "
                      "loop-warren and catmull-clark");
  if(where.kind == S::Vertex_kind::crease) {
    for(const int k : {where.first_side, where.second_side()})
      if(k < 1 || k > max_crease_side)
        throw Input_error("--crease K1,K2: the faces on each side must be between 1 and " +
                          std::to_string(max_crease_side) + ", got " + std::to_string(k));
    if(where.valence == 2 && facts->split != "quad split")
      throw Input_error(
        "--crease 1,1: an interior vertex of valence 2 in a triangle mesh cannot be laid out (its "
        "two triangles share all three edges)");
  } else if(where.valence < min_sharp_valence || where.valence > max_sharp_valence) {
    throw Input_error(option + " N: the valence must be between " + std::to_string(min_sharp_valence) + " and " +
                      std::to_string(max_sharp_valence) + ", got " + std::to_string(where.valence));
  }
  return analyse_at(keyword, where, characteristic_map, verify_limit);
}

} // namespace cgal_subdiv
