#include "wheelwear/tangential/linear_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {
namespace {

using contactgeom::Sdec;

const Material kSteel{80e9, 0.25};

// Eq. 11 with Table 1's g = 1 row written out by hand: C11 = 4.12, B11 = 0.143, K13 = 3.18,
// C22 = 3.67, B22 = 0.109, C23 = 1.47, B23 = 0.063.
TEST(LinearSdec, EvaluatesEquation11) {
  const Sdec patch{5e-3, 5e-3, 0.5};
  const Creepages v{1e-3, -2e-3, 0.4};
  const CreepForces f = linear_sdec_forces(patch, v, kSteel);
  const double c = 5e-3, G = 80e9, psi2 = 0.25;
  const double fx =
      -G * c * c * (4.12 + 0.143 * psi2) * v.vx - G * c * c * c * (-3.18 * 0.5) * v.phi;
  const double fy =
      -G * c * c * (3.67 + 0.109 * psi2) * v.vy - G * c * c * c * (1.47 + 0.063 * psi2) * v.phi;
  constexpr double kSameFormula = 1e-9;  // [relative] the same sums in another order
  EXPECT_NEAR(f.Fx, fx, kSameFormula * std::abs(fx));
  EXPECT_NEAR(f.Fy, fy, kSameFormula * std::abs(fy));
  EXPECT_FALSE(f.Mz.has_value());
}

TEST(LinearSdec, ForcesOpposeTheCreepages) {
  const Sdec patch{4e-3, 6e-3, 0.0};
  EXPECT_LT(linear_sdec_forces(patch, {1e-3, 0, 0}, kSteel).Fx, 0.0);
  EXPECT_LT(linear_sdec_forces(patch, {0, 1e-3, 0}, kSteel).Fy, 0.0);
  // Pure spin with psi > 0, phi > 0: Fx > 0 and Fy < 0 (reference README, section 2).
  const CreepForces spin = linear_sdec_forces(Sdec{4e-3, 6e-3, 0.6}, {0, 0, 1.0}, kSteel);
  EXPECT_GT(spin.Fx, 0.0);
  EXPECT_LT(spin.Fy, 0.0);
}

// Shen-Hedrick-Elkins: f_s = f - f^2/3 + f^3/27 below 3, mu N above; at f = 1e-4 the linear
// force is reached to within f/3 relative.
TEST(SheSdec, SaturatesAsShenHedrickElkins) {
  const Sdec patch{4e-3, 5e-3, 0.3};
  const ContactLoad load{40e3, 0.3};
  const double limit = load.mu * load.N;
  const Creepages tiny{1e-8, 0, 0};
  const CreepForces lin = linear_sdec_forces(patch, tiny, kSteel);
  const CreepForces she = she_sdec_forces(patch, tiny, kSteel, load);
  const double f = std::abs(lin.Fx) / limit;
  EXPECT_NEAR(she.Fx / lin.Fx, 1 - f / 3 + f * f / 27, 1e-12);

  const CreepForces big = she_sdec_forces(patch, {0.05, 0.01, 0.2}, kSteel, load);
  EXPECT_NEAR(std::hypot(big.Fx, big.Fy), limit, 1e-9 * limit);

  double previous = 0.0;
  for (double vx = 1e-5; vx < 0.02; vx *= 1.5) {
    const double magnitude = std::abs(she_sdec_forces(patch, {vx, 0, 0}, kSteel, load).Fx);
    EXPECT_GE(magnitude, previous);  // flat at mu N once f >= 3
    EXPECT_LE(magnitude, limit * (1 + 1e-12));
    previous = magnitude;
  }
}

TEST(SheSdec, RejectsBadLoads) {
  const Sdec patch{4e-3, 5e-3, 0.3};
  EXPECT_THROW(she_sdec_forces(patch, {}, kSteel, {-1.0, 0.3}), InputError);
  EXPECT_THROW(she_sdec_forces(patch, {}, kSteel, {1e4, 0.0}), InputError);
  EXPECT_THROW(linear_sdec_forces(patch, {std::nan(""), 0, 0}, kSteel), InputError);
  EXPECT_THROW(linear_sdec_forces(patch, {}, Material{-1.0, 0.25}), InputError);
}

}  // namespace
}  // namespace wheelwear::tangential
