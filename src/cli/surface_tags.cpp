// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "surface_tags.h"

#include "errors.h"

#include <CGAL/Subdiv/mark_sharp_edges.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cgal_subdiv {

namespace {

// the boundary mode of each `t interpolateboundary` value (RenderMan's numbering), for reading and writing
constexpr std::array<CGAL::Subdiv::Boundary_interpolation, 3> interpolateboundary_modes = {
  CGAL::Subdiv::Boundary_interpolation::none, CGAL::Subdiv::Boundary_interpolation::edges_and_corners,
  CGAL::Subdiv::Boundary_interpolation::edges_only};

using Edge_map = Surface::Property_map<Surface::Edge_index, double>;
using Vertex_map = Surface::Property_map<Surface::Vertex_index, double>;
using Hole_map = Surface::Property_map<Surface::Face_index, bool>;

// "FILE:LINE: tag NAME: " for the messages
std::string where(const std::string& path, const Obj_tag& tag)
{
  return "'" + path + "' line " + std::to_string(tag.line) + ": tag '" + tag.name + "': ";
}

// the sharpness values of a tag with `items` items: one for all, or one each;
// semi-sharp ones refused when `semi_sharp_refused_by` names a scheme
std::vector<double> sharpness_values(const Obj_tag& tag, std::size_t items, const std::string& at,
                                     const std::string& semi_sharp_refused_by)
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
    if(!semi_sharp_refused_by.empty() && CGAL::Subdiv::internal::Crease_rules<double>::is_semi_sharp(s))
      throw Input_error(at + "the sharpness " + std::to_string(s) + " is semi-sharp: --scheme " +
                        semi_sharp_refused_by + " takes 0 or 10 and above only (infinitely sharp creases and corners)");
    values.push_back(s);
  }
  return values;
}

class Tag_reader
{
public:
  Tag_reader(Surface& mesh, std::size_t file_vertices, const std::vector<std::size_t>& file_numbers,
             const std::string& path, const std::string& semi_sharp_refused_by)
    : m_mesh(mesh), m_path(path), m_semi_sharp_refused_by(semi_sharp_refused_by), m_copies_of(file_vertices)
  {
    for(Surface::Vertex_index v : mesh.vertices())
      if(v.idx() < file_numbers.size() && file_numbers[v.idx()] >= 1 && file_numbers[v.idx()] <= file_vertices)
        m_copies_of[file_numbers[v.idx()] - 1].push_back(v);
  }

  void crease(const Obj_tag& tag)
  {
    const std::string at = where(m_path, tag);
    if(tag.ints.empty() || tag.ints.size() % 2 != 0)
      throw Input_error(at + "needs pairs of vertices, got " + std::to_string(tag.ints.size()) + " numbers");
    const std::vector<double> values = sharpness_values(tag, tag.ints.size() / 2, at, m_semi_sharp_refused_by);
    Edge_map edges = m_mesh.add_property_map<Surface::Edge_index, double>(edge_sharpness_name, 0).first;
    for(std::size_t k = 0; k < values.size(); ++k) {
      bool joined = false; // by one edge, or by several between the copies of a split vertex
      for(const Surface::Vertex_index a : copies(tag.ints[2 * k], at))
        for(const Surface::Vertex_index b : copies(tag.ints[2 * k + 1], at)) {
          const Surface::Halfedge_index h = m_mesh.halfedge(a, b);
          if(h != Surface::null_halfedge()) {
            edges[m_mesh.edge(h)] = std::max(edges[m_mesh.edge(h)], values[k]);
            joined = true;
          }
        }
      if(!joined)
        throw Input_error(at + "vertices " + std::to_string(tag.ints[2 * k]) + " and " +
                          std::to_string(tag.ints[2 * k + 1]) + " are not joined by an edge of the mesh");
    }
  }

  void corner(const Obj_tag& tag)
  {
    const std::string at = where(m_path, tag);
    if(tag.ints.empty())
      throw Input_error(at + "needs at least one vertex");
    const std::vector<double> values = sharpness_values(tag, tag.ints.size(), at, m_semi_sharp_refused_by);
    Vertex_map vertices = m_mesh.add_property_map<Surface::Vertex_index, double>(vertex_sharpness_name, 0).first;
    for(std::size_t k = 0; k < values.size(); ++k)
      for(const Surface::Vertex_index v : copies(tag.ints[k], at))
        vertices[v] = std::max(vertices[v], values[k]);
  }

  // faces numbered from 0 in the order of the file, which is the mesh's
  void hole(const Obj_tag& tag)
  {
    const std::string at = where(m_path, tag);
    if(tag.ints.empty() || !tag.floats.empty() || !tag.strings.empty())
      throw Input_error(at + "needs one or more faces, and nothing else");
    Hole_map holes = m_mesh.add_property_map<Surface::Face_index, bool>(face_hole_name, false).first;
    for(long long number : tag.ints) {
      if(number < 0 || static_cast<unsigned long long>(number) >= m_mesh.number_of_faces())
        throw Input_error(at + "face " + std::to_string(number) + " is out of range (the mesh has " +
                          std::to_string(m_mesh.number_of_faces()) + " faces, numbered from 0 in tags)");
      holes[Surface::Face_index(static_cast<Surface::size_type>(number))] = true;
    }
  }

private:
  // the vertex of file vertex `number` (from 0), or its copies if the soup was split
  const std::vector<Surface::Vertex_index>& copies(long long number, const std::string& at) const
  {
    if(number < 0 || static_cast<unsigned long long>(number) >= m_copies_of.size())
      throw Input_error(at + "vertex " + std::to_string(number) + " is out of range (the file has " +
                        std::to_string(m_copies_of.size()) + " vertices, numbered from 0 in tags)");
    const std::vector<Surface::Vertex_index>& copies = m_copies_of[static_cast<std::size_t>(number)];
    if(copies.empty())
      throw Input_error(at + "vertex " + std::to_string(number) + " is in no face");
    return copies;
  }

  Surface& m_mesh;
  const std::string& m_path;
  const std::string& m_semi_sharp_refused_by;
  std::vector<std::vector<Surface::Vertex_index>> m_copies_of; // by file vertex, from 0
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
                             std::vector<std::string>& notes, const std::string& semi_sharp_refused_by)
{
  Sharp_options options;
  Tag_reader reader(mesh, file_vertices, file_numbers, path, semi_sharp_refused_by);
  std::size_t ignored = 0;
  const Obj_tag* propagate_corners = nullptr;
  for(const Obj_tag& tag : tags) {
    const std::string at = where(path, tag);
    if(tag.name == "facevaryinginterpolateboundary") { // not a tag of the geometry: `present` stays
      require_one_value(tag, true, at);
      if(tag.ints[0] < 0 || tag.ints[0] > 5)
        throw Input_error(at + "is 0 (none), 1 (corners only), 2 (corners plus1), 3 (corners plus2), " +
                          "4 (boundaries) or 5 (all), not " + std::to_string(tag.ints[0]));
      options.face_varying = static_cast<CGAL::Subdiv::Face_varying_interpolation>(tag.ints[0]);
      continue;
    }
    if(tag.name == "facevaryingpropagatecorners") {
      require_one_value(tag, true, at);
      if(tag.ints[0] != 0 && tag.ints[0] != 1)
        throw Input_error(at + "is 0 or 1, not " + std::to_string(tag.ints[0]));
      propagate_corners = tag.ints[0] == 1 ? &tag : nullptr;
      continue;
    }
    if(tag.name == "crease") {
      reader.crease(tag);
    } else if(tag.name == "corner") {
      reader.corner(tag);
    } else if(tag.name == "hole") {
      reader.hole(tag);
    } else if(tag.name == "interpolateboundary") {
      require_one_value(tag, true, at);
      if(tag.ints[0] < 0 || tag.ints[0] > 2)
        throw Input_error(at + "is 0 (none), 1 (edges and corners) or 2 (edges only), not " +
                          std::to_string(tag.ints[0]));
      options.boundary = interpolateboundary_modes[static_cast<std::size_t>(tag.ints[0])];
    } else if(tag.name == "creasemethod") {
      require_one_value(tag, false, at);
      if(tag.strings[0] != "normal" && tag.strings[0] != "chaikin")
        throw Input_error(at + "is 'normal' or 'chaikin', not '" + tag.strings[0] + "'");
      options.method =
        tag.strings[0] == "chaikin" ? CGAL::Subdiv::Crease_method::chaikin : CGAL::Subdiv::Crease_method::uniform;
    } else if(tag.name == "smoothtriangles") {
      require_one_value(tag, false, at);
      if(tag.strings[0] != "catmark" && tag.strings[0] != "smooth")
        throw Input_error(at + "is 'catmark' or 'smooth', not '" + tag.strings[0] + "'");
      options.triangles = tag.strings[0] == "smooth" ? CGAL::Subdiv::Triangle_subdivision::smooth
                                                     : CGAL::Subdiv::Triangle_subdivision::catmark;
    } else {
      ++ignored;
      continue;
    }
    options.present = true;
  }
  // Hbr's "propagate corners" went with its "edge and corner" mode only, which
  // is corners plus1; with it, that is corners plus2 (OpenSubdiv's
  // compatibility notes); with the other modes Hbr ignored it
  using Fvar = CGAL::Subdiv::Face_varying_interpolation;
  if(propagate_corners != nullptr && options.face_varying == Fvar::corners_plus1)
    options.face_varying = Fvar::corners_plus2;
  else if(propagate_corners != nullptr)
    notes.push_back(where(path, *propagate_corners) + "ignored: it applies to facevaryinginterpolateboundary 2 " +
                    "(corners plus1) only, which it makes corners plus2, and the mode is " +
                    face_varying_keywords()[static_cast<std::size_t>(options.face_varying)]);
  if(ignored > 0)
    notes.push_back("ignored " + std::to_string(ignored) + (ignored == 1 ? " tag line" : " tag lines") + " of '" +
                    path +
                    "' (only crease, corner, hole, interpolateboundary, creasemethod, smoothtriangles, "
                    "facevaryinginterpolateboundary and facevaryingpropagatecorners are read)");
  return options;
}

// the tag's numbers are the enum's order, as OpenSubdiv's are Sdc's
static_assert(static_cast<int>(CGAL::Subdiv::Face_varying_interpolation::none) == 0 &&
              static_cast<int>(CGAL::Subdiv::Face_varying_interpolation::all) == 5);

const std::vector<std::string>& face_varying_keywords()
{
  static const std::vector<std::string> keywords = {"none",          "corners-only", "corners-plus1",
                                                    "corners-plus2", "boundaries",   "all"};
  return keywords;
}

CGAL::Subdiv::Face_varying_interpolation face_varying_mode(const std::string& keyword)
{
  const std::vector<std::string>& keywords = face_varying_keywords();
  const auto found = std::find(keywords.begin(), keywords.end(), keyword);
  if(found == keywords.end())
    throw Usage_error("--fvar is none, corners-only, corners-plus1, corners-plus2, boundaries or all, not '" + keyword +
                      "'");
  return static_cast<CGAL::Subdiv::Face_varying_interpolation>(found - keywords.begin());
}

void write_obj_face_varying_tag(std::ostream& out, CGAL::Subdiv::Face_varying_interpolation mode)
{
  out << "t facevaryinginterpolateboundary 1/0/0 " << static_cast<int>(mode) << '\n';
}

std::size_t mark_sharp_angle(Surface& mesh, double angle_in_degrees)
{
  const Edge_map edges = mesh.add_property_map<Surface::Edge_index, double>(edge_sharpness_name, 0).first;
  return CGAL::Subdiv::mark_sharp_edges(mesh, angle_in_degrees, edges);
}

bool has_sharpness(const Surface& mesh)
{
  return mesh.property_map<Surface::Edge_index, double>(edge_sharpness_name).second ||
         mesh.property_map<Surface::Vertex_index, double>(vertex_sharpness_name).second;
}

std::optional<Surface> without_holes(const Surface& mesh)
{
  if(!mesh.property_map<Surface::Face_index, bool>(face_hole_name).second)
    return std::nullopt;
  Surface copy = mesh;
  const auto holes = copy.property_map<Surface::Face_index, bool>(face_hole_name);
  std::vector<Surface::Face_index> hole_faces;
  for(Surface::Face_index f : copy.faces())
    if(holes.first[f])
      hole_faces.push_back(f);
  for(Surface::Face_index f : hole_faces)
    CGAL::Euler::remove_face(copy.halfedge(f), copy);
  copy.collect_garbage();
  return copy;
}

void write_obj_tags(std::ostream& out, const Surface& mesh, const Sharp_options& options)
{
  out.precision(17); // the values are floats in doubles (views/Sharpness.h): read back, they are the same
  const auto mode = std::find(interpolateboundary_modes.begin(), interpolateboundary_modes.end(), options.boundary);
  out << "t interpolateboundary 1/0/0 " << (mode - interpolateboundary_modes.begin()) << '\n';
  out << "t creasemethod 0/0/1 " << (options.method == CGAL::Subdiv::Crease_method::chaikin ? "chaikin" : "normal")
      << '\n';
  if(options.triangles == CGAL::Subdiv::Triangle_subdivision::smooth)
    out << "t smoothtriangles 0/0/1 smooth\n";
  const auto holes = mesh.property_map<Surface::Face_index, bool>(face_hole_name);
  if(holes.second)
    for(Surface::Face_index f : mesh.faces())
      if(holes.first[f])
        out << "t hole 1/0/0 " << f.idx() << '\n';
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
