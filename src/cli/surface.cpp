// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "surface.h"
#include "files.h"

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace cgal_subdiv {
namespace {

namespace fs = std::filesystem;
using Point_3 = Double_kernel::Point_3;

// CGAL's writers may talk on std::cerr; keep it off the one-line error rule
class Captured_cerr
{
public:
  Captured_cerr() : m_old(std::cerr.rdbuf(m_buffer.rdbuf())) {}
  ~Captured_cerr() { std::cerr.rdbuf(m_old); }
  Captured_cerr(const Captured_cerr&) = delete;
  Captured_cerr& operator=(const Captured_cerr&) = delete;

private:
  std::ostringstream m_buffer;
  std::streambuf* m_old;
};

std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

} // namespace

std::string list_surface_schemes()
{
  const std::vector<std::string>& names = surface_scheme_keywords();
  std::string list;
  for(std::size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return list;
}

const Surface_scheme& find_surface_scheme(const std::string& name)
{
  for(const Surface_scheme& scheme : surface_schemes())
    if(scheme.name == name)
      return scheme;
  const std::vector<std::string>& known = surface_scheme_keywords();
  if(std::find(known.begin(), known.end(), name) != known.end())
    throw Input_error("the scheme '" + name + "' is not yet available in this build of cgal-subdiv");
  throw Usage_error("unknown scheme '" + name + "' (expected " + list_surface_schemes() + ")");
}

Mesh_format mesh_format(const std::string& path, const std::string& role)
{
  const std::string extension = lower(fs::path(path).extension().string());
  if(extension == ".off")
    return Mesh_format::off;
  if(extension == ".obj")
    return Mesh_format::obj;
  if(extension == ".ply")
    return Mesh_format::ply;
  if(extension == ".stl")
    return Mesh_format::stl;
  throw Usage_error(role + " '" + path + "': unknown format " +
                    (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
                    " (expected .off, .obj, .ply or .stl)");
}

Mesh_counts counts(const Surface& mesh)
{
  return Mesh_counts{mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces()};
}

std::string describe(const Mesh_counts& c)
{
  return std::to_string(c.vertices) + " V, " + std::to_string(c.edges) + " E, " + std::to_string(c.faces) + " F";
}

std::string seconds_text(double seconds)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f s", seconds);
  return buffer;
}

Surface read_surface(const std::string& path, Soup_fix fix, std::vector<std::string>& notes,
                     std::vector<std::size_t>* file_numbers)
{
  const Mesh_format format = mesh_format(path, "INPUT");
  // every index in range, every coordinate finite, before CGAL sees anything
  return surface_from_soup(read_mesh_soup(path, format), path, format, fix, notes, file_numbers);
}

Surface read_surface(const std::string& path, Soup_fix fix, std::vector<std::string>& notes,
                     std::vector<std::size_t>* file_numbers, File_tags& tags)
{
  const Mesh_format format = mesh_format(path, "INPUT");
  Mesh_soup soup = read_mesh_soup(path, format);
  tags.tags = std::move(soup.tags);
  soup.tags.clear();
  tags.file_vertices = soup.points.size();
  return surface_from_soup(soup, path, format, fix, notes, file_numbers);
}

Largest_coordinate largest_coordinate(const Surface& mesh)
{
  Largest_coordinate largest;
  for(const Surface::Vertex_index v : mesh.vertices())
    for(int i = 0; i < 3; ++i)
      if(std::abs(mesh.point(v)[i]) > std::abs(largest.value)) {
        largest.vertex = v;
        largest.value = mesh.point(v)[i];
      }
  return largest;
}

void check_finite_result(const Surface& result, const std::string& what, const std::string& input,
                         const Largest_coordinate& largest, const std::vector<std::size_t>& file_numbers)
{
  for(const Surface::Vertex_index v : result.vertices()) {
    const auto& p = result.point(v);
    if(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()))
      continue;
    std::ostringstream value;
    value.precision(6);
    value << largest.value;
    const std::string at = largest.vertex < file_numbers.size()
                             ? "vertex " + std::to_string(file_numbers[largest.vertex])
                             : "vertex " + std::to_string(largest.vertex) + " of the mesh read";
    throw Input_error(what + " on '" + input + "' gives a non-finite coordinate (output vertex " +
                      std::to_string(static_cast<std::size_t>(v)) + "): the coordinates of '" + input +
                      "' are too large for the scheme's weights (the largest, " + value.str() + ", is at " + at +
                      "); scale the mesh down. Nothing was written");
  }
}

namespace {

// The unit normal of triangle (a, b, c), computed on the sides scaled by their
// largest coordinate so that it is finite for any finite points (CGAL's STL
// writer squares the sides: 1e200 gave "facet normal 0 0 -nan"); zero for a
// degenerate triangle.
std::array<double, 3> unit_normal(const Point_3& a, const Point_3& b, const Point_3& c)
{
  double scale = 0;
  for(int i = 0; i < 3; ++i)
    scale = std::max({scale, std::abs(b[i] - a[i]), std::abs(c[i] - a[i])});
  if(!(scale > 0) || !std::isfinite(scale))
    return {0, 0, 0};
  const double u[3] = {(b[0] - a[0]) / scale, (b[1] - a[1]) / scale, (b[2] - a[2]) / scale};
  const double v[3] = {(c[0] - a[0]) / scale, (c[1] - a[1]) / scale, (c[2] - a[2]) / scale};
  const Normal n =
    unit_or_zero(Normal(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]));
  return {n.x(), n.y(), n.z()};
}

// the normal of the surface at `v`: the normalised sum of the unit normals
// of its corners (zero where that is zero)
Normal surface_normal(const Surface& mesh, Surface::Vertex_index v)
{
  Normal sum = CGAL::NULL_VECTOR;
  for(const Surface::Halfedge_index h : CGAL::halfedges_around_target(v, mesh)) {
    if(mesh.is_border(h))
      continue;
    const std::array<double, 3> n =
      unit_normal(mesh.point(v), mesh.point(mesh.target(mesh.next(h))), mesh.point(mesh.source(h)));
    sum = sum + Normal(n[0], n[1], n[2]);
  }
  return unit_or_zero(sum);
}

void put_uint32_le(std::ostream& out, std::uint32_t bits)
{
  const char bytes[4] = {static_cast<char>(bits & 0xff), static_cast<char>((bits >> 8) & 0xff),
                         static_cast<char>((bits >> 16) & 0xff), static_cast<char>((bits >> 24) & 0xff)};
  out.write(bytes, 4);
}

void put_float_le(std::ostream& out, double value)
{
  const float f = static_cast<float>(value);
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  put_uint32_le(out, bits);
}

// STL, ASCII or binary (32-bit floats: a coordinate beyond the float range is
// refused, not written as inf), of a triangle mesh
void write_stl(const Surface& triangles, std::ostream& out, bool binary, const std::string& path)
{
  if(binary) {
    const std::string header = "cgal-subdiv binary STL";
    std::string head(80, ' ');
    head.replace(0, header.size(), header);
    out.write(head.data(), 80);
    put_uint32_le(out, static_cast<std::uint32_t>(triangles.number_of_faces()));
  } else {
    out.precision(17);
    out << "solid cgal-subdiv\n";
  }
  for(const Surface::Face_index f : triangles.faces()) {
    std::array<Point_3, 3> p;
    int k = 0;
    for(const Surface::Vertex_index v : CGAL::vertices_around_face(triangles.halfedge(f), triangles))
      p[static_cast<std::size_t>(k++)] = triangles.point(v);
    const std::array<double, 3> n = unit_normal(p[0], p[1], p[2]);
    if(binary) {
      for(double x : n)
        put_float_le(out, x);
      for(const Point_3& q : p)
        for(int i = 0; i < 3; ++i) {
          if(std::abs(q[i]) > std::numeric_limits<float>::max())
            throw Input_error("cannot write '" + path + "' as binary STL: the coordinate " + std::to_string(q[i]) +
                              " does not fit in its 32-bit floats (write ASCII STL, or PLY)");
          put_float_le(out, q[i]);
        }
      out.write("\0\0", 2);
    } else {
      out << "facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\n outer loop\n";
      for(const Point_3& q : p)
        out << "  vertex " << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
      out << " endloop\nendfacet\n";
    }
  }
  if(!binary)
    out << "endsolid cgal-subdiv\n";
}

// the vt lines of a textured mesh, numbered in the order of the first corner
// that uses them; returns the vt number (from 1) of each texture index
std::vector<std::size_t> write_obj_texture_points(const Surface& mesh, const Texture_index_map& indices,
                                                  std::ostream& out)
{
  const Texture_point_map values = mesh.property_map<Surface::Halfedge_index, Texture_point>(texture_point_name).first;
  std::vector<std::size_t> number_of_index; // 0: not yet written
  std::size_t written = 0;
  for(const Surface::Face_index f : mesh.faces())
    for(const Surface::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      if(indices[h] >= number_of_index.size())
        number_of_index.resize(indices[h] + 1, 0);
      if(number_of_index[indices[h]] == 0) {
        number_of_index[indices[h]] = ++written;
        out << "vt " << values[h].x() << ' ' << values[h].y() << '\n';
      }
    }
  return number_of_index;
}

// the vn lines of a mesh with vertex normals, one per vertex, in the order
// of the v lines, so that a corner's normal has its vertex's number
void write_obj_normals(const Normal_map& normals, const Surface& mesh, std::ostream& out)
{
  for(const Surface::Vertex_index v : mesh.vertices()) {
    const Normal n = unit_or_zero(normals[v]); // finish_normals did it; never a nan here
    out << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
  }
}

// OBJ: the points (v), the texture coordinates if the mesh has them (vt,
// numbered in the order of the first corner that uses them, so that a value
// no corner uses is left out), the vertex normals if it has them (vn, one per
// vertex), the faces (f v, f v/vt, f v//vn or f v/vt/vn) and, with `tags`,
// the tag lines; vertices and faces numbered in the mesh's order, as the tag
// lines number them (from 0 there)
void write_obj(const Surface& mesh, std::ostream& out, const Sharp_options* tags,
               CGAL::Subdiv::Face_varying_interpolation face_varying)
{
  out.precision(17);
  out << "# cgal-subdiv: " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces\n";
  for(const Surface::Vertex_index v : mesh.vertices()) {
    const Point_3& p = mesh.point(v);
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  const bool textured = has_texture_points(mesh);
  const Texture_index_map indices =
    textured ? mesh.property_map<Surface::Halfedge_index, std::size_t>(texture_index_name).first : Texture_index_map();
  const std::vector<std::size_t> number_of_index =
    textured ? write_obj_texture_points(mesh, indices, out) : std::vector<std::size_t>();
  const std::optional<Normal_map> normals = normals_of(mesh);
  if(normals)
    write_obj_normals(*normals, mesh, out);
  for(const Surface::Face_index f : mesh.faces()) {
    out << 'f';
    for(const Surface::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const std::size_t vertex = mesh.target(h).idx() + 1;
      out << ' ' << vertex;
      if(textured || normals)
        out << '/';
      if(textured)
        out << number_of_index[indices[h]];
      if(normals)
        out << '/' << vertex;
    }
    out << '\n';
  }
  if(tags != nullptr)
    write_obj_tags(out, mesh, *tags);
  if(textured)
    write_obj_face_varying_tag(out, face_varying);
}

} // namespace

std::size_t finish_normals(Surface& mesh)
{
  const std::optional<Normal_map> normals = normals_of(mesh);
  if(!normals)
    return 0;
  std::size_t fallbacks = 0;
  for(const Surface::Vertex_index v : mesh.vertices()) {
    Normal& n = (*normals)[v];
    n = unit_or_zero(n);
    if(n == CGAL::NULL_VECTOR) {
      n = surface_normal(mesh, v);
      ++fallbacks;
    }
  }
  return fallbacks;
}

void write_surface(const Surface& mesh, const std::string& path, bool binary, const Sharp_options* tags,
                   CGAL::Subdiv::Face_varying_interpolation face_varying)
{
  const Mesh_format format = mesh_format(path, "OUTPUT");
  if(binary && format != Mesh_format::ply && format != Mesh_format::stl)
    throw Usage_error("--binary writes PLY and STL only; OUTPUT '" + path + "' is " + mesh_format_name(format));
  Atomic_file file(path);
  std::ostream& out = file.stream();
  const auto np = CGAL::parameters::stream_precision(17);
  // OFF, PLY and STL have no hole tags: the faces that are holes are left out
  const std::optional<Surface> without = format != Mesh_format::obj ? without_holes(mesh) : std::nullopt;
  const Surface& drawn = without ? *without : mesh;
  bool ok = true;
  {
    Captured_cerr quiet;
    switch(format) {
      case Mesh_format::off: // COFF with the vertex colours, if any
        if(const std::optional<Colour_map> colours = colours_of(drawn))
          ok = CGAL::IO::write_OFF(out, drawn, np.vertex_color_map(*colours));
        else
          ok = CGAL::IO::write_OFF(out, drawn, np);
        break;
      case Mesh_format::obj: // the holes stay, tagged
        write_obj(mesh, out, tags, face_varying);
        break;
      case Mesh_format::ply:
        if(binary)
          CGAL::IO::set_binary_mode(out);
        ok = CGAL::IO::write_PLY(out, drawn, np);
        break;
      case Mesh_format::stl:
        // STL holds triangles only: split the faces of a copy
        if(CGAL::is_triangle_mesh(drawn)) {
          write_stl(drawn, out, binary, path);
        } else {
          Surface triangles = drawn;
          CGAL::Polygon_mesh_processing::triangulate_faces(triangles);
          write_stl(triangles, out, binary, path);
        }
        break;
    }
  }
  if(!ok)
    throw Input_error("cannot write '" + path + "' as " + mesh_format_name(format));
  file.commit();
}

double predicted_faces(const Surface_scheme& scheme, double faces, int levels)
{
  return faces * std::pow(scheme.face_growth, levels);
}

void check_output_size(const Surface_scheme& scheme, const Surface& mesh, int levels, double max_memory)
{
  CGAL::Subdiv::internal::check_output_faces(scheme.name, static_cast<double>(mesh.number_of_faces()),
                                             scheme.face_growth, scheme.bytes_per_face, levels, max_memory,
                                             "--max-memory raises it");
}

void refuse_tags_unless_taken(const Surface_scheme& scheme, const Sharp_options* tags)
{
  if(tags != nullptr && !scheme.run_sharp)
    throw Input_error(
      "--scheme " + scheme.name +
      " does not take OpenSubdiv's crease, corner and boundary tags yet, nor --sharp-angle and the boundary "
      "options (loop, loop-warren, catmull-clark, linear, butterfly, modified-butterfly, sqrt3 and "
      "interpolating-sqrt3 do)");
}

Surface_result subdivide_surface(Surface& mesh, const Surface_scheme& scheme, int levels, double max_memory,
                                 const Level_callback& on_level, const Sharp_options* tags)
{
  refuse_tags_unless_taken(scheme, tags);
  const auto run = [&](int n) {
    if(tags != nullptr)
      scheme.run_sharp(mesh, n, max_memory, *tags);
    else
      scheme.run(mesh, n, max_memory);
  };
  Surface_result result;
  result.in = counts(mesh);
  // refuse before any work (the library would refuse too, level by level)
  check_output_size(scheme, mesh, levels, max_memory);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  if(on_level && scheme.level_by_level && levels > 1) {
    for(int level = 1; level <= levels; ++level) {
      run(1);
      on_level(level, counts(mesh), seconds());
    }
  } else {
    run(levels);
    if(on_level && levels > 0)
      on_level(levels, counts(mesh), seconds());
  }
  result.seconds = seconds();
  result.out = counts(mesh);
  return result;
}

} // namespace cgal_subdiv
