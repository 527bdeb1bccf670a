// The refinement call of the compile-time probes (probe.cpp, refine_only.cpp):
// a Surface_mesh refined 3 levels, the library and the scheme chosen by
//   -DPROBE_SUBDIV         ours, with <CGAL/Subdiv.h>
//   -DPROBE_SUBDIV_NARROW  ours, with the scheme's header only
//                         (<CGAL/Subdiv/loop_subdivision.h>, <CGAL/Subdiv/catmull_clark_subdivision.h>)
//   -DPROBE_SM3            CGAL's Subdivision_method_3
//   none of them          no refinement (the mesh is cleared)
// and -DPROBE_LOOP for Loop (otherwise Catmull-Clark).
#ifndef CGAL_SUBDIV_BENCH_COMPILE_TIME_REFINE_H
#define CGAL_SUBDIV_BENCH_COMPILE_TIME_REFINE_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#if defined(PROBE_SUBDIV)
#include <CGAL/Subdiv.h>
#elif defined(PROBE_SUBDIV_NARROW) && defined(PROBE_LOOP)
#include <CGAL/Subdiv/loop_subdivision.h>
#elif defined(PROBE_SUBDIV_NARROW)
#include <CGAL/Subdiv/catmull_clark_subdivision.h>
#elif defined(PROBE_SM3)
#include <CGAL/subdivision_method_3.h>
#endif

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

inline void refine(Mesh& mesh)
{
  const auto three = CGAL::parameters::number_of_iterations(3);
#if defined(PROBE_SUBDIV) || defined(PROBE_SUBDIV_NARROW)
#if defined(PROBE_LOOP)
  CGAL::Subdiv::loop_subdivision(mesh, three);
#else
  CGAL::Subdiv::catmull_clark_subdivision(mesh, three);
#endif
#elif defined(PROBE_SM3)
#if defined(PROBE_LOOP)
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, three);
#else
  CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, three);
#endif
#else
  (void)three;
  mesh.clear();
#endif
}

#endif // CGAL_SUBDIV_BENCH_COMPILE_TIME_REFINE_H
