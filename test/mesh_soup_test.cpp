// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The checked polygon-soup reader of the command-line tool (src/cli/mesh_soup.h):
// every valid variant of OFF, OBJ, PLY and STL it accepts, every refusal with
// its message, and hostile input (lying counts, truncations at every byte,
// random byte flips): nothing but a valid soup or an Input_error comes out.
#include "mesh_soup.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <random>
#include <string>
#include <utility>
#include <vector>

// The largest single allocation since the last reset: the lying counts must
// not reach reserve(). (The replaced operator new forwards to malloc, which
// the sanitizers still watch; g++ warns about free() on memory from operator
// new when it inlines the pair, which is what this replacement means.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
namespace {
std::atomic<std::size_t> largest_allocation{0};
} // namespace

void* operator new(std::size_t size)
{
  std::size_t largest = largest_allocation.load();
  while(size > largest && !largest_allocation.compare_exchange_weak(largest, size)) {
  }
  if(void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size)
{
  return operator new(size);
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete[](void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept
{
  std::free(p);
}

namespace {

using cgal_subdiv::Input_error;
using cgal_subdiv::Mesh_format;
using cgal_subdiv::Mesh_soup;
using cgal_subdiv::parse_mesh_soup;

Mesh_soup parse(const std::string& text, Mesh_format format, const std::string& name)
{
  return parse_mesh_soup(text.data(), text.size(), format, name);
}
Mesh_soup parse_off(const std::string& text)
{
  return parse(text, Mesh_format::off, "a.off");
}
Mesh_soup parse_obj(const std::string& text)
{
  return parse(text, Mesh_format::obj, "a.obj");
}
Mesh_soup parse_ply(const std::string& text)
{
  return parse(text, Mesh_format::ply, "a.ply");
}
Mesh_soup parse_stl(const std::string& text)
{
  return parse(text, Mesh_format::stl, "a.stl");
}

/// the message of the Input_error that parsing `text` throws ("" if none)
std::string refusal(const std::string& text, Mesh_format format)
{
  static const char* const names[] = {"a.off", "a.obj", "a.ply", "a.stl"};
  try {
    parse(text, format, names[static_cast<int>(format)]);
  } catch(const Input_error& error) {
    return error.what();
  }
  return "";
}
std::string off_refusal(const std::string& text)
{
  return refusal(text, Mesh_format::off);
}
std::string obj_refusal(const std::string& text)
{
  return refusal(text, Mesh_format::obj);
}
std::string ply_refusal(const std::string& text)
{
  return refusal(text, Mesh_format::ply);
}
std::string stl_refusal(const std::string& text)
{
  return refusal(text, Mesh_format::stl);
}

using Colour = std::array<unsigned char, 4>;

std::vector<std::size_t> face(const Mesh_soup& soup, std::size_t f)
{
  return std::vector<std::size_t>(soup.indices.begin() + static_cast<std::ptrdiff_t>(soup.face_starts[f]),
                                  soup.indices.begin() + static_cast<std::ptrdiff_t>(soup.face_starts[f + 1]));
}

using Point = std::array<double, 3>;
using Face = std::vector<std::size_t>;
using Uv = std::array<double, 2>;

/// why the corner indices of a list of the soup (vt, vn) and its values
/// break its invariant, or ""
template <class Values>
std::string broken_corner_list(const Mesh_soup& soup, const std::vector<std::size_t>& indices, const Values& values,
                               const std::string& what)
{
  if(!indices.empty() && indices.size() != soup.indices.size())
    return what + " indices and indices differ in size";
  for(std::size_t index : indices)
    if(index >= values.size())
      return what + " index " + std::to_string(index) + " out of range";
  for(const auto& value : values)
    for(double c : value)
      if(!std::isfinite(c))
        return "a " + what + " value is not finite";
  return "";
}

/// what every soup the reader returns satisfies (empty if it does)
std::string broken_invariant(const Mesh_soup& soup)
{
  if(soup.face_starts.empty() || soup.face_starts.front() != 0 || soup.face_starts.back() != soup.indices.size())
    return "face_starts does not span the indices";
  for(std::size_t f = 0; f + 1 < soup.face_starts.size(); ++f)
    if(soup.face_starts[f + 1] < soup.face_starts[f] + 3)
      return "face " + std::to_string(f) + " has fewer than 3 vertices";
  for(std::size_t index : soup.indices)
    if(index >= soup.points.size())
      return "index " + std::to_string(index) + " out of range";
  for(const Point& p : soup.points)
    for(double c : p)
      if(!std::isfinite(c))
        return "a coordinate is not finite";
  const std::string texture = broken_corner_list(soup, soup.texture_indices, soup.texture_points, "texture");
  return texture.empty() ? broken_corner_list(soup, soup.normal_indices, soup.normals, "normal") : texture;
}

/// the bytes of a binary file, built value by value
class Bytes
{
public:
  explicit Bytes(bool big_endian) : m_big_endian(big_endian) {}

  Bytes& text(const std::string& s)
  {
    m_data += s;
    return *this;
  }
  Bytes& u8(unsigned value) { return put(value, 1); }
  Bytes& i16(std::int16_t value) { return put(static_cast<std::uint16_t>(value), 2); }
  Bytes& i32(std::int32_t value) { return put(static_cast<std::uint32_t>(value), 4); }
  Bytes& u32(std::uint32_t value) { return put(value, 4); }
  Bytes& f32(float value)
  {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    return put(bits, 4);
  }
  Bytes& f64(double value)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &value, 8);
    return put(bits, 8);
  }
  Bytes& f32s(std::initializer_list<float> values)
  {
    for(float value : values)
      f32(value);
    return *this;
  }
  Bytes& i32s(std::initializer_list<std::int32_t> values)
  {
    for(std::int32_t value : values)
      i32(value);
    return *this;
  }
  const std::string& str() const { return m_data; }
  std::size_t size() const { return m_data.size(); }

private:
  Bytes& put(std::uint64_t value, int bytes)
  {
    for(int i = 0; i < bytes; ++i) {
      const int shift = 8 * (m_big_endian ? bytes - 1 - i : i);
      m_data += static_cast<char>((value >> shift) & 0xFF);
    }
    return *this;
  }

  bool m_big_endian;
  std::string m_data;
};

const float nan_f = std::numeric_limits<float>::quiet_NaN();
const float inf_f = std::numeric_limits<float>::infinity();

// ---------------------------------------------------------------------------
// Valid files, used by several tests

const std::string tetra_off =
  "OFF\n"
  "# a tetrahedron\n"
  "4 4 6\n"
  "1 1 1\n"
  "1 -1 -1\n"
  "-1 1 -1\n"
  "-1 -1 1\n"
  "3 0 1 2\n"
  "3 0 2 3\n"
  "3 0 3 1\n"
  "3 1 3 2\n";

const std::string colour_off =
  "# colours\r\n"
  "COFF\r\n"
  "5 2 0 # counts\r\n"
  "\r\n"
  "0 0 0 0.9 0 0 1\r\n"
  "1 0 0 0 0.9 0\r\n"
  "1 1 0 0 0 0.9 # blue\r\n"
  "0 1 0 3\r\n"
  "9 9 9\r\n"
  "4 0 1 2 3 0.5 0.5 0.5\r\n"
  "3 0 2 3\r\n";

const std::string cube_obj =
  "# a unit cube\n"
  "mtllib cube.mtl\n"
  "o cube\n"
  "v 0 0 0\n"
  "v 1 0 0\n"
  "v 1 1 0\n"
  "v 0 1 0\n"
  "v 0 0 1\n"
  "v 1 0 1\n"
  "v 1 1 1\n"
  "v 0 1 1\n"
  "vt 0 0\n"
  "vt 1 0\n"
  "vn 0 0 1\n"
  "g sides\n"
  "usemtl red\n"
  "s 1\n"
  "f 1 4 3 2\n"
  "f 5/1 6/2 7/1 8/2\n"
  "f 1//1 2//1 6//1 5//1\n"
  "f 2/1/1 3/2/1 7/1/1 6/2/1\n"
  "f -5 -1 -2 -6\n"
  "f 4 1 5 8 # the last one\n"
  "t crease 2/1/0 0 1 2.5\n"
  "t interpolateboundary 1/0/0 1\n"
  "t creasemethod 0/0/1 chaikin\n";

// the unit cube of cube_obj, its four sides unrolled into a strip: the side
// faces (front, right, back, left) go from u = 0 to u = 1, and the vertical
// edge of vertices 1 and 5 is a seam (u = 0 in the front, u = 1 in the left
// face); the bottom and top faces reuse the front face's square
const std::string seam_cube_obj =
  "v 0 0 0\n"
  "v 1 0 0\n"
  "v 1 1 0\n"
  "v 0 1 0\n"
  "v 0 0 1\n"
  "v 1 0 1\n"
  "v 1 1 1\n"
  "v 0 1 1\n"
  "vt 0 0\n"
  "vt 0.25 0\n"
  "vt 0.5 0\n"
  "vt 0.75 0\n"
  "vt 1 0\n"
  "vt 0 1\n"
  "vt 0.25 1\n"
  "vt 0.5 1\n"
  "vt 0.75 1\n"
  "vt 1 1\n"
  "f 1/1 2/2 6/7 5/6\n"
  "f 2/2 3/3 7/8 6/7\n"
  "f 3/3 4/4 8/9 7/8\n"
  "f 4/4 1/5 5/10 8/9 # the seam\n"
  "f 1/1 4/6 3/7 2/2\n"
  "f 5/1 6/2 7/7 8/6\n";

const std::string tetra_ply =
  "ply\n"
  "format ascii 1.0\n"
  "comment a regular tetrahedron\n"
  "element vertex 4\n"
  "property double x\n"
  "property double y\n"
  "property double z\n"
  "property uchar red\n"
  "element face 4\n"
  "property list uchar int vertex_indices\n"
  "property float quality\n"
  "element edge 2\n"
  "property int vertex1\n"
  "property list uchar int ends\n"
  "end_header\n"
  "1 1 1 255\n"
  "1 -1 -1 0\n"
  "-1 1 -1 0\n"
  "-1 -1 1 0\n"
  "3 0 1 2 0.5\n"
  "3 0 2 3 0.5\n"
  "3 0 3 1 0.5\n"
  "3 1 3 2 0.5\n"
  "0 2 0 1\n"
  "1 0\n";

const std::string tetra_stl =
  "solid tetra\n"
  "facet normal 0.57735 0.57735 -0.57735\n"
  " outer loop\n"
  "  vertex 1 1 1\n"
  "  vertex 1 -1 -1\n"
  "  vertex -1 1 -1\n"
  " endloop\n"
  "endfacet\n"
  "facet normal -0.57735 0.57735 0.57735\n"
  " outer loop\n"
  "  vertex 1 1 1\n"
  "  vertex -1 1 -1\n"
  "  vertex -1 -1 1\n"
  " endloop\n"
  "endfacet\n"
  "facet normal 0.57735 -0.57735 0.57735\n"
  " outer loop\n"
  "  vertex 1 1 1\n"
  "  vertex -1 -1 1\n"
  "  vertex 1 -1 -1\n"
  " endloop\n"
  "endfacet\n"
  "facet normal -0.57735 -0.57735 -0.57735\n"
  " outer loop\n"
  "  vertex 1 -1 -1\n"
  "  vertex -1 -1 1\n"
  "  vertex -1 1 -1\n"
  " endloop\n"
  "endfacet\n"
  "endsolid tetra\n";

/// "OFF BINARY" (or `keyword` BINARY) with two triangles on four points
std::string binary_off(const std::string& keyword = "OFF")
{
  Bytes b(true);
  b.text(keyword + " BINARY\n").i32s({4, 2, 0});
  const bool colour = keyword.find('C') != std::string::npos;
  const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for(const auto& p : points) {
    b.f32s({p[0], p[1], p[2]});
    if(colour)
      b.f32s({0.5f, 0.5f, 0.5f, 1.0f});
  }
  b.i32s({3, 0, 1, 2, 0});
  b.i32s({3, 0, 2, 3, 3}).f32s({1, 0, 0});
  return b.str();
}

/// a binary PLY square (two triangles), a colour per vertex, an edge element
std::string binary_ply(bool big_endian)
{
  Bytes b(big_endian);
  b.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\n"
         "element vertex 4\n"
         "property float x\nproperty double y\nproperty short z\nproperty uchar red\n"
         "element face 2\n"
         "property list uchar int vertex_indices\n"
         "property list int float texcoord\n"
         "element edge 1\n"
         "property list uint uint ends\n"
         "end_header\n");
  const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for(const auto& p : points)
    b.f32(p[0]).f64(p[1]).i16(static_cast<std::int16_t>(p[2])).u8(200);
  b.u8(3).i32s({0, 1, 2}).i32(2).f32s({0.25f, 0.75f});
  b.u8(3).i32s({0, 2, 3}).i32(0);
  b.u32(2).u32(0).u32(2);
  return b.str();
}

/// a binary STL square: two triangles sharing an edge (4 distinct points,
/// one written as -0.0)
std::string binary_stl()
{
  Bytes b(false);
  b.text("solid but binary");
  b.text(std::string(80 - 16, ' ')).u32(2);
  b.f32s({0, 0, 1}).f32s({0, 0, 0}).f32s({1, 0, 0}).f32s({1, 1, 0}).u8(0).u8(0);
  b.f32s({0, 0, 1}).f32s({-0.0f, 0, 0}).f32s({1, 1, 0}).f32s({0, 1, 0}).u8(0).u8(0);
  return b.str();
}

// ---------------------------------------------------------------------------
// OFF

TEST(MeshSoupOff, ReadsATetrahedron)
{
  const Mesh_soup soup = parse_off(tetra_off);
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[1], (Point{1, -1, -1}));
  EXPECT_EQ(soup.points[3], (Point{-1, -1, 1}));
  ASSERT_EQ(soup.number_of_faces(), 4u);
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_EQ(face(soup, 3), (Face{1, 3, 2}));
  EXPECT_TRUE(soup.notes.empty());
  EXPECT_TRUE(soup.tags.empty());
}

TEST(MeshSoupOff, CountsOnTheKeywordLineAndNoEdgeCount)
{
  const Mesh_soup soup = parse_off("OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2");
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[2], (Point{0, 1, 0}));
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
}

TEST(MeshSoupOff, ColoursCommentsAndWindowsLineEndings)
{
  const Mesh_soup soup = parse_off(colour_off);
  ASSERT_EQ(soup.points.size(), 5u); // the unreferenced vertex 4 is kept
  EXPECT_EQ(soup.points[2], (Point{1, 1, 0}));
  EXPECT_EQ(soup.points[4], (Point{9, 9, 9}));
  ASSERT_EQ(soup.number_of_faces(), 2u);
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2, 3}));
  EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
  // vertex 3 has one colour component and vertex 4 none: no colours
  EXPECT_TRUE(soup.colours.empty());
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex colours of 'a.off': vertex 3 (line 8) has 1 "
                                                  "colour component (expected red green blue [alpha])",
                                                  "ignored the face colours of 'a.off'"}));
}

TEST(MeshSoupOff, KeywordVariants)
{
  // STOFF crashed CGAL's reader
  Mesh_soup soup = parse_off("STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n");
  EXPECT_EQ(soup.points[1], (Point{1, 0, 0}));
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex texture coordinates of 'a.off'"}));
  soup = parse_off("CNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0\n1 0 0 0 0 1 1 0 0\n0 1 0 0 0 1 1 0 0\n3 0 1 2\n");
  EXPECT_EQ(soup.points[2], (Point{0, 1, 0}));
  // integer components are from 0 to 255: "1 0 0" is a very dark red
  EXPECT_EQ(soup.colours, (std::vector<Colour>(3, Colour{1, 0, 0, 255})));
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex normals of 'a.off'"}));
  soup = parse_off("NOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"); // no normals after all: no note
  EXPECT_TRUE(soup.notes.empty());
  soup = parse_off("nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n");
  EXPECT_EQ(face(soup, 0), (Face{2, 1, 0}));
  soup = parse_off("STCNOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(soup.points.size(), 3u);
  soup = parse_off("OFF\n3 1 0\n0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{"ignored the values after x y z on the vertex lines of 'a.off' (from line 3)"}));
}

TEST(MeshSoupOff, TruncatedColourOfCoffIsIgnored)
{
  // a COFF vertex with only part of its colour crashed CGAL's reader
  const Mesh_soup soup = parse_off("COFF\n3 1 0\n0 0 0 1\n1 0 0\n0 1 0 0.5 0.5\n3 0 1 2\n");
  EXPECT_EQ(soup.points[0], (Point{0, 0, 0}));
  EXPECT_EQ(soup.points[2], (Point{0, 1, 0}));
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_TRUE(soup.colours.empty());
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex colours of 'a.off': vertex 0 (line 3) has 1 "
                                                  "colour component (expected red green blue [alpha])"}));
}

TEST(MeshSoupOff, KeepsTheVertexColoursOfCoff)
{
  // integers from 0 to 255, alpha or not
  Mesh_soup soup = parse_off("COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 128 0 64\n0 1 0 0 0 7 255\n3 0 1 2\n");
  EXPECT_EQ(soup.colours, (std::vector<Colour>{{255, 0, 0, 255}, {0, 128, 0, 64}, {0, 0, 7, 255}}));
  EXPECT_TRUE(soup.notes.empty());
  // reals from 0 to 1 when a component of the vertex is written as one;
  // after the normal (N), before the texture coordinates (ST)
  soup = parse_off(
    "STCNOFF\n3 1 0\n0 0 0 0 0 1 0.5 0.25 1 0.5 0.5\n1 0 0 0 0 1 1 1 1 1.0 0 0\n"
    "0 1 0 0 0 1 0 0 1e0 1 1\n3 0 1 2\n");
  EXPECT_EQ(soup.colours, (std::vector<Colour>{{128, 64, 255, 255}, {255, 255, 255, 255}, {0, 0, 255, 255}}));
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex normals of 'a.off'",
                                                  "ignored the vertex texture coordinates of 'a.off'"}));
}

TEST(MeshSoupOff, RefusesColourComponentsOutOfRange)
{
  EXPECT_EQ(off_refusal("COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 300 0 0\n0 1 0 0 0 0\n3 0 1 2\n"),
            "'a.off' line 4: vertex 1: the colour component '300' is out of range (integers from 0 to 255, or reals "
            "from 0 to 1)");
  EXPECT_EQ(off_refusal("COFF\n3 1 0\n0 0 0 0.5 1.5 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n3 0 1 2\n"),
            "'a.off' line 3: vertex 0: the colour component '1.5' is out of range (integers from 0 to 255, or reals "
            "from 0 to 1)");
  EXPECT_EQ(off_refusal("COFF\n3 1 0\n0 0 0 0 -1 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n3 0 1 2\n"),
            "'a.off' line 3: vertex 0: the colour component '-1' is out of range (integers from 0 to 255, or reals "
            "from 0 to 1)");
  EXPECT_EQ(off_refusal("COFF\n3 1 0\n0 0 0 0 red 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n3 0 1 2\n"),
            "'a.off' line 3: vertex 0: expected a colour component, found 'red'");
}

TEST(MeshSoupOff, TrailingContent)
{
  Mesh_soup soup = parse_off(tetra_off + "\n  # done\n\n");
  EXPECT_TRUE(soup.notes.empty());
  soup = parse_off(tetra_off + "# done\n3 0 1 2\n");
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the text after the last face of 'a.off' (from line 13)"}));
}

TEST(MeshSoupOff, SmallNumbersAndSigns)
{
  const Mesh_soup soup = parse_off("OFF\n3 1 0\n1e-400 +2 -0.5\n1.5e3 .25 -1E2\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(soup.points[0], (Point{0, 2, -0.5}));
  EXPECT_EQ(soup.points[1], (Point{1500, 0.25, -100}));
}

TEST(MeshSoupOff, Binary)
{
  const Mesh_soup soup = parse_off(binary_off());
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[2], (Point{1, 1, 0}));
  ASSERT_EQ(soup.number_of_faces(), 2u);
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the face colours of 'a.off'"}));
}

TEST(MeshSoupOff, BinaryWithColours)
{
  const Mesh_soup soup = parse_off(binary_off("COFF") + "extra");
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[3], (Point{0, 1, 0}));
  EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{"ignored the vertex colours of 'a.off'", "ignored the face colours of 'a.off'",
                                      "ignored 5 bytes after the last face of 'a.off'"}));
}

TEST(MeshSoupOff, RefusesAnAsciiBodyAfterABinaryHeader)
{
  // grew to 18.7 GB in CGAL's reader; "4 4 " read as a big-endian int32 is 874525728
  std::string file = "OFF BINARY\n4 4 0\n";
  for(int i = 0; i < 1000; ++i)
    file += "1 1 1\n";
  largest_allocation = 0;
  EXPECT_EQ(off_refusal(file), "'a.off' byte 23: header says 874525728 vertices, but the file has only " +
                                 std::to_string(file.size() - 23) +
                                 " bytes after the header (truncated, or the counts are wrong)");
  EXPECT_LT(largest_allocation.load(), 4096u);
}

TEST(MeshSoupOff, RefusesLyingCountsBeforeAllocating)
{
  const auto start = std::chrono::steady_clock::now();
  largest_allocation = 0;
  EXPECT_EQ(off_refusal("OFF\n2147483648 1 0\n0 0 0\n"),
            "'a.off' line 2: header says 2147483648 vertices, but the file has only 7 bytes after the header "
            "(truncated, or the counts are wrong)");
  EXPECT_EQ(off_refusal("OFF\n3 2147483648 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
            "'a.off' line 2: header says 3 vertices and 2147483648 faces, but the file has only 27 bytes after the "
            "header (truncated, or the counts are wrong)");
  EXPECT_EQ(off_refusal("OFF\n4294967296 0 0\n"),
            "'a.off' line 2: header says 4294967296 vertices: more than "
            "4294967295 are not supported (the meshes use 32-bit indices)");
  EXPECT_EQ(off_refusal(Bytes(true).text("OFF BINARY\n").i32s({2147483647, 1, 0}).f32s({0, 0, 0}).str()),
            "'a.off' byte 23: header says 2147483647 vertices, but the file has only 12 bytes after the header "
            "(truncated, or the counts are wrong)");
  EXPECT_LT(largest_allocation.load(), 4096u);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(MeshSoupOff, RefusesBadCounts)
{
  EXPECT_EQ(off_refusal("OFF\n-4 1 0\n"), "'a.off' line 2: the vertex count -4 is negative");
  EXPECT_EQ(off_refusal("OFF\nfour 1 0\n"), "'a.off' line 2: expected the vertex count, found 'four'");
  EXPECT_EQ(off_refusal("OFF\n3 1 0 7\n"), "'a.off' line 2: unexpected '7' after the counts");
  EXPECT_EQ(off_refusal("OFF\n3 99999999999999999999 0\n"),
            "'a.off' line 2: the face count 99999999999999999999 is too large");
  EXPECT_EQ(off_refusal("OFF\n# only a comment\n"),
            "'a.off' line 2: the file ends before the vertex count (truncated)");
  EXPECT_EQ(off_refusal(Bytes(true).text("OFF BINARY\n").i32s({-1, 1, 0}).str()),
            "'a.off' byte 11: the vertex count -1 is negative");
}

TEST(MeshSoupOff, RefusesOtherKeywordsAnd4D)
{
  EXPECT_EQ(off_refusal(""), "'a.off' line 1: the file is empty (no OFF keyword)");
  EXPECT_EQ(off_refusal("# nothing\n\n"), "'a.off' line 2: the file is empty (no OFF keyword)");
  EXPECT_EQ(off_refusal("ply\n"),
            "'a.off' line 1: expected the keyword OFF (or COFF, NOFF, STOFF, nOFF, OFF BINARY, ...), found 'ply'");
  EXPECT_EQ(off_refusal("CCOFF\n3 1 0\n"),
            "'a.off' line 1: expected the keyword OFF (or COFF, NOFF, STOFF, nOFF, OFF BINARY, ...), found 'CCOFF'");
  EXPECT_EQ(off_refusal("4OFF\n3 1 0\n0 0 0 1\n"),
            "'a.off' line 1: 4D points are not supported (the keyword '4OFF' says 4 coordinates)");
  EXPECT_EQ(off_refusal("nOFF 4\n3 1 0\n"), "'a.off' line 1: nOFF points of dimension 4 are not supported (only 3)");
  EXPECT_EQ(off_refusal(Bytes(true).text("nOFF BINARY\n").i32s({2, 3, 1, 0}).str()),
            "'a.off' byte 12: nOFF points of dimension 2 are not supported (only 3)");
  EXPECT_EQ(off_refusal("OFF BINARY x\n"), "'a.off' line 1: unexpected 'x' after BINARY");
}

TEST(MeshSoupOff, RefusesIndicesOutOfRange)
{
  std::string file = "OFF\n8 1 0\n";
  for(int i = 0; i < 8; ++i)
    file += "0 0 " + std::to_string(i) + "\n";
  EXPECT_EQ(off_refusal(file + "3 0 1 9\n"),
            "'a.off' line 11: face 0 has vertex index 9, but the file has 8 vertices (0 to 7)");
  EXPECT_EQ(off_refusal(file + "3 0 -1 2\n"),
            "'a.off' line 11: face 0 has vertex index -1, but the file has 8 vertices (0 to 7)");
  EXPECT_EQ(off_refusal(file + "3 0 1 99999999999999999999\n"),
            "'a.off' line 11: face 0 has vertex index 99999999999999999999, but the file has 8 vertices (0 to 7)");
  EXPECT_EQ(off_refusal(file + "3 0 1 x\n"), "'a.off' line 11: face 0: expected a vertex index, found 'x'");
  EXPECT_EQ(off_refusal("OFF\n0 1 0\n3 0 1 2\n"),
            "'a.off' line 3: face 0 has vertex index 0, but the file has no vertices");
  EXPECT_EQ(
    off_refusal(
      Bytes(true).text("OFF BINARY\n").i32s({3, 1, 0}).f32s({0, 0, 0, 1, 0, 0, 0, 1, 0}).i32s({3, 0, -1, 2, 0}).str()),
    "'a.off' byte 67: face 0 has vertex index -1, but the file has 3 vertices (0 to 2)");
  EXPECT_EQ(
    off_refusal(
      Bytes(true).text("OFF BINARY\n").i32s({3, 1, 0}).f32s({0, 0, 0, 1, 0, 0, 0, 1, 0}).i32s({3, 0, 1, 3, 0}).str()),
    "'a.off' byte 71: face 0 has vertex index 3, but the file has 3 vertices (0 to 2)");
}

TEST(MeshSoupOff, RefusesFacesWithFewerThanThreeVertices)
{
  const std::string head = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string pad = "# enough bytes for the size check\n";
  EXPECT_EQ(off_refusal(head + "2 0 1\n" + pad), "'a.off' line 7: face 1 has 2 vertices (a face needs at least 3)");
  EXPECT_EQ(off_refusal(head + "1 0\n" + pad), "'a.off' line 7: face 1 has 1 vertex (a face needs at least 3)");
  EXPECT_EQ(off_refusal(head + "0\n" + pad), "'a.off' line 7: face 1 has 0 vertices (a face needs at least 3)");
  EXPECT_EQ(off_refusal(head + "-3 0 1 2\n"), "'a.off' line 7: face 1 has -3 vertices (a face needs at least 3)");
  EXPECT_EQ(off_refusal(head + "4 0 1 2\n"), "'a.off' line 7: face 1 has only 3 of its 4 vertex indices on its line");
  // without the padding, the size check refuses the counts first
  EXPECT_EQ(off_refusal(head + "2 0 1\n"),
            "'a.off' line 2: header says 3 vertices and 2 faces, but the file has "
            "only 33 bytes after the header (truncated, or the counts are wrong)");
  EXPECT_EQ(off_refusal(head + "2147483647 0 1 2\n"),
            "'a.off' line 7: face 1 has only 3 of its 2147483647 vertex indices on its line");
  EXPECT_EQ(off_refusal(Bytes(true)
                          .text("OFF BINARY\n")
                          .i32s({3, 1, 0})
                          .f32s({0, 0, 0, 1, 0, 0, 0, 1, 0})
                          .i32s({2, 0, 1, 0, 0, 0, 0, 0})
                          .str()),
            "'a.off' byte 59: face 0 has 2 vertices (a face needs at least 3)");
  EXPECT_EQ(off_refusal(Bytes(true)
                          .text("OFF BINARY\n")
                          .i32s({3, 1, 0})
                          .f32s({0, 0, 0, 1, 0, 0, 0, 1, 0})
                          .i32s({2147483647, 0, 1, 2, 0})
                          .str()),
            "'a.off' byte 59: face 0 says it has 2147483647 vertices, but only 16 bytes are left (truncated, or "
            "the count is wrong)");
  EXPECT_EQ(
    off_refusal(
      Bytes(true).text("OFF BINARY\n").i32s({3, 1, 0}).f32s({0, 0, 0, 1, 0, 0, 0, 1, 0}).i32s({3, 0, 1, 2, 5}).str()),
    "'a.off' byte 75: face 0 has 5 colour components (expected 0 to 4)");
}

TEST(MeshSoupOff, RefusesShortVertexLines)
{
  const std::string pad = "# enough bytes for the size check\n";
  EXPECT_EQ(off_refusal("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n" + pad),
            "'a.off' line 4: vertex 1 has only 2 coordinates (expected x y z)");
  EXPECT_EQ(off_refusal("OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n"),
            "'a.off' line 4: vertex 1: expected a coordinate, found 'zero'");
  EXPECT_EQ(off_refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n" + pad),
            "'a.off' line 5: the file ends after 2 of the 3 vertices (truncated)");
  EXPECT_EQ(off_refusal("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" + pad),
            "'a.off' line 7: the file ends after 1 of the 2 faces (truncated)");
}

TEST(MeshSoupOff, RefusesNonFiniteCoordinates)
{
  EXPECT_EQ(off_refusal("OFF\n3 1 0\n0 0 0\n1 1e400 0\n0 1 0\n3 0 1 2\n"),
            "'a.off' line 4: vertex 1 has the coordinate 1e400, which is not a finite number");
  EXPECT_EQ(off_refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n"),
            "'a.off' line 5: vertex 2 has the coordinate nan, which is not a finite number");
  EXPECT_EQ(off_refusal("OFF\n3 1 0\n-inf 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
            "'a.off' line 3: vertex 0 has the coordinate -inf, which is not a finite number");
  EXPECT_EQ(off_refusal(Bytes(true)
                          .text("OFF BINARY\n")
                          .i32s({3, 1, 0})
                          .f32s({0, 0, 0, 1, nan_f, 0, 0, 1, 0})
                          .i32s({3, 0, 1, 2, 0})
                          .str()),
            "'a.off' byte 39: vertex 1 has the coordinate nan, which is not a finite number");
  EXPECT_EQ(off_refusal(Bytes(true)
                          .text("OFF BINARY\n")
                          .i32s({3, 1, 0})
                          .f32s({0, 0, 0, 1, 0, 0, 0, 1, -inf_f})
                          .i32s({3, 0, 1, 2, 0})
                          .str()),
            "'a.off' byte 55: vertex 2 has the coordinate -inf, which is not a finite number");
}

TEST(MeshSoupOff, RefusesATruncatedBinaryBody)
{
  const std::string file = binary_off();
  EXPECT_EQ(off_refusal(file.substr(0, file.size() - 4)),
            "'a.off' byte 111: the file ends inside face 1 (its colour) (truncated)");
  EXPECT_EQ(off_refusal(file.substr(0, file.size() - 14)),
            "'a.off' byte 23: header says 4 vertices and 2 faces, but the file has only 86 bytes after the header "
            "(truncated, or the counts are wrong)");
  EXPECT_EQ(off_refusal(file.substr(0, 13)),
            "'a.off' byte 11: the file ends inside the vertex count of the header (truncated)");
}

// ---------------------------------------------------------------------------
// OBJ

TEST(MeshSoupObj, ReadsACubeWithEveryFaceForm)
{
  const Mesh_soup soup = parse_obj(cube_obj);
  ASSERT_EQ(soup.points.size(), 8u);
  EXPECT_EQ(soup.points[0], (Point{0, 0, 0}));
  EXPECT_EQ(soup.points[6], (Point{1, 1, 1}));
  ASSERT_EQ(soup.number_of_faces(), 6u);
  EXPECT_EQ(face(soup, 0), (Face{0, 3, 2, 1}));
  EXPECT_EQ(face(soup, 1), (Face{4, 5, 6, 7}));
  EXPECT_EQ(face(soup, 2), (Face{0, 1, 5, 4}));
  EXPECT_EQ(face(soup, 3), (Face{1, 2, 6, 5}));
  EXPECT_EQ(face(soup, 4), (Face{3, 7, 6, 2})); // -5 -1 -2 -6 with 8 vertices
  EXPECT_EQ(face(soup, 5), (Face{3, 0, 4, 7}));
  // face 0 (f 1 4 3 2) has no vt, face 1 (f 5/1 6/2 7/1 8/2) has
  EXPECT_EQ(soup.texture_points, (std::vector<Uv>{{0, 0}, {1, 0}}));
  EXPECT_TRUE(soup.texture_indices.empty());
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{
              "ignored the texture coordinates (vt) of 'a.obj': face 0 has none, but face 1 has",
              "ignored the normals (vn) of 'a.obj': face 0 has none, but face 2 has",
              "ignored 1 material library (mtllib) of 'a.obj'", "ignored 1 material assignment (usemtl) of 'a.obj'"}));
}

TEST(MeshSoupObj, KeepsTheTags)
{
  const Mesh_soup soup = parse_obj(cube_obj);
  ASSERT_EQ(soup.tags.size(), 3u);
  EXPECT_EQ(soup.tags[0].name, "crease");
  EXPECT_EQ(soup.tags[0].ints, (std::vector<long long>{0, 1}));
  EXPECT_EQ(soup.tags[0].floats, (std::vector<double>{2.5}));
  EXPECT_TRUE(soup.tags[0].strings.empty());
  EXPECT_EQ(soup.tags[0].line, 24u);
  EXPECT_EQ(soup.tags[1].name, "interpolateboundary");
  EXPECT_EQ(soup.tags[1].ints, (std::vector<long long>{1}));
  EXPECT_EQ(soup.tags[2].name, "creasemethod");
  EXPECT_EQ(soup.tags[2].strings, (std::vector<std::string>{"chaikin"}));
  EXPECT_EQ(soup.tags[2].line, 26u);
}

TEST(MeshSoupObj, ForwardReferencesLinesAndOtherStatements)
{
  const Mesh_soup soup = parse_obj(
    "f 1 2 3\r\nv 0 0 0 1\r\nv 1 0 0 1 0.5 0.5 0.5\r\nv 0 1 0\r\n"
    "l 1 2\r\np 3\r\nfoo bar\r\nfoo\r\ncstype bspline\r\n");
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[1], (Point{1, 0, 0}));
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{
              "ignored the values after x y z (w, colours) of the vertices of 'a.obj' (from line 2)",
              "ignored 1 polyline (l) of 'a.obj'", "ignored 1 point element (p) of 'a.obj'",
              "ignored 2 lines with the unknown keyword 'foo' of 'a.obj'", "ignored 1 'cstype' line of 'a.obj'"}));
}

TEST(MeshSoupObj, RefusesBadIndices)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  EXPECT_EQ(obj_refusal(square + "f 1 2 3\nf 0 1 2\n"),
            "'a.obj' line 6: face 1 has vertex index 0 (OBJ counts vertices from 1, or from -1 backwards)");
  EXPECT_EQ(obj_refusal(square + "f 1 2 3\nf 1 2 9\nf 1 2 4\n"),
            "'a.obj' line 6: face 1 has vertex index 9, but the file has 4 vertices (1 to 4)");
  EXPECT_EQ(obj_refusal("f 1 2 3\n"), "'a.obj' line 1: face 0 has vertex index 3, but the file has no vertices");
  EXPECT_EQ(obj_refusal(square + "f -1 -2 -5\n"),
            "'a.obj' line 5: face 0 has vertex index -5, but only 4 vertices precede it (-1 to -4)");
  EXPECT_EQ(obj_refusal("v 0 0 0\nf -1 -2 -3\n"),
            "'a.obj' line 2: face 0 has vertex index -2, but only 1 vertex precedes it (-1 to -1)");
  EXPECT_EQ(obj_refusal("f -1 -2 -3\n"), "'a.obj' line 1: face 0 has vertex index -1, but no vertex precedes it");
  EXPECT_EQ(obj_refusal(square + "f 1 2 -99999999999999999999\n"),
            "'a.obj' line 5: face 0 has vertex index -99999999999999999999, but only 4 vertices precede it (-1 to -4)");
  EXPECT_EQ(obj_refusal(square + "f 1 2 99999999999\n"),
            "'a.obj' line 5: face 0 has vertex index 99999999999, but a mesh has at most 4294967295 vertices");
  EXPECT_EQ(obj_refusal(square + "f 1 2 3/x\n"),
            "'a.obj' line 5: face 0: '3/x' is not a vertex reference (expected v, v/vt, v//vn or v/vt/vn)");
  EXPECT_EQ(obj_refusal(square + "f 1 2 3/1/1/1\n"),
            "'a.obj' line 5: face 0: '3/1/1/1' is not a vertex reference (expected v, v/vt, v//vn or v/vt/vn)");
  EXPECT_EQ(obj_refusal(square + "f 1 2 /1\n"),
            "'a.obj' line 5: face 0: '/1' is not a vertex reference (expected v, v/vt, v//vn or v/vt/vn)");
}

TEST(MeshSoupObj, RefusesFacesWithFewerThanThreeVertices)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  EXPECT_EQ(obj_refusal(square + "f 1 2\n"), "'a.obj' line 4: face 0 has 2 vertices (a face needs at least 3)");
  EXPECT_EQ(obj_refusal(square + "f 1 2 3\nf 1\n"), "'a.obj' line 5: face 1 has 1 vertex (a face needs at least 3)");
  EXPECT_EQ(obj_refusal(square + "f # nothing\n"), "'a.obj' line 4: face 0 has 0 vertices (a face needs at least 3)");
}

TEST(MeshSoupObj, RefusesBadVertices)
{
  EXPECT_EQ(obj_refusal("v 0 0 0\nv 1 1e400 0\n"),
            "'a.obj' line 2: vertex 2 has the coordinate 1e400, which is not a finite number");
  EXPECT_EQ(obj_refusal("v nan 0 0\n"),
            "'a.obj' line 1: vertex 1 has the coordinate nan, which is not a finite number");
  EXPECT_EQ(obj_refusal("v 0 0 0\nv 0 0 0\nv 0 0 inf\n"),
            "'a.obj' line 3: vertex 3 has the coordinate inf, which is not a finite number");
  EXPECT_EQ(obj_refusal("v 0 0\n"), "'a.obj' line 1: vertex 1 has only 2 coordinates (expected x y z)");
  EXPECT_EQ(obj_refusal("v 0 0 z\n"), "'a.obj' line 1: vertex 1: expected a coordinate, found 'z'");
}

TEST(MeshSoupObj, RefusesMalformedTags)
{
  EXPECT_EQ(obj_refusal("v 0 0 0\nt crease 2/1/0 0 1\n"),
            "'a.obj' line 2: tag 'crease' announces 2/1/0, but 2 values follow");
  EXPECT_EQ(obj_refusal("t crease 2/1/0 0 1 2 3\n"),
            "'a.obj' line 1: tag 'crease' announces 2/1/0, but 4 values follow");
  EXPECT_EQ(obj_refusal("t crease 2/1 0 1 2\n"),
            "'a.obj' line 1: tag 'crease': expected the counts INTS/FLOATS/STRINGS (e.g. 2/1/0), found '2/1'");
  EXPECT_EQ(obj_refusal("t crease\n"),
            "'a.obj' line 1: tag 'crease': expected the counts INTS/FLOATS/STRINGS (e.g. 2/1/0), found nothing");
  EXPECT_EQ(obj_refusal("t crease -1/0/0\n"),
            "'a.obj' line 1: tag 'crease': expected the counts INTS/FLOATS/STRINGS (e.g. 2/1/0), found '-1/0/0'");
  EXPECT_EQ(obj_refusal("t\n"), "'a.obj' line 1: a tag line (t) needs a name and the counts INTS/FLOATS/STRINGS");
  EXPECT_EQ(obj_refusal("t crease 2/1/0 0 x 1\n"), "'a.obj' line 1: tag 'crease': expected an integer, found 'x'");
  EXPECT_EQ(obj_refusal("t crease 2/1/0 0 1 y\n"), "'a.obj' line 1: tag 'crease': expected a number, found 'y'");
  EXPECT_EQ(obj_refusal("t crease 2/1/0 0 1 nan\n"),
            "'a.obj' line 1: tag 'crease' has the value nan, which is not a finite number");
  EXPECT_EQ(obj_refusal("t crease 18446744073709551615/0/0 1\n"),
            "'a.obj' line 1: tag 'crease': expected the counts INTS/FLOATS/STRINGS (e.g. 2/1/0), found "
            "'18446744073709551615/0/0'");
  EXPECT_EQ(obj_refusal("t crease 1000000000/1000000000/0 1\n"),
            "'a.obj' line 1: tag 'crease' announces 1000000000/1000000000/0, but 1 value follows");
}

TEST(MeshSoupObj, RefusesLineContinuations)
{
  EXPECT_EQ(obj_refusal("v 0 0 0\nf 1 2 \\\n 3\n"),
            "'a.obj' line 2: the line ends with '\\' (line continuations are not supported)");
  // in a comment, a backslash is only text
  EXPECT_EQ(parse_obj("v 0 0 0 # \\\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").number_of_faces(), 1u);
}

TEST(MeshSoupObj, ReadsTheTextureCoordinatesOfACubeWithASeam)
{
  const Mesh_soup soup = parse_obj(seam_cube_obj);
  ASSERT_EQ(soup.points.size(), 8u);
  ASSERT_EQ(soup.number_of_faces(), 6u);
  EXPECT_EQ(face(soup, 3), (Face{3, 0, 4, 7}));
  EXPECT_EQ(
    soup.texture_points,
    (std::vector<Uv>{{0, 0}, {0.25, 0}, {0.5, 0}, {0.75, 0}, {1, 0}, {0, 1}, {0.25, 1}, {0.5, 1}, {0.75, 1}, {1, 1}}));
  EXPECT_EQ(soup.texture_indices,
            (std::vector<std::size_t>{0, 1, 6, 5, 1, 2, 7, 6, 2, 3, 8, 7, 3, 4, 9, 8, 0, 5, 6, 1, 0, 1, 6, 5}));
  // the seam: vertex 0 has u = 0 in face 0 and u = 1 in face 3
  EXPECT_EQ(soup.texture_points[soup.texture_indices[0]], (Uv{0, 0}));
  EXPECT_EQ(soup.texture_points[soup.texture_indices[13]], (Uv{1, 0}));
  EXPECT_TRUE(soup.notes.empty());
  EXPECT_EQ(broken_invariant(soup), "");
}

TEST(MeshSoupObj, ReadsTextureCoordinatesWithNormals)
{
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
  const Mesh_soup soup = parse_obj(triangle + "f 1/1/1 2/2/1 3/3/1\nf 3/3/ 2/2/ 1/1/\n");
  EXPECT_EQ(soup.indices, (std::vector<std::size_t>{0, 1, 2, 2, 1, 0}));
  EXPECT_EQ(soup.texture_indices, (std::vector<std::size_t>{0, 1, 2, 2, 1, 0}));
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{"ignored the normals (vn) of 'a.obj': face 0 has them, but face 1 has none"}));
  // v//vn and v/ give no texture coordinate
  const Mesh_soup without = parse_obj(triangle + "f 1//1 2//1 3//1\nf 3/ 2/ 1/\n");
  EXPECT_TRUE(without.texture_indices.empty());
  EXPECT_EQ(without.notes,
            (std::vector<std::string>{"no face refers to the 3 texture coordinates (vt) of 'a.obj'",
                                      "ignored the normals (vn) of 'a.obj': face 0 has them, but face 1 has none"}));
}

TEST(MeshSoupObj, ReadsNormals)
{
  // v//vn and v/vt/vn, relative and forward references, normals as written
  const Mesh_soup soup = parse_obj(
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvt 0 0\n"
    "f 1//1 2//-1 3//2\nf 3/1/2 2/1/1 1/1/1\nvn 0 1e-3 -1\n");
  EXPECT_EQ(soup.normals, (std::vector<Point>{{0, 0, 2}, {0, 1e-3, -1}}));
  EXPECT_EQ(soup.normal_indices, (std::vector<std::size_t>{0, 0, 1, 1, 0, 0}));
  EXPECT_TRUE(soup.texture_indices.empty());
  EXPECT_EQ(broken_invariant(soup), "");
  EXPECT_EQ(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nf 1 2 3\n").notes,
            (std::vector<std::string>{"no face refers to the 2 normals (vn) of 'a.obj'"}));
}

TEST(MeshSoupObj, RefusesBadNormals)
{
  EXPECT_EQ(obj_refusal("vn\n"), "'a.obj' line 1: normal 1 has no value (expected x y z)");
  EXPECT_EQ(obj_refusal("vn 0 0 1\nvn 0 1\n"), "'a.obj' line 2: normal 2 has 2 values (expected x y z)");
  EXPECT_EQ(obj_refusal("vn 0 0 1 0\n"), "'a.obj' line 1: normal 1 has 4 values (expected x y z)");
  EXPECT_EQ(obj_refusal("vn 0 y 1\n"), "'a.obj' line 1: normal 1: expected a number, found 'y'");
  EXPECT_EQ(obj_refusal("vn 0 0 inf\n"), "'a.obj' line 1: normal 1 has the value inf, which is not a finite number");
}

TEST(MeshSoupObj, RefusesBadNormalIndices)
{
  const std::string normals = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 1 0\n"; // 5 lines
  EXPECT_EQ(obj_refusal(normals + "f 1//1 2//0 3//1\n"),
            "'a.obj' line 6: face 0 has normal index 0 (OBJ counts normals from 1, or from -1 backwards)");
  EXPECT_EQ(obj_refusal(normals + "f 1//1 2//2 3//3\n"),
            "'a.obj' line 6: face 0 has normal index 3, but the file has 2 normals (1 to 2)");
  EXPECT_EQ(obj_refusal(normals + "f 1//1 2//2 3//-3\n"),
            "'a.obj' line 6: face 0 has normal index -3, but only 2 normals precede it (-1 to -2)");
  EXPECT_EQ(obj_refusal(normals + "f 1//1 2 3//1\n"),
            "'a.obj' line 6: face 0: corner '2' has no normal (vn), but corner '1//1' has one");
  EXPECT_EQ(obj_refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n"),
            "'a.obj' line 4: face 0 has normal index 1, but the file has no normals");
  // the earliest face past the end, whichever list it refers to
  EXPECT_EQ(obj_refusal(normals + "vt 0 0\nf 1/1/1 2/1/1 3/1/4\nf 1/2/1 2/1/1 3/1/1\n"),
            "'a.obj' line 7: face 0 has normal index 4, but the file has 2 normals (1 to 2)");
}

TEST(MeshSoupObj, NegativeTextureIndicesCountBackFromTheLastRead)
{
  const Mesh_soup soup = parse_obj(
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/-3 2/-2 3/-1\n"
    "vt 0 1\nf 1/-4 -2/-2 -1/-1\nf 1/1 3/3 4/-1\n");
  EXPECT_EQ(soup.indices, (std::vector<std::size_t>{0, 1, 2, 0, 2, 3, 0, 2, 3}));
  EXPECT_EQ(soup.texture_indices, (std::vector<std::size_t>{0, 1, 2, 0, 2, 3, 0, 2, 3}));
  EXPECT_TRUE(soup.notes.empty());
}

TEST(MeshSoupObj, ForwardTextureReferences)
{
  // the vt lines (and the v lines) may follow the faces that use them
  const Mesh_soup soup = parse_obj("f 1/3 2/2 3/1\nvt 0 0\nv 0 0 0\nf 3/2 2/3 1/1\nvt 1 0\nvt 0 1\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(soup.indices, (std::vector<std::size_t>{0, 1, 2, 2, 1, 0}));
  EXPECT_EQ(soup.texture_indices, (std::vector<std::size_t>{2, 1, 0, 1, 2, 0}));
  EXPECT_EQ(soup.texture_points, (std::vector<Uv>{{0, 0}, {1, 0}, {0, 1}}));
}

TEST(MeshSoupObj, TextureCoordinatesWithOneOrThreeValues)
{
  const Mesh_soup soup = parse_obj(
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nvt 0.25 0.75 0.125\nvt -1e-3 +2 # a comment\nvt 1e-400 -0\n"
    "f 1/1 2/2 3/3\nf 1/4 2/4 3/4\n");
  EXPECT_EQ(soup.texture_points, (std::vector<Uv>{{0.5, 0}, {0.25, 0.75}, {-1e-3, 2}, {0, 0}}));
  EXPECT_EQ(soup.texture_indices, (std::vector<std::size_t>{0, 1, 2, 3, 3, 3}));
  EXPECT_TRUE(soup.notes.empty());
}

TEST(MeshSoupObj, NotesTextureCoordinatesThatNotEveryFaceUses)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n";
  const Mesh_soup later = parse_obj(square + "f 1 2 3\nf 1/1 3/1 4/1\nf 1 3 4\n");
  EXPECT_EQ(later.number_of_faces(), 3u);
  EXPECT_EQ(later.texture_points.size(), 1u);
  EXPECT_TRUE(later.texture_indices.empty());
  EXPECT_EQ(
    later.notes,
    (std::vector<std::string>{"ignored the texture coordinates (vt) of 'a.obj': face 0 has none, but face 1 has"}));
  const Mesh_soup first = parse_obj(square + "f 1/1 2/1 3/1\nf 1/1 3/1 4/1\nf 1 2 4\nf 2 3 4\nf 1/1 2/1 4/1\n");
  EXPECT_TRUE(first.texture_indices.empty());
  EXPECT_EQ(first.notes, (std::vector<std::string>{
                           "ignored the texture coordinates (vt) of 'a.obj': face 0 has them, but face 2 has none"}));
  const Mesh_soup unused = parse_obj(square + "vt 1 1\nf 1 2 3\n");
  EXPECT_EQ(unused.texture_points, (std::vector<Uv>{{0, 0}, {1, 1}}));
  EXPECT_TRUE(unused.texture_indices.empty());
  EXPECT_EQ(unused.notes, (std::vector<std::string>{"no face refers to the 2 texture coordinates (vt) of 'a.obj'"}));
  EXPECT_EQ(parse_obj("vt 0 0\n").notes,
            (std::vector<std::string>{"no face refers to the 1 texture coordinate (vt) of 'a.obj'"}));
  EXPECT_TRUE(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").notes.empty());
}

TEST(MeshSoupObj, RefusesBadTextureCoordinates)
{
  EXPECT_EQ(obj_refusal("vt\n"), "'a.obj' line 1: texture coordinate 1 has no value (expected u, u v or u v w)");
  EXPECT_EQ(obj_refusal("vt 0 0\nvt # none\n"),
            "'a.obj' line 2: texture coordinate 2 has no value (expected u, u v or u v w)");
  EXPECT_EQ(obj_refusal("vt 0 0\nvt 0 0 0 0\n"),
            "'a.obj' line 2: texture coordinate 2 has 4 values (expected u, u v or u v w)");
  EXPECT_EQ(obj_refusal("vt 0 0 0 0 x y\n"),
            "'a.obj' line 1: texture coordinate 1 has 6 values (expected u, u v or u v w)");
  EXPECT_EQ(obj_refusal("vt 0 x\n"), "'a.obj' line 1: texture coordinate 1: expected a number, found 'x'");
  EXPECT_EQ(obj_refusal("vt 0,5 0\n"), "'a.obj' line 1: texture coordinate 1: expected a number, found '0,5'");
  EXPECT_EQ(obj_refusal("vt nan\n"),
            "'a.obj' line 1: texture coordinate 1 has the value nan, which is not a finite number");
  EXPECT_EQ(obj_refusal("vt 0 1e400\n"),
            "'a.obj' line 1: texture coordinate 1 has the value 1e400, which is not a finite number");
  EXPECT_EQ(obj_refusal("vt 0 0 -inf\n"),
            "'a.obj' line 1: texture coordinate 1 has the value -inf, which is not a finite number");
}

TEST(MeshSoupObj, RefusesBadTextureIndices)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  const std::string uvs = square + "vt 0 0\nvt 1 0\nvt 1 1\n"; // 7 lines
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/3\nf 1/0 2/1 3/1\n"),
            "'a.obj' line 9: face 1 has texture coordinate index 0 (OBJ counts texture coordinates from 1, or from -1 "
            "backwards)");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/4\nf 1/1 2/2 3/9\n"),
            "'a.obj' line 8: face 0 has texture coordinate index 4, but the file has 3 texture coordinates (1 to 3)");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/3\nf 1/1 2/2 3/9\nf 1/1 2/2 3/4\n"),
            "'a.obj' line 9: face 1 has texture coordinate index 9, but the file has 3 texture coordinates (1 to 3)");
  EXPECT_EQ(obj_refusal(square + "f 1/1 2/1 3/1\n"),
            "'a.obj' line 5: face 0 has texture coordinate index 1, but the file has no texture coordinates");
  EXPECT_EQ(obj_refusal(square + "vt 0 0\nf 1/1 2/2 3/1\n"),
            "'a.obj' line 6: face 0 has texture coordinate index 2, but the file has 1 texture coordinate (1 to 1)");
  EXPECT_EQ(obj_refusal(uvs + "f 1/-1 2/-2 3/-4\n"),
            "'a.obj' line 8: face 0 has texture coordinate index -4, but only 3 texture coordinates precede it (-1 to "
            "-3)");
  EXPECT_EQ(obj_refusal(square + "vt 0 0\nf 1/-1 2/-1 3/-2\n"),
            "'a.obj' line 6: face 0 has texture coordinate index -2, but only 1 texture coordinate precedes it (-1 to "
            "-1)");
  EXPECT_EQ(obj_refusal(square + "f 1/-1 2/-1 3/-1\nvt 0 0\n"),
            "'a.obj' line 5: face 0 has texture coordinate index -1, but no texture coordinate precedes it");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/-99999999999999999999\n"),
            "'a.obj' line 8: face 0 has texture coordinate index -99999999999999999999, but only 3 texture "
            "coordinates precede it (-1 to -3)");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/99999999999\n"),
            "'a.obj' line 8: face 0 has texture coordinate index 99999999999, but a mesh has at most 4294967295 "
            "texture coordinates");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/99999999999999999999/1\n"),
            "'a.obj' line 8: face 0 has texture coordinate index 99999999999999999999, but a mesh has at most "
            "4294967295 texture coordinates");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/1.5\n"),
            "'a.obj' line 8: face 0: '3/1.5' is not a vertex reference (expected v, v/vt, v//vn or v/vt/vn)");
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 3/1/x\n"),
            "'a.obj' line 8: face 0: '3/1/x' is not a vertex reference (expected v, v/vt, v//vn or v/vt/vn)");
  // the vertex of a corner is checked first
  EXPECT_EQ(obj_refusal(uvs + "f 1/1 2/2 0/0\n"),
            "'a.obj' line 8: face 0 has vertex index 0 (OBJ counts vertices from 1, or from -1 backwards)");
  // the texture indices are checked even when the soup cannot keep them
  EXPECT_EQ(obj_refusal(square + "vt 0 0\nf 1 2 3\nf 1/5 2/5 3/5\n"),
            "'a.obj' line 7: face 1 has texture coordinate index 5, but the file has 1 texture coordinate (1 to 1)");
  EXPECT_EQ(obj_refusal(square + "vt 0 0\nf 1 2 3\nf 1/1 2/1 3/-2\n"),
            "'a.obj' line 7: face 1 has texture coordinate index -2, but only 1 texture coordinate precedes it (-1 to "
            "-1)");
}

TEST(MeshSoupObj, RefusesTheFirstForwardReferencePastTheEnd)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n";
  EXPECT_EQ(obj_refusal(square + "f 1/1 2/1 3/2\nf 1/1 2/1 9/1\n"),
            "'a.obj' line 6: face 0 has texture coordinate index 2, but the file has 1 texture coordinate (1 to 1)");
  EXPECT_EQ(obj_refusal(square + "f 1/1 2/1 9/1\nf 1/1 2/1 3/2\n"),
            "'a.obj' line 6: face 0 has vertex index 9, but the file has 4 vertices (1 to 4)");
  EXPECT_EQ(obj_refusal(square + "f 1/1 2/1 9/2\n"),
            "'a.obj' line 6: face 0 has vertex index 9, but the file has 4 vertices (1 to 4)");
  EXPECT_EQ(obj_refusal(square + "f 1 2 5\nf 1 2 9\nf 1 2 6\n"),
            "'a.obj' line 6: face 0 has vertex index 5, but the file has 4 vertices (1 to 4)");
}

// The texture data grows with the file, a few bytes per byte: the largest
// allocation, that of a vector grown to twice its size, stays below 8 times
// the file even in the shortest lines that make it grow.
TEST(MeshSoupObj, TextureDataStaysAFewTimesTheFileSize)
{
  const int lines = 100000;
  std::string faces = "v 0 0 0\nvt 0\n", points, forward = "v 0 0 0\n";
  for(int i = 0; i < lines; ++i) {
    faces += "f 1/1 1/1 1/1\n";
    points += "vt 0\n";
    const std::string index = std::to_string(i + 1);
    forward += "f 1/" + index + " 1/" + index + " 1/" + index + "\n";
  }
  largest_allocation = 0;
  EXPECT_EQ(parse_obj(faces).texture_indices.size(), 3u * lines);
  EXPECT_LT(largest_allocation.load(), 8 * faces.size());
  largest_allocation = 0;
  EXPECT_EQ(parse_obj(points).texture_points.size(), std::size_t(lines));
  EXPECT_LT(largest_allocation.load(), 8 * points.size());
  largest_allocation = 0;
  EXPECT_EQ(obj_refusal(forward),
            "'a.obj' line 2: face 0 has texture coordinate index 1, but the file has no "
            "texture coordinates");
  EXPECT_LT(largest_allocation.load(), 8 * forward.size());
}

TEST(MeshSoupObj, RefusesFacesWithAndWithoutTextureCoordinates)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n";
  EXPECT_EQ(obj_refusal(square + "f 1/1 2 3/1\n"),
            "'a.obj' line 6: face 0: corner '2' has no texture coordinate (vt), but corner '1/1' has one");
  EXPECT_EQ(obj_refusal(square + "f 1 2/ 3/1\n"),
            "'a.obj' line 6: face 0: corner '1' has no texture coordinate (vt), but corner '3/1' has one");
  EXPECT_EQ(obj_refusal(square + "f 1/1 2/1 3/1\nf 1//1 3/1/1 4/1/1\n"),
            "'a.obj' line 7: face 1: corner '1//1' has no texture coordinate (vt), but corner '3/1/1' has one");
}

// ---------------------------------------------------------------------------
// PLY

TEST(MeshSoupPly, ReadsAsciiWithOtherPropertiesAndElements)
{
  const Mesh_soup soup = parse_ply(tetra_ply);
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[0], (Point{1, 1, 1}));
  EXPECT_EQ(soup.points[3], (Point{-1, -1, 1}));
  ASSERT_EQ(soup.number_of_faces(), 4u);
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_EQ(face(soup, 3), (Face{1, 3, 2}));
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex property red of 'a.ply'",
                                                  "ignored the face property quality of 'a.ply'",
                                                  "ignored the element 'edge' (2 items) of 'a.ply'"}));
}

TEST(MeshSoupPly, KeepsTheVertexColours)
{
  const std::string header =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  // uchar components, alpha or not, in any order among the other properties
  Mesh_soup soup =
    parse_ply(header + "property uchar blue\nproperty uchar green\nproperty float quality\n" + "property uchar red\n" +
              faces + "0 0 0 1 2 0.5 3\n1 0 0 0 0 0 255\n0 1 0 9 8 0 7\n3 0 1 2\n");
  EXPECT_EQ(soup.colours, (std::vector<Colour>{{3, 2, 1, 255}, {255, 0, 0, 255}, {7, 8, 9, 255}}));
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex property quality of 'a.ply'"}));
  // floating-point components from 0 to 1
  soup = parse_ply(header + "property float red\nproperty float green\nproperty float blue\nproperty float alpha\n" +
                   faces + "0 0 0 1 0.5 0 0.25\n1 0 0 0 0 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n");
  EXPECT_EQ(soup.colours, (std::vector<Colour>{{255, 128, 0, 64}, {0, 0, 0, 255}, {0, 0, 255, 255}}));
  EXPECT_EQ(ply_refusal(header + "property float red\nproperty float green\nproperty float blue\n" + faces +
                        "0 0 0 1 0.5 0\n1 0 0 0 1.5 0\n0 1 0 0 0 1\n3 0 1 2\n"),
            "'a.ply' line 14: vertex 1: its green 1.5 is out of range (integers from 0 to 255, or reals from 0 to 1)");
  EXPECT_EQ(ply_refusal(header + "property int red\nproperty int green\nproperty int blue\n" + faces +
                        "0 0 0 1 2 3\n1 0 0 0 256 0\n0 1 0 0 0 1\n3 0 1 2\n"),
            "'a.ply' line 14: vertex 1: its green 256 is out of range (integers from 0 to 255, or reals from 0 to 1)");
  // red and green without blue: no colours
  soup = parse_ply(header + "property uchar red\nproperty uchar green\n" + faces +
                   "0 0 0 1 2\n1 0 0 3 4\n0 1 0 5 6\n3 0 1 2\n");
  EXPECT_TRUE(soup.colours.empty());
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex properties red, green of 'a.ply'"}));
}

TEST(MeshSoupPly, AsciiIsATokenStream)
{
  const Mesh_soup soup = parse_ply(
    "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float32 z\r\n"
    "property int8 y\r\nproperty float64 x\r\nelement face 1\r\n"
    "property list uint8 uint32 vertex_index\r\nend_header\r\n"
    "1 2 3 4 5\r\n6 7 8 9\r\n3 0\r\n1\r\n2\r\n");
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[0], (Point{3, 2, 1}));
  EXPECT_EQ(soup.points[1], (Point{6, 5, 4}));
  EXPECT_EQ(soup.points[2], (Point{9, 8, 7}));
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_TRUE(soup.notes.empty());
  // the line of the token, not of the item
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                        "0 0 0 1 0 0 0 1 0 3 0\n1\n\n3\n"),
            "'a.ply' line 13: face 0 has vertex index 3, but the file has 3 vertices (0 to 2)");
}

TEST(MeshSoupPly, ReadsBinaryInBothByteOrders)
{
  for(bool big_endian : {false, true}) {
    SCOPED_TRACE(big_endian ? "big endian" : "little endian");
    const Mesh_soup soup = parse_ply(binary_ply(big_endian));
    ASSERT_EQ(soup.points.size(), 4u);
    EXPECT_EQ(soup.points[1], (Point{1, 0, 0}));
    EXPECT_EQ(soup.points[2], (Point{1, 1, 0}));
    ASSERT_EQ(soup.number_of_faces(), 2u);
    EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
    EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
    EXPECT_EQ(soup.notes, (std::vector<std::string>{"ignored the vertex property red of 'a.ply'",
                                                    "ignored the face property texcoord of 'a.ply'",
                                                    "ignored the element 'edge' (1 item) of 'a.ply'"}));
  }
}

TEST(MeshSoupPly, TrailingContentAndEmptyElements)
{
  Mesh_soup soup = parse_ply(binary_ply(false) + "xyz");
  EXPECT_EQ(soup.notes.back(), "ignored 3 bytes after the last element of 'a.ply'");
  soup = parse_ply(tetra_ply + "\n\n  \n");
  EXPECT_EQ(soup.notes.size(), 3u);
  soup = parse_ply(tetra_ply + "7\n");
  EXPECT_EQ(soup.notes.back(), "ignored the text after the last element of 'a.ply' (from line 26)");
  // an element without properties takes no bytes, whatever its count
  soup = parse_ply(
    "ply\nformat ascii 1.0\nelement nothing 4000000000\nelement vertex 0\nproperty float x\n"
    "property float y\nproperty float z\nelement face 0\nproperty list uchar int vertex_indices\n"
    "end_header\n");
  EXPECT_EQ(soup.points.size(), 0u);
  EXPECT_EQ(soup.number_of_faces(), 0u);
}

TEST(MeshSoupPly, RefusesBadHeaders)
{
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 0\nproperty list uchar int vertex_indices\n";
  EXPECT_EQ(ply_refusal("PLY\n"), "'a.ply' line 1: the file does not start with the line 'ply' (not a PLY file)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\n"),
            "'a.ply' line 3: a property line before any element line");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n"),
            "'a.ply' line 4: unknown property type 'real' (expected char, uchar, short, ushort, int, uint, float, "
            "double, int8, uint8, int16, uint16, int32, uint32, float32 or float64)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + face),
            "'a.ply' line 8: the header has no end_header line (truncated?)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\n" + face + "end_header\n"),
            "'a.ply' line 5: the header declares no vertex element");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 0\n" + xyz + "end_header\n"),
            "'a.ply' line 7: the header declares no face element");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n" + face +
                        "end_header\n"),
            "'a.ply' line 3: the vertex element has no property z");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 0\n" + xyz +
                        "element face 0\nproperty list uchar int vertex_list\nend_header\n"),
            "'a.ply' line 7: the face element has no list property vertex_indices (or vertex_index)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 0\n" + xyz +
                        "element face 0\nproperty list uchar float vertex_indices\nend_header\n"),
            "'a.ply' line 8: the face list vertex_indices has items of a floating-point type (expected an integer "
            "type)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 0\n" + xyz +
                        "element face 0\nproperty list float int vertex_indices\nend_header\n"),
            "'a.ply' line 8: a list with the count type 'float' (expected an integer type)");
  EXPECT_EQ(ply_refusal("ply\nformat binary_middle_endian 1.0\n"),
            "'a.ply' line 2: unknown PLY format 'binary_middle_endian' (expected ascii, binary_little_endian or "
            "binary_big_endian)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 2.0\n"), "'a.ply' line 2: unsupported PLY version '2.0' (expected 1.0)");
  EXPECT_EQ(ply_refusal("ply\nelement vertex 0\n" + xyz + face + "end_header\n"),
            "'a.ply' line 8: the header has no format line");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex -1\n"),
            "'a.ply' line 3: element 'vertex' has the count -1 (negative)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement edge 99999999999999999999\n"),
            "'a.ply' line 3: element 'edge' has the count 99999999999999999999 (too large)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 0\n" + xyz + "element vertex 0\n"),
            "'a.ply' line 7: a second 'vertex' element (the first is on line 3)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nfoo\n"),
            "'a.ply' line 3: unexpected 'foo' in the header (expected format, element, property, comment, obj_info "
            "or end_header)");
}

TEST(MeshSoupPly, RefusesLyingCountsBeforeAllocating)
{
  const std::string header =
    "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  largest_allocation = 0;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(ply_refusal(header + std::string(100, '\0')),
            "'a.ply' line 3: header says 2147483648 vertices, but the file has only 100 bytes after the header "
            "(truncated, or the counts are wrong)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 1000\nproperty list uchar int vertex_indices\nend_header\n"
                        "0 0 0 1 0 0 0 1 0 3 0 1 2\n"),
            "'a.ply' line 7: header says 3 vertices and 1000 faces, but the file has only 26 bytes after the header "
            "(truncated, or the counts are wrong)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 4294967296\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"),
            "'a.ply' line 3: header says 4294967296 vertices: more than 4294967295 are not supported (the meshes "
            "use 32-bit indices)");
  // a list count of 2147483647 allocated 8.4 GB in CGAL's reader
  Bytes list(false);
  list.text(
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n");
  const std::size_t body = list.size();
  list.f32s({0, 0, 0, 1, 0, 0, 0, 1, 0}).i32(2147483647).i32s({0, 1, 2});
  EXPECT_EQ(ply_refusal(list.str()), "'a.ply' byte " + std::to_string(body + 36) +
                                       ": face 0 says it has 2147483647 vertices, but only 12 bytes are left "
                                       "(truncated, or the count is wrong)");
  EXPECT_EQ(ply_refusal("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nproperty list int int normals\nelement face 0\n"
                        "property list uchar int vertex_indices\nend_header\n"
                        "0 0 0 2147483647 1 2\n" +
                        std::string(10, ' ')),
            "'a.ply' line 11: vertex 0 says its list 'normals' has 2147483647 values, but only 15 bytes are left "
            "(truncated, or the count is wrong)");
  EXPECT_LT(largest_allocation.load(), 4096u);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(MeshSoupPly, RefusesBadIndices)
{
  const std::string ascii =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(ply_refusal(ascii + "3 0 -1 2\n"),
            "'a.ply' line 13: face 0 has vertex index -1, but the file has 3 vertices (0 to 2)");
  EXPECT_EQ(ply_refusal(ascii + "3 0 1 2000000000\n"),
            "'a.ply' line 13: face 0 has vertex index 2000000000, but the file has 3 vertices (0 to 2)");
  EXPECT_EQ(ply_refusal(ascii + "2 0 1    \n"), "'a.ply' line 13: face 0 has 2 vertices (a face needs at least 3)");
  EXPECT_EQ(ply_refusal(ascii + "3 0 1 x\n"), "'a.ply' line 13: expected an integer in face 0, found 'x'");
  EXPECT_EQ(ply_refusal(ascii + "3 0 1    \n"), "'a.ply' line 13: the file ends inside face 0 (truncated)");
  for(bool big_endian : {false, true}) {
    Bytes b(big_endian);
    b.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
           "property list uchar int vertex_indices\nend_header\n");
    const std::size_t body = b.size();
    b.f32s({0, 0, 0, 1, 0, 0, 0, 1, 0});
    EXPECT_EQ(ply_refusal(Bytes(b).u8(3).i32s({0, -1, 2}).str()),
              "'a.ply' byte " + std::to_string(body + 41) +
                ": face 0 has vertex index -1, but the file has 3 vertices (0 to 2)");
    EXPECT_EQ(ply_refusal(Bytes(b).u8(3).i32s({0, 1, 2000000000}).str()),
              "'a.ply' byte " + std::to_string(body + 45) +
                ": face 0 has vertex index 2000000000, but the file has 3 vertices (0 to 2)");
    EXPECT_EQ(ply_refusal(Bytes(b).u8(1).i32s({0, 1, 2}).str()),
              "'a.ply' byte " + std::to_string(body + 36) + ": face 0 has 1 vertex (a face needs at least 3)");
    EXPECT_EQ(ply_refusal(Bytes(b).u8(4).i32s({0, 1, 2}).str()),
              "'a.ply' byte " + std::to_string(body + 36) +
                ": face 0 says it has 4 vertices, but only 12 bytes are left (truncated, or the count is wrong)");
  }
  // a list longer than the least one leaves too few bytes for what follows
  Bytes b(false);
  b.text(
    "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nproperty float quality\n"
    "end_header\n");
  const std::size_t body = b.size();
  b.f32s({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}).u8(4).i32s({0, 1, 2, 3});
  EXPECT_EQ(ply_refusal(b.str()),
            "'a.ply' byte " + std::to_string(body + 65) + ": the file ends inside face 0 (truncated)");
}

TEST(MeshSoupPly, RefusesNonFiniteCoordinates)
{
  const std::string header =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(ply_refusal(header + "0 0 0\n1 0 0\n0 1e400 0\n"),
            "'a.ply' line 12: vertex 2 has the coordinate 1e400, which is not a finite number");
  EXPECT_EQ(ply_refusal(header + "0 0 0\n1 nan 0\n0 1 0\n"),
            "'a.ply' line 11: vertex 1 has the coordinate nan, which is not a finite number");
  EXPECT_EQ(ply_refusal(header + "inf 0 0\n1 0 0\n0 1 0\n"),
            "'a.ply' line 10: vertex 0 has the coordinate inf, which is not a finite number");
  Bytes b(false);
  b.text(
    "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n");
  const std::size_t body = b.size();
  EXPECT_EQ(
    ply_refusal(Bytes(b).f64(0).f32s({0, 0}).f64(0).f32s({inf_f, 0}).str()),
    "'a.ply' byte " + std::to_string(body + 24) + ": vertex 1 has the coordinate inf, which is not a finite number");
  EXPECT_EQ(ply_refusal(Bytes(b).f64(std::nan("")).f32s({0, 0}).f64(0).f32s({0, 0}).str()),
            "'a.ply' byte " + std::to_string(body) + ": vertex 0 has the coordinate nan, which is not a finite number");
}

TEST(MeshSoupPly, RefusesBadListsOfOtherElements)
{
  Bytes b(true);
  b.text(
    "ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nelement edge 1\n"
    "property list int int ends\nend_header\n");
  const std::size_t body = b.size();
  EXPECT_EQ(ply_refusal(Bytes(b).i32(-2).i32s({0, 0}).str()),
            "'a.ply' byte " + std::to_string(body) +
              ": item 0 of the element 'edge' has the list count -2 (negative) for 'ends'");
  EXPECT_EQ(ply_refusal(Bytes(b).i32(3).i32s({0, 0}).str()),
            "'a.ply' byte " + std::to_string(body) +
              ": item 0 of the element 'edge' says its list 'ends' has 3 values, but only 8 bytes are left "
              "(truncated, or the count is wrong)");
}

// ---------------------------------------------------------------------------
// STL

TEST(MeshSoupStl, ReadsAsciiAndMergesEqualCorners)
{
  const Mesh_soup soup = parse_stl(tetra_stl);
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[0], (Point{1, 1, 1}));
  EXPECT_EQ(soup.points[1], (Point{1, -1, -1}));
  EXPECT_EQ(soup.points[2], (Point{-1, 1, -1}));
  EXPECT_EQ(soup.points[3], (Point{-1, -1, 1}));
  ASSERT_EQ(soup.number_of_faces(), 4u);
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
  EXPECT_EQ(face(soup, 2), (Face{0, 3, 1}));
  EXPECT_EQ(face(soup, 3), (Face{1, 3, 2}));
  EXPECT_TRUE(soup.notes.empty());
}

TEST(MeshSoupStl, AsciiIgnoresCaseAndMergesNegativeZero)
{
  const Mesh_soup soup = parse_stl(
    "  SOLID\r\nFacet Normal 0 0 1\r\nOuter Loop\r\nVertex 0 0 0\r\n"
    "VERTEX 1 0 0\r\nvertex 1 1 0\r\nENDLOOP\r\nendfacet\r\n"
    "facet normal 0 0 1 outer loop vertex -0.0 -0 0 vertex 1 1 0 vertex 0 1 0 "
    "endloop endfacet\r\nEndSolid\r\n");
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
  EXPECT_FALSE(std::signbit(soup.points[0][0]));
}

TEST(MeshSoupStl, SeveralSolidsAndTrailingText)
{
  Mesh_soup soup = parse_stl(tetra_stl + tetra_stl);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.number_of_faces(), 8u);
  EXPECT_EQ(soup.notes, (std::vector<std::string>{"read the 2 solids of 'a.stl' as one mesh"}));
  soup = parse_stl(tetra_stl + "that's all\n");
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{"ignored the text after the last 'endsolid' of 'a.stl' (from line 31)"}));
}

TEST(MeshSoupStl, ReadsBinary)
{
  const Mesh_soup soup = parse_stl(binary_stl());
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[0], (Point{0, 0, 0}));
  EXPECT_EQ(soup.points[2], (Point{1, 1, 0}));
  EXPECT_EQ(soup.points[3], (Point{0, 1, 0}));
  ASSERT_EQ(soup.number_of_faces(), 2u);
  EXPECT_EQ(face(soup, 0), (Face{0, 1, 2}));
  EXPECT_EQ(face(soup, 1), (Face{0, 2, 3}));
  EXPECT_TRUE(soup.notes.empty());
  const Mesh_soup empty = parse_stl(std::string(84, '\0'));
  EXPECT_EQ(empty.points.size(), 0u);
  EXPECT_EQ(empty.number_of_faces(), 0u);
}

TEST(MeshSoupStl, RefusesWhatIsNeitherAsciiNorBinary)
{
  EXPECT_EQ(stl_refusal("hello"),
            "'a.stl': neither ASCII STL (it does not start with 'solid') nor binary STL (it has "
            "only 5 bytes, fewer than the 84 of a binary STL header)");
  const std::string binary = binary_stl();
  std::string renamed = "SOLIT" + binary.substr(5);
  EXPECT_EQ(stl_refusal(renamed.substr(0, renamed.size() - 1)),
            "'a.stl': neither ASCII STL (it does not start with 'solid') nor binary STL (its size 183 is not 84 + 50 "
            "x 2, the triangle count at byte 80)");
  EXPECT_EQ(stl_refusal(binary.substr(0, binary.size() - 1)),
            "'a.stl' line 1: the file ends before 'endsolid' (truncated) (if it is a binary STL: its size 183 is not "
            "84 + 50 x 2, the triangle count at byte 80)");
}

TEST(MeshSoupStl, RefusesBadFacets)
{
  const std::string head = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n";
  EXPECT_EQ(stl_refusal(head + "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n"),
            "'a.stl' line 2: facet 0 has 4 vertices (STL facets are triangles)");
  EXPECT_EQ(stl_refusal(head + "endloop\nendfacet\nendsolid\n"),
            "'a.stl' line 2: facet 0 has 2 vertices (STL facets are triangles)");
  EXPECT_EQ(stl_refusal(head + "vertex 1 1e400 0\nendloop\nendfacet\nendsolid\n"),
            "'a.stl' line 6: facet 0 has the coordinate 1e400, which is not a finite number");
  EXPECT_EQ(stl_refusal(head + "vertex nan 1 0\nendloop\nendfacet\nendsolid\n"),
            "'a.stl' line 6: facet 0 has the coordinate nan, which is not a finite number");
  EXPECT_EQ(stl_refusal(head + "vertex 1 1 -inf\nendloop\nendfacet\nendsolid\n"),
            "'a.stl' line 6: facet 0 has the coordinate -inf, which is not a finite number");
  EXPECT_EQ(stl_refusal(head + "vertex 1 1 0\nendloop\nendfacet\n"),
            "'a.stl' line 8: the file ends before 'endsolid' (truncated)");
  EXPECT_EQ(stl_refusal(head + "vertex 1 1\n"), "'a.stl' line 6: the file ends inside facet 0 (truncated)");
  EXPECT_EQ(stl_refusal(head + "vertex 1 1 0\nendloop\nendfacets\n"),
            "'a.stl' line 8: facet 0: expected 'endfacet', found 'endfacets'");
  EXPECT_EQ(stl_refusal("solid s\nfacet 0 0 1\n"), "'a.stl' line 2: facet 0: expected 'normal', found '0'");
  EXPECT_EQ(stl_refusal(head + "vertex 1 1 x\n"), "'a.stl' line 6: facet 0: expected a number, found 'x'");
  Bytes b(false);
  b.text(std::string(80, ' ')).u32(1).f32s({0, 0, 1, 0, 0, 0, 1, 0, 0, 1, nan_f, 0}).u8(0).u8(0);
  EXPECT_EQ(stl_refusal(b.str()), "'a.stl' byte 124: facet 0 has the coordinate nan, which is not a finite number");
}

// ---------------------------------------------------------------------------
// Reading files

TEST(MeshSoupFile, ReadsAFileAndRefusesMissingOnesAndDirectories)
{
  namespace fs = std::filesystem;
  const fs::path directory = fs::temp_directory_path() / ("mesh_soup_test_" + std::to_string(::getpid()));
  fs::create_directories(directory);
  const std::string path = (directory / "tetra.off").string();
  std::ofstream(path, std::ios::binary) << tetra_off;
  const Mesh_soup soup = cgal_subdiv::read_mesh_soup(path, Mesh_format::off);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(face(soup, 2), (Face{0, 3, 1}));
  std::ofstream(path, std::ios::binary) << "OFF\n3 1 0\n0 0 0\n";
  try {
    cgal_subdiv::read_mesh_soup(path, Mesh_format::off);
    ADD_FAILURE() << "no error";
  } catch(const Input_error& error) {
    EXPECT_EQ(std::string(error.what()), "'" + path +
                                           "' line 2: header says 3 vertices, but the file has only 7 bytes "
                                           "after the header (truncated, or the counts are wrong)");
  }
  const std::string missing = (directory / "missing.off").string();
  try {
    cgal_subdiv::read_mesh_soup(missing, Mesh_format::off);
    ADD_FAILURE() << "no error";
  } catch(const Input_error& error) {
    EXPECT_EQ(std::string(error.what()), "cannot read '" + missing + "': no such file");
  }
  try {
    cgal_subdiv::read_mesh_soup(directory.string(), Mesh_format::obj);
    ADD_FAILURE() << "no error";
  } catch(const Input_error& error) {
    EXPECT_EQ(std::string(error.what()), "cannot read '" + directory.string() + "': it is a directory");
  }
  fs::remove_all(directory);
}

/// the cells of a Markdown table row "| a | b |", without their blanks
[[maybe_unused]] std::vector<std::string> table_cells(const std::string& line)
{
  std::vector<std::string> cells;
  std::size_t begin = line.find('|');
  while(begin != std::string::npos) {
    const std::size_t end = line.find('|', begin + 1);
    if(end == std::string::npos)
      break;
    std::string cell = line.substr(begin + 1, end - begin - 1);
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    cells.push_back(cell);
    begin = end;
  }
  return cells;
}

[[maybe_unused]] bool is_count(const std::string& text)
{
  return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
}

// Every mesh of ../shared/data/meshes (OFF, OBJ with tags, PLY) gives the
// vertex and face counts that its SOURCES.md lists, computed independently.
// (Its name says "shared": test/CMakeLists.txt labels it shared-data.)
TEST(MeshSoupFile, reads_every_shared_mesh_with_the_counts_of_sources_md)
{
#ifndef SUBDIV_SHARED_DATA_DIR
  GTEST_SKIP() << "built without SUBDIV_SHARED_DATA_DIR";
#else
  const std::string meshes = std::string(SUBDIV_SHARED_DATA_DIR) + "/meshes/";
  std::ifstream sources(meshes + "SOURCES.md");
  if(!sources)
    GTEST_SKIP() << "../shared/data is not beside the checkout";
  const std::vector<std::pair<std::string, Mesh_format>> extensions = {
    {".off", Mesh_format::off}, {".obj", Mesh_format::obj}, {".ply", Mesh_format::ply}, {".stl", Mesh_format::stl}};
  std::size_t checked = 0;
  for(std::string line; std::getline(sources, line);) {
    // | `cgal/3torus.off` | source | license | 19 | 23 | ...
    const std::vector<std::string> cells = table_cells(line);
    if(cells.size() < 5 || cells[0].size() < 3 || cells[0].front() != '`' || cells[0].back() != '`' ||
       !is_count(cells[3]) || !is_count(cells[4]))
      continue;
    const std::string file = cells[0].substr(1, cells[0].size() - 2);
    for(const auto& [extension, format] : extensions) {
      if(file.size() <= extension.size() || file.compare(file.size() - extension.size(), extension.size(), extension))
        continue;
      SCOPED_TRACE(file);
      const Mesh_soup soup = cgal_subdiv::read_mesh_soup(meshes + file, format);
      EXPECT_EQ(soup.points.size(), std::stoul(cells[3]));
      EXPECT_EQ(soup.number_of_faces(), std::stoul(cells[4]));
      EXPECT_EQ(broken_invariant(soup), "");
      ++checked;
    }
  }
  EXPECT_GT(checked, 200u);
#endif
}

TEST(MeshSoupFile, FormatNames)
{
  EXPECT_STREQ(cgal_subdiv::mesh_format_name(Mesh_format::off), "OFF");
  EXPECT_STREQ(cgal_subdiv::mesh_format_name(Mesh_format::obj), "OBJ");
  EXPECT_STREQ(cgal_subdiv::mesh_format_name(Mesh_format::ply), "PLY");
  EXPECT_STREQ(cgal_subdiv::mesh_format_name(Mesh_format::stl), "STL");
}

// ---------------------------------------------------------------------------
// Hostile input: truncations and byte flips of valid files

struct Sample
{
  const char* what;
  std::string data;
  Mesh_format format;
};

std::vector<Sample> samples()
{
  return {{"ASCII OFF", tetra_off, Mesh_format::off},
          {"COFF", colour_off, Mesh_format::off},
          {"binary OFF", binary_off(), Mesh_format::off},
          {"binary COFF", binary_off("COFF"), Mesh_format::off},
          {"OBJ", cube_obj, Mesh_format::obj},
          {"OBJ with a UV seam", seam_cube_obj, Mesh_format::obj},
          {"ASCII PLY", tetra_ply, Mesh_format::ply},
          {"binary PLY (little endian)", binary_ply(false), Mesh_format::ply},
          {"binary PLY (big endian)", binary_ply(true), Mesh_format::ply},
          {"ASCII STL", tetra_stl, Mesh_format::stl},
          {"binary STL", binary_stl(), Mesh_format::stl}};
}

/// parses `data`: "" if it gives a valid soup (`accepted` then true) or an
/// Input_error, else what went wrong
std::string check_hostile(const std::string& data, Mesh_format format, bool& accepted)
{
  accepted = false;
  try {
    const Mesh_soup soup = parse_mesh_soup(data.data(), data.size(), format, "hostile");
    accepted = true;
    return broken_invariant(soup);
  } catch(const Input_error&) {
    return "";
  } catch(const std::exception& error) {
    return std::string("exception other than Input_error: ") + error.what();
  }
}

TEST(MeshSoupHostile, SamplesAreValid)
{
  for(const Sample& sample : samples()) {
    SCOPED_TRACE(sample.what);
    const Mesh_soup soup = parse_mesh_soup(sample.data.data(), sample.data.size(), sample.format, "sample");
    EXPECT_EQ(broken_invariant(soup), "");
    EXPECT_GE(soup.number_of_faces(), 2u);
  }
}

TEST(MeshSoupHostile, EveryPrefixParsesOrIsRefused)
{
  std::size_t refused = 0, parsed = 0;
  for(const Sample& sample : samples()) {
    SCOPED_TRACE(sample.what);
    for(std::size_t size = 0; size < sample.data.size(); ++size) {
      bool accepted = false;
      ASSERT_EQ(check_hostile(sample.data.substr(0, size), sample.format, accepted), "")
        << "prefix of " << size << " bytes";
      ++(accepted ? parsed : refused);
    }
  }
  EXPECT_GT(refused, 1000u); // most prefixes cut a face short
  EXPECT_GT(parsed, 0u);     // some end where trailing text or comments were cut
}

TEST(MeshSoupHostile, RandomByteFlipsParseOrAreRefused)
{
  std::mt19937 random(20260101);
  const char interesting[] = {'0', '1', '9',  '-',  '+',    '.',    'e', ' ', '\n', '\r',
                              '#', '/', '\\', '\0', '\x7f', '\xff', 'n', 'a', 'i'};
  std::size_t parsed = 0, refused = 0;
  for(const Sample& sample : samples()) {
    SCOPED_TRACE(sample.what);
    for(int round = 0; round < 3000; ++round) {
      std::string data = sample.data;
      const int flips = 1 + static_cast<int>(random() % 4);
      for(int i = 0; i < flips; ++i) {
        const std::size_t at = random() % data.size();
        switch(random() % 4) {
          case 0:
            data[at] = static_cast<char>(random() % 256);
            break;
          case 1:
            data[at] = interesting[random() % sizeof interesting];
            break;
          case 2:
            data[at] = static_cast<char>(data[at] ^ (1 << (random() % 8)));
            break;
          default:
            data.insert(at, 1, interesting[random() % sizeof interesting]);
        }
      }
      bool accepted = false;
      ASSERT_EQ(check_hostile(data, sample.format, accepted), "") << "round " << round;
      ++(accepted ? parsed : refused);
    }
  }
  EXPECT_EQ(parsed + refused, 33000u);
  EXPECT_GT(parsed, 1000u); // changed coordinates, comments, names: still valid
  EXPECT_GT(refused, 1000u);
}

} // namespace
