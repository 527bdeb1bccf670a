// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Concept page (documentation only: compiled by Doxygen, never by a compiler).

/*!
 * \ingroup PkgSubdivConcepts
 * \cgalConcept
 *
 * The rules of a surface subdivision scheme: for each new vertex of one level,
 * which old vertices contribute with which weight. A mask never computes a
 * point: it reports `(vertex, weight)` pairs to an accumulator (a model of
 * `SubdivisionAccumulator`) by calling `acc.add(v, w)`, and knows nothing of
 * what the accumulator does with them. The same mask therefore drives
 * `CGAL::Subdiv::subdivide()` (points summed), carried data and
 * `CGAL::Subdiv::make_stencil_table()` (stencils recorded and composed), the
 * analysis (`CGAL::Subdiv::analyse_surface_scheme()`: the local subdivision
 * matrix) and the limit (`CGAL::Subdiv::project_to_limit()`,
 * `CGAL::Subdiv::limit_normals()`).
 *
 * A mask does not walk the mesh to find its element: the refinement host of its
 * split (a model of `SubdivisionHost`, chosen by `CGAL::Subdiv::Host_of`)
 * visits each new vertex, builds the view of the old element it comes from
 * (`CGAL::Subdiv::Vertex_view`, `CGAL::Subdiv::Edge_view`,
 * `CGAL::Subdiv::Face_view`, `CGAL::Subdiv::Corner_view`) and calls the
 * node function of the mask for that kind of element. From the view the mask
 * may read the old mesh (`view.mesh()`) around the element.
 *
 * <b>What a node function must do.</b>
 * - report every contribution as `acc.add(v, w)`, with `v` a
 *   `boost::graph_traits<Polygon_mesh>::%vertex_descriptor` of the old mesh and
 *   `w` a `Number_type`, and call nothing else on `acc`;
 * - read only the old mesh, through the view, and change nothing: the node
 *   functions are `const`, and the hosts call them for different new vertices
 *   from several threads at once (with the named parameter `threads`);
 * - report the same terms in the same order every time: refinement, stencil
 *   tables and the analysis then agree bit for bit (composed rows list their
 *   terms in the order their sources first appear);
 * - make the weights of each new vertex sum to 1 (affine invariance): the
 *   analysis checks it (`Surface_analysis::rows_sum_to_one`, else
 *   `Analysis_status::not_affine_invariant`).
 *
 * A vertex may be reported more than once (Catmull-Clark reports the face
 * points' vertices through every face): the accumulator adds the weights up.
 * Weights may be negative (the butterflies). Rational weights should be written
 * as ratios of `Number_type`, `FT(3) / FT(8)`, so that they are exact in exact
 * number types.
 *
 * <b>The node functions a host calls</b>, by `split`:
 *
 * | `split` | host | node functions |
 * |---|---|---|
 * | `Split::triangle_quadrisection` | `CGAL::Subdiv::Triangle_quadrisection` | `vertex_node()`, `edge_node()` |
 * | `Split::quad` | `CGAL::Subdiv::Quad_split` | `vertex_node()`, `edge_node()`, `face_node()` |
 * | `Split::dual` | `CGAL::Subdiv::Dual_split` | `corner_node()` |
 * | `Split::sqrt3` | `CGAL::Subdiv::Sqrt3_split` | `vertex_node()` (interior vertices), `face_node()`, `resting_border_vertex_node()`, `border_vertex_node()`, `border_edge_node()` |
 *
 * A mask needs only the node functions of its split. It must be
 * `CopyConstructible` (`CGAL::Subdiv::Limit_evaluator` keeps a copy), and
 * `DefaultConstructible` for `Limit_evaluator<Mask>()` without an argument.
 *
 * \cgalHasModelsBegin
 * \cgalHasModels{CGAL::Subdiv::Loop_mask (and CGAL::Subdiv::Loop_warren_mask)}
 * \cgalHasModels{CGAL::Subdiv::Catmull_clark_mask}
 * \cgalHasModels{CGAL::Subdiv::Doo_sabin_mask}
 * \cgalHasModels{CGAL::Subdiv::Sqrt3_mask}
 * \cgalHasModels{CGAL::Subdiv::Interpolating_sqrt3_mask}
 * \cgalHasModels{CGAL::Subdiv::Butterfly_mask}
 * \cgalHasModels{CGAL::Subdiv::Modified_butterfly_mask}
 * \cgalHasModels{CGAL::Subdiv::Linear_triangle_mask}
 * \cgalHasModels{CGAL::Subdiv::Linear_quad_mask}
 * \cgalHasModelsEnd
 *
 * \sa `SubdivisionAccumulator`, `SubdivisionHost`, `CurveSubdivisionScheme`
 */
class SurfaceSubdivisionMask
{
public:
  /// \name Types and traits
  /// @{

  /// the mesh the mask reads, a model of `FaceGraph` (`CGAL::Surface_mesh`,
  /// `CGAL::Polyhedron_3`, ...): the refinement requires it to be the type of
  /// the mesh refined (a `static_assert`), and `CGAL::Subdiv::Host_of` builds
  /// the host over it
  typedef unspecified_type Polygon_mesh;

  /// the number type of the weights; `CGAL::Subdiv::subdivide()` requires it
  /// to be the number type of the points of the vertex point map, and a stencil
  /// table made from the mask is a `CGAL::Subdiv::Stencil_table<Number_type>`
  typedef unspecified_type Number_type;

  /// the topological split of the scheme: which host refines with the mask
  /// (`CGAL::Subdiv::Host_of<Mask>` is `Host_for<Mask::split, Polygon_mesh>::type`)
  static constexpr CGAL::Subdiv::Split split = unspecified;

  /// @}

  /// \name Operations used by every consumer
  /// @{

  /// the name of the scheme, in the messages of `CGAL::Subdiv::Bad_input` and
  /// in the reports of the analysis (`Surface_analysis::scheme`)
  std::string name() const;

  /// the same rules, with the same options, over another mesh type and number
  /// type: a model of this concept whose `Polygon_mesh` is `OtherMesh` and
  /// whose `Number_type` is `OtherFT`. Used by the analysis (rebound to
  /// `CGAL::Subdiv::Analysis_mesh` with an exact type and with `double`) and by
  /// `CGAL::Subdiv::Limit_evaluator` (rebound to each call's mesh and kernel);
  /// `subdivide()` and stencil tables do not need it.
  template <class OtherMesh, class OtherFT>
  unspecified_type rebind() const;

  /// optional: what happens at a border vertex with a single face. When the
  /// mask has this member, `Triangle_quadrisection` and `Quad_split` build their
  /// views with it (the view's `rule()` is then `Vertex_rule::corner` at such
  /// vertices with `Border_corners::sharp`); without it, `Border_corners::smooth`.
  /// `Dual_split` and `Sqrt3_split` do not read it.
  CGAL::Subdiv::Border_corners border_corners() const;

  /// optional: the edge rule next to triangles (`Catmull_clark_mask`), which
  /// the named parameter `triangle_subdivision` of `subdivide()` must match;
  /// without it, `Triangle_subdivision::catmark`.
  CGAL::Subdiv::Triangle_subdivision triangle_subdivision() const;

  /// optional: a copy of the mask that refines with the sharpness tags of
  /// `level` (made by `subdivide()` for each level). When the mask has it,
  /// `subdivide()` accepts `edge_sharpness_map` and `vertex_sharpness_map`;
  /// `Loop_mask` and `Catmull_clark_mask` have it (`With_sharp_rules`). The
  /// copy is of another type, whose `refines_with_tags` is true and whose
  /// `sharp_level()` gives the tags: `Triangle_quadrisection` and
  /// `Quad_split` then build their views from them (the rules of
  /// `Sharp_rules`). Masks without tags compile only their border rules.
  unspecified_type with_sharp_level(const unspecified_type* level) const;

  /// @}

  /// \name Node functions of the primal splits (Split::triangle_quadrisection, Split::quad, Split::sqrt3)
  /// @{

  /// reports the weights of the new vertex of old vertex `v.vertex()`. The
  /// view gives its valence, its faces, its border halfedges and its rule
  /// (`Vertex_rule::smooth`, `crease` on the border, `corner`; with
  /// sharpness tags also `dart`, interior creases and the rule of the next level). With
  /// `Split::sqrt3` it is called for interior vertices only.
  template <class Accumulator>
  void vertex_node(const CGAL::Subdiv::Vertex_view<Polygon_mesh>& v, Accumulator& acc) const;

  /// reports the weights of the new vertex of the edge of `e.halfedge()` (the
  /// host gives `halfedge(edge)`); `e.on_border()` tells a border edge.
  /// (`Split::triangle_quadrisection` and `Split::quad`.)
  template <class Accumulator>
  void edge_node(const CGAL::Subdiv::Edge_view<Polygon_mesh>& e, Accumulator& acc) const;

  /// reports the weights of the new vertex of face `f.face()` (the face point).
  /// (`Split::quad` and `Split::sqrt3`.)
  template <class Accumulator>
  void face_node(const CGAL::Subdiv::Face_view<Polygon_mesh>& f, Accumulator& acc) const;

  /// @}

  /// \name Node function of the dual split (Split::dual)
  /// @{

  /// reports the weights of the new vertex of the corner of `face(h)` at
  /// `target(h)`, `h = corner.halfedge()`; the view tells whether the face's
  /// edges before and after the corner are on the border.
  template <class Accumulator>
  void corner_node(const CGAL::Subdiv::Corner_view<Polygon_mesh>& corner, Accumulator& acc) const;

  /// @}

  /// \name Border node functions of the sqrt3 split (Split::sqrt3)
  /// `CGAL::Subdiv::Sqrt3_split` refines the border on every second step only.
  /// @{

  /// a border vertex on a step that leaves the border alone (a "resting" step)
  template <class Accumulator>
  void resting_border_vertex_node(const CGAL::Subdiv::Vertex_view<Polygon_mesh>& v, Accumulator& acc) const;

  /// a border vertex on a step that refines the border
  template <class Accumulator>
  void border_vertex_node(const CGAL::Subdiv::Vertex_view<Polygon_mesh>& v, Accumulator& acc) const;

  /// on a step that refines the border, the new vertex at `k`/3 (`k` = 1 or 2)
  /// of the way along the border edge of the face halfedge `e.halfedge()`
  template <class Accumulator>
  void border_edge_node(const CGAL::Subdiv::Edge_view<Polygon_mesh>& e, int k, Accumulator& acc) const;

  /// @}
};
