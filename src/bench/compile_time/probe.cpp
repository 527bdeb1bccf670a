// Compile-time probe (src/scripts/compile_time.sh): a new user's program,
// read a mesh, refine it 3 levels, write it. The script compiles it once per
// library and scheme, with the flags of refine.h.
#include "refine.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 3 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  refine(mesh);
  return CGAL::IO::write_polygon_mesh(argv[2], mesh) ? 0 : 1;
}
