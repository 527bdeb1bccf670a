// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Concept page (documentation only: compiled by Doxygen, never by a compiler).

/*!
 * \ingroup PkgSubdivConcepts
 * \cgalConcept
 *
 * A refinement host: the topology of one topological split (`CGAL::Subdiv::Split`),
 * and nothing of the weights. Built on the old mesh of a level, it numbers the
 * new vertices, tells where each came from, makes a mask report the weights of
 * any new vertex (by building the view of its old element and calling the
 * mask's node function, see `SurfaceSubdivisionMask`), and makes the record of
 * the new faces. The one level pipeline (`internal::refine_level`,
 * refinement/refine_level.h) builds the host of the mask's split,
 * `CGAL::Subdiv::Host_of<Mask>`, and every consumer (`subdivide()`, carried
 * data, `make_stencil_table()`, the analysis, the limit) refines through it.
 *
 * A host is an extension point of the package rather than a user-facing type:
 * the record of the new faces and the numbering are internal types
 * (refinement/Child_faces.h, internal/Mesh_numbering.h). A new host is added
 * with a value of `CGAL::Subdiv::Split` and a specialisation of
 * `CGAL::Subdiv::Host_for` (hosts/Host_for.h); the masks and the analysis do not
 * change.
 *
 * <b>Numbering.</b> New vertices are numbered 0 .. `number_of_new_vertices()` - 1
 * by the host; the same numbers index `report()`, `origin()`, the new faces'
 * corners, the rows of stencil tables and the vertices of the refined mesh (a
 * `Surface_mesh` refined in place gets new vertex j as index j). The primal
 * hosts number the old vertices first, in the mesh's iteration order. Old
 * elements are known by their ordinals in the mesh's iteration order
 * (`numbering()`); halfedges by 2e and 2e + 1 for edge e.
 *
 * <b>Thread safety.</b> `report()` and `child_faces()` read only the old mesh
 * and the host's own data, and are called for different new vertices (or
 * blocks of faces) from several threads at once.
 *
 * \cgalHasModelsBegin
 * \cgalHasModels{CGAL::Subdiv::Triangle_quadrisection (`Split::triangle_quadrisection`: Loop, the butterflies, linear)}
 * \cgalHasModels{CGAL::Subdiv::Quad_split (`Split::quad`: Catmull-Clark, linear quad)}
 * \cgalHasModels{CGAL::Subdiv::Dual_split (`Split::dual`: Doo-Sabin)}
 * \cgalHasModels{CGAL::Subdiv::Sqrt3_split (`Split::sqrt3`: sqrt3, interpolating sqrt3)}
 * \cgalHasModelsEnd
 *
 * \sa `SurfaceSubdivisionMask`, `CGAL::Subdiv::Host_for`
 */
class SubdivisionHost
{
public:
  /// \name Types
  /// @{

  /// the mesh type, a model of `FaceGraph`
  typedef unspecified_type Polygon_mesh;

  /// @}

  /// \name Static traits read before refining
  /// @{

  /// the size every face of the input must have (3 for the triangle splits), or
  /// 0 for any; the input checks of `subdivide()` throw `Bad_input` otherwise
  static constexpr int required_face_size = unspecified;

  /// about how many new faces one old face makes, for the check that the output
  /// of a call fits in memory (`Bad_input` before anything changes)
  static double face_growth();

  /// replaces the counts `c` (vertices, edges, faces, corners) by those after one
  /// level and returns true, or returns false if they are not known in advance;
  /// a `Surface_mesh` refined several levels reserves room for the last one at once
  static bool next_counts(internal::Mesh_counts& c);

  /// @}

  /// \name Static traits read by the analysis and the limit
  /// @{

  /// the face size of the regular meshes the analysed neighbourhoods are made of
  static constexpr int regular_face_size = unspecified;

  /// whether the analysed neighbourhood is centred at a face (dual schemes) rather
  /// than at a vertex
  static constexpr bool face_centred = unspecified;

  /// host steps per analysed step: 1, or 2 for `Sqrt3_split` (two steps are the
  /// 1-to-9 split, which maps every ring of the neighbourhood onto itself)
  static constexpr int analysis_steps = unspecified;

  /// by how much an analysed step multiplies the rings of a neighbourhood (2, or 3
  /// for two sqrt3 steps)
  static constexpr int ring_growth = unspecified;

  /// @}

  /// \name Construction and counts
  /// @{

  /// a host for one level of `mesh`, which must outlive the host; its indices are
  /// dense (`subdivide()` collects the garbage of a `Surface_mesh` first). The
  /// host keeps what it needs of the old level before the writers rewire the mesh.
  explicit SubdivisionHost(const Polygon_mesh& mesh);

  /// the number of vertices of the new level
  std::size_t number_of_new_vertices() const;

  /// the number of faces of the new level
  std::size_t number_of_new_faces() const;

  /// the number of edges of the new level; needed by the hosts whose
  /// `child_faces()` is an `internal::Split_faces` (the edge splits: the record and
  /// the threaded `Surface_mesh` writer read it). `Sqrt3_split` has it for its own
  /// face list; `Dual_split`, whose counts come with its face list, has none.
  std::size_t number_of_new_edges() const;

  /// the ordinals of the old vertices, edges, halfedges and faces that the new
  /// elements are numbered by (`make_stencil_table()` maps the reported vertices
  /// to the columns of its rows with it)
  const internal::Mesh_numbering<Polygon_mesh>& numbering() const;

  /// @}

  /// \name The new vertices
  /// @{

  /// what new vertex `j` came from: an old vertex, edge, face or face corner, by
  /// ordinal (`Carried_data::origins()`, the neighbourhood walk of the analysis)
  CGAL::Subdiv::Vertex_origin origin(std::size_t j) const;

  /// makes `mask` report the weights of new vertex `j` (`j < number_of_new_vertices()`)
  /// to `acc`: builds the view of the old element of `j` (the edge splits pass the
  /// mask's `border_corners()` if it has one) and calls the node function of the
  /// mask for it. Random access: the new vertices are handed out in chunks to
  /// threads.
  template <class Mask, class Accumulator>
  void report(std::size_t j, const Mask& mask, Accumulator& acc) const;

  /// @}

  /// \name The new faces
  /// @{

  /// the record of the new faces, read by the writers of the level and by the
  /// sinks (face data goes from each new face's parent): every face corner holds its
  /// new vertex and the id of the new halfedge to the next corner (2e and 2e + 1
  /// are the halves of new edge e), every face its parent (an old face ordinal),
  /// plus the new border halfedges. The edge splits return an
  /// `internal::Split_faces<Host>`, made on the fly from a snapshot of the old
  /// corners (in parallel chunks by `loop`), and then provide
  /// `for_each_new_face(snapshot, parent, emit)` and `static constexpr int
  /// new_face_size`; `Dual_split` and `Sqrt3_split` return a list of faces,
  /// `internal::Face_soup`.
  unspecified_type child_faces(const internal::Parallel_loop& loop) const;

  /// only for `analysis_steps == 2` (`Sqrt3_split`): whether this step refines the
  /// border (the limit evaluates border vertices one step further when it does)
  bool refines_border() const;

  /// @}
};
