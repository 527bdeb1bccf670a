// The typed property suite of surface_properties.h for the schemes of the
// 1-to-4 triangle split (Loop, Loop with Warren's weights, butterfly,
// modified butterfly, linear) in four kernels, and Polyhedron_3 against
// Surface_mesh in two.
#include "surface_properties.h"

namespace surface_properties {

using Cases =
  ::testing::Types<Case<Loop, Double_kernel>, Case<Loop, Epick>, Case<Loop, Epeck>, Case<Loop, Rational_kernel>,
                   Case<Loop_warren, Double_kernel>, Case<Loop_warren, Epick>, Case<Loop_warren, Epeck>,
                   Case<Loop_warren, Rational_kernel>, Case<Butterfly, Double_kernel>, Case<Butterfly, Epick>,
                   Case<Butterfly, Epeck>, Case<Butterfly, Rational_kernel>, Case<Modified_butterfly, Double_kernel>,
                   Case<Modified_butterfly, Epick>, Case<Modified_butterfly, Epeck>,
                   Case<Modified_butterfly, Rational_kernel>, Case<Linear_triangle, Double_kernel>,
                   Case<Linear_triangle, Epick>, Case<Linear_triangle, Epeck>, Case<Linear_triangle, Rational_kernel>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Schemes, Surface_properties, Cases);

using Mesh_type_cases =
  ::testing::Types<Case<Loop, Double_kernel>, Case<Loop, Rational_kernel>, Case<Loop_warren, Double_kernel>,
                   Case<Loop_warren, Rational_kernel>, Case<Butterfly, Double_kernel>, Case<Butterfly, Rational_kernel>,
                   Case<Modified_butterfly, Double_kernel>, Case<Modified_butterfly, Rational_kernel>,
                   Case<Linear_triangle, Double_kernel>, Case<Linear_triangle, Rational_kernel>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Schemes, Surface_mesh_types, Mesh_type_cases);

} // namespace surface_properties
