#include "wheelwear/profiles/wear_update.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/smoothing_spline.hpp"
#include "wheelwear/profiles/validation.hpp"

namespace wheelwear::profiles {

double WearDepth::at(double y_query) const {
  if (y.empty() || y_query < y.front() || y_query > y.back()) return 0.0;
  const auto it = std::upper_bound(y.begin(), y.end(), y_query);
  if (it == y.end()) return depth.back();
  const auto i = static_cast<std::size_t>(it - y.begin()) - 1;
  const double t = (y_query - y[i]) / (y[i + 1] - y[i]);
  return depth[i] + t * (depth[i + 1] - depth[i]);
}

void WearDepth::validate() const {
  require(y.size() >= 2, "wear depth table size", static_cast<double>(y.size()),
          "needs at least 2 points");
  require(depth.size() == y.size(), "wear depth count", static_cast<double>(depth.size()),
          "must equal the number of y positions");
  for (std::size_t i = 0; i < y.size(); ++i) {
    require_finite("wear depth y [m]", y[i]);
    if (i > 0) require(y[i] > y[i - 1], "wear depth y [m]", y[i], "must increase strictly");
    require(std::isfinite(depth[i]) && depth[i] >= 0.0 && depth[i] < 0.01, "wear depth [m]",
            depth[i], "must be finite, >= 0 and < 0.01 per update");
  }
}

void WearUpdateOptions::validate() const {
  require(std::isfinite(smoothing_length) && smoothing_length >= 0.0, "wear smoothing length [m]",
          smoothing_length, "must be finite and >= 0");
}

Profile apply_wear(const Profile& profile, const WearDepth& wear,
                   const WearUpdateOptions& options) {
  wear.validate();
  options.validate();
  const double h = profile.curve().knot_spacing();
  const std::vector<double>& s = profile.curve().knots();
  const std::size_t n = s.size();
  const double towards_mate = profile.body() == Body::wheel ? 1.0 : -1.0;
  PointList points(n), normals(n);
  Eigen::MatrixXd depth(static_cast<Eigen::Index>(n), 1);
  for (std::size_t j = 0; j < n; ++j) {
    points[j] = profile.position(s[j]);
    normals[j] = profile.normal(s[j]);
    const bool facing = towards_mate * normals[j][1] > 0.0;
    depth(static_cast<Eigen::Index>(j), 0) = facing ? wear.at(points[j][0]) : 0.0;
  }
  if (options.smoothing_length > 0.0)
    depth = smooth_values(s, depth, smoothing_lambda(options.smoothing_length, h));
  for (std::size_t j = 0; j < n; ++j)
    points[j] -= std::max(0.0, depth(static_cast<Eigen::Index>(j), 0)) * normals[j];
  if (const auto crossing = find_self_intersection(points)) {
    std::ostringstream message;
    message << "wear update of " << profile.info().name << ": the worn profile crosses itself near"
            << " (y, z) = (" << crossing->where[0] * 1e3 << ", " << crossing->where[1] * 1e3
            << ") mm; the depth is too large for the local curvature";
    throw InputError(message.str());
  }
  CurveOptions curve = profile.curve_options();
  curve.smoothing_length = 0.0;
  curve.knot_spacing = h;
  Profile worn(points, profile.info(), curve);
  return worn;
}

}  // namespace wheelwear::profiles
