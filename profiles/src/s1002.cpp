#include "wheelwear/profiles/s1002.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

// S1002 in millimetres, as the standard's definition is written. Coefficients of H. Netter's
// (DLR) S1002 routine, sections A-H (y from the field side to the flange back):
//   A  z = AA - BA y                                 y in [ 32.15796,     60]
//   B  z = AB - BB y + CB y^2 - ... + IB y^8          y in [-26,           32.15796]
//   C  z = -AC - BC y - ... - HC y^7                  y in [-35,          -26]
//   D  z = AD - sqrt(BD^2 - (y + CD)^2)  (R13 root)   y in [-38.426669071, -35]
//   E  z = -AE - BE y                   (flank)      y in [-39.764473993, -38.426669071]
//   F  z = AF + sqrt(BF^2 - (y + CF)^2)  (R20 face)   y in [-49.662510381, -39.764473993]
//   G  z = AG + sqrt(BG^2 - (y + CG)^2)  (R12 tip)    y in [-62.764705882, -49.662510381]
//   H  z = AH + sqrt(BH^2 - (y + CH)^2)  (R20.5 back) y in [-70,          -62.764705882]
// Checked against CONTACT's MBench_S1002_v3.prw (Manchester contact benchmark, mirrored in y by
// its header): all 399 points agree within 1.6e-6 mm, the file's printing precision. The
// sections join within 1.2e-4 mm (C/D) and 4e-5 mm (B/C), the rounding of the coefficients; the
// flank at 10 mm below the running circle is at y = -37.500000 (Sd = 32.5 mm) and the tip at
// z = AG + BG = 28 mm (Sh = 28 mm), as EN 13715 specifies.
constexpr double kAA = 1.364323640, kBA = 0.066666667;
constexpr std::array<double, 9> kB = {0.0,
                                      3.358537058e-02,
                                      1.565681624e-03,
                                      2.810427944e-05,
                                      5.844240864e-08,
                                      1.562379023e-08,
                                      5.309217349e-15,
                                      5.957839843e-12,
                                      2.646656573e-13};
constexpr std::array<double, 8> kC = {4.320221063e+03, 1.038384026e+03, 1.065501873e+02,
                                      6.051367875,     2.054332446e-01, 4.169739389e-03,
                                      4.687195829e-05, 2.252755540e-07};
constexpr double kAD = 16.446, kBD = 13.0, kCD = 26.210665;
constexpr double kAE = 93.576667419, kBE = 2.747477419;
constexpr double kAF = 8.834924130, kBF = 20.0, kCF = 58.558326413;
constexpr double kAG = 16.0, kBG = 12.0, kCG = 55.0;
constexpr double kAH = 9.519259302, kBH = 20.5, kCH = 49.5;
// Section bounds [mm], from the flange back to the field side.
constexpr std::array<double, 9> kBounds = {-70.0,         -62.764705882, -49.662510381,
                                           -39.764473993, -38.426669071, -35.0,
                                           -26.0,         32.15796,      60.0};
// EN 13715: running circle (taping line) 70 mm from the internal face; Sd is measured 10 mm
// below it (EN 15313).
constexpr double kInternalFace = -70.0;
constexpr double kSdHeight = 10.0;
constexpr double kNominalHeight = 28.0;
// The connection zone C, where a lowered or thinned flange blends into the unchanged tread.
constexpr double kBlendStart = -35.0, kBlendEnd = -26.0;

double circle(double a, double b, double c, double y, double sign) {
  const double d = y + c;
  return a + sign * std::sqrt(std::max(0.0, b * b - d * d));
}

double nominal_z_mm(double y) {
  if (y >= kBounds[7]) return kAA - kBA * y;
  if (y >= kBounds[6]) {
    // B: alternating signs, AB - BB y + CB y^2 - DB y^3 + ...
    double sum = 0.0;
    for (std::size_t i = kB.size(); i-- > 0;) sum = sum * y + ((i % 2) ? -kB[i] : kB[i]);
    return sum;
  }
  if (y >= kBounds[5]) {
    double sum = 0.0;
    for (std::size_t i = kC.size(); i-- > 0;) sum = sum * y - kC[i];
    return sum;
  }
  if (y >= kBounds[4]) return circle(kAD, kBD, kCD, y, -1.0);
  if (y >= kBounds[3]) return -kAE - kBE * y;
  if (y >= kBounds[2]) return circle(kAF, kBF, kCF, y, 1.0);
  if (y >= kBounds[1]) return circle(kAG, kBG, kCG, y, 1.0);
  return circle(kAH, kBH, kCH, y, 1.0);
}

// Weight of the flange displacement: 1 on the flange (y <= -35), 0 on the tread (y >= -26), a
// quintic smoothstep between, so the blended profile stays C2 where the zone meets its neighbours.
double flange_weight(double y) {
  if (y <= kBlendStart) return 1.0;
  if (y >= kBlendEnd) return 0.0;
  const double x = (y - kBlendStart) / (kBlendEnd - kBlendStart);
  return 1.0 - x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}

struct ArcSection {
  double a, b, c, sign;  // z = a + sign sqrt(b^2 - (y + c)^2); centre (-c, a), radius b
};

void sample_arc(const ArcSection& arc, double y0, double y1, double spacing, PointList& out) {
  const double yc = -arc.c, zc = arc.a;
  const double t0 = std::atan2(circle(arc.a, arc.b, arc.c, y0, arc.sign) - zc, y0 - yc);
  const double t1 = std::atan2(circle(arc.a, arc.b, arc.c, y1, arc.sign) - zc, y1 - yc);
  const auto n = static_cast<int>(std::ceil(arc.b * std::abs(t1 - t0) / spacing));
  for (int k = 0; k < n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    out.emplace_back(yc + arc.b * std::cos(t), zc + arc.b * std::sin(t));
  }
}

// Lines and polynomials: march in y with steps that keep the chord near `spacing`.
void sample_graph(double y0, double y1, double spacing, PointList& out) {
  double y = y0;
  while (y < y1 - 1e-9 * spacing) {
    out.emplace_back(y, nominal_z_mm(y));
    const double e = 1e-6;
    const double slope = (nominal_z_mm(std::min(y + e, y1)) - nominal_z_mm(y)) / e;
    y += spacing / std::sqrt(1.0 + slope * slope);
  }
}

// Nominal S1002 [mm] from the back arc's vertical tangent (-70, AH) to the field side (60, ..).
PointList nominal_points_mm(double spacing) {
  PointList points;
  sample_arc({kAH, kBH, kCH, 1.0}, kBounds[0], kBounds[1], spacing, points);
  sample_arc({kAG, kBG, kCG, 1.0}, kBounds[1], kBounds[2], spacing, points);
  sample_arc({kAF, kBF, kCF, 1.0}, kBounds[2], kBounds[3], spacing, points);
  sample_graph(kBounds[3], kBounds[4], spacing, points);
  sample_arc({kAD, kBD, kCD, -1.0}, kBounds[4], kBounds[5], spacing, points);
  sample_graph(kBounds[5], kBounds[8], spacing, points);
  points.emplace_back(kBounds[8], nominal_z_mm(kBounds[8]));
  return points;
}

// y [mm] of the nominal flank point whose lowered height z + dh w(y) is 10 mm (the Sd height):
// bisection on the flange face between the tip's face side and the taping line, where that height
// falls monotonically.
double sd_point_nominal_mm(double dh) {
  double lo = kBounds[2], hi = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (nominal_z_mm(mid) + dh * flange_weight(mid) > kSdHeight)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// Where the flange back meets the internal face [mm]. Unshifted, the back arc H starts at the face
// with a vertical tangent. Shifted by de towards the face, the face cuts H; a fillet of radius
// kBackFillet rounds that corner (wheelwear's choice, not a value from EN 13715), so the profile
// stays C1 and its spline does not ring at a corner.
constexpr double kBackFillet = 3.0;

struct BackJoint {
  double face_bottom;  // z where the vertical internal face ends
  PointList fillet;    // fillet points after the face, before the back arc resumes
  double resume_y;     // the moved back arc continues beyond this y
};

BackJoint back_joint(double de, double dh) {
  BackJoint joint{kAH + dh, {}, kInternalFace};
  if (de <= 1e-9) return joint;
  const Point ch(-kCH - de, kAH + dh);  // moved centre of the back arc
  const double r = kBackFillet, R = kBH;
  const double dy = kInternalFace + r - ch[0];
  const Point cf(kInternalFace + r, ch[1] + std::sqrt((R - r) * (R - r) - dy * dy));
  const Point touch = ch + R * (cf - ch).normalized();
  joint.face_bottom = cf[1];
  joint.resume_y = touch[0];
  const double t0 = std::numbers::pi, t1 = std::atan2(touch[1] - cf[1], touch[0] - cf[0]);
  // A corner of less than 2 deg (a shift of a few micrometres) needs no rounding.
  if (r * std::abs(t0 - t1) < 0.1) return joint;
  const int n = std::max(2, static_cast<int>(std::ceil(r * std::abs(t0 - t1) / 0.05)));
  for (int k = 1; k <= n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    joint.fillet.push_back(cf + r * Point(std::cos(t), std::sin(t)));
  }
  return joint;
}

// Lateral flange shift [mm] that makes Sd equal e [mm] for a flange lowered by dh [mm], counted
// from the definition's own Sd (32.5 mm to the 3e-8 mm its rounded coefficients allow), so that
// h28/e32.5 is the definition itself.
double thickness_shift_mm(double e, double dh) {
  static const double nominal_sd = sd_point_nominal_mm(0.0) - kInternalFace;
  const double y = sd_point_nominal_mm(dh);
  return (y - kInternalFace - nominal_sd + (32.5 - e)) / flange_weight(y);
}

}  // namespace

void S1002Options::validate() const {
  require(std::isfinite(flange_height) && flange_height >= 0.028 - 1e-12 &&
              flange_height <= 0.032 + 1e-12,
          "S1002 flange height [m]", flange_height, "must be in [0.028, 0.032] (EN 13715 h28-h32)");
  require(std::isfinite(flange_thickness) && flange_thickness >= 0.028 - 1e-12 &&
              flange_thickness <= 0.0325 + 1e-12,
          "S1002 flange thickness [m]", flange_thickness,
          "must be in [0.028, 0.0325] (EN 13715 e28-e32.5)");
  require(std::isfinite(nominal_radius) && nominal_radius > 0.0, "S1002 nominal radius [m]",
          nominal_radius, "must be finite and > 0");
  require(std::isfinite(point_spacing) && point_spacing >= 1e-5 && point_spacing <= 1e-3,
          "S1002 point spacing [m]", point_spacing, "must be in [1e-5, 1e-3]");
  require_finite("S1002 back face top [m]", back_face_top);
  const double dh = flange_height * 1e3 - kNominalHeight;
  const double de = thickness_shift_mm(flange_thickness * 1e3, dh);
  // A negative shift would pull the back arc off the internal face; a shift beyond the back arc's
  // lateral extent (7.235 mm) would cut into the tip.
  require(de >= -1e-9 && de <= kBounds[1] - kBounds[0], "S1002 flange thickness [m]",
          flange_thickness,
          "with this flange height the flange cannot be moved to that thickness (needs a lateral "
          "shift of 0 to 7.2 mm towards the internal face)");
  const double face_bottom = back_joint(std::max(de, 0.0), dh).face_bottom;
  require(back_face_top * 1e3 <= face_bottom + 1e-9, "S1002 back face top [m]", back_face_top,
          "must not be below the lower end of the vertical flange back (z = " +
              std::to_string(face_bottom * 1e-3) + " m)");
}

double s1002_nominal_z(double y) {
  require(std::isfinite(y) && y >= -0.070 - 1e-12 && y <= 0.060 + 1e-12, "S1002 y [m]", y,
          "must be in [-0.070, 0.060]");
  return 1e-3 * nominal_z_mm(std::clamp(y * 1e3, kBounds[0], kBounds[8]));
}

PointList s1002_points(const S1002Options& options) {
  options.validate();
  const double spacing = options.point_spacing * 1e3;
  const double dh = options.flange_height * 1e3 - kNominalHeight;
  const double de = std::max(0.0, thickness_shift_mm(options.flange_thickness * 1e3, dh));
  const BackJoint joint = back_joint(de, dh);
  PointList out;
  const double top = options.back_face_top * 1e3;
  const auto face_steps = static_cast<int>(std::ceil((joint.face_bottom - top) / spacing));
  for (int k = 0; k < face_steps; ++k)
    out.emplace_back(kInternalFace, top + (joint.face_bottom - top) * k / face_steps);
  out.emplace_back(kInternalFace, joint.face_bottom);
  // The fillet is sampled more finely than `spacing`: 0.05 mm keeps its 3 mm radius exact.
  out.insert(out.end(), joint.fillet.begin(), joint.fillet.end());
  for (const Point& p : nominal_points_mm(spacing)) {
    const double w = flange_weight(p[0]);
    const Point q(p[0] - de * w, p[1] + dh * w);
    // Drop what the internal face and the fillet replace, and points too close to be distinct.
    if (q[0] <= joint.resume_y + 1e-6 * spacing) continue;
    if ((q - out.back()).norm() < 1e-3 * spacing) continue;
    out.push_back(q);
  }
  for (Point& p : out) p *= 1e-3;
  return out;
}

Profile s1002(const S1002Options& options, const CurveOptions& curve) {
  ProfileInfo info{"S1002", Body::wheel, options.side, options.nominal_radius};
  return Profile(s1002_points(options), info, curve);
}

}  // namespace wheelwear::profiles
