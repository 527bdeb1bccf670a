// The typed property suite of surface_properties.h for Catmull-Clark,
// Doo-Sabin, linear quad subdivision and the two sqrt3 schemes in four
// kernels, and Polyhedron_3 against Surface_mesh in two.
#include "surface_properties.h"

namespace surface_properties {

using Cases =
  ::testing::Types<Case<Catmull_clark, Double_kernel>, Case<Catmull_clark, Epick>, Case<Catmull_clark, Epeck>,
                   Case<Catmull_clark, Rational_kernel>, Case<Doo_sabin, Double_kernel>, Case<Doo_sabin, Epick>,
                   Case<Doo_sabin, Epeck>, Case<Doo_sabin, Rational_kernel>, Case<Linear_quad, Double_kernel>,
                   Case<Linear_quad, Epick>, Case<Linear_quad, Epeck>, Case<Linear_quad, Rational_kernel>,
                   Case<Sqrt3, Double_kernel>, Case<Sqrt3, Epick>, Case<Sqrt3, Epeck>, Case<Sqrt3, Rational_kernel>,
                   Case<Interpolating_sqrt3, Double_kernel>, Case<Interpolating_sqrt3, Epick>,
                   Case<Interpolating_sqrt3, Epeck>, Case<Interpolating_sqrt3, Rational_kernel>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Schemes, Surface_properties, Cases);

using Mesh_type_cases =
  ::testing::Types<Case<Catmull_clark, Double_kernel>, Case<Catmull_clark, Rational_kernel>,
                   Case<Doo_sabin, Double_kernel>, Case<Doo_sabin, Rational_kernel>, Case<Linear_quad, Double_kernel>,
                   Case<Linear_quad, Rational_kernel>, Case<Sqrt3, Double_kernel>, Case<Sqrt3, Rational_kernel>,
                   Case<Interpolating_sqrt3, Double_kernel>, Case<Interpolating_sqrt3, Rational_kernel>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Schemes, Surface_mesh_types, Mesh_type_cases);

} // namespace surface_properties
