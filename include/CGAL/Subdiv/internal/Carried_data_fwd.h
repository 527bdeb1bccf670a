// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_CARRIED_DATA_FWD_H
#define CGAL_SUBDIV_INTERNAL_CARRIED_DATA_FWD_H

// The declaration of `Carried_data` (CGAL/Subdiv/Carried_data.h), for
// subdivide.h: a program that passes no `carried_data` does not parse the
// class (compile time is part of the API, doc/compile_time.md); one that
// makes a `Carried_data` has included its header.

#include <CGAL/Subdiv/internal/mesh_traits.h>

namespace CGAL {
namespace Subdiv {

template <class Mesh, class FT = internal::Mesh_FT<Mesh>>
class Carried_data;

namespace internal {

/// what the package's own functions reach of `Carried_data` beside its
/// public API (`make_face_varying_stencil_table()`'s channel of rows)
struct Carried_data_access;

} // namespace internal

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_CARRIED_DATA_FWD_H
