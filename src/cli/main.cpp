// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv: subdivision curves from the command line.
#include "commands.h"
#include "common.h"
#include "files.h"

#include <CGAL/Subdiv/errors.h>
#include <CGAL/exceptions.h>

#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

const char* const main_help = R"(usage: cgal-subdiv COMMAND [OPTIONS]

Subdivision curves and surfaces with CGAL Subdiv.

Commands:
  curve       refine a polyline from a file with a curve scheme (bezier,
              bspline, chaikin, corner-cutting, four-point); optional SVG
              figure and convergence report
  surface     refine a polygon mesh (OFF, OBJ, PLY, STL) with a surface scheme
              (loop, loop-warren, catmull-clark, doo-sabin, sqrt3, butterfly,
              modified-butterfly, interpolating-sqrt3, linear)
  evaluate    the limit surface of a mesh (catmull-clark, loop) at parameters
              read from a file: position, first and second derivatives,
              normal; lines or one JSON object (--json)
  tessellate  a mesh of points of the limit surface (catmull-clark, loop), N
              segments per edge, without cracks; quads or triangles, normals
  analyse     eigen-analysis of a scheme from its masks: eigenvalues, C1
              verdict, limit mask (surfaces at a vertex of valence N, interior
              or border; curves); a table or one JSON object (--json)
  demo        run every curve scheme on the bundled polygon and every surface
              scheme on the bundled meshes; write points, meshes, figures,
              convergence tables and an index to a directory (out/)

Run 'cgal-subdiv COMMAND --help' for the options of a command.

Exit status: 0 on success, 1 if the input cannot be used, 2 for a malformed
command line. Errors are one line on stderr: "cgal-subdiv: error: ...".
)";

// one line, whatever the message (CGAL's own exceptions span several)
int fail(std::string message, int code)
{
  for(char& c : message)
    if(c == '\n' || c == '\r')
      c = ' ';
  std::cerr << "cgal-subdiv: error: " << message << std::endl;
  return code;
}

int dispatch(const std::vector<std::string>& args, const std::string& program)
{
  if(args.empty()) {
    std::cerr << main_help;
    return 2;
  }
  const std::string& command = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if(command == "-h" || command == "--help" || command == "help") {
    std::cout << main_help;
    return 0;
  }
  if(command == "curve")
    return cgal_subdiv::curve_command(rest);
  if(command == "surface")
    return cgal_subdiv::surface_command(rest);
  if(command == "demo")
    return cgal_subdiv::demo_command(rest, program);
  if(command == "evaluate")
    return cgal_subdiv::evaluate_command(rest);
  if(command == "tessellate")
    return cgal_subdiv::tessellate_command(rest);
  if(command == "analyse" || command == "analyze")
    return cgal_subdiv::analyse_command(rest);
  throw cgal_subdiv::Usage_error(
    "unknown command '" + command +
    "' (expected curve, surface, evaluate, tessellate, analyse or demo; see 'cgal-subdiv --help')");
}

} // namespace

int main(int argc, char** argv)
{
  cgal_subdiv::remove_temporary_files_on_signals();
  try {
    return dispatch(std::vector<std::string>(argv + 1, argv + argc), argc > 0 ? argv[0] : "cgal-subdiv");
  } catch(const cgal_subdiv::Usage_error& e) {
    return fail(e.what(), 2);
  } catch(const cgal_subdiv::Input_error& e) {
    return fail(e.what(), 1);
  } catch(const CGAL::Subdiv::Bad_input& e) {
    return fail(e.what(), 1);
  } catch(const std::bad_alloc&) {
    return fail("out of memory (a smaller --levels, or --max-memory to be refused before the work)", 1);
  } catch(const std::length_error&) { // the C++ library's text ("vector::_M_default_append") says nothing
    return fail("out of memory: a size beyond what this machine can hold", 1);
  } catch(const CGAL::Failure_exception& e) { // a CGAL assertion: a bug, ours or CGAL's
    return fail("internal error, please report it with the command and the input: CGAL says " + e.message() + " (" +
                  e.expression() + ", " + e.filename() + ":" + std::to_string(e.line_number()) + ")",
                1);
  } catch(const std::exception&) {
    return fail("internal error, please report it with the command and the input", 1);
  } catch(...) {
    return fail("internal error, please report it with the command and the input", 1);
  }
}
