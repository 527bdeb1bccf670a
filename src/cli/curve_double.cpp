// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "curve_impl.h"

namespace cgal_subdiv {

template std::size_t compute_curve<Double_kernel>(const Curve_job&, const Input_polyline&, std::ostream&, Figure*);

} // namespace cgal_subdiv
