// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "surface_tags.h"

#include "errors.h"

#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <limits>

namespace cgal_subdiv {

const char* const edge_sharpness_name = "e:sharpness";
const char* const vertex_sharpness_name = "v:sharpness";

namespace {

using Edge_map = Surface::Property_map<Surface::Edge_index, double>;
using Vertex_map = Surface::Property_map<Surface::Vertex_index, double>;

// "FILE:LINE: tag NAME: " for the messages
std::string where(const std::string& path, const Obj_tag& tag)
{
  return "'" + path + "' line " + std::to_string(tag.line) + ": tag '" + tag.name + "': ";
}

// the sharpness values of a tag with `items` items: one for all, or one each
std::vector<double> sharpness_values(const Obj_tag& tag, std::size_t items, const std::string& at)
{
  if(!tag.strings.empty())
    throw Input_error(at + "takes no strings");
  if(tag.floats.size() != 1 && tag.floats.size() != items)
    throw Input_error(at + "needs one sharpness, or one per item (" + std::to_string(items) + "), not " +
                      std::to_string(tag.floats.size()));
  std::vector<double> values;
  for(std::size_t k = 0; k < items; ++k) {
    const double s = tag.floats.size() == 1 ? tag.floats[0] : tag.floats[k];
    if(!(s >= 0))
      throw Input_error(at + "the sharpness " + std::to_string(s) + " is negative or NaN");
    values.push_back(s);
  }
  return values;
}

class Tag_reader
{
public:
  Tag_reader(Surface& mesh, std::size_t file_vertices, const std::vector<std::size_t>& file_numbers,
             const std::string& path)
    : m_mesh(mesh), m_path(path), m_vertex_of(file_vertices, Surface::null_vertex())
  {
    for(Surface::Vertex_index v : mesh.vertices())
      if(v.idx() < file_numbers.size() && file_numbers[v.idx()] >= 1 && file_numbers[v.idx()] <= file_vertices)
        m_vertex_of[file_numbers[v.idx()] - 1] = v;
  }

  void crease(const Obj_tag& tag)
  {
    const std::string at = where(m_path, tag);
    if(tag.ints.empty() || tag.ints.size() % 2 != 0)
      throw Input_error(at + "needs pairs of vertices, got " + std::to_string(tag.ints.size()) + " numbers");
    const std::vector<double> values = sharpness_values(tag, tag.ints.size() / 2, at);
    Edge_map edges = m_mesh.add_property_map<Surface::Edge_index, double>(edge_sharpness_name, 0).first;
    for(std::size_t k = 0; k < values.size(); ++k) {
      const Surface::Vertex_index a = vertex(tag.ints[2 * k], at), b = vertex(tag.ints[2 * k + 1], at);
      const Surface::Halfedge_index h = m_mesh.halfedge(a, b);
      if(h == Surface::null_halfedge())
        throw Input_error(at + "vertices " + std::to_string(tag.ints[2 * k]) + " and " +
                          std::to_string(tag.ints[2 * k + 1]) + " are not joined by an edge of the mesh");
      edges[m_mesh.edge(h)] = values[k];
    }
  }

  void corner(const Obj_tag& tag)
  {
    const std::string at = where(m_path, tag);
    if(tag.ints.empty())
      throw Input_error(at + "needs at least one vertex");
    const std::vector<double> values = sharpness_values(tag, tag.ints.size(), at);
    Vertex_map vertices = m_mesh.add_property_map<Surface::Vertex_index, double>(vertex_sharpness_name, 0).first;
    for(std::size_t k = 0; k < values.size(); ++k)
      vertices[vertex(tag.ints[k], at)] = values[k];
  }

private:
  Surface::Vertex_index vertex(long long number, const std::string& at) const
  {
    if(number < 0 || static_cast<unsigned long long>(number) >= m_vertex_of.size())
      throw Input_error(at + "vertex " + std::to_string(number) + " is out of range (the file has " +
                        std::to_string(m_vertex_of.size()) + " vertices, numbered from 0 in tags)");
    const Surface::Vertex_index v = m_vertex_of[static_cast<std::size_t>(number)];
    if(v == Surface::null_vertex())
      throw Input_error(at + "vertex " + std::to_string(number) + " is in no face");
    return v;
  }

  Surface& m_mesh;
  const std::string& m_path;
  std::vector<Surface::Vertex_index> m_vertex_of; // by file vertex, from 0
};

// the single integer of `t NAME 1/0/0 N`, or the single string of `t NAME 0/0/1 S`
void require_one_value(const Obj_tag& tag, bool integer, const std::string& at)
{
  const bool ok = integer ? tag.ints.size() == 1 && tag.floats.empty() && tag.strings.empty()
                          : tag.strings.size() == 1 && tag.ints.empty() && tag.floats.empty();
  if(!ok)
    throw Input_error(at + (integer ? "needs one integer" : "needs one string"));
}

} // namespace

Sharp_options apply_obj_tags(const std::vector<Obj_tag>& tags, std::size_t file_vertices, Surface& mesh,
                             const std::vector<std::size_t>& file_numbers, const std::string& path,
                             std::vector<std::string>& notes)
{
  Sharp_options options;
  Tag_reader reader(mesh, file_vertices, file_numbers, path);
  std::size_t ignored = 0;
  for(const Obj_tag& tag : tags) {
    const std::string at = where(path, tag);
    if(tag.name == "crease") {
      reader.crease(tag);
    } else if(tag.name == "corner") {
      reader.corner(tag);
    } else if(tag.name == "interpolateboundary") {
      require_one_value(tag, true, at);
      if(tag.ints[0] < 0 || tag.ints[0] > 2)
        throw Input_error(at + "is 0 (none), 1 (edges and corners) or 2 (edges only), not " +
                          std::to_string(tag.ints[0]));
      options.border = tag.ints[0] == 1 ? CGAL::Subdiv::Border_corners::sharp : CGAL::Subdiv::Border_corners::smooth;
      if(tag.ints[0] == 0)
        notes.push_back(at + "boundary interpolation 'none' is refined as 'edges only'");
    } else if(tag.name == "creasemethod") {
      require_one_value(tag, false, at);
      if(tag.strings[0] != "normal" && tag.strings[0] != "chaikin")
        throw Input_error(at + "is 'normal' or 'chaikin', not '" + tag.strings[0] + "'");
      options.method =
        tag.strings[0] == "chaikin" ? CGAL::Subdiv::Crease_method::chaikin : CGAL::Subdiv::Crease_method::uniform;
    } else {
      ++ignored;
      continue;
    }
    options.present = true;
  }
  if(ignored > 0)
    notes.push_back("ignored " + std::to_string(ignored) + (ignored == 1 ? " tag line" : " tag lines") + " of '" +
                    path + "' (only crease, corner, interpolateboundary and creasemethod are read)");
  return options;
}

bool has_sharpness(const Surface& mesh)
{
  return mesh.property_map<Surface::Edge_index, double>(edge_sharpness_name).second ||
         mesh.property_map<Surface::Vertex_index, double>(vertex_sharpness_name).second;
}

void write_obj_tags(std::ostream& out, const Surface& mesh, const Sharp_options& options)
{
  out.precision(17); // the values are floats in doubles (views/Sharpness.h): read back, they are the same
  out << "t interpolateboundary 1/0/0 " << (options.border == CGAL::Subdiv::Border_corners::sharp ? 1 : 2) << '\n';
  out << "t creasemethod 0/0/1 " << (options.method == CGAL::Subdiv::Crease_method::chaikin ? "chaikin" : "normal")
      << '\n';
  const auto edges = mesh.property_map<Surface::Edge_index, double>(edge_sharpness_name);
  if(edges.second)
    for(Surface::Edge_index e : mesh.edges())
      if(edges.first[e] > 0 && !mesh.is_border(e))
        out << "t crease 2/1/0 " << mesh.source(mesh.halfedge(e)).idx() << ' ' << mesh.target(mesh.halfedge(e)).idx()
            << ' ' << edges.first[e] << '\n';
  const auto vertices = mesh.property_map<Surface::Vertex_index, double>(vertex_sharpness_name);
  if(vertices.second)
    for(Surface::Vertex_index v : mesh.vertices())
      if(vertices.first[v] > 0)
        out << "t corner 1/1/0 " << v.idx() << ' ' << vertices.first[v] << '\n';
}

} // namespace cgal_subdiv
