// Vehicle files: the built-in Manchester benchmark coach reads back the numbers of
// data/vehicles/default.toml, and every kind of bad input is refused with a message that names
// the key.

#include "wheelwear/vehicle/vehicle_file.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {
namespace {

// The built-in file with `from` replaced by `to` (the first occurrence; the test fails if absent).
std::string edited(const std::string& from, const std::string& to) {
  std::string text(default_vehicle_text());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string error_of(const std::string& text) {
  try {
    parse_vehicle(text, "vehicle file test.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(VehicleFile, TheBuiltInVehicleIsTheManchesterCoach) {
  const Vehicle v = default_vehicle();
  // Values of data/vehicles/default.toml (Iwnicki 1998 via its secondary sources), read back
  // exactly: they pass through the TOML reader as decimal literals.
  EXPECT_EQ(v.car_body.mass, 32000.0);
  EXPECT_EQ(v.car_body.cg_height, 1.8);
  EXPECT_EQ(v.bogie.mass, 2615.0);
  EXPECT_EQ(v.bogie.yaw_inertia, 3067.0);
  EXPECT_EQ(v.wheelset.body.mass, 1813.0);
  EXPECT_EQ(v.wheelset.body.cg_height, 0.46);  // the axle height: the wheel radius
  EXPECT_EQ(v.bogie_wheelbase, 2.56);
  EXPECT_EQ(v.pivot_spacing, 19.0);
  EXPECT_EQ(v.primary.kx, 31.391e6);
  EXPECT_EQ(v.primary.ky, 3.884e6);
  EXPECT_EQ(v.secondary.ky, 160.0e3);
  EXPECT_EQ(v.secondary.kpsi, 10.5e3);
  EXPECT_EQ(v.lateral_stop.deflection.size(), 9u);
  EXPECT_EQ(v.contact.gauge, 1.435);
  // Derived: 2 kx (spacing/2)^2 + 2 kpsi per joint; the total mass.
  EXPECT_DOUBLE_EQ(v.primary.joint_yaw_stiffness(), 2.0 * 31.391e6 * 1.0 * 1.0);
  EXPECT_DOUBLE_EQ(v.mass(), 32000.0 + 2 * 2615.0 + 4 * 1813.0);
  // Wheelsets in order of travel at +-9.5 +-1.28 m.
  EXPECT_DOUBLE_EQ(v.wheelset_x(0), 10.78);
  EXPECT_DOUBLE_EQ(v.wheelset_x(1), 8.22);
  EXPECT_DOUBLE_EQ(v.wheelset_x(2), -8.22);
  EXPECT_DOUBLE_EQ(v.wheelset_x(3), -10.78);
}

TEST(VehicleFile, TheLateralStopFollowsItsTable) {
  const LateralStop& s = default_vehicle().lateral_stop;
  EXPECT_EQ(s.force_at(0.02), 0.0);               // inside the clearance
  EXPECT_DOUBLE_EQ(s.force_at(0.0275), 300.0);    // half-way between 0 and 600 N
  EXPECT_DOUBLE_EQ(s.force_at(-0.0275), -300.0);  // odd
  EXPECT_DOUBLE_EQ(s.stiffness_at(0.0275), 600.0 / 0.005);
  EXPECT_DOUBLE_EQ(s.force_at(0.07),
                   230000.0 + (230000.0 - 29200.0) / 0.005 * 0.005);  // last slope
}

TEST(VehicleFile, BadInputIsRefusedNamingTheKey) {
  int checked = 0;
  const auto refused = [&](const std::string& from, const std::string& to,
                           const std::string& says) {
    const std::string message = error_of(edited(from, to));
    EXPECT_NE(message.find(says), std::string::npos) << "'" << to << "' gave: " << message;
    ++checked;
  };
  refused("mass_kg = 32000.0", "mass_kg = -32000.0", "car_body.mass_kg");
  refused("mass_kg = 32000.0", "mass_kg = nan", "car_body.mass_kg");
  refused("mass_kg = 32000.0", "mass_kg = \"heavy\"", "expected a number");
  refused("mass_kg = 32000.0", "mass_t = 32.0", "unknown key");
  refused("mass_kg = 32000.0", "", "car_body.mass_kg is missing");
  refused("wheelbase_m = 2.56", "wheelbase_m = 2.56e3", "bogie.wheelbase_m");
  refused("basis = \"per_axlebox\"", "basis = \"per_wheelset\"", "per_axlebox");
  refused("0.0, 600.0, 1760.0", "0.0, 600.0, 100.0", "must not decrease");
  refused("lateral_clearance_m = 0.025", "lateral_clearance_m = 0.02", "lateral_clearance_m");
  refused("[car_body]", "[car_body", "vehicle file test.toml line");
  refused("powered_wheelsets = [1, 2, 3, 4]", "powered_wheelsets = [1, 5]", "wheelset.powered");
  refused("powered_wheelsets = [1, 2, 3, 4]", "powered_wheelsets = [1, 1]", "once");
  refused("powered_wheelsets = [1, 2, 3, 4]", "powered_wheelsets = 2", "list of wheelset");
  refused("powered_wheelsets = [1, 2, 3, 4]", "powered_wheelsets = [1.5]", "once");
  EXPECT_EQ(checked, 14);
}

// The axles a route's traction acts on: all four in the built-in coach (its brakes), any subset
// in a file, none with [].
TEST(VehicleFile, PoweredWheelsetsAreReadInOrderOfTravel) {
  const std::array<bool, 4> all{true, true, true, true};
  EXPECT_EQ(default_vehicle().powered, all);
  const std::array<bool, 4> leading_bogie{true, true, false, false};
  EXPECT_EQ(parse_vehicle(edited("powered_wheelsets = [1, 2, 3, 4]", "powered_wheelsets = [2, 1]"),
                          "test")
                .powered,
            leading_bogie);
  const std::array<bool, 4> none{false, false, false, false};
  EXPECT_EQ(
      parse_vehicle(edited("powered_wheelsets = [1, 2, 3, 4]", "powered_wheelsets = []"), "test")
          .powered,
      none);
  // A file without the key: every axle, as before the key existed.
  EXPECT_EQ(parse_vehicle(edited("powered_wheelsets = [1, 2, 3, 4]", ""), "test").powered, all);
}

}  // namespace
}  // namespace wheelwear::vehicle
