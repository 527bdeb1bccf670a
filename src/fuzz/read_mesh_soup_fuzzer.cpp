// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// libFuzzer target: the checked mesh reader of the command-line tool
// (src/cli/mesh_soup.h) on any bytes. The first byte picks the format (its
// value modulo 4: OFF, OBJ, PLY, STL), the rest is the file. A refusal
// (Input_error) is a fine answer, if its message names the file and the line
// or byte; a soup that breaks an invariant of Mesh_soup traps; any other
// exception escapes, which libFuzzer reports. Built and run by
// src/scripts/fuzz.sh.
#include "mesh_soup.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace {

using cgal_subdiv::Mesh_soup;

const char* const file_name = "fuzz";

/// what Mesh_soup promises: faces spanning the indices, each of 3 or more,
/// every index a point, every coordinate finite
bool keeps_its_promises(const Mesh_soup& soup)
{
  if(soup.face_starts.empty() || soup.face_starts.front() != 0 || soup.face_starts.back() != soup.indices.size())
    return false;
  for(std::size_t f = 0; f + 1 < soup.face_starts.size(); ++f)
    if(soup.face_starts[f + 1] < soup.face_starts[f] || soup.face_starts[f + 1] - soup.face_starts[f] < 3)
      return false;
  for(std::size_t index : soup.indices)
    if(index >= soup.points.size())
      return false;
  for(const auto& p : soup.points)
    for(double c : p)
      if(!std::isfinite(c))
        return false;
  // texture coordinates: none, or one reference per corner, each in range,
  // every value finite
  if(!soup.texture_indices.empty() && soup.texture_indices.size() != soup.indices.size())
    return false;
  for(std::size_t index : soup.texture_indices)
    if(index >= soup.texture_points.size())
      return false;
  for(const auto& t : soup.texture_points)
    for(double c : t)
      if(!std::isfinite(c))
        return false;
  // colours: none, or one per point
  return soup.colours.empty() || soup.colours.size() == soup.points.size();
}

/// "'fuzz' line 12: ...", "'fuzz' byte 80: ..." or STL's "'fuzz': neither ..."
bool names_the_place(const char* message)
{
  const std::string text = message;
  const std::string file = "'" + std::string(file_name) + "'";
  for(const char* place : {" line ", " byte "}) {
    const std::string prefix = file + place;
    if(text.compare(0, prefix.size(), prefix) == 0) {
      std::size_t i = prefix.size();
      const std::size_t digits = i;
      while(i < text.size() && text[i] >= '0' && text[i] <= '9')
        ++i;
      return i > digits && text.compare(i, 2, ": ") == 0 && text.size() > i + 2;
    }
  }
  const std::string neither = file + ": neither ";
  return text.compare(0, neither.size(), neither) == 0;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0)
    return 0;
  const auto format = static_cast<cgal_subdiv::Mesh_format>(data[0] % 4);
  try {
    const Mesh_soup soup =
      cgal_subdiv::parse_mesh_soup(reinterpret_cast<const char*>(data + 1), size - 1, format, file_name);
    if(!keeps_its_promises(soup))
      __builtin_trap();
  } catch(const cgal_subdiv::Input_error& error) {
    if(!names_the_place(error.what()))
      __builtin_trap();
  }
  return 0;
}
