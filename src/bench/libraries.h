// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the jobs of every library. A function returns nullptr when its
// library (or the scheme in it) is not there; `*_missing()` says why.
#ifndef SUBDIV_BENCH_LIBRARIES_H
#define SUBDIV_BENCH_LIBRARIES_H

#include "bench.h"

#include <string>
#include <vector>

namespace subdiv_bench {

struct Input;

// --- CGAL Subdiv (ours) and CGAL's Subdivision_method_3 (ours.cpp) ----------------

/// whether CGAL Subdiv has the named parameter `threads(n)` (multi-threaded
/// paths), and whether it is compiled with TBB (CGAL_LINKED_WITH_TBB)
bool ours_has_threads();
bool ours_with_tbb();
/// `loop_subdivision`, ... into the input's Surface_mesh (a copy), with
/// `threads(threads)` when the library has it; nullptr for threads > 1 if not;
/// a creased input refines with its creases (`edge_sharpness_map`, Loop and
/// Catmull-Clark)
Job_ptr ours_refinement(const Input& input, Scheme scheme, int levels, int threads = 1);
/// the `Surface_mesh::resize` calls alone that a Loop or Catmull-Clark
/// refinement in place makes (reserve, then resize to each level's counts)
/// on a copy of the input: the floor of a refinement into a Surface_mesh
Job_ptr surface_mesh_resize_floor(const Input& input, Scheme scheme, int levels);
/// `CGAL::Subdivision_method_3::Loop_subdivision`, ... on a copy
Job_ptr cgal_refinement(const Input& input, Scheme scheme, int levels);
/// `make_stencil_table(mesh, mask, levels)` (Loop and Catmull-Clark), threads as above
Job_ptr ours_stencil_build(const Input& input, Scheme scheme, int levels, int threads = 1);
/// `Stencil_table::apply` on std::vector<Point_3> (one thread) or `apply_range`
/// on two halves of the stencils (two std::threads); the table is made here
Apply_ptr ours_apply(const Input& input, Scheme scheme, int levels);
/// the same refinements with CGAL::Epick or CGAL::Epeck points (exact.cpp)
Job_ptr ours_refinement_kernel(const Input& input, Scheme scheme, int levels, bool exact);
Job_ptr cgal_refinement_kernel(const Input& input, Scheme scheme, int levels, bool exact);
/// the limit surface (Loop or Catmull-Clark; nullptr for the other schemes):
/// `Limit_surface<Mesh, Mask>` made, then evaluated once in every face (at
/// u = v = 1/4; a Catmull-Clark face with n != 4 corners in its sub-quad at
/// corner 0), which builds the Stam eigenbases the mesh needs (a face where
/// it throws `Bad_input` gets a NaN point)
Job_ptr ours_limit_build(const Input& input, Scheme scheme);
/// `Limit_surface::evaluate(f, u, v)` once at every location, outside any
/// timer: `refused[i]` whether it throws `Bad_input` there; returns the first
/// message (empty if none)
std::string ours_limit_refusals(const Input& input, Scheme scheme, const std::vector<Limit_location>& locations,
                                std::vector<bool>& refused);
/// `Limit_surface::evaluate(f, u, v)` at every location, the surface made and
/// its eigenbases built outside the timer; `keep`: the surface keeps the
/// faces' trees (`cached_faces`, default), so that after the warm-up every
/// face is found kept; otherwise (`cached_faces = 0`) every evaluation starts
/// from the mesh; `second_derivatives`: `Limit_surface::second_derivatives`
/// (Bfr is asked for P, Du and Dv only). Output points: the positions, in the
/// order of the locations
Job_ptr ours_limit_evaluation(const Input& input, Scheme scheme, const std::vector<Limit_location>& locations,
                              bool keep, bool second_derivatives = false);
/// `tessellate(surface, out, rate, output_normals(true))`, the surface made
/// outside the timer; output points: the vertices of `out` (none if it
/// throws `Bad_input`)
Job_ptr ours_tessellation(const Input& input, Scheme scheme, int rate);

// --- OpenMesh (peer_openmesh.cpp) ------------------------------------------------

std::string openmesh_missing(); // empty if OpenMesh is there
std::string openmesh_version();
/// Subdivider::Uniform::LoopT on a TriMesh / CatmullClarkT on a PolyMesh (double points)
Job_ptr openmesh_refinement(const Soup& input, Scheme scheme, int levels);

// --- OpenSubdiv Far (peer_opensubdiv.cpp) -----------------------------------------

std::string osd_missing(); // empty if OpenSubdiv is there
std::string osd_version();
/// TopologyRefinerFactory<TopologyDescriptor>::Create + RefineUniform +
/// PrimvarRefinerReal<double>::Interpolate level by level (no conversion into a
/// halfedge mesh). Options: VTX_BOUNDARY_EDGE_ONLY, TRI_SUB_CATMARK.
Job_ptr osd_refinement(const Soup& input, Scheme scheme, int levels);
/// StencilTableFactoryReal<double>::Create (uniform, finest level only,
/// factorized): with the refinement of the topology in the timer, or
/// (`factory_only`) with the refiner made and refined in prepare()
Job_ptr osd_stencil_build(const Soup& input, Scheme scheme, int levels, bool factory_only);
/// StencilTableReal<double>::UpdateValues, one thread or two std::threads on
/// two halves of the stencils (the `start`, `end` arguments)
Apply_ptr osd_apply(const Soup& input, Scheme scheme, int levels);
/// Osd::OmpEvaluator::EvalStencils on a float table (what Debian's libosdCPU
/// offers for several threads; floats, so it moves fewer bytes)
Apply_ptr osd_apply_omp_float(const Soup& input, Scheme scheme, int levels);
/// Bfr's limit surface, with Sdc options as above: the `Far::TopologyRefiner`
/// of the base mesh (not refined) and a `Bfr::RefinerSurfaceFactory<>` on it
Job_ptr osd_limit_build(const Soup& input, Scheme scheme);
/// P, Du and Dv at every location (`Bfr::Surface<double>::Evaluate`): either
/// `InitVertexSurface` + `PreparePatchPoints` + `Evaluate` for each location,
/// or (`per_face`) one surface per face, then all of that face's locations;
/// output points: the positions, in the order of the locations
Job_ptr osd_limit_evaluation(const Soup& input, Scheme scheme, const std::vector<Limit_location>& locations,
                             bool per_face);
/// every face: `InitVertexSurface` + `PreparePatchPoints`, `Bfr::Tessellation`
/// at the uniform rate (quads kept under Catmull-Clark), P, Du and Dv at each
/// of its coordinates and the unit normal; output points: every face's points
/// (those on an edge once per face)
Job_ptr osd_tessellation(const Soup& input, Scheme scheme, int rate);

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_LIBRARIES_H
