#include <cmath>
#include <filesystem>

#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace wheelwear::pipeline {

namespace {

// Half a millimetre: below what a wheel's radius or a track's gauge is given to.
constexpr double kLength = 0.5e-3;

std::string millimetres(double metres) {
  return core::format_number(metres * 1e3) + " mm";
}

// A scene names a profile by a standard name (any case) or a resolved path, a vehicle file by a
// name or a path of its own: the same profile where their file names agree, ignoring case.
bool same_profile(const std::string& scene, const std::string& proposed) {
  return core::to_lower(std::filesystem::path(scene).filename().string()) ==
         core::to_lower(std::filesystem::path(proposed).filename().string());
}

}  // namespace

std::vector<std::string> vehicle_scene_differences(const vehicle::Vehicle& v,
                                                   const std::string& vehicle_name,
                                                   const Scene& scene, double wheel_radius,
                                                   std::optional<double> friction) {
  std::vector<std::string> out;
  const auto say = [&](const std::string& text) { out.push_back(vehicle_name + ": " + text); };
  const vehicle::WheelsetBody& ws = v.wheelset;
  if (std::abs(ws.wheel_radius - wheel_radius) > kLength)
    say("[wheelset] wheel_radius_m = " + millimetres(ws.wheel_radius) + ", the scene's wheel " +
        millimetres(wheel_radius) +
        ": the contact rolls on the scene's wheel, and the vehicle's radius only sets its axles' "
        "height above the rail; make them agree (this key, or the scene's [wheel] radius_m)");
  if (std::abs(ws.lateral_arm - scene.lateral_arm) > kLength)
    say("[wheelset] lateral_arm_m = " + millimetres(ws.lateral_arm) + " is not used: the scene's " +
        millimetres(scene.lateral_arm) + " ([track] lateral_arm_m) is");

  // The pairing the file proposes ([contact]), key by key where it states one.
  const vehicle::VehicleContactDefaults& c = v.contact;
  const auto stated = [&](const char* key) { return c.given.count(key) > 0; };
  const auto unused = [&](const std::string& key, const std::string& proposed,
                          const std::string& used) {
    say("[contact] " + key + " = " + proposed + " is not used: " + used + " is");
  };
  if (stated("wheel_profile") && !same_profile(scene.wheel_profile, c.wheel_profile))
    unused("wheel_profile", c.wheel_profile, "the scene's " + scene.wheel_profile);
  const bool same_rail = same_profile(scene.rail_profile, c.rail_profile);
  if (stated("rail_profile") && !same_rail)
    unused("rail_profile", c.rail_profile, "the scene's " + scene.rail_profile);
  // An inclination is the mounting of one rail profile: compared on the same profile only.
  const double inclination =
      scene.rail_inclination.value_or(profiles::default_inclination(scene.rail_profile));
  if (stated("rail_inclination") && same_rail &&
      std::abs(std::atan(c.rail_inclination) - inclination) > 1e-6)
    unused("rail_inclination", core::format_number(c.rail_inclination),
           "the scene's " + core::format_number(std::tan(inclination)) + " ([rail] inclination)");
  if (stated("gauge_m") && std::abs(c.gauge - scene.gauge) > kLength)
    unused("gauge_m", millimetres(c.gauge),
           "the scene's " + millimetres(scene.gauge) + " ([track] gauge_m)");
  if (stated("back_to_back_m") && std::abs(c.back_to_back - scene.back_to_back) > kLength)
    unused("back_to_back_m", millimetres(c.back_to_back),
           "the scene's " + millimetres(scene.back_to_back) + " ([track] back_to_back_m)");
  if (stated("friction")) {
    if (!friction)
      unused("friction", core::format_number(c.friction),
             "the route's, each section its own ([route] friction and the sections' keys)");
    else if (std::abs(c.friction - *friction) > 1e-9)
      unused("friction", core::format_number(c.friction),
             "the curve's " + core::format_number(*friction) +
                 " (the scene's [contact] friction, or --friction)");
  }
  return out;
}

}  // namespace wheelwear::pipeline
