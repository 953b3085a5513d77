// The conical wheel: its surface is the line z = -lambda y (the spline reproduces a line
// exactly), it places like an S1002 (internal face by convention 70 mm from the taping line).

#include "wheelwear/profiles/conical_wheel.hpp"

#include <gtest/gtest.h>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/internal_face.hpp"

namespace wheelwear::profiles {
namespace {

TEST(ConicalWheel, IsTheConeItsConicityStates) {
  int compared = 0;
  for (double conicity : {0.0, 0.05, 0.2}) {
    const Profile wheel = conical_wheel({.conicity = conicity});
    for (int k = 0; k <= 128; ++k, ++compared) {
      const double y = -0.069 + 1e-3 * k;
      ASSERT_NEAR(*wheel.z_at(y), -conicity * y, 1e-12) << conicity << " " << y;
    }
    EXPECT_EQ(internal_face(wheel).y, -0.070);
    EXPECT_FALSE(internal_face(wheel).measured);
    EXPECT_EQ(wheel.info().nominal_radius, 0.46);
  }
  EXPECT_EQ(compared, 3 * 129);
}

TEST(ConicalWheel, BadOptionsAreRefused) {
  EXPECT_THROW(conical_wheel({.conicity = -0.1}), InputError);
  EXPECT_THROW(conical_wheel({.conicity = 0.6}), InputError);
  EXPECT_THROW(conical_wheel({.nominal_radius = 0.0}), InputError);
  EXPECT_THROW(conical_wheel({.flange_side = -0.01}), InputError);
  EXPECT_THROW(conical_wheel({.point_spacing = 1e-2}), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
