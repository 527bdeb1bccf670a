// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// A checked reader of polygon soups in OFF, OBJ, PLY and STL, on the standard
// library only: whatever a file says, it either returns a soup whose every
// index is in range and every coordinate finite, or throws Input_error naming
// the file, the line (text) or the byte offset (binary) and the problem. Counts
// in a header are checked against the bytes left before anything is reserved,
// so that memory stays a small multiple of the file size.
//
// Numbering in the messages: faces from 0 in the order of the file (the
// index of the face in the soup); vertices as the file numbers them (from 0
// in OFF and PLY, from 1 in OBJ), and so OBJ's texture coordinates and
// normals (vt and vn, from 1); lines from 1; byte offsets from 0.
#ifndef CGAL_SUBDIV_CLI_MESH_SOUP_H
#define CGAL_SUBDIV_CLI_MESH_SOUP_H

#include "errors.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace cgal_subdiv {

enum class Mesh_format { off, obj, ply, stl };

/// "OFF", "OBJ", "PLY" or "STL"
const char* mesh_format_name(Mesh_format format);

/// An OBJ `t` tag line (OpenSubdiv's crease/corner/hole tags), kept for later
/// use: `t NAME nint/nfloat/nstring ints... floats... strings...`
struct Obj_tag
{
  std::string name;
  std::vector<long long> ints;
  std::vector<double> floats;
  std::vector<std::string> strings;
  std::size_t line = 0;
};

/// Points and faces as a file lists them, nothing shared or oriented yet
/// (repeated vertices in a face, non-manifold configurations and unreferenced
/// vertices are the caller's business).
struct Mesh_soup
{
  std::vector<std::array<double, 3>> points; // every coordinate finite
  /// face f has the indices [face_starts[f], face_starts[f+1]) of `indices`,
  /// at least 3 of them; size = faces + 1
  std::vector<std::size_t> face_starts{0};
  std::vector<std::size_t> indices; // every index < points.size()
  /// OBJ only: every `vt` line in the order of the file, (u, v), finite
  /// (`vt u` has v = 0; a third value, w, is dropped)
  std::vector<std::array<double, 2>> texture_points;
  /// OBJ only: empty, or the texture point of each corner, index for index
  /// with `indices` (every index < texture_points.size()): face-varying, so
  /// that a vertex on a seam has a texture point per side. Empty unless every
  /// face gives every corner one (`v/vt` or `v/vt/vn`); a note says why
  /// when there are texture points.
  std::vector<std::size_t> texture_indices;
  /// OBJ only: every `vn` line in the order of the file, (x, y, z), finite,
  /// as written (not normalised)
  std::vector<std::array<double, 3>> normals;
  /// OBJ only: empty, or the normal of each corner, index for index with
  /// `indices` (every index < normals.size()). Empty unless every face gives
  /// every corner one (`v//vn` or `v/vt/vn`); a note says why when there are
  /// normals.
  std::vector<std::size_t> normal_indices;
  /// ASCII OFF (COFF) and PLY only: empty, or the colour of every point,
  /// index for index with `points`: red, green, blue and alpha from 0 to 255
  /// (components written as reals, from 0 to 1, are scaled and rounded;
  /// alpha is 255 when the file gives none)
  std::vector<std::array<unsigned char, 4>> colours;
  std::vector<Obj_tag> tags; // OBJ only
  /// one line per thing that was read but ignored (colours, normals, other
  /// PLY elements, text after the last face, ...), each naming the file
  std::vector<std::string> notes;

  std::size_t number_of_faces() const { return face_starts.size() - 1; }
};

/// parses the `size` bytes at `data`, the content of a file called `name`
/// (used in messages only)
/// \throws Input_error naming `name` and the line or byte of the problem
Mesh_soup parse_mesh_soup(const char* data, std::size_t size, Mesh_format format, const std::string& name);

/// reads the whole file `path` and parses it
/// \throws Input_error if it is missing, a directory, unreadable or malformed
Mesh_soup read_mesh_soup(const std::string& path, Mesh_format format);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_MESH_SOUP_H
