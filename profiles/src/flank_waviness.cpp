#include "flank_waviness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "wheelwear/profiles/profile_source.hpp"

namespace wheelwear::profiles::detail {

namespace {

// A wave's peak stands this far above the dips on either side of it [degrees]: measured
// records of smooth flanks vary by about 1 degree from the fit's 0.3 mm smoothing.
constexpr double kPeakDrop_deg = 4.0;
// Peaks this close laterally are waves of one flank, not two worn facets [m]: the measured
// record this was found on has them 1.0-1.8 mm apart.
constexpr double kWaveSpan_m = 3e-3;
// Only the flank counts: the tread and the flange tip's rounding lie below it [degrees].
constexpr double kFlankAngle_deg = 40.0;
// Sampling along the arc length [m]: a tenth of the shortest wave that matters.
constexpr double kStep_m = 0.05e-3;

struct SlopePeak {
  double y = 0.0;      // lateral position [m]
  double angle = 0.0;  // [degrees]
};

double slope_angle_deg(const Profile& wheel, double s) {
  const Point t = wheel.tangent(s);
  return std::atan2(std::abs(t.y()), std::abs(t.x())) * 180.0 / std::numbers::pi;
}

// The arc length of the flange tip: the lowest point (largest z, + downwards) on the flange
// side of the taping line (y < 0).
double flange_tip(const Profile& wheel) {
  double tip = 0.0, deepest = -std::numeric_limits<double>::infinity();
  for (double s = 0.0; s <= wheel.length(); s += kStep_m) {
    const Point p = wheel.position(s);
    if (p.x() < 0.0 && p.y() > deepest) {
      deepest = p.y();
      tip = s;
    }
  }
  return tip;
}

// The slope's peaks from the flange tip to the taping line, each standing kPeakDrop_deg above
// the dips on both sides (hysteresis: a peak counts once the slope has fallen that far).
std::vector<SlopePeak> flank_peaks(const Profile& wheel) {
  const double tip = flange_tip(wheel);
  const double direction =
      wheel.position(std::min(tip + kStep_m, wheel.length())).x() > wheel.position(tip).x() ? 1.0
                                                                                            : -1.0;
  std::vector<SlopePeak> peaks;
  SlopePeak top{wheel.position(tip).x(), 0.0};
  double dip = 0.0;
  bool rising = true;
  for (double s = tip; s >= 0.0 && s <= wheel.length(); s += direction * kStep_m) {
    const double y = wheel.position(s).x();
    if (y > 0.0) break;  // past the taping line
    const double angle = slope_angle_deg(wheel, s);
    if (rising) {
      if (angle > top.angle) top = {y, angle};
      if (angle < top.angle - kPeakDrop_deg) {
        if (top.angle >= kFlankAngle_deg) peaks.push_back(top);
        rising = false;
        dip = angle;
      }
    } else {
      dip = std::min(dip, angle);
      if (angle > dip + kPeakDrop_deg) {
        rising = true;
        top = {y, angle};
      }
    }
  }
  return peaks;
}

}  // namespace

std::optional<std::string> wavy_flank_warning(const Profile& wheel, const std::string& source,
                                              double smoothing_length) {
  const std::vector<SlopePeak> peaks = flank_peaks(wheel);
  // Waves repeat: three peaks in a row, each within kWaveSpan_m of the next (two can be the
  // facets of a worn flank: its original slope and a band worn steeper).
  bool wavy = false;
  for (std::size_t k = 2; k < peaks.size(); ++k)
    wavy = wavy || (std::abs(peaks[k].y - peaks[k - 1].y) < kWaveSpan_m &&
                    std::abs(peaks[k - 1].y - peaks[k - 2].y) < kWaveSpan_m);
  if (!wavy) return std::nullopt;
  std::string angles;
  for (const SlopePeak& p : peaks) {
    char text[16];
    std::snprintf(text, sizeof text, "%s%.0f", angles.empty() ? "" : ", ", p.angle);
    angles += text;
  }
  // Twice the present smoothing, at least 2 mm (which fits the record this was found on as
  // one flank), at most what a fit admits.
  const double longer = std::clamp(2.0 * smoothing_length, 2e-3, kMaxSmoothingLength);
  char present[16], suggested[16], metres[16], option[16];
  std::snprintf(present, sizeof present, "%.2g mm", smoothing_length * 1e3);
  std::snprintf(suggested, sizeof suggested, "%.2g mm", longer * 1e3);
  std::snprintf(metres, sizeof metres, "%.2g", longer);
  std::snprintf(option, sizeof option, "%.4g", longer);
  return source + ": the flank is wavy: its slope peaks " + std::to_string(peaks.size()) +
         " times (" + angles + " degrees) within a few millimetres with the fit's " + present +
         " smoothing; the contact then jumps from wave to wave and a vehicle on it may find no "
         "balance. A longer smoothing fits one flank (" +
         suggested + ": the scene's [wheel] smoothing_length_m = " + metres + ", or --smoothing " +
         option + ")";
}

}  // namespace wheelwear::profiles::detail
