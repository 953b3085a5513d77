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

// The points of each of `worn` (what another process of the job rebuilds them from).
inline std::vector<profiles::PointList> points_of(const std::vector<WornProfile>& worn) {
  std::vector<profiles::PointList> points;
  for (const WornProfile& w : worn) points.push_back(w.points);
  return points;
}

// `wheels` as the evaluators take them.
inline std::vector<const profiles::Profile*> pointers_to(
    const std::vector<profiles::Profile>& wheels) {
  std::vector<const profiles::Profile*> pointers;
  for (const profiles::Profile& w : wheels) pointers.push_back(&w);
  return pointers;
}

}  // namespace wheelwear::pipeline::detail
