#include "surface_walk.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace wheelwear::contactgeom::detail {

namespace {

double cubic(const std::array<double, 4>& c, double u) {
  return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
}

double cubic_slope(const std::array<double, 4>& c, double u) {
  return c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]);
}

// Bernstein coefficients of c0 + c1 u + c2 u^2 + c3 u^3 on [0, h]: the cubic lies in their
// convex hull, and it rises strictly where they do.
std::array<double, 4> bernstein(const std::array<double, 4>& c, double h) {
  return {c[0], c[0] + c[1] * h / 3.0, c[0] + (2.0 * c[1] * h + c[2] * h * h) / 3.0,
          c[0] + h * (c[1] + h * (c[2] + h * c[3]))};
}

}  // namespace

void SurfaceWalk::reset(const profiles::Profile& profile, double roll, double z_pivot) {
  curve_ = &profile.curve();
  cos_ = std::cos(roll);
  sin_ = std::sin(roll);
  z0_ = z_pivot;
  n_ = curve_->segment_count();
  rising_.assign(n_, -1);
  seeded_ = open_ = false;
  auto rotated_y = [&](const profiles::Point& p) { return cos_ * p[0] - sin_ * (p[1] - z0_); };
  y_start_ = n_ > 0 ? rotated_y(curve_->position(0.0)) : 0.0;
  y_end_ = n_ > 0 ? rotated_y(curve_->position(curve_->length())) : 0.0;
}

bool SurfaceWalk::rising(std::size_t k) {
  if (rising_[k] < 0) {
    const double h = curve_->knots()[k + 1] - curve_->knots()[k];
    std::array<double, 4> b = bernstein(curve_->y_spline().coefficients(k), h);
    if (sin_ != 0.0) {
      const auto bz = bernstein(curve_->z_spline().coefficients(k), h);
      for (int j = 0; j < 4; ++j) b[j] = cos_ * b[j] - sin_ * (bz[j] - z0_);
    }
    rising_[k] = b[1] > b[0] && b[2] > b[1] && b[3] > b[2];
  }
  return rising_[k] == 1;
}

void SurfaceWalk::seed(double y, double s) {
  seeded_ = false;
  open_ = false;
  if (n_ == 0) return;
  i_ = curve_->y_spline().locate(s);
  u_ = s - curve_->knots()[i_];
  if (!rising(i_)) return;
  seeded_ = true;
  seed_y_ = last_y_ = y;
  have_rate_ = false;
  last_s_ = s;
}

std::optional<WalkPoint> SurfaceWalk::at(double y) {
  if (!seeded_) return std::nullopt;
  const std::vector<double>& knots = curve_->knots();
  const auto& ys = curve_->y_spline();
  const auto& zs = curve_->z_spline();
  std::size_t i = i_;
  double u = u_;
  // Start from the line through the last two answers (arc length against y): its error,
  // about t''(y) dy^2, leaves one Newton step on flat stretches, two on curved ones.
  if (have_rate_) {
    u += rate_ * (y - last_y_);
    while (u > knots[i + 1] - knots[i] && i + 1 < n_ && rising(i + 1)) {
      u -= knots[i + 1] - knots[i];
      ++i;
    }
    u = std::min(u, knots[i + 1] - knots[i]);
  }
  for (int iteration = 0; iteration < 12; ++iteration) {
    const auto& cy = ys.coefficients(i);
    double Y = cubic(cy, u), dY = cubic_slope(cy, u);
    if (sin_ != 0.0) {
      const auto& cz = zs.coefficients(i);
      Y = cos_ * Y - sin_ * (cubic(cz, u) - z0_);
      dY = cos_ * dY - sin_ * cubic_slope(cz, u);
    }
    if (!(dY > 0.0)) break;
    const double du = (y - Y) / dY;
    u += du;
    // Move to the interval that holds the new parameter, forwards only, through rising ones.
    while (u > knots[i + 1] - knots[i] && i + 1 < n_ && rising(i + 1)) {
      u -= knots[i + 1] - knots[i];
      ++i;
    }
    while (u < 0.0 && i > i_) {
      --i;
      u += knots[i + 1] - knots[i];
    }
    if (u < 0.0 || u > knots[i + 1] - knots[i]) break;  // off the curve or the rising stretch
    // Newton's error after a step du is |Y''/(2 Y')| du^2: below 1e-15 m for du <= 1e-9 m on
    // any profile (|Y''| <= curvature < 1/(5 mm) on an arc-length curve) where Y' > 0.1.
    if (std::abs(du) > 1e-15 && (std::abs(du) > 1e-9 || !(dY > 0.1))) continue;
    i_ = i;
    u_ = u;
    WalkPoint p;
    p.y = cubic(ys.coefficients(i), u);
    p.z = cubic(zs.coefficients(i), u);
    p.s = knots[i] + u;
    p.z_rolled = sin_ == 0.0 ? p.z : sin_ * p.y + cos_ * (p.z - z0_) + z0_;
    have_rate_ = y > last_y_;
    if (have_rate_) rate_ = (p.s - last_s_) / (y - last_y_);
    last_y_ = y;
    last_s_ = p.s;
    open_ = true;
    return p;
  }
  seeded_ = false;
  return std::nullopt;
}

bool SurfaceWalk::close(std::optional<double> looked_up_s) {
  const bool was_open = open_;
  open_ = false;
  seeded_ = false;
  if (!was_open) return true;
  auto inside = [&](double end) { return end > seed_y_ && end < last_y_; };
  return looked_up_s && std::abs(*looked_up_s - last_s_) <= 1e-9 && !inside(y_start_) &&
         !inside(y_end_);
}

}  // namespace wheelwear::contactgeom::detail
