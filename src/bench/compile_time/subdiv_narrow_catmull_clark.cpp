// Compile-time probe (src/scripts/compile_time.sh): a new user's program,
// read a mesh, Catmull-Clark 3 levels with <CGAL/Subdiv/surface_subdivision.h>, write it.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 3 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  CGAL::Subdiv::catmull_clark_subdivision(mesh, CGAL::parameters::number_of_iterations(3));
  return CGAL::IO::write_polygon_mesh(argv[2], mesh) ? 0 : 1;
}
