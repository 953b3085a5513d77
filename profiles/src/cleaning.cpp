#include "wheelwear/profiles/cleaning.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

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

constexpr std::size_t kListedLines = 20;

// Counts the flagged points and collects their lines (first_lines_in_file_order sorts them).
void record(CleaningStep& step, const RawProfile& raw, const std::vector<bool>& drop) {
  for (std::size_t i = 0; i < drop.size(); ++i) {
    if (!drop[i]) continue;
    ++step.dropped;
    if (i < raw.lines.size() && raw.lines[i] > 0) step.lines.push_back(raw.lines[i]);
  }
}

void first_lines_in_file_order(std::vector<int>& lines) {
  std::sort(lines.begin(), lines.end());
  if (lines.size() > kListedLines) lines.resize(kListedLines);
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

std::string CropReport::summary() const {
  if (cropped() == 0) return "";
  std::ostringstream out;
  const auto side = [&](const char* name, std::size_t count, std::pair<int, int> lines) {
    out << name << " " << count;
    if (lines.first > 0) {
      out << (lines.first == lines.second ? ", line " : ", lines ") << lines.first;
      if (lines.second != lines.first) out << " ... " << lines.second;
    }
    out << "; ";
  };
  out << "cropped " << cropped() << (cropped() == 1 ? " point" : " points") << " deeper than "
      << format_mm(depth) << " below the top of rail (";
  if (gauge_side > 0) side("gauge side", gauge_side, gauge_lines);
  if (field_side > 0) side("field side", field_side, field_lines);
  out << "down to " << core::format_mm(deepest, 1) << ")";
  return out.str();
}

std::size_t CleaningReport::merged() const {
  for (const CleaningStep& step : steps)
    if (step.name == "merge_duplicates") return step.dropped;
  return 0;
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
  if (crop.cropped() > 0)
    out << "; cropped " << crop.cropped() << " below " << format_mm(crop.depth);
  if (lip.hidden > 0) out << "; shadowed " << lip.hidden << " under a lip";
  std::string read;
  for (const ReadRepair& repair : reading)
    read += (read.empty() ? "" : ", ") + repair.name + " " + std::to_string(repair.count);
  if (!read.empty()) out << "; read: " << read;
  return out.str();
}

void check_crop_depth(double depth) {
  require(std::isfinite(depth) && (depth == 0.0 || (depth >= 0.014 && depth <= 0.2)),
          "rail crop depth [m]", depth,
          "must be 0 (no crop) or in [0.014, 0.2]: the gauge point lies 14 mm below the top");
}

CropReport crop_rail(RawProfile& raw, double depth, const CleaningOptions& options) {
  check_crop_depth(depth);
  options.validate();
  CropReport report;
  report.depth = depth;
  auto& pts = raw.points;
  if (depth == 0.0 || pts.size() < 3) return report;
  if (raw.lines.size() != pts.size()) raw.lines.assign(pts.size(), 0);

  std::vector<double> ys, zs;
  for (const Point& p : pts) {
    ys.push_back(p[0]);
    zs.push_back(p[1]);
  }
  const double ym = median(ys), zm = median(zs);
  double top = std::numeric_limits<double>::infinity();
  for (const Point& p : pts)
    if (std::abs(p[0] - ym) <= options.box_half_width &&
        std::abs(p[1] - zm) <= options.box_half_height)
      top = std::min(top, p[1]);
  if (!std::isfinite(top)) return report;
  report.top = top;
  const auto deep = [&](std::size_t i) { return pts[i][1] - top > depth; };

  // The runs of deep points at both ends; each keeps its point next to the head.
  const std::size_t n = pts.size();
  std::size_t first = 0;
  while (first < n && deep(first)) ++first;
  if (first == n) return report;  // nothing above the depth: leave it to validation
  std::size_t last = n - 1;
  while (deep(last)) --last;
  // The deep point next to the head is kept only where the measurement runs on through the
  // depth; one far below it lies across a gap in the data, which it would only carry inwards.
  const auto reaches = [&](std::size_t i) {
    return pts[i][1] - top <= depth + kCropNeighbourReach;
  };
  const std::size_t keep_first = first > 0 && reaches(first - 1) ? 1 : 0;
  const std::size_t keep_last = last + 1 < n && reaches(last + 1) ? 1 : 0;
  std::vector<bool> drop(n, false);
  for (std::size_t i = 0; i + keep_first < first; ++i) drop[i] = true;
  for (std::size_t i = last + 1 + keep_last; i < n; ++i) drop[i] = true;
  report.gauge_side = first - keep_first;
  report.field_side = n - 1 - last - keep_last;
  // Line ranges in file order: orientation may have reversed the rows.
  const auto range = [&](std::size_t from, std::size_t to) {  // points [from, to)
    std::pair<int, int> lines{0, 0};
    if (from >= to || raw.lines[from] <= 0 || raw.lines[to - 1] <= 0) return lines;
    lines = {raw.lines[from], raw.lines[to - 1]};
    if (lines.first > lines.second) std::swap(lines.first, lines.second);
    return lines;
  };
  report.gauge_lines = range(0, report.gauge_side);
  report.field_lines = range(n - report.field_side, n);
  for (std::size_t i = 0; i < n; ++i)
    if (drop[i]) report.deepest = std::max(report.deepest, pts[i][1] - top);
  raw.erase_if(drop);
  return report;
}

std::string LipReport::summary() const {
  if (hidden == 0) return "";
  std::ostringstream out;
  out << "shadowed " << hidden << " points under the head's lips";
  if (lines.first > 0) out << " (lines " << lines.first << " ... " << lines.second << ")";
  out << " from " << core::format_mm(edge_depth, 1) << " below the top of rail, down to "
      << core::format_mm(deepest, 1)
      << ": a face below its lip's edge is taken as vertical, as a wheel's flange meets it";
  if (added > 0) out << " (" << added << " points added)";
  return out.str();
}

namespace {

// The points of one side of the head hidden under a lip: walking away from the top (towards
// index 0 for the gauge side, `step` -1, or the last index for the field side, +1), each point
// that lies behind the outermost one so far. Returns the outermost point's index (the edge).
std::size_t hide_under_lip(const PointList& pts, std::size_t top, int step,
                           std::vector<bool>& hidden) {
  std::size_t edge = top;
  const double outward = step < 0 ? -1.0 : 1.0;  // the gauge side lies at -y
  for (auto i = static_cast<long>(top) + step; i >= 0 && i < static_cast<long>(pts.size());
       i += step) {
    const auto k = static_cast<std::size_t>(i);
    if (outward * (pts[k][0] - pts[edge][0]) >= 0.0)
      edge = k;
    else
      hidden[k] = true;
  }
  return edge;
}

// Vertical points every 0.5 mm below `edge` down to z `bottom`, from the edge downwards.
PointList vertical_face(const Point& edge, double bottom) {
  constexpr double kSpacing = 0.5e-3;
  PointList face;
  for (double z = edge[1] + kSpacing; z < bottom + 1e-12; z += kSpacing)
    face.emplace_back(edge[0], z);
  return face;
}

}  // namespace

LipReport shadow_lip(RawProfile& raw, double max_depth) {
  LipReport report;
  auto& pts = raw.points;
  if (pts.size() < 3) return report;
  if (raw.lines.size() != pts.size()) raw.lines.assign(pts.size(), 0);
  std::size_t top = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i][1] < pts[top][1]) top = i;
  const double top_z = pts[top][1];
  std::vector<bool> hidden(pts.size(), false);
  const Point gauge_edge = pts[hide_under_lip(pts, top, -1, hidden)];
  const Point field_edge = pts[hide_under_lip(pts, top, +1, hidden)];
  std::vector<int> hidden_lines;
  double gauge_deepest = 0.0, field_deepest = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!hidden[i]) continue;
    ++report.hidden;
    if (raw.lines[i] > 0) hidden_lines.push_back(raw.lines[i]);
    double& deepest = i < top ? gauge_deepest : field_deepest;
    deepest = std::max(deepest, pts[i][1] - top_z);
  }
  if (report.hidden == 0) return report;
  if (!hidden_lines.empty())
    report.lines = {*std::min_element(hidden_lines.begin(), hidden_lines.end()),
                    *std::max_element(hidden_lines.begin(), hidden_lines.end())};
  report.deepest = std::max(gauge_deepest, field_deepest);
  report.edge_depth = (gauge_deepest > 0.0 ? gauge_edge : field_edge)[1] - top_z;
  const bool gauge_ends_hidden = hidden.front();
  const bool field_ends_hidden = hidden.back();
  raw.erase_if(hidden);
  // Where a side ends under its lip, its face continues vertically below the edge (deepest
  // first at the gauge end, which runs towards index 0).
  // The faces reach no deeper than a wheel can touch (the crop depth): a damaged file's stray
  // point metres down must not become a face of thousands of points.
  gauge_deepest = std::min(gauge_deepest, max_depth);
  field_deepest = std::min(field_deepest, max_depth);
  if (gauge_ends_hidden) {
    PointList face = vertical_face(gauge_edge, top_z + gauge_deepest);
    std::reverse(face.begin(), face.end());
    report.added += face.size();
    pts.insert(pts.begin(), face.begin(), face.end());
    raw.lines.insert(raw.lines.begin(), face.size(), 0);
  }
  if (field_ends_hidden) {
    const PointList face = vertical_face(field_edge, top_z + field_deepest);
    report.added += face.size();
    pts.insert(pts.end(), face.begin(), face.end());
    raw.lines.insert(raw.lines.end(), face.size(), 0);
  }
  return report;
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
    first_lines_in_file_order(step.lines);
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
    first_lines_in_file_order(step.lines);
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
    first_lines_in_file_order(step.lines);
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
    first_lines_in_file_order(step.lines);
    report.steps.push_back(step);
  }

  // 5. kinks (reported only)
  for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
    const double angle = turn_deg(pts[k - 1], pts[k], pts[k + 1]);
    if (angle > options.kink_deg) report.kinks.push_back({raw.lines[k], pts[k], angle});
  }
  std::stable_sort(report.kinks.begin(), report.kinks.end(),
                   [](const Kink& a, const Kink& b) { return a.line < b.line; });

  report.kept_points = pts.size();
  const double fraction = report.input_points > 0 ? static_cast<double>(report.discarded()) /
                                                        static_cast<double>(report.input_points)
                                                  : 0.0;
  if (fraction > options.max_drop_fraction) {
    std::ostringstream message;
    message << raw.source << ": cleaning dropped " << report.discarded() << " of "
            << report.input_points << " points (" << std::lround(100.0 * fraction)
            << "%), more than the allowed " << 100.0 * options.max_drop_fraction << "%: ";
    bool first = true;
    for (const CleaningStep& step : report.steps)
      if (step.dropped > 0 && step.name != "merge_duplicates") {
        message << (first ? "" : ", ") << step.name << " " << step.dropped << " (" << step.rule
                << ")";
        first = false;
      }
    if (report.merged() > 0)
      message << "; besides, " << report.merged() << " near-duplicate points were merged (not "
              << "counted)";
    message << ". The data are too noisy or are not one profile.";
    throw InputError(message.str());
  }
  return report;
}

}  // namespace wheelwear::profiles
