// Compile-time probe (src/scripts/compile_time.sh): a new user's program,
// read a mesh, refine it 3 levels, write it. The script compiles it once per
// library and scheme:
//   -DPROBE_SUBDIV         ours, with <CGAL/Subdiv.h>
//   -DPROBE_SUBDIV_NARROW  ours, with <CGAL/Subdiv/surface_subdivision.h> only
//   -DPROBE_SM3            CGAL's Subdivision_method_3
//   none of them          read and write only (the part every probe shares)
// and -DPROBE_LOOP for Loop (otherwise Catmull-Clark).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#if defined(PROBE_SUBDIV)
#include <CGAL/Subdiv.h>
#elif defined(PROBE_SUBDIV_NARROW)
#include <CGAL/Subdiv/surface_subdivision.h>
#elif defined(PROBE_SM3)
#include <CGAL/subdivision_method_3.h>
#endif

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 3 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
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
#endif
  return CGAL::IO::write_polygon_mesh(argv[2], mesh) ? 0 : 1;
}
