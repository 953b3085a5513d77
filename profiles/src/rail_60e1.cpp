#include "wheelwear/profiles/rail_60e1.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

// Upright 60E1 head in millimetres (origin on the crown top, z down, y towards the field side).
// Defining dimensions: radii 300, 80 and 13 mm; the R300 crown ends at |y| = 10.5 mm; the head
// flanks are inclined 1:20 and touch the R13 arcs at |y| = 36 mm. Everything else follows from
// tangency. Checked against EN 15302:2021 Annex I "rail A" (arc centres and its Table I.6, as
// transcribed in rohrbecka/EN15302, RailA.swift): rotating this head by 0.0500 rad and
// translating it reproduces the five centres to 2e-5 mm and the 72 tabulated heights to 6e-5 mm;
// the R13 centres then sit at |y| = 23.01622 mm, z = 14.90893 mm as this construction gives.
constexpr double kR300 = 300.0, kR80 = 80.0, kR13 = 13.0;
constexpr double kCrownHalfWidth = 10.5;
constexpr double kHalfWidth = 36.0;
const double kFlankAngle = std::atan(1.0 / 20.0);

struct Geometry {
  double phi_crown;  // angle from the vertical of the R300/R80 joint [rad]
  Point c80;         // right R80 centre [mm]
  double phi_80;     // angle of the R80/R13 joint [rad]
  Point c13;         // right R13 centre [mm]
  double phi_13;     // angle of the R13/flank joint [rad]
  Point flank_top;   // right flank tangent point [mm]
};

Geometry geometry() {
  Geometry g;
  g.phi_crown = std::asin(kCrownHalfWidth / kR300);
  g.c80 =
      Point(kCrownHalfWidth, kR300 - std::sqrt(kR300 * kR300 - kCrownHalfWidth * kCrownHalfWidth)) -
      kR80 * Point(std::sin(g.phi_crown), -std::cos(g.phi_crown));
  const double y13 = kHalfWidth - kR13 * std::cos(kFlankAngle);
  const double d = kR80 - kR13;
  const double dy = y13 - g.c80[0];
  g.c13 = Point(y13, g.c80[1] - std::sqrt(d * d - dy * dy));
  g.phi_80 = std::atan2(dy, g.c80[1] - g.c13[1]);
  g.phi_13 = std::numbers::pi / 2.0 - kFlankAngle;
  g.flank_top = g.c13 + kR13 * Point(std::sin(g.phi_13), -std::cos(g.phi_13));
  return g;
}

// Point at angle phi from the vertical on an arc: outward normal (sin phi, -cos phi).
Point on_arc(const Point& centre, double radius, double phi) {
  return centre + radius * Point(std::sin(phi), -std::cos(phi));
}

void sample_arc(const Point& centre, double radius, double phi0, double phi1, double spacing,
                PointList& out) {
  const auto n = static_cast<int>(std::ceil(radius * std::abs(phi1 - phi0) / spacing));
  for (int k = 0; k < n; ++k) out.push_back(on_arc(centre, radius, phi0 + (phi1 - phi0) * k / n));
}

// Right half of the upright head [mm], from the crown top (excluded) to the flank bottom.
PointList right_half_mm(double spacing, double depth) {
  const Geometry g = geometry();
  PointList half;
  sample_arc(Point(0.0, kR300), kR300, 0.0, g.phi_crown, spacing, half);
  sample_arc(g.c80, kR80, g.phi_crown, g.phi_80, spacing, half);
  sample_arc(g.c13, kR13, g.phi_80, g.phi_13, spacing, half);
  const Point bottom(g.flank_top[0] + (depth - g.flank_top[1]) * std::tan(kFlankAngle), depth);
  const auto n = static_cast<int>(std::ceil((bottom - g.flank_top).norm() / spacing));
  for (int k = 0; k <= n; ++k) half.push_back(g.flank_top + (bottom - g.flank_top) * k / n);
  half.erase(half.begin());  // the crown top is added once, between the halves
  return half;
}

// Top of rail [mm] after an inclination alpha: the point whose outward normal the rotation makes
// vertical, i.e. the point at angle alpha from the vertical on the field side of the upright head.
Point top_of_rail(double alpha) {
  const Geometry g = geometry();
  if (alpha <= g.phi_crown) return on_arc(Point(0.0, kR300), kR300, alpha);
  if (alpha <= g.phi_80) return on_arc(g.c80, kR80, alpha);
  return on_arc(g.c13, kR13, std::min(alpha, g.phi_13));
}

}  // namespace

double inclination_angle(RailInclination inclination) {
  switch (inclination) {
    case RailInclination::one_in_40:
      return std::atan(1.0 / 40.0);
    case RailInclination::one_in_20:
      return std::atan(1.0 / 20.0);
    case RailInclination::none:
      break;
  }
  return 0.0;
}

std::vector<HeadArc> rail_60e1_arcs() {
  const Geometry g = geometry();
  const double y80 = on_arc(g.c80, kR80, g.phi_80)[0];
  const double y13 = g.flank_top[0];
  const Point c80l(-g.c80[0], g.c80[1]), c13l(-g.c13[0], g.c13[1]);
  return {
      {c13l * 1e-3, kR13 * 1e-3, -y13 * 1e-3, -y80 * 1e-3},
      {c80l * 1e-3, kR80 * 1e-3, -y80 * 1e-3, -kCrownHalfWidth * 1e-3},
      {Point(0.0, kR300 * 1e-3), kR300 * 1e-3, -kCrownHalfWidth * 1e-3, kCrownHalfWidth * 1e-3},
      {g.c80 * 1e-3, kR80 * 1e-3, kCrownHalfWidth * 1e-3, y80 * 1e-3},
      {g.c13 * 1e-3, kR13 * 1e-3, y80 * 1e-3, y13 * 1e-3},
  };
}

void Rail60E1Options::validate() const {
  require(std::isfinite(inclination) && inclination >= 0.0 && inclination <= 0.1,
          "60E1 inclination [rad]", inclination, "must be in [0, 0.1] (1:20 is 0.05)");
  require(std::isfinite(flank_depth) && flank_depth >= 0.0145 && flank_depth <= 0.0375,
          "60E1 flank depth [m]", flank_depth,
          "must be in [0.0145, 0.0375] (below the R13 arcs, within the head)");
  require(std::isfinite(point_spacing) && point_spacing >= 1e-5 && point_spacing <= 1e-3,
          "60E1 point spacing [m]", point_spacing, "must be in [1e-5, 1e-3]");
}

PointList rail_60e1_points(const Rail60E1Options& options) {
  options.validate();
  const double spacing = options.point_spacing * 1e3;
  const PointList half = right_half_mm(spacing, options.flank_depth * 1e3);
  PointList upright;
  upright.reserve(2 * half.size() + 1);
  for (auto it = half.rbegin(); it != half.rend(); ++it) upright.emplace_back(-(*it)[0], (*it)[1]);
  upright.emplace_back(0.0, 0.0);
  upright.insert(upright.end(), half.begin(), half.end());

  // Inward cant: the crown turns towards the gauge side (-y), so with z down the field side rises:
  // y' = cos(a) y + sin(a) z, z' = -sin(a) y + cos(a) z, then the top of rail goes to the origin.
  const double a = options.inclination;
  const double c = std::cos(a), s = std::sin(a);
  auto rotate = [&](const Point& p) { return Point(c * p[0] + s * p[1], -s * p[0] + c * p[1]); };
  const Point top = rotate(top_of_rail(a));
  PointList out;
  out.reserve(upright.size());
  for (const Point& p : upright) out.push_back((rotate(p) - top) * 1e-3);
  return out;
}

Profile rail_60e1(const Rail60E1Options& options, const CurveOptions& curve) {
  ProfileInfo info{"60E1", Body::rail, options.side, 0.0};
  return Profile(rail_60e1_points(options), info, curve);
}

}  // namespace wheelwear::profiles
