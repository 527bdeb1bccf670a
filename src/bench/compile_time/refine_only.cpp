// Compile-time probe (src/scripts/compile_time.sh), the refinement alone: a
// function that refines a Surface_mesh 3 levels (refine.h), with nothing else
// in the translation unit, so that the time the refinement adds is a larger
// part of the whole than in probe.cpp (where reading and writing take most of
// it) and the noise hides less of it.
#include "refine.h"

void refine_only(Mesh& mesh)
{
  refine(mesh);
}
