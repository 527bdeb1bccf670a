// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_POINT_SUMS_H
#define CGAL_SUBDIV_REFINEMENT_POINT_SUMS_H

/// \file point_sums.h
/// The point accumulators of the surface masks: a mask reports (vertex,
/// weight) pairs, these sum weight * (point - ORIGIN) and make one point.

#include <CGAL/Subdiv/internal/points.h>

#include <CGAL/Origin.h>
#include <CGAL/property_map.h>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// any kernel, any vertex point map: one vector sum
template <class VertexPointMap>
class Mesh_point_sum
{
public:
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using FT = Point_FT<Point>;

  explicit Mesh_point_sum(const VertexPointMap& vpm) : m_vpm(vpm), m_sum(CGAL::NULL_VECTOR) {}

  template <class VertexDescriptor>
  void add(VertexDescriptor v, const FT& weight)
  {
    m_sum = m_sum + (get(m_vpm, v) - CGAL::ORIGIN) * weight;
  }

  Point point() const { return CGAL::ORIGIN + m_sum; }

private:
  const VertexPointMap& m_vpm;
  Point_vector<Point> m_sum;
};

/*
 * The accumulator of the fast path, for 3D points with double coordinates
 * (Simple_cartesian<double>, Epick) stored in one array (a Surface_mesh
 * point map): sums weight * coordinate in three doubles, in the order and
 * with the operations of `Mesh_point_sum`, so the points are the same bit
 * for bit.
 */
template <class Point>
class Flat_point_sum
{
public:
  explicit Flat_point_sum(const Point* points) : m_points(points) {}

  template <class VertexIndex>
  void add(VertexIndex v, double weight)
  {
    const Point& p = m_points[v.idx()];
    m_x = m_x + p.x() * weight;
    m_y = m_y + p.y() * weight;
    m_z = m_z + p.z() * weight;
  }

  Point point() const { return Point(m_x, m_y, m_z); }

private:
  const Point* m_points;
  double m_x = 0, m_y = 0, m_z = 0;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_POINT_SUMS_H
