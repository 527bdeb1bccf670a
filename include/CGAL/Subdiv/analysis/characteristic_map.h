// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CHARACTERISTIC_MAP_H
#define CGAL_SUBDIV_ANALYSIS_CHARACTERISTIC_MAP_H

// The characteristic-map test of the surface analysis: the subdominant
// eigenvectors as a planar net over rings of the neighbourhood, tested for
// regularity and injectivity, with the extended spectrum on the way.

#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/curve_analysis.h> // sort_eigenvalues
#include <CGAL/Subdiv/analysis/surface_neighbourhood.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/assertions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The verdict of the characteristic-map test (see `analyse_surface_scheme()`).
 */
enum class Characteristic_map_verdict {
  regular_injective, ///< regular and injective: with the eigenvalue conditions, C1
  not_regular,       ///< some face of the refined ring flips (or degenerates)
  not_injective,     ///< regular, but the ring overlaps itself (winding number != 1)
  not_applicable     ///< no subdominant pair to build the map from
};

/// the name used in reports: "regular_injective", "not_regular", "not_injective", "not_applicable"
inline std::string to_string(Characteristic_map_verdict verdict)
{
  switch(verdict) {
    case Characteristic_map_verdict::regular_injective:
      return "regular_injective";
    case Characteristic_map_verdict::not_regular:
      return "not_regular";
    case Characteristic_map_verdict::not_injective:
      return "not_injective";
    default:
      return "not_applicable";
  }
}

namespace internal {

// what the analysis computes, from its named parameters (`analyse_surface_scheme()`)
struct Surface_analysis_options
{
  /// the extended spectrum and the characteristic map (steps 4 to 6; the
  /// costliest: an eigen-solve on about twice the rings); without them the
  /// verdict `c1` stays false
  bool extended_spectrum = true;
  /// test the characteristic map
  bool characteristic_map = true;
  /// subdivide a random neighbourhood and compare its limit with the limit mask
  bool verify_limit = true;
  /// the characteristic-map and verification meshes stop growing at this many faces
  std::size_t max_faces = 120000;
  /// seed of the random neighbourhood of the verification
  unsigned seed = 20260;
};

} // namespace internal

namespace internal {

inline void canonical_pair(Eigen::VectorXd& a, Eigen::VectorXd& b)
{
  if(a.norm() == 0 || a.size() < 3)
    return;
  a.normalize();
  b = b - a.dot(b) * a;
  if(b.norm() == 0)
    return;
  b.normalize();
  const double x = a[1], y = b[1], r = std::hypot(x, y);
  if(r > 1e-12) {
    const Eigen::VectorXd first = (x * a + y * b) / r;
    const Eigen::VectorXd second = (-y * a + x * b) / r;
    a = first;
    b = second;
  }
  if(b[2] < 0)
    b = -b;
}

using Point_2d = std::array<double, 2>;

struct Annulus_test
{
  Characteristic_map_verdict verdict = Characteristic_map_verdict::not_applicable;
  int inner = 0, outer = 0;
};

// regularity and injectivity of the planar net over the rings [inner, outer]
inline Annulus_test test_annulus(const Analysis_mesh& mesh, const std::vector<int>& ring_of_vertex, int inner,
                                 int outer, bool border)
{
  using EK = CGAL::Exact_predicates_inexact_constructions_kernel;
  Annulus_test result;
  result.inner = inner;
  result.outer = outer;
  const auto point = [&](Analysis_vertex v) -> Point_2d {
    const auto& p = mesh.point(v);
    return {p.x(), p.y()};
  };
  std::vector<char> in_annulus(mesh.number_of_faces(), 0);
  double scale = 0;
  std::vector<Analysis_face> faces;
  for(Analysis_face f : mesh.faces()) {
    bool inside = true;
    for(Analysis_vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const int r = ring_of_vertex[v.idx()];
      inside = inside && r >= inner && r <= outer;
    }
    if(!inside)
      continue;
    in_annulus[f.idx()] = 1;
    faces.push_back(f);
    for(Analysis_vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const Point_2d p = point(v);
      scale = (std::max)(scale, p[0] * p[0] + p[1] * p[1]);
    }
  }
  if(faces.empty() || scale == 0)
    return result;
  // regular: every corner of every face turns the same way (strictly convex faces, one orientation)
  int sign = 0;
  for(Analysis_face f : faces) {
    std::vector<Point_2d> corners;
    for(Analysis_vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners.push_back(point(v));
    const std::size_t m = corners.size();
    for(std::size_t k = 0; k < m; ++k) {
      const Point_2d& a = corners[(k + m - 1) % m];
      const Point_2d& b = corners[k];
      const Point_2d& c = corners[(k + 1) % m];
      const double cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
      if(std::abs(cross) <= 1e-12 * scale) {
        result.verdict = Characteristic_map_verdict::not_regular;
        return result;
      }
      const int s = cross > 0 ? 1 : -1;
      if(sign == 0)
        sign = s;
      if(s != sign) {
        result.verdict = Characteristic_map_verdict::not_regular;
        return result;
      }
    }
  }
  // boundary of the annulus: halfedges whose face is in it and whose opposite's is not
  std::vector<Analysis_halfedge> boundary;
  std::map<Analysis_vertex, Analysis_halfedge> leaving;
  bool pinched = false;
  for(Analysis_face f : faces)
    for(Analysis_halfedge h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Analysis_face g = mesh.face(mesh.opposite(h));
      if(g != Analysis_mesh::null_face() && in_annulus[g.idx()])
        continue;
      boundary.push_back(h);
      pinched = pinched || !leaving.emplace(mesh.source(h), h).second;
    }
  if(pinched) {
    result.verdict = Characteristic_map_verdict::not_injective;
    return result;
  }
  // no two boundary segments meet, except consecutive ones at their common vertex
  std::vector<EK::Segment_2> segments;
  std::vector<CGAL::Bbox_2> boxes;
  for(Analysis_halfedge h : boundary) {
    const Point_2d p = point(mesh.source(h)), q = point(mesh.target(h));
    segments.emplace_back(EK::Point_2(p[0], p[1]), EK::Point_2(q[0], q[1]));
    boxes.push_back(segments.back().bbox());
  }
  for(std::size_t i = 0; i < boundary.size(); ++i)
    for(std::size_t j = i + 1; j < boundary.size(); ++j) {
      if(!CGAL::do_overlap(boxes[i], boxes[j]))
        continue;
      const Analysis_vertex a = mesh.source(boundary[i]), b = mesh.target(boundary[i]);
      const Analysis_vertex c = mesh.source(boundary[j]), d = mesh.target(boundary[j]);
      if(a == c || a == d || b == c || b == d)
        continue;
      if(CGAL::do_intersect(segments[i], segments[j])) {
        result.verdict = Characteristic_map_verdict::not_injective;
        return result;
      }
    }
  // loops and their winding numbers around the origin (the image of the centre)
  std::vector<int> windings;
  std::vector<double> areas;
  std::map<Analysis_vertex, char> used;
  for(Analysis_halfedge first : boundary) {
    if(used[mesh.source(first)])
      continue;
    double angle = 0, area = 0;
    Analysis_halfedge h = first;
    std::size_t steps = 0;
    do {
      used[mesh.source(h)] = 1;
      const Point_2d p = point(mesh.source(h)), q = point(mesh.target(h));
      angle += std::atan2(p[0] * q[1] - p[1] * q[0], p[0] * q[0] + p[1] * q[1]);
      area += p[0] * q[1] - p[1] * q[0];
      const auto next_edge = leaving.find(mesh.target(h));
      if(next_edge == leaving.end() || ++steps > boundary.size()) {
        result.verdict = Characteristic_map_verdict::not_injective;
        return result;
      }
      h = next_edge->second;
    } while(h != first);
    windings.push_back(static_cast<int>(std::lround(angle / (2 * 3.14159265358979323846))));
    areas.push_back(area);
  }
  bool injective = false;
  if(border) // one simple loop around the sector annulus, oriented as the faces
    injective = windings.size() == 1 && areas[0] * sign > 0;
  else // an outer loop around the origin as the faces turn, an inner one against
    injective = windings.size() == 2 &&
                ((windings[0] == sign && windings[1] == -sign) || (windings[0] == -sign && windings[1] == sign));
  result.verdict =
    injective ? Characteristic_map_verdict::regular_injective : Characteristic_map_verdict::not_injective;
  return result;
}

// rings of every vertex of a mesh from the centre given by `start`
inline std::vector<int> rings_of_vertices(const Analysis_mesh& mesh, Analysis_halfedge start, bool face_centred)
{
  const Labelling labels = label_neighbourhood(mesh, start, face_centred, (std::numeric_limits<int>::max)() - 1);
  std::vector<int> result(mesh.number_of_vertices(), (std::numeric_limits<int>::max)());
  for(std::size_t i = 0; i < labels.size(); ++i)
    result[labels.vertex_of[i].idx()] = labels.ring[i];
  return result;
}

// returns false when the refined net's part that the patch border has not
// reached stays under 6 rings: a larger neighbourhood is needed (schemes with
// wide stencils, e.g. interpolating sqrt3, lose rings to the patch border
// faster than the refinement adds them)
template <class DoubleMask, class Result>
bool characteristic_map_with_rings(const DoubleMask& mask, Result& result,
                                   const internal::Surface_analysis_options& options, int big)
{
  using Traits = Host_of<DoubleMask>;
  const std::complex<double> lambda = result.subdominant, lambda2 = result.second_subdominant;
  const bool complex_pair = std::abs(lambda.imag()) > 1e-12;
  const std::complex<double> other = complex_pair ? std::conj(lambda) : lambda2;
  result.extended_rings = big;
  result.characteristic_map = Characteristic_map_verdict::not_applicable;
  result.characteristic_map_levels = result.annulus_inner = result.annulus_outer = 0;
  const auto extended = local_matrix_of_rings(mask, result.configuration, big);
  require(extended.invariant, "the extended neighbourhood is not invariant");
  const Eigen::MatrixXd S = extended.S;
  Eigen::EigenSolver<Eigen::MatrixXd> solver(S, true);
  if(solver.info() != Eigen::Success)
    return true;
  // the extended spectrum
  const double tol = 1e-9;
  int ones = 0, near_pair = 0;
  std::vector<Eigen::Index> pair;
  result.extended_largest_other = 0;
  for(Eigen::Index i = 0; i < S.rows(); ++i) {
    const std::complex<double> mu = solver.eigenvalues()[i];
    if(std::abs(mu - 1.0) < 1e-8) {
      ++ones;
    } else if(std::abs(mu - lambda) < 1e-7 || std::abs(mu - other) < 1e-7) {
      ++near_pair;
      pair.push_back(i);
    } else {
      result.extended_largest_other = (std::max)(result.extended_largest_other, std::abs(mu));
    }
  }
  result.extended_spectrum_ok =
    ones == 1 && near_pair == 2 && result.extended_largest_other < (std::min)(std::abs(lambda), std::abs(other)) - tol;
  if(!result.c1_necessary && !complex_pair && !(result.subdominant_multiplicity == 2))
    return true; // no pair to build the map from
  if(near_pair != 2 || !options.characteristic_map)
    return true;
  // the two real vectors spanning the subdominant eigenspace: for a real
  // eigenvalue the right singular vectors of the smallest singular values of
  // S - lambda I (two for a double eigenvalue: both ~0 unless it is
  // defective); for a complex one the real and imaginary parts of its eigenvector
  const auto kernel = [&](double value, int dimension, Eigen::VectorXd* first, Eigen::VectorXd* second) -> bool {
    const Eigen::MatrixXd shifted = S - value * Eigen::MatrixXd::Identity(S.rows(), S.cols());
    Eigen::BDCSVD<Eigen::MatrixXd> svd(shifted, Eigen::ComputeFullV);
    const Eigen::Index last = S.rows() - 1;
    if(!(svd.singularValues()[last - (dimension - 1)] < 1e-7 * (1 + svd.singularValues()[0])))
      return false;
    *first = svd.matrixV().col(last);
    if(second)
      *second = svd.matrixV().col(last - 1);
    return true;
  };
  Eigen::VectorXd x, y;
  if(complex_pair) {
    const Eigen::VectorXcd v = solver.eigenvectors().col(pair[0]);
    x = v.real();
    y = v.imag();
  } else if(std::abs(lambda - lambda2) < 1e-8) {
    const double value = 0.5 * (solver.eigenvalues()[pair[0]].real() + solver.eigenvalues()[pair[1]].real());
    if(!kernel(value, 2, &x, &y)) {
      result.characteristic_map = Characteristic_map_verdict::not_regular; // a Jordan block: no 2D eigenspace
      return true;
    }
  } else if(!kernel(lambda.real(), 1, &x, nullptr) || !kernel(lambda2.real(), 1, &y, nullptr)) {
    return true;
  }
  const double gram = x.squaredNorm() * y.squaredNorm() - CGAL::square(x.dot(y));
  if(!(gram > 1e-12 * x.squaredNorm() * y.squaredNorm())) {
    result.characteristic_map = Characteristic_map_verdict::not_regular; // a Jordan block: no 2D eigenspace
    return true;
  }
  // the planar control net, then refinement by the real host with the double mask
  Patch patch = analysis_patch(mask, result.configuration, big);
  const Labelling labels = label_neighbourhood(patch.mesh, patch.start, Traits::face_centred, big);
  CGAL_assertion_msg(
    labels.size() == static_cast<std::size_t>(S.rows()) && labels.size() == patch.mesh.number_of_vertices(),
    "the characteristic-map patch does not match its matrix");
  std::vector<char> trusted(patch.mesh.number_of_vertices(), 0);
  for(std::size_t i = 0; i < labels.size(); ++i) {
    patch.mesh.point(labels.vertex_of[i]) =
      Analysis_mesh::Point(x[static_cast<Eigen::Index>(i)], y[static_cast<Eigen::Index>(i)], 0);
    trusted[labels.vertex_of[i].idx()] = labels.ring[i] < big; // the outer ring is the patch border
  }
  Analysis_mesh mesh = patch.mesh;
  Analysis_halfedge start = patch.start;
  std::vector<int> rings;
  int outer = 0;
  for(int level = 1; level <= 8; ++level) {
    if(mesh.number_of_faces() * static_cast<std::size_t>(Traits::analysis_steps == 2 ? 9 : 4) > options.max_faces &&
       level > 2)
      break;
    auto step = analysed_step(mesh, start, mask);
    std::vector<char> next_trusted(step.mesh.number_of_vertices(), 0);
    for(std::size_t j = 0; j < step.stencils.size(); ++j) {
      bool all = !step.stencils[j].empty();
      for(const auto& term : step.stencils[j].terms())
        all = all && trusted[term.first.idx()];
      next_trusted[j] = all;
    }
    mesh = std::move(step.mesh);
    start = step.start;
    trusted.swap(next_trusted);
    result.characteristic_map_levels = level;
    rings = rings_of_vertices(mesh, start, Traits::face_centred);
    outer = (std::numeric_limits<int>::max)();
    for(Analysis_vertex v : mesh.vertices())
      if(!trusted[v.idx()])
        outer = (std::min)(outer, rings[v.idx()] - 1);
    if(outer >= 24)
      break;
  }
  if(outer < 6)
    return false; // too little of the map is known
  const int inner = (std::max)(1, outer / Traits::ring_growth - 1);
  const Annulus_test test = test_annulus(mesh, rings, inner, outer, result.boundary);
  result.characteristic_map = test.verdict;
  result.annulus_inner = test.inner;
  result.annulus_outer = test.outer;
  return true;
}

/*
 * The extended spectrum and the characteristic map over 2r + 2 rings, or
 * 2 rings more, up to 2r + 8, while too little of the map is known.
 */
template <class DoubleMask, class Result>
void characteristic_map_and_extended_spectrum(const DoubleMask& mask, Result& result,
                                              const internal::Surface_analysis_options& options)
{
  for(int big = 2 * result.rings + 2; big <= 2 * result.rings + 8; big += 2)
    if(characteristic_map_with_rings(mask, result, options, big))
      return;
}

// the point the verification tracks: the centre, or the first corner of the central face

} // namespace internal

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CHARACTERISTIC_MAP_H
