#pragma once
// A short route for vehicle-run tests: one lubricated curve whose quasi-static solve converges
// on S1002/60E1, a transition and a tangent (three running conditions).

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

}  // namespace wheelwear::pipeline
