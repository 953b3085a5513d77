#pragma once
// A worn wheel profile as a run carries it from step to step.

#include <string>
#include <vector>

#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::pipeline::detail {

// The points a worn profile is built from (exactly what the results file records, so that a
// resumed run, or another process of the job, rebuilds the identical profile).
struct WornProfile {
  std::string name;  // group name in the file
  profiles::ProfileInfo info;
  profiles::CurveOptions curve;
  profiles::PointList points;

  profiles::Profile build() const { return profiles::Profile(points, info, curve); }
};

// The scene's new wheel profile, once per profile its run wears (profile_names' order).
std::vector<WornProfile> new_profiles(const Scene& scene);

}  // namespace wheelwear::pipeline::detail
