#pragma once
// What the real-rail tests share: the small test files, the message of a refused load, rail
// load options, and a point-by-point comparison of two loads.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_loader.hpp"

namespace wheelwear::profiles::real_rail {

using testing::data_path;

inline std::filesystem::path rail_file(const std::string& name) {
  return data_path("profiles/" + name);
}

inline std::string error_of(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

inline LoadOptions as_rail() {
  LoadOptions options;
  options.read.body = Body::rail;
  return options;
}

// Same points and lines, and the same fitted curve, bit for bit; returns the points compared.
inline std::size_t expect_same_profile(const LoadedProfile& a, const LoadedProfile& b,
                                       int line_shift) {
  EXPECT_EQ(a.points.points.size(), b.points.points.size());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < std::min(a.points.points.size(), b.points.points.size()); ++i) {
    EXPECT_EQ(a.points.points[i], b.points.points[i]) << i;
    EXPECT_EQ(a.points.lines[i], b.points.lines[i] + line_shift) << i;
    ++compared;
  }
  const PointList ka = a.profile.knot_points(), kb = b.profile.knot_points();
  EXPECT_EQ(ka.size(), kb.size());
  for (std::size_t i = 0; i < std::min(ka.size(), kb.size()); ++i, ++compared)
    EXPECT_EQ(ka[i], kb[i]) << "knot " << i;
  return compared;
}

}  // namespace wheelwear::profiles::real_rail
