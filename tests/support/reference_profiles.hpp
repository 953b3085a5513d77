#pragma once
// The Manchester-benchmark S1002 wheel and UIC60 rail (canted 1:40 in the file) that CONTACT's
// wheel/rail reference results were computed with (tests/data/contact/profiles).

#include <string>

#include "support/csv_table.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/profiles/profile_loader.hpp"

namespace wheelwear::testing {

/// tests/data/`path`, read as a `body` and fitted with the smoothing length `smoothing` [m].
inline profiles::Profile test_profile(
    const std::string& path, profiles::Body body,
    double smoothing = profiles::LoadOptions{}.curve.smoothing_length) {
  profiles::LoadOptions options;
  options.read.body = body;
  options.curve.smoothing_length = smoothing;
  return profiles::load_profile(test_data(path), options).profile;
}

inline profiles::Profile load_reference_profile(const std::string& file, profiles::Body body) {
  return test_profile("contact/profiles/" + file, body);
}

/// A wheel worn by this program, tests/data/profiles/`file` (y, z in mm).
inline profiles::Profile worn_wheel(const std::string& file) {
  return test_profile("profiles/" + file, profiles::Body::wheel);
}

/// The pair of CONTACT's set d, built once.
inline const contactgeom::WheelRailPair& benchmark_pair() {
  static const contactgeom::WheelRailPair pair(
      load_reference_profile("MBench_S1002_v3.prw", profiles::Body::wheel),
      load_reference_profile("MBench_UIC60_v3.prr", profiles::Body::rail));
  return pair;
}

}  // namespace wheelwear::testing
