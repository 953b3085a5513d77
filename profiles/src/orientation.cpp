#include "wheelwear/profiles/orientation.hpp"

#include <algorithm>

namespace wheelwear::profiles {

namespace {

std::size_t arg_min_z(const PointList& points) {
  return static_cast<std::size_t>(
      std::min_element(points.begin(), points.end(),
                       [](const Point& a, const Point& b) { return a[1] < b[1]; }) -
      points.begin());
}

std::size_t arg_max_z(const PointList& points) {
  return static_cast<std::size_t>(
      std::max_element(points.begin(), points.end(),
                       [](const Point& a, const Point& b) { return a[1] < b[1]; }) -
      points.begin());
}

bool near_end(std::size_t index, std::size_t count, double fraction) {
  const double position = static_cast<double>(index);
  const double n = static_cast<double>(count);
  return position < fraction * n || position > (1.0 - fraction) * n - 1.0;
}

}  // namespace

std::optional<Mirror> gauge_side_mirror(std::string_view text) {
  if (text == "auto") return Mirror::automatic;
  if (text == "left") return Mirror::keep;
  if (text == "right") return Mirror::flip;
  return std::nullopt;
}

OrientationReport orient(RawProfile& raw, Body body, const OrientationOptions& options) {
  OrientationReport report;
  auto& points = raw.points;
  if (points.size() < 3) return report;

  bool flip_z = options.mirror_z == Mirror::flip;
  if (options.mirror_z == Mirror::automatic) {
    if (body == Body::wheel) {
      const bool lowest_at_end = near_end(arg_min_z(points), points.size(), 0.05);
      const bool highest_at_end = near_end(arg_max_z(points), points.size(), 0.05);
      flip_z = !lowest_at_end && highest_at_end;
      report.notes.push_back(lowest_at_end ? "z: side faces at the ends, z already points down"
                             : highest_at_end
                                 ? "z: side faces point to +z, z negated"
                                 : "z: no side faces at the ends, kept as in the file");
    } else {
      flip_z = near_end(arg_min_z(points), points.size(), 0.10);
      report.notes.push_back(flip_z ? "z: top of rail at an end, so z pointed up; negated"
                                    : "z: top of rail inside, z already points down");
    }
  }
  if (flip_z) {
    for (Point& p : points) p[1] = -p[1];
    report.mirrored_z = true;
  }

  bool flip_y = options.mirror_y == Mirror::flip;
  if (options.mirror_y == Mirror::automatic) {
    const auto [lo, hi] = std::minmax_element(
        points.begin(), points.end(), [](const Point& a, const Point& b) { return a[0] < b[0]; });
    if (body == Body::wheel) {
      const Point& flange = points[arg_max_z(points)];
      flip_y = flange[0] > 0.5 * ((*lo)[0] + (*hi)[0]);
      report.notes.push_back(flip_y ? "y: flange on the +y side, y negated"
                                    : "y: flange on the -y side");
    } else {
      const double margin = 1e-3;  // depth difference that identifies the gauge end [m]
      flip_y = (*hi)[1] > (*lo)[1] + margin;
      report.notes.push_back(flip_y ? "y: the +y end is deeper (gauge face), y negated"
                                    : "y: gauge face taken on the -y side");
    }
  }
  if (options.mirror_y != Mirror::automatic) {
    if (body == Body::rail)
      report.notes.push_back(flip_y ? "y: gauge face at the file's larger y as set, y negated"
                                    : "y: gauge face at the file's smaller y as set");
    else
      report.notes.push_back(flip_y ? "y: negated as set" : "y: kept as set");
  }
  if (flip_y) {
    for (Point& p : points) p[0] = -p[0];
    report.mirrored_y = true;
  }

  if (points.front()[0] > points.back()[0]) {
    std::reverse(points.begin(), points.end());
    std::reverse(raw.lines.begin(), raw.lines.end());
    report.reversed = true;
    report.notes.push_back("order reversed to run from -y to +y");
  }
  return report;
}

}  // namespace wheelwear::profiles
