#include "wheelwear/contactgeom/undeformed_distance.hpp"

#include <cmath>
#include <numbers>

#include "wheel_rail_gap.hpp"
#include "wheel_rail_solve.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

std::optional<double> undeformed_distance(const WheelRailPair& pair, const WheelsetPose& pose,
                                          double x, double y) {
  pair.validate();
  detail::validate_pose(pose);
  require_finite("x", x);
  require_finite("y", y);
  const auto rail = pair.rail.surface_at(y);
  if (!rail) return std::nullopt;
  // Where the wheel profile's y = 0 (the taping point) lies in the rail frame.
  const WheelRailOptions options;
  const detail::WheelRailGap placed(pair, pose, options, detail::rail_gauge_y(pair));
  const double shift = placed.shift(), z_tape = placed.z_tape(), r0 = pair.wheel_radius;
  const double cr = std::cos(pose.roll), sr = std::sin(pose.roll);
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);

  // A wheel point (eta, phi): X = R sin(phi) along its rolling direction, lateral eta and
  // height Zw = z_tape - r0 + R cos(phi) in the wheel's frame; rolled in the (eta, Zw) plane
  // about (0, z_tape), yawed in the (X, eta) plane, shifted into the rail frame.
  struct Point {
    double x, y, z;       // rail frame [m]
    double jx[2], jy[2];  // d(x, y)/d(eta, phi)
  };
  auto wheel_point = [&](double eta, double phi) -> std::optional<Point> {
    const auto w = pair.wheel.surface_at(eta);
    if (!w || !std::isfinite(w->dz_dy)) return std::nullopt;
    const double R = r0 + w->z - z_tape, dR = w->dz_dy;
    const double sp = std::sin(phi), cp = std::cos(phi);
    const double X = R * sp, dX[2] = {dR * sp, R * cp};
    const double Zw = z_tape - r0 + R * cp, dZ[2] = {dR * cp, -R * sp};
    const double Y = cr * eta - sr * (Zw - z_tape), dY[2] = {cr - sr * dZ[0], -sr * dZ[1]};
    Point p;
    p.x = cy * X - sy * Y;
    p.y = sy * X + cy * Y + shift;
    p.z = sr * eta + cr * (Zw - z_tape) + z_tape;
    for (int k = 0; k < 2; ++k) {
      p.jx[k] = cy * dX[k] - sy * dY[k];
      p.jy[k] = sy * dX[k] + cy * dY[k];
    }
    return p;
  };

  double eta = y - shift, phi = x / r0;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const auto p = wheel_point(eta, phi);
    if (!p) return std::nullopt;
    const double fx = p->x - x, fy = p->y - y;
    if (std::abs(fx) <= 1e-14 && std::abs(fy) <= 1e-14) {
      if (std::abs(phi) >= 0.25 * std::numbers::pi) return std::nullopt;
      return rail->z - p->z;
    }
    const double det = p->jx[0] * p->jy[1] - p->jx[1] * p->jy[0];
    if (!(std::abs(det) > 0.0)) return std::nullopt;
    eta -= (fx * p->jy[1] - fy * p->jx[1]) / det;
    phi -= (p->jx[0] * fy - p->jy[0] * fx) / det;
  }
  return std::nullopt;
}

}  // namespace wheelwear::contactgeom
