// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_INHERITED_FACE_MAP_H
#define CGAL_SUBDIV_REFINEMENT_INHERITED_FACE_MAP_H

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * A sink of `refine_level` (refinement/refine_level.h) that gives every new
 * face the value of its parent in a face property map: the values of the old
 * faces are read before the level (by ordinal, in the iteration order of
 * `faces(mesh)`), and written to the new faces after it. Carried face data
 * (`Carried_data::face_map`) and the hole tags go through it.
 */
template <class Mesh, class FaceMap>
class Inherited_face_map
{
public:
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  using Value = typename boost::property_traits<FaceMap>::value_type;

  Inherited_face_map(const Mesh& mesh, FaceMap map) : m_mesh(&mesh), m_map(map) {}

  /// reads the values of the old faces
  template <class Host, class Mask, class Loop>
  void read(const Host&, const Mask&, const Loop&)
  {
    read_old_values();
  }

  void read_old_values()
  {
    m_old.clear();
    for(face_descriptor f : faces(*m_mesh))
      m_old.push_back(get(m_map, f));
  }

  template <class Level>
  void write(const Level& level) const
  {
    write_new_values(level.elements().faces, level.parents());
  }

  /// new face k gets the value of old face `parents[k]`
  void write_new_values(const std::vector<face_descriptor>& new_faces, const std::vector<std::size_t>& parents) const
  {
    for(std::size_t k = 0; k < new_faces.size(); ++k)
      put(m_map, new_faces[k], m_old[parents[k]]);
  }

private:
  const Mesh* m_mesh;
  FaceMap m_map;
  std::vector<Value> m_old;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_INHERITED_FACE_MAP_H
