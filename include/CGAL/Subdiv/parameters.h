// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_PARAMETERS_H
#define CGAL_SUBDIV_PARAMETERS_H

/// \file parameters.h
/// The named parameters of CGAL Subdiv: CGAL's own ones that the package
/// reads, and the package's, in one chain in any order:
/// `CGAL::Subdiv::parameters::number_of_iterations(3).carried_data(data).threads(2)`.
/// A chain of CGAL's own (`CGAL::parameters::number_of_iterations(3)`) is
/// accepted everywhere too; only the package's parameters cannot be appended
/// to it (CGAL's list is closed), so start the chain here.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// tags of the package's own named parameters (not in a namespace
/// `internal_np`, which would hide CGAL's from code in CGAL::Subdiv)
struct carried_data_t
{};
struct threads_t
{};
struct closed_t
{};
struct end_rule_t
{};
struct max_output_points_t
{};
struct flatness_tolerance_t
{};
struct refined_mesh_t
{};
struct refined_corner_indices_t
{};
struct non_manifold_copies_t
{};
struct characteristic_map_t
{};
struct verify_limit_t
{};
struct max_faces_t
{};
struct seed_t
{};
struct rings_t
{};
struct max_memory_t
{};
struct extended_spectrum_t
{};
struct isolated_vertices_t
{};
struct edge_sharpness_map_t
{};
struct vertex_sharpness_map_t
{};
struct crease_method_t
{};
struct face_hole_map_t
{};
struct boundary_interpolation_t
{};
struct triangle_subdivision_t
{};
struct triangulate_t
{};
struct output_normals_t
{};

} // namespace internal

/*!
 * \ingroup PkgSubdivFunctions
 * What `subdivide()` does with a vertex that belongs to no face (OpenSubdiv
 * accepts them; OBJ and PLY files often hold some).
 */
enum class Isolated_vertices {
  /// a `Bad_input` that names the vertex (the default: a mesh with one is
  /// often a broken mesh)
  refuse,
  /// removed before the refinement (the other vertices may be renumbered, as
  /// `Surface_mesh::collect_garbage()` does)
  drop,
  /// kept where they are, unrefined, after the refined vertices (the limit of
  /// a vertex in no face is the vertex)
  keep
};

namespace parameters {

// CGAL's accessors, so that `parameters::choose_parameter` and the like keep
// working from code in CGAL::Subdiv
using CGAL::parameters::choose_parameter;
using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::default_values;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

/*
 * Every named parameter the package reads, listed once; each becomes a free
 * function (`CGAL::Subdiv::parameters::threads(2)`) and a member of the chain
 * (`....threads(2)`).
 *
 * CGAL's own:
 *  - number_of_iterations: how many levels (default 1);
 *  - vertex_point_map: the points (default the mesh's);
 *  - geom_traits: the kernel;
 *  - vertex_normal_map: where the limit functions write normals.
 * The package's:
 *  - threads: how many threads the fast paths use (see `subdivide()`): 1 (the
 *    default) the calling thread, 0 TBB's choice, n > 1 at most n; the
 *    results do not depend on it, bit for bit;
 *  - closed: curves, whether the polyline is closed (default false);
 *  - end_rule: curves, what happens at the ends of an open polyline (`End_rule`);
 *  - max_output_points: curves and `tessellate()`, refuse, before allocating,
 *    a call whose output would have more points;
 *  - flatness_tolerance: Bezier curves, refine each segment until it is this
 *    flat (instead of a fixed depth);
 *  - characteristic_map: analysis, test the characteristic map, the costliest
 *    part (default true);
 *  - extended_spectrum: analysis, the spectrum of the extended neighbourhood
 *    and the characteristic map (default true; false: the spectrum and the
 *    masks only, and no C1 verdict);
 *  - verify_limit: analysis, subdivide a random neighbourhood and compare its
 *    limit with the limit mask (default true);
 *  - max_faces: analysis, the characteristic-map and verification meshes stop
 *    growing at this many faces (default 120000);
 *  - seed: analysis, the seed of the random neighbourhood of the verification
 *    (default 20260);
 *  - rings: analysis, the rings of the neighbourhood of a local subdivision
 *    matrix (default: the smallest invariant one);
 *  - max_memory: surfaces, the memory (bytes) that the output may take
 *    (default this machine's): a level count whose output would take more
 *    is refused before any work;
 *  - isolated_vertices: surfaces, what `subdivide()` does with vertices that
 *    belong to no face (`Isolated_vertices`; default refuse);
 *  - edge_sharpness_map, vertex_sharpness_map: surfaces, read-write property
 *    maps of the sharpness of every edge and vertex, as OpenSubdiv defines it
 *    (0 smooth, 10 and above infinitely sharp); `subdivide()` writes the
 *    sharpness of the children into them;
 *  - crease_method: surfaces, how semi-sharp edges decay (`Crease_method`;
 *    default uniform);
 *  - face_hole_map: surfaces, a read-write property map of the faces that are
 *    holes (bool); `subdivide()` makes the children of a hole holes;
 *  - boundary_interpolation: surfaces, OpenSubdiv's boundary modes
 *    (`Boundary_interpolation`; default edges only);
 *  - triangle_subdivision: Catmull-Clark, the edge rule next to triangles
 *    (`Triangle_subdivision`; default catmark);
 *  - triangulate: `tessellate()`, triangles only (default false: quads where
 *    the domain is a quad grid);
 *  - output_normals: `tessellate()`, the limit normals into the vertex
 *    property "v:normal" of the output (default false);
 *  - non_manifold_copies: `face_varying_limit()`, a vertex property map giving
 *    every vertex the point it copies, as `Carried_data::non_manifold_copies`
 *    takes and keeps it.
 * Kept by reference (the chain holds a pointer to the argument):
 *  - carried_data: other vertex and face data to carry through the levels
 *    (`Carried_data`);
 *  - refined_mesh: where `make_stencil_table()` puts the refined mesh;
 *  - refined_corner_indices: where `make_face_varying_stencil_table()` puts
 *    the value index of every corner of the refined mesh.
 */
#define CGAL_SUBDIV_FOR_EACH_VALUE_PARAMETER(X)                      \
  X(number_of_iterations, CGAL::internal_np::number_of_iterations_t) \
  X(vertex_point_map, CGAL::internal_np::vertex_point_t)             \
  X(geom_traits, CGAL::internal_np::geom_traits_t)                   \
  X(vertex_normal_map, CGAL::internal_np::vertex_normal_map_t)       \
  X(threads, internal::threads_t)                                    \
  X(closed, internal::closed_t)                                      \
  X(end_rule, internal::end_rule_t)                                  \
  X(max_output_points, internal::max_output_points_t)                \
  X(flatness_tolerance, internal::flatness_tolerance_t)              \
  X(characteristic_map, internal::characteristic_map_t)              \
  X(verify_limit, internal::verify_limit_t)                          \
  X(max_faces, internal::max_faces_t)                                \
  X(seed, internal::seed_t)                                          \
  X(rings, internal::rings_t)                                        \
  X(max_memory, internal::max_memory_t)                              \
  X(extended_spectrum, internal::extended_spectrum_t)                \
  X(isolated_vertices, internal::isolated_vertices_t)                \
  X(edge_sharpness_map, internal::edge_sharpness_map_t)              \
  X(vertex_sharpness_map, internal::vertex_sharpness_map_t)          \
  X(crease_method, internal::crease_method_t)                        \
  X(face_hole_map, internal::face_hole_map_t)                        \
  X(boundary_interpolation, internal::boundary_interpolation_t)      \
  X(triangle_subdivision, internal::triangle_subdivision_t)          \
  X(triangulate, internal::triangulate_t)                            \
  X(output_normals, internal::output_normals_t)                      \
  X(non_manifold_copies, internal::non_manifold_copies_t)
// (name, tag, const if the argument is read only)
#define CGAL_SUBDIV_FOR_EACH_REFERENCE_PARAMETER(X) \
  X(carried_data, internal::carried_data_t, const)  \
  X(refined_mesh, internal::refined_mesh_t, )       \
  X(refined_corner_indices, internal::refined_corner_indices_t, )

/*!
 * \ingroup PkgSubdivFunctions
 * A chain of named parameters: a `CGAL::Named_function_parameters` (so every
 * CGAL function that reads named parameters reads it) whose member functions
 * also append the package's own parameters.
 */
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  using Nfp = CGAL::Named_function_parameters<T, Tag, Base>;
  using self = Named_parameters<T, Tag, Base>;

  Named_parameters() = default;
  Named_parameters(const T& v) : Nfp(v) {}
  Named_parameters(const T& v, const Base& b) : Nfp(v, b) {}

#define CGAL_SUBDIV_VALUE_MEMBER(NAME, TAG)             \
  template <class K>                                    \
  Named_parameters<K, TAG, self> NAME(const K& k) const \
  {                                                     \
    return Named_parameters<K, TAG, self>(k, *this);    \
  }
#define CGAL_SUBDIV_REFERENCE_MEMBER(NAME, TAG, CONST)         \
  template <class K>                                           \
  Named_parameters<CONST K*, TAG, self> NAME(CONST K& k) const \
  {                                                            \
    return Named_parameters<CONST K*, TAG, self>(&k, *this);   \
  }
  CGAL_SUBDIV_FOR_EACH_VALUE_PARAMETER(CGAL_SUBDIV_VALUE_MEMBER)
  CGAL_SUBDIV_FOR_EACH_REFERENCE_PARAMETER(CGAL_SUBDIV_REFERENCE_MEMBER)
#undef CGAL_SUBDIV_VALUE_MEMBER
#undef CGAL_SUBDIV_REFERENCE_MEMBER
};

#define CGAL_SUBDIV_VALUE_FUNCTION(NAME, TAG) \
  template <class K>                          \
  Named_parameters<K, TAG> NAME(const K& k)   \
  {                                           \
    return Named_parameters<K, TAG>(k);       \
  }
#define CGAL_SUBDIV_REFERENCE_FUNCTION(NAME, TAG, CONST) \
  template <class K>                                     \
  Named_parameters<CONST K*, TAG> NAME(CONST K& k)       \
  {                                                      \
    return Named_parameters<CONST K*, TAG>(&k);          \
  }
CGAL_SUBDIV_FOR_EACH_VALUE_PARAMETER(CGAL_SUBDIV_VALUE_FUNCTION)
CGAL_SUBDIV_FOR_EACH_REFERENCE_PARAMETER(CGAL_SUBDIV_REFERENCE_FUNCTION)
#undef CGAL_SUBDIV_VALUE_FUNCTION
#undef CGAL_SUBDIV_REFERENCE_FUNCTION
#undef CGAL_SUBDIV_FOR_EACH_VALUE_PARAMETER
#undef CGAL_SUBDIV_FOR_EACH_REFERENCE_PARAMETER

} // namespace parameters

namespace internal {

/// the `max_memory` parameter in bytes, 0 if not given (this machine's memory)
template <class NamedParameters>
double max_memory_of(const NamedParameters& np)
{
  return static_cast<double>(parameters::choose_parameter(parameters::get_parameter(np, max_memory_t()), 0));
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_PARAMETERS_H
