// Compile-time probe (src/scripts/compile_time.sh): the same program with
// CGAL's Subdivision_method_3.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 3 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, CGAL::parameters::number_of_iterations(3));
  return CGAL::IO::write_polygon_mesh(argv[2], mesh) ? 0 : 1;
}
