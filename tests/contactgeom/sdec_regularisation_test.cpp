// SDEC regularisation (Liu, Fu & Bruni 2022, Eq. 13-14): an exact SDEC outline gives back its
// a, b, psi; the sign convention of psi; the equivalent ellipse of FASTSIM-EQ.E.

#include "wheelwear/contactgeom/sdec_regularisation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;

// Outline of an SDEC with O at (0, y_O): the two half-ellipses (Eq. 1-3), n vertices each.
PatchRing sdec_outline(const Sdec& s, double y_O, int n) {
  PatchRing ring;
  const double bp = s.b * (1.0 + s.psi), bn = s.b * (1.0 - s.psi);
  for (int i = 0; i < n; ++i) {  // +y half, semi-axis b(1 + psi): x from +a to -a
    const double t = kPi * i / n;
    ring.emplace_back(s.a * std::cos(t), y_O + bp * std::sin(t));
  }
  for (int i = 0; i < n; ++i) {  // -y half, semi-axis b(1 - psi): x from -a to +a
    const double t = kPi + kPi * i / n;
    ring.emplace_back(s.a * std::cos(t), y_O + bn * std::sin(t));
  }
  return ring;
}

TEST(SdecRegularisation, ExactSdecOutlineGivesBackItsParameters) {
  // Polygonal outline with 2 x 4000 vertices: area too small by (pi/n)^2/6 = 1e-7 relative;
  // extents exact at t = 0, pi/2, pi, 3pi/2.
  for (double psi : {-0.6, -0.2, 0.0, 0.3, 0.8}) {
    SCOPED_TRACE(psi);
    const Sdec truth{4.25e-3, 6e-3, psi};
    const PatchMeasures m = measure_polygons({sdec_outline(truth, 1e-3, 4000)}, 1e-3);
    const Sdec s = regularise_sdec(m);
    EXPECT_NEAR(s.a / truth.a, 1.0, 1e-7);
    EXPECT_NEAR(s.b / truth.b, 1.0, 1e-7);
    EXPECT_NEAR(s.psi, psi, 1e-12);
    EXPECT_NEAR(s.area(), m.area, 1e-12 * m.area);  // Eq. 14: pi a b = A_n exactly
  }
}

TEST(SdecRegularisation, ClosedFormsOfEq14) {
  PatchMeasures m;
  m.area = 100e-6;
  m.length = 10e-3;
  m.width = 16e-3;
  m.W1 = 11e-3;
  m.W2 = 5e-3;
  const Sdec s = regularise_sdec(m);
  EXPECT_DOUBLE_EQ(s.a, std::sqrt(100e-6 * 10e-3 / (kPi * 16e-3)));
  EXPECT_DOUBLE_EQ(s.b, std::sqrt(100e-6 * 16e-3 / (kPi * 10e-3)));
  EXPECT_NEAR(s.a / s.b, 10.0 / 16.0, 1e-15);  // a/b = L/W
  // More of the patch on the +y (gauge) side of O: psi > 0, as the reference data's psi_equiv.
  EXPECT_NEAR(s.psi, 6.0 / 16.0, 1e-15);
}

TEST(SdecRegularisation, ReferenceDataConvention) {
  // Row y_ws = 0 of d_wheelrail_patches_dx0.2.csv: area 143.12 mm^2, length 8.6, width 19.6,
  // W_pos 12.9249, W_neg 6.6751 mm; its convenience columns a_equiv 4.4709, b_equiv 10.1895 mm,
  // psi_equiv 0.3189 (printed to 4 decimals).
  PatchMeasures m;
  m.area = 143.12e-6;
  m.length = 8.6e-3;
  m.width = 19.6e-3;
  m.W1 = 12.9249e-3;
  m.W2 = 6.6751e-3;
  const Sdec s = regularise_sdec(m);
  EXPECT_NEAR(s.a * 1e3, 4.4709, 1e-4);
  EXPECT_NEAR(s.b * 1e3, 10.1895, 1e-4);
  EXPECT_NEAR(s.psi, 0.3189, 1e-4);
}

TEST(SdecRegularisation, EquivalentEllipse) {
  const Sdec s{4e-3, 5e-3, 0.4};
  const EquivalentEllipse at_o = equivalent_ellipse(s, EllipseCentre::at_O);
  const EquivalentEllipse at_o_prime = equivalent_ellipse(s, EllipseCentre::at_O_prime);
  EXPECT_EQ(at_o.a, s.a);
  EXPECT_EQ(at_o.b, s.b);
  EXPECT_EQ(at_o.y_centre, 0.0);
  EXPECT_DOUBLE_EQ(at_o_prime.y_centre, 0.4 * 5e-3);  // O' = O + psi b
  EXPECT_EQ(at_o_prime.shape().psi, 0.0);
  // The shifted ellipse spans the same lateral extent as the SDEC.
  EXPECT_DOUBLE_EQ(at_o_prime.y_centre + at_o_prime.b, s.y_max());
  EXPECT_DOUBLE_EQ(at_o_prime.y_centre - at_o_prime.b, s.y_min());
}

TEST(SdecRegularisation, RejectsInconsistentMeasures) {
  PatchMeasures m;
  m.area = 1e-4;
  m.length = 1e-2;
  m.width = 1e-2;
  m.W1 = 0.6e-2;
  m.W2 = 0.4e-2;
  EXPECT_NO_THROW(regularise_sdec(m));
  PatchMeasures bad = m;
  bad.W1 = 0.7e-2;  // W1 + W2 != W
  EXPECT_THROW(regularise_sdec(bad), InputError);
  bad = m;
  bad.W1 = 1e-2;  // O on the edge: psi = 1
  bad.W2 = 0.0;
  EXPECT_THROW(regularise_sdec(bad), InputError);
  bad = m;
  bad.area = 0.0;
  EXPECT_THROW(regularise_sdec(bad), InputError);
  bad = m;
  bad.length = std::nan("");
  EXPECT_THROW(regularise_sdec(bad), InputError);
  EXPECT_THROW(equivalent_ellipse(Sdec{1e-3, 1e-3, 1.0}, EllipseCentre::at_O), InputError);
}

}  // namespace
}  // namespace wheelwear::contactgeom
