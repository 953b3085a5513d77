#include "wheelwear/contactgeom/equivalent_conicity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

namespace {

// Rolling radius at the first touch of the undeformed surfaces (no load), NaN without contact.
double rolling_radius(const contactgeom::WheelRailPair& pair, double dy) {
  contactgeom::WheelsetPose pose;
  pose.dy = dy;
  const contactgeom::WheelRailTouch touch = contactgeom::first_touch(pair, pose);
  return touch.found ? touch.rolling_radius : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

RollingRadiusDifference rolling_radius_difference(const contactgeom::WheelRailPair& left,
                                                  const contactgeom::WheelRailPair& right,
                                                  double max_shift, int samples) {
  require(std::isfinite(max_shift) && max_shift > 0.0 && max_shift < 0.05, "max_shift [m]",
          max_shift, "must lie in (0, 0.05)");
  require(samples >= 3, "samples", samples, "need at least 3 shifts");
  RollingRadiusDifference out;
  for (int i = 0; i < samples; ++i) {
    const double dy = -max_shift + 2.0 * max_shift * i / (samples - 1);
    out.dy.push_back(dy);
    // Shifted to the left, the left wheel moves towards its flange, the right one away.
    out.delta_r.push_back(rolling_radius(left, dy) - rolling_radius(right, -dy));
  }
  return out;
}

double equivalent_conicity(const RollingRadiusDifference& f, double amplitude) {
  require(std::isfinite(amplitude) && amplitude > 0.0, "amplitude [m]", amplitude,
          "must be positive");
  const std::size_t n = f.dy.size();
  if (n < 2 || amplitude > -f.dy.front() || amplitude > f.dy.back())
    return std::numeric_limits<double>::quiet_NaN();
  // Sampling t uniformly weights Delta r like a harmonic oscillation of the wheelset does.
  constexpr int kPhases = 720;
  double num = 0.0, den = 0.0;
  for (int k = 0; k < kPhases; ++k) {
    const double t = 2.0 * std::numbers::pi * (k + 0.5) / kPhases;
    const double y = amplitude * std::sin(t);
    const auto hi = std::upper_bound(f.dy.begin(), f.dy.end(), y);
    const std::size_t i =
        std::min(n - 2, static_cast<std::size_t>(std::max<long>(0, hi - f.dy.begin() - 1)));
    const double w = (y - f.dy[i]) / (f.dy[i + 1] - f.dy[i]);
    const double dr = f.delta_r[i] + w * (f.delta_r[i + 1] - f.delta_r[i]);
    if (!std::isfinite(dr)) return std::numeric_limits<double>::quiet_NaN();
    num += dr * y;
    den += y * y;
  }
  return num / (2.0 * den);
}

}  // namespace wheelwear::contactgeom
