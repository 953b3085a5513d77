#pragma once
// A short route for vehicle-run tests: one lubricated curve whose quasi-static solve converges
// on S1002/60E1, a transition and a tangent (three running conditions).

#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {

// One km of R 3000 m (whose quasi-static solve converges on S1002/60E1) with a lubricated gauge
// face, eased out to tangent track in 60 m, then 940 m of tangent.
inline constexpr const char* kShortRoute = R"(
[route]
name = "short"
speed_m_s = 40
[[section]]
kind = "curve"
length_m = 1000
radius_m = 3000
cant_m = 0.03
friction_flange = 0.1
[[section]]
kind = "transition"
length_m = 60
radius_m = 0
cant_m = 0
[[section]]
kind = "tangent"
length_m = 940
)";

// The built-in coach on the short route, every section solved quasi-statically, without the
// critical speed's search.
inline VehicleRun short_route_run() {
  VehicleRun run;
  run.vehicle = vehicle::default_vehicle();
  run.route = vehicle::parse_route(kShortRoute, "test route");
  run.time_domain.enabled = false;
  run.critical_speed = false;
  return run;
}

}  // namespace wheelwear::pipeline
