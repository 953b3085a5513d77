#include "wheelwear/profiles/cleaning.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

double median(std::vector<double> values) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// Turning angle [deg] at b of the path a -> b -> c; 0 when a segment has no length.
double turn_deg(const Point& a, const Point& b, const Point& c) {
  const Point u = b - a, v = c - b;
  const double nu = u.norm(), nv = v.norm();
  if (nu == 0.0 || nv == 0.0) return 0.0;
  const double cosine = std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0);
  return std::acos(cosine) * 180.0 / std::numbers::pi;
}

void record(CleaningStep& step, const RawProfile& raw, const std::vector<bool>& drop) {
  for (std::size_t i = 0; i < drop.size(); ++i) {
    if (!drop[i]) continue;
    ++step.dropped;
    if (step.lines.size() < 20 && i < raw.lines.size()) step.lines.push_back(raw.lines[i]);
  }
}

std::string format_deg(double value) {
  std::ostringstream out;
  out << value << " deg";
  return out.str();
}

std::string format_mm(double metres) {
  std::ostringstream out;
  out << metres * 1e3 << " mm";
  return out.str();
}

}  // namespace

void CleaningOptions::validate() const {
  require(std::isfinite(box_half_width) && box_half_width > 0.0, "cleaning box half width [m]",
          box_half_width, "must be > 0");
  require(std::isfinite(box_half_height) && box_half_height > 0.0, "cleaning box half height [m]",
          box_half_height, "must be > 0");
  require(std::isfinite(merge_distance) && merge_distance >= 0.0, "merge distance [m]",
          merge_distance, "must be >= 0");
  require(std::isfinite(max_turn_deg) && max_turn_deg > 0.0 && max_turn_deg <= 180.0,
          "maximum turn [deg]", max_turn_deg, "must be in (0, 180]");
  require(std::isfinite(reversal_tolerance) && reversal_tolerance >= 0.0, "reversal tolerance [m]",
          reversal_tolerance, "must be >= 0");
  require(std::isfinite(max_segment_angle_deg) && max_segment_angle_deg > 0.0 &&
              max_segment_angle_deg <= 90.0,
          "maximum segment angle [deg]", max_segment_angle_deg, "must be in (0, 90]");
  require(std::isfinite(kink_deg) && kink_deg > 0.0 && kink_deg <= 180.0, "kink angle [deg]",
          kink_deg, "must be in (0, 180]");
  require(std::isfinite(max_drop_fraction) && max_drop_fraction >= 0.0 && max_drop_fraction <= 1.0,
          "maximum drop fraction", max_drop_fraction, "must be in [0, 1]");
}

std::string CleaningReport::summary() const {
  std::ostringstream out;
  out << "kept " << kept_points << " of " << input_points << " points";
  std::string details;
  for (const CleaningStep& step : steps)
    if (step.dropped > 0)
      details += (details.empty() ? "" : ", ") + step.name + " " + std::to_string(step.dropped);
  if (!details.empty()) out << " (" << details << ")";
  if (!kinks.empty()) out << "; " << kinks.size() << (kinks.size() == 1 ? " kink" : " kinks");
  return out.str();
}

CleaningReport clean(RawProfile& raw, Body body, const CleaningOptions& options) {
  options.validate();
  CleaningReport report;
  report.input_points = raw.points.size();
  auto& pts = raw.points;
  if (raw.lines.size() != pts.size()) raw.lines.assign(pts.size(), 0);

  // 1. bounding_box
  {
    CleaningStep step{"bounding_box",
                      "farther than " + format_mm(options.box_half_width) + " across or " +
                          format_mm(options.box_half_height) + " in height from the median point",
                      0,
                      {}};
    if (!pts.empty()) {
      std::vector<double> ys, zs;
      for (const Point& p : pts) {
        ys.push_back(p[0]);
        zs.push_back(p[1]);
      }
      const double ym = median(ys), zm = median(zs);
      std::vector<bool> drop(pts.size());
      for (std::size_t i = 0; i < pts.size(); ++i)
        drop[i] = !(std::abs(pts[i][0] - ym) <= options.box_half_width &&
                    std::abs(pts[i][1] - zm) <= options.box_half_height);
      record(step, raw, drop);
      raw.erase_if(drop);
    }
    report.steps.push_back(step);
  }

  // 2. merge_duplicates
  {
    CleaningStep step{"merge_duplicates", "within " + format_mm(options.merge_distance), 0, {}};
    std::vector<bool> drop(pts.size(), false);
    std::size_t i = 0;
    while (i < pts.size()) {
      std::size_t j = i + 1;
      Point sum = pts[i];
      while (j < pts.size() && (pts[j] - pts[i]).norm() <= options.merge_distance) {
        sum += pts[j];
        drop[j] = true;
        ++j;
      }
      pts[i] = sum / static_cast<double>(j - i);
      i = j;
    }
    record(step, raw, drop);
    raw.erase_if(drop);
    report.steps.push_back(step);
  }

  // 3. fold_backs: drop turns above max_turn_deg, local maxima first, until none is left.
  {
    CleaningStep step{
        "fold_backs", "turning by more than " + format_deg(options.max_turn_deg), 0, {}};
    for (std::size_t pass = 0; pass < pts.size() && pts.size() >= 3; ++pass) {
      const std::size_t n = pts.size();
      std::vector<double> turn(n, 0.0);
      for (std::size_t k = 1; k + 1 < n; ++k) turn[k] = turn_deg(pts[k - 1], pts[k], pts[k + 1]);
      std::vector<bool> drop(n, false);
      bool any = false;
      for (std::size_t k = 1; k + 1 < n; ++k) {
        if (turn[k] <= options.max_turn_deg) continue;
        if (turn[k] < turn[k - 1] || turn[k] < turn[k + 1] || (k >= 2 && drop[k - 1])) continue;
        drop[k] = any = true;
      }
      if (!any) break;
      record(step, raw, drop);
      raw.erase_if(drop);
    }
    report.steps.push_back(step);
  }

  // 4. reversing_segments
  {
    const bool enabled = options.remove_reversals.value_or(body == Body::rail);
    const bool vertical = options.max_segment_angle_deg < 90.0;
    std::string rule = "off (wheel profiles may overhang)";
    if (enabled) {
      rule = "y stepping back by more than " + format_mm(options.reversal_tolerance);
      if (vertical)
        rule += " or segments steeper than " + format_deg(options.max_segment_angle_deg);
    }
    CleaningStep step{"reversing_segments", rule, 0, {}};
    if (enabled && !pts.empty()) {
      const double max_slope = std::tan(options.max_segment_angle_deg * std::numbers::pi / 180.0);
      std::vector<bool> drop(pts.size(), false);
      Point last = pts.front();
      for (std::size_t k = 1; k < pts.size(); ++k) {
        const Point d = pts[k] - last;
        if (d[0] < -options.reversal_tolerance ||
            (vertical && std::abs(d[1]) > max_slope * std::max(d[0], 0.0)))
          drop[k] = true;
        else
          last = pts[k];
      }
      record(step, raw, drop);
      raw.erase_if(drop);
    }
    report.steps.push_back(step);
  }

  // 5. kinks (reported only)
  for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
    const double angle = turn_deg(pts[k - 1], pts[k], pts[k + 1]);
    if (angle > options.kink_deg) report.kinks.push_back({raw.lines[k], pts[k], angle});
  }

  report.kept_points = pts.size();
  const double fraction = report.input_points > 0 ? static_cast<double>(report.dropped()) /
                                                        static_cast<double>(report.input_points)
                                                  : 0.0;
  if (fraction > options.max_drop_fraction) {
    std::ostringstream message;
    message << raw.source << ": cleaning dropped " << report.dropped() << " of "
            << report.input_points << " points (" << std::lround(100.0 * fraction)
            << "%), more than the allowed " << 100.0 * options.max_drop_fraction << "%: ";
    bool first = true;
    for (const CleaningStep& step : report.steps)
      if (step.dropped > 0) {
        message << (first ? "" : ", ") << step.name << " " << step.dropped << " (" << step.rule
                << ")";
        first = false;
      }
    message << ". The data are too noisy or are not one profile.";
    throw InputError(message.str());
  }
  return report;
}

}  // namespace wheelwear::profiles
