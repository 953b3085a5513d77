// A vehicle file and the scene it runs in: the scene's profiles, track and friction are used,
// and every difference is named (pipeline::vehicle_scene_differences), where it used to be
// silent; a vehicle whose own wheel radius is not the scene's still finds its balance.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>

#include "support/run_command.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;

bool names(const std::vector<std::string>& warnings, const std::string& key) {
  for (const std::string& w : warnings)
    if (w.find(key) != std::string::npos) return true;
  return false;
}

// The built-in coach proposes the built-in scene's pairing: nothing to say. Each changed key is
// named once with both values, the others not.
TEST(VehicleSceneCheck, NamesEveryKeyWhereTheVehicleFileAndTheSceneDiffer) {
  const Scene scene = default_scene();
  const double radius = 0.46;  // the built-in scene's S1002 (profiles::kDefaultWheelRadius)
  vehicle::Vehicle v = vehicle::default_vehicle();
  EXPECT_TRUE(vehicle_scene_differences(v, "vehicle file v.toml", scene, radius, 0.3).empty());

  v.wheelset.wheel_radius = 0.5;
  v.contact.friction = 0.4;
  v.contact.gauge = 1.432;
  v.contact.wheel_profile = "measured/wheel_0042.whl";
  const auto warnings = vehicle_scene_differences(v, "vehicle file v.toml", scene, radius, 0.3);
  EXPECT_EQ(warnings.size(), 4u);
  for (const char* text :
       {"vehicle file v.toml: [wheelset] wheel_radius_m = 500 mm, the scene's wheel 460 mm",
        "vehicle file v.toml: [contact] friction = 0.4 is not used: the curve's 0.3",
        "vehicle file v.toml: [contact] gauge_m = 1432 mm is not used: the scene's 1435 mm",
        "vehicle file v.toml: [contact] wheel_profile = measured/wheel_0042.whl is not used: "
        "the scene's S1002"})
    EXPECT_TRUE(names(warnings, text)) << text;
  // On a route every section gives its own friction: a stated one is never used.
  EXPECT_TRUE(names(vehicle_scene_differences(v, "v", scene, radius, std::nullopt),
                    "[contact] friction = 0.4 is not used: the route's"));
}

// What the file does not state is no proposal: the defaults a vehicle file without [contact]
// falls back on are not compared (a scene with a measured wheel warned of "S1002"). A standard
// name matches in any case, as a scene reads it.
TEST(VehicleSceneCheck, ComparesOnlyWhatTheFileStatesAndStandardNamesInAnyCase) {
  const Scene scene = default_scene();
  vehicle::Vehicle v = vehicle::default_vehicle();
  v.contact.wheel_profile = "s1002";
  v.contact.rail_profile = "60e1";
  EXPECT_TRUE(vehicle_scene_differences(v, "v", scene, 0.46, 0.3).empty());
  v.contact.wheel_profile = "other.whl";
  v.contact.friction = 0.2;
  v.contact.given.clear();
  EXPECT_TRUE(vehicle_scene_differences(v, "v", scene, 0.46, 0.3).empty());
}

// A vehicle file's inclination is a slope, a scene's an angle: 1:20 is 0.05 either way. It is
// the mounting of one rail profile and is compared on the same profile only.
TEST(VehicleSceneCheck, ComparesTheInclinationAsASlopeOnTheSameRail) {
  const Scene steep = parse_scene("[rail]\nprofile = \"60E1\"\ninclination = \"1:20\"\n", ".", {},
                                  SceneUse::vehicle_solve);
  vehicle::Vehicle v = vehicle::default_vehicle();
  v.contact.rail_inclination = 0.05;
  EXPECT_TRUE(vehicle_scene_differences(v, "v", steep, 0.46, 0.3).empty());
  v.contact.rail_inclination = 0.025;
  EXPECT_TRUE(names(vehicle_scene_differences(v, "v", steep, 0.46, 0.3),
                    "[contact] rail_inclination = 0.025 is not used: the scene's 0.05"));
  v.contact.rail_profile = "measured.ban";
  const auto other = vehicle_scene_differences(v, "v", steep, 0.46, 0.3);
  EXPECT_EQ(other.size(), 1u);  // the rail profile, not its inclination
  EXPECT_TRUE(names(other, "[contact] rail_profile = measured.ban is not used"));
}

class VehicleSceneCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wheelwear_vehicle_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// `curving --vehicle` with a vehicle file whose wheel radius (0.5 m) and friction (0.4) are not
// the scene's: both are named on stderr, and the balance is found. Newton starts every axle at
// the free rolling of the contact's 0.46 m wheels; from the vehicle's own radius (a spin 8 %
// too slow) it stalled ("the line search found no smaller residual").
TEST_F(VehicleSceneCommand, CurvingNamesTheDifferencesAndUsesTheScenesWheel) {
  std::string text(vehicle::default_vehicle_text());
  text =
      std::regex_replace(text, std::regex("\nwheel_radius_m = [0-9.]+"), "\nwheel_radius_m = 0.5");
  text = std::regex_replace(text, std::regex("\nfriction = [0-9.]+"), "\nfriction = 0.4");
  std::ofstream(dir_ / "vehicle.toml") << text;
  const std::string curve = " --radius 500 --cant 0.1 --speed 20 --json";
  const auto builtin = testing::run_wheelwear("curving" + curve);
  const auto own =
      testing::run_wheelwear("curving --vehicle " + (dir_ / "vehicle.toml").string() + curve);
  ASSERT_EQ(builtin.exit_code, 0) << builtin.err;
  ASSERT_EQ(own.exit_code, 0) << own.err;
  EXPECT_NE(own.err.find("[wheelset] wheel_radius_m = 500 mm, the scene's wheel 460 mm"),
            std::string::npos)
      << own.err;
  EXPECT_NE(own.err.find("[contact] friction = 0.4 is not used: the curve's 0.3"),
            std::string::npos)
      << own.err;
  EXPECT_EQ(builtin.err.find("warning"), std::string::npos) << builtin.err;
  // The wheels' radius is the contact's: the leading wheelset's shift as the built-in coach's
  // (whose axle height alone differs) within 1 %.
  const std::regex dy_re(R"re("dy": ([-+0-9.eE]+))re");
  std::smatch a, b;
  ASSERT_TRUE(std::regex_search(builtin.out, a, dy_re));
  ASSERT_TRUE(std::regex_search(own.out, b, dy_re));
  EXPECT_NEAR(std::stod(b[1]), std::stod(a[1]), 0.01 * std::abs(std::stod(a[1])));

  // Without --vehicle, the scene's [vehicle] (it used to be the built-in coach); a scene with a
  // vehicle and no route will do for a curve.
  std::ofstream(dir_ / "scene.toml") << "[vehicle]\nfile = \"vehicle.toml\"\n";
  const auto scenes = testing::run_wheelwear("curving " + (dir_ / "scene.toml").string() + curve);
  EXPECT_EQ(scenes.exit_code, 0) << scenes.err;
  EXPECT_NE(scenes.err.find("vehicle.toml: [wheelset] wheel_radius_m = 500 mm"), std::string::npos)
      << scenes.err;
}

// A scene of profiles alone (no collective, vehicle or hook) is what `curving` and `route` need:
// accepted for a vehicle solve, refused for a wear run as before.
TEST(VehicleSceneUse, AProfileOnlySceneServesAVehicleSolveButNotARun) {
  const std::string text = "[wheel]\nprofile = \"S1002\"\n[rail]\nprofile = \"60E1\"\n";
  const Scene s = parse_scene(text, ".", {}, SceneUse::vehicle_solve);
  EXPECT_EQ(s.wheel_profile, "S1002");
  EXPECT_TRUE(s.states.empty());
  EXPECT_FALSE(s.vehicle_run.has_value());
  EXPECT_THROW((void)parse_scene(text, "."), InputError);
}

}  // namespace
}  // namespace wheelwear::pipeline
