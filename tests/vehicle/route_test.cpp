// Routes: the track along a route against hand-computed clothoids with linear cant ramps, the
// cutting into wear-step pieces (once over the route, shares summing to 1), the built-in default
// route against its stated rules (EN 13803 transition criteria, cant deficiency, the
// collective's shares), and the mirror image of a route. The reader: route_file_test.cpp.

#include "wheelwear/vehicle/route.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Interpolated values come from t = offset / L and one multiply-add on values of order 1: a few
// roundings, so 1e-12 relative is ample and still catches any wrong formula.
constexpr double kInterpolation = 1e-12;
// Piece lengths are differences of boundaries within a factor 2 of each other (Sterbenz: exact),
// so they add up, compensated, to the route's length to the last bits of 1e5 m (1.5e-11 m);
// 1e-9 m leaves room and is the bound a wear step needs.
constexpr double kLengthTolerance_m = 1e-9;

RouteSection section(SectionKind kind, double length, double radius, double cant, double speed,
                     std::string name = {}) {
  RouteSection s;
  s.kind = kind;
  s.length_m = length;
  s.radius_m = radius;
  s.cant_m = cant;
  s.speed_m_s = speed;
  s.name = std::move(name);
  return s;
}

// Tangent, a transition into R 500, the curve, a compound transition out to R 1000 with less
// cant, that curve, a transition to tangent track, a tangent.
Route hand_route() {
  Route r;
  r.name = "hand";
  r.sections = {
      section(SectionKind::tangent, 100.0, 0.0, 0.0, 40.0, "tangent in"),
      section(SectionKind::transition, 50.0, 500.0, 0.1, 25.0),
      section(SectionKind::curve, 200.0, 500.0, 0.1, 25.0, "R500"),
      section(SectionKind::transition, 40.0, 1000.0, 0.05, 25.0),
      section(SectionKind::curve, 100.0, 1000.0, 0.05, 30.0, "R1000"),
      section(SectionKind::transition, 60.0, 0.0, 0.0, 30.0),
      section(SectionKind::tangent, 100.0, 0.0, 0.0, 40.0, "tangent out"),
  };
  return r;
}

// Neumaier's compensated sum: its own rounding stays at a few eps of the total, so a test of a
// sum sees the summands' errors, not the summation's.
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    compensation_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0, compensation_ = 0.0;
};

void expect_relative(double actual, double expected, double relative, const std::string& what) {
  EXPECT_NEAR(actual, expected, relative * std::max(std::abs(expected), 1e-300)) << what;
}

TEST(Route, TrackAtBoundariesAndInsideTransitions) {
  const Route r = hand_route();
  EXPECT_TRUE(r.validate().empty());
  ASSERT_EQ(r.total_length(), 650.0);  // whole metres: exact
  struct Expected {
    double s, curvature, cant;
    std::size_t section;
  };
  // Hand-computed: in the first transition (100 ... 150 m) kappa = t / 500, C = 0.1 t with
  // t = (s - 100) / 50; in the compound one (350 ... 390 m) kappa = 1/500 + t (1/1000 - 1/500),
  // C = 0.1 - 0.05 t; in the last (490 ... 550 m) kappa = (1 - t) / 1000, C = 0.05 (1 - t).
  const Expected points[] = {
      {0.0, 0.0, 0.0, 0},                 // route start
      {100.0, 0.0, 0.0, 1},               // boundary: the transition's start
      {110.0, 0.2 / 500.0, 0.02, 1},      // t = 0.2
      {125.0, 0.5 / 500.0, 0.05, 1},      // t = 0.5
      {150.0, 1.0 / 500.0, 0.1, 2},       // boundary: the curve
      {250.0, 1.0 / 500.0, 0.1, 2},       // inside the curve
      {350.0, 1.0 / 500.0, 0.1, 3},       // boundary: the compound transition's start
      {360.0, 0.00175, 0.0875, 3},        // t = 0.25
      {380.0, 0.00125, 0.0625, 3},        // t = 0.75
      {390.0, 1.0 / 1000.0, 0.05, 4},     // boundary: R 1000
      {490.0, 1.0 / 1000.0, 0.05, 5},     // boundary: the last transition
      {505.0, 0.75 / 1000.0, 0.0375, 5},  // t = 0.25
      {550.0, 0.0, 0.0, 6},               // boundary: tangent
      {650.0, 0.0, 0.0, 6},               // route end: the last section's
  };
  int compared = 0;
  for (const Expected& e : points) {
    const TrackPoint p = track_at(r, e.s);
    const std::string at = "s = " + std::to_string(e.s);
    EXPECT_EQ(p.section, e.section) << at;
    expect_relative(p.curvature_1_m, e.curvature, kInterpolation, at + " curvature");
    expect_relative(p.cant_m, e.cant, kInterpolation, at + " cant");
    expect_relative(p.radius_m, e.curvature == 0.0 ? 0.0 : 1.0 / e.curvature, kInterpolation,
                    at + " radius");
    const double speed = r.sections[e.section].speed_m_s;
    EXPECT_EQ(p.speed_m_s, speed) << at;
    // Cant deficiency 1.5 V^2 kappa / 9.81 - C, the same few roundings.
    EXPECT_NEAR(p.cant_deficiency_m, 1.5 * speed * speed * e.curvature / 9.81 - e.cant,
                kInterpolation)
        << at;
    compared += 6;
  }
  // Curvature and cant are continuous at every boundary (the sections join): just before each
  // boundary they equal the values at it to within the slope times 1e-9 m.
  for (double boundary : {100.0, 150.0, 350.0, 390.0, 490.0, 550.0}) {
    const TrackPoint before = track_at(r, boundary - 1e-9);
    const TrackPoint at = track_at(r, boundary);
    EXPECT_NEAR(before.curvature_1_m, at.curvature_1_m, 1e-12) << boundary;  // slope <= 4e-5 /m
    EXPECT_NEAR(before.cant_m, at.cant_m, 1e-11) << boundary;                // slope <= 2e-3
    compared += 2;
  }
  // A curve's radius is its own, not 1 / (1 / R).
  EXPECT_EQ(track_at(r, 250.0).radius_m, 500.0);
  EXPECT_EQ(track_at(r, 125.0).offset_m, 25.0);
  compared += 2;
  std::printf("compared %d values\n", compared);
}

TEST(Route, TrackAtRefusesPointsOutsideTheRoute) {
  const Route r = hand_route();
  for (double s : {-1e-9, 650.0 + 1e-6, std::nan("")})
    EXPECT_THROW(track_at(r, s), InputError) << s;
}

// The pieces of a route for one maximum piece length.
void expect_pieces_cover(const Route& r, double max_length) {
  const std::vector<RoutePiece> pieces = route_pieces(r, max_length);
  const double total = r.total_length();
  ASSERT_FALSE(pieces.empty());
  CompensatedSum length_sum, share_sum;
  double plain_share_sum = 0.0;
  double expected_start = 0.0;
  std::size_t expected_count = 0;
  for (std::size_t i = 0; i < r.sections.size(); ++i) {
    const RouteSection& s = r.sections[i];
    expected_count += s.kind == SectionKind::curve
                          ? 1
                          : static_cast<std::size_t>(std::ceil(s.length_m / max_length - 1e-12));
  }
  EXPECT_EQ(pieces.size(), expected_count) << "max " << max_length;
  std::map<std::size_t, CompensatedSum> per_section;
  for (const RoutePiece& p : pieces) {
    // Each piece starts where the one before ends (no gap, no overlap).
    EXPECT_NEAR(p.start_m, expected_start, kLengthTolerance_m) << "max " << max_length;
    expected_start = p.start_m + p.length_m;
    EXPECT_GT(p.length_m, 0.0);
    const RouteSection& s = r.sections[p.section];
    if (s.kind == SectionKind::curve) {
      EXPECT_EQ(p.kind, PieceKind::constant_curve);
      EXPECT_NEAR(p.length_m, s.length_m, kLengthTolerance_m);  // whole
    } else {
      EXPECT_EQ(p.kind, PieceKind::time_domain);
      EXPECT_LE(p.length_m, max_length * (1.0 + 1e-12));  // one rounding of L / n
    }
    // The share is the length's: one division.
    EXPECT_NEAR(p.share, p.length_m / total, 2.0 * kEps * p.share);
    length_sum.add(p.length_m);
    share_sum.add(p.share);
    plain_share_sum += p.share;
    per_section[p.section].add(p.length_m);
  }
  EXPECT_NEAR(expected_start, total, kLengthTolerance_m);
  EXPECT_NEAR(length_sum.value(), total, kLengthTolerance_m) << "max " << max_length;
  // Each share is its length's with one rounding (eps / 2 relative), so compensated they sum to
  // 1 within eps / 2 plus the sum's own few eps: 4 eps.
  EXPECT_NEAR(share_sum.value(), 1.0, 4.0 * kEps) << "max " << max_length;
  // Summed plainly, as a caller would, each addition may round once more: n eps.
  EXPECT_NEAR(plain_share_sum, 1.0, static_cast<double>(pieces.size()) * kEps)
      << "max " << max_length;
  ASSERT_EQ(per_section.size(), r.sections.size());  // every section, once
  for (const auto& [i, length] : per_section)
    EXPECT_NEAR(length.value(), r.sections[i].length_m, kLengthTolerance_m) << "section " << i;
}

TEST(Route, PiecesCoverTheRouteOnceAndSharesSumToOne) {
  int routes = 0;
  for (const Route& r : {hand_route(), default_route(), mirrored(default_route())}) {
    for (double max_length : {1.0, 7.0, 33.3, 100.0, 1000.0, 1e6}) {
      SCOPED_TRACE(r.name + ", max " + std::to_string(max_length));
      expect_pieces_cover(r, max_length);
      ++routes;
    }
  }
  std::printf("checked %d route / piece-length combinations\n", routes);
}

TEST(Route, PiecesOfTheDefaultRoute) {
  const Route r = default_route();
  const std::vector<RoutePiece> pieces = route_pieces(r, 100.0);
  double curve_share = 0.0;
  std::size_t curves = 0;
  for (const RoutePiece& p : pieces)
    if (p.kind == PieceKind::constant_curve) {
      curve_share += p.share;
      ++curves;
    }
  EXPECT_EQ(curves, 10u);                 // ten curves, each one piece
  EXPECT_NEAR(curve_share, 0.45, 1e-14);  // 45 km of 100 km; a few roundings
  // 54.32 km of tangent in 5 x 109 pieces, 14 transitions of <= 70 m in one piece each.
  EXPECT_EQ(pieces.size(), 10u + 5u * 109u + 14u);
}

TEST(Route, PiecesRefuseBadLengths) {
  const Route r = hand_route();
  for (double max_length : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(route_pieces(r, max_length), InputError) << max_length;
  // 100 km in pieces of 1 mm would be 1e8 pieces.
  EXPECT_THROW(route_pieces(default_route(), 1e-3), InputError);
}

// The start of a valid route file; the cases append one bad section to it.
TEST(Route, LargeCantDeficiencyWarnsButIsAccepted) {
  Route r;
  r.name = "fast";
  // 1.5 x 50^2 / (9.81 x 500) - 0.1 = 0.665 m: far beyond any limit, but a warning only.
  r.sections = {section(SectionKind::curve, 100.0, 500.0, 0.1, 50.0, "too fast")};
  const std::vector<std::string> warnings = r.validate();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("section 1 (\"too fast\")"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("cant deficiency 0.66"), std::string::npos) << warnings[0];
  EXPECT_NO_THROW(track_at(r, 50.0));
}

TEST(Route, DefaultRouteKeepsItsRules) {
  const Route r = default_route();
  // The file on disk is the text compiled in.
  const Route from_file = read_route(std::filesystem::path(WHEELWEAR_TEST_DATA) / ".." / ".." /
                                     "data" / "routes" / "default.toml");
  ASSERT_EQ(from_file.sections.size(), r.sections.size());
  EXPECT_TRUE(r.validate().empty());
  EXPECT_LE(r.sections.size(), 30u);
  EXPECT_EQ(r.total_length(), 100e3);  // whole metres: exact

  int compared = 0;
  std::map<double, double> curve_length;  // per |R|
  std::map<double, double> hand_balance;  // per |R|: right minus left
  double tangent_and_transitions = 0.0;
  for (std::size_t i = 0; i < r.sections.size(); ++i) {
    const RouteSection& s = r.sections[i];
    const std::string at = "section " + std::to_string(i + 1);
    if (s.kind == SectionKind::curve) {
      // The stated rule: cant deficiency about 0.07 m, within 0.05 ... 0.10 m.
      const double deficiency = cant_deficiency(s.speed_m_s, s.curvature(), s.cant_m);
      EXPECT_GE(deficiency, 0.05) << at;
      EXPECT_LE(deficiency, 0.10) << at;
      curve_length[std::abs(s.radius_m)] += s.length_m;
      hand_balance[std::abs(s.radius_m)] += std::copysign(s.length_m, s.radius_m);
      compared += 2;
    } else {
      tangent_and_transitions += s.length_m;
    }
    if (s.kind == SectionKind::transition) {
      // EN 13803 criteria as the file states them, at the transition's speed: the cant gradient
      // <= 2.25 mm/m, the rate of change of cant <= 50 mm/s and of cant deficiency <= 55 mm/s.
      const TrackPoint a = track_at(r, r.section_starts()[i]);
      const TrackPoint b =
          track_at(r, r.section_starts()[i] + s.length_m * (1.0 - 1e-12));  // still this section
      ASSERT_EQ(b.section, i);
      const double dC = std::abs(b.cant_m - a.cant_m);
      const double dI = std::abs(cant_deficiency(s.speed_m_s, b.curvature_1_m, b.cant_m) -
                                 cant_deficiency(s.speed_m_s, a.curvature_1_m, a.cant_m));
      const double time = s.length_m / s.speed_m_s;
      EXPECT_LE(dC / s.length_m, 2.25e-3) << at;
      EXPECT_LE(dC / time, 0.050) << at;
      EXPECT_LE(dI / time, 0.055) << at;
      // Rounded up to 10 m: no more than 10 m beyond the longest requirement.
      const double needed =
          std::max({dC / 2.25e-3, s.speed_m_s * dC / 0.050, s.speed_m_s * dI / 0.055});
      EXPECT_LT(s.length_m - needed, 10.0) << at;
      compared += 4;
    }
  }
  // The collective's shares of the distance (scripts/make_frozen_collective.py): tangent 55 %,
  // R 3000 ... 500: 12, 10, 9, 8, 6 %, as much right- as left-hand. Whole metres: exact.
  const std::map<double, double> shares = {
      {3000.0, 0.12}, {1500.0, 0.10}, {1000.0, 0.09}, {700.0, 0.08}, {500.0, 0.06}};
  EXPECT_EQ(curve_length.size(), shares.size());
  for (const auto& [radius, share] : shares) {
    EXPECT_NEAR(curve_length[radius] / r.total_length(), share, 1e-15) << radius;
    EXPECT_EQ(hand_balance[radius], 0.0) << radius;
    compared += 2;
  }
  EXPECT_NEAR(tangent_and_transitions / r.total_length(), 0.55, 1e-15);
  // Along the whole route, every 10 m, the cant deficiency stays within the same 0.10 m.
  double largest = 0.0;
  for (double s = 0.0; s <= r.total_length(); s += 10.0)
    largest = std::max(largest, track_at(r, s).cant_deficiency_m);
  EXPECT_LE(largest, 0.10);
  // One lubricated gauge face, on the tightest curve.
  int lubricated = 0;
  for (const RouteSection& s : r.sections)
    if (s.friction_flange < s.friction_top) {
      ++lubricated;
      EXPECT_EQ(std::abs(s.radius_m), 500.0);
      EXPECT_EQ(s.kind, SectionKind::curve);
      EXPECT_EQ(s.friction_flange, 0.1);
    }
  EXPECT_EQ(lubricated, 1);
  compared += 3;
  std::printf("default route: %zu sections, largest cant deficiency %.4f m, compared %d\n",
              r.sections.size(), largest, compared);
}

// The manual's example (docs/routes.md) is a valid route.
TEST(Route, MirroredRouteIsLeftHanded) {
  const Route right = hand_route();
  const Route left = mirrored(right);
  EXPECT_TRUE(left.validate().empty());
  for (std::size_t i = 0; i < right.sections.size(); ++i)
    EXPECT_EQ(left.sections[i].radius_m, -right.sections[i].radius_m);
  // The same track with its curvature's sign changed, point by point (exact: one negation).
  int compared = 0;
  for (double s = 0.0; s <= right.total_length(); s += 2.5) {
    const TrackPoint a = track_at(right, s);
    const TrackPoint b = track_at(left, s);
    EXPECT_EQ(b.curvature_1_m, -a.curvature_1_m) << s;
    EXPECT_EQ(b.radius_m, -a.radius_m) << s;
    EXPECT_EQ(b.cant_m, a.cant_m) << s;
    EXPECT_EQ(b.cant_deficiency_m, a.cant_deficiency_m) << s;
    EXPECT_EQ(b.section, a.section) << s;
    compared += 5;
  }
  // The same pieces.
  const auto pa = route_pieces(right, 20.0);
  const auto pb = route_pieces(left, 20.0);
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t k = 0; k < pa.size(); ++k) {
    EXPECT_EQ(pa[k].share, pb[k].share);
    EXPECT_EQ(pa[k].kind, pb[k].kind);
    compared += 2;
  }
  // A left-hand route written as such reads as the mirror of the right-hand one.
  const char* right_text = R"([route]
speed_m_s = 25
[[section]]
kind = "tangent"
length_m = 100
[[section]]
kind = "transition"
length_m = 50
radius_m = 600
cant_m = 0.08
[[section]]
kind = "curve"
length_m = 300
radius_m = 600
cant_m = 0.08
)";
  std::string left_text = right_text;
  for (std::size_t at; (at = left_text.find("= 600")) != std::string::npos;)
    left_text.replace(at, 5, "= -600");
  const Route parsed_left = parse_route(left_text, "left.toml");
  const Route mirror = mirrored(parse_route(right_text, "right.toml"));
  ASSERT_EQ(parsed_left.sections.size(), mirror.sections.size());
  for (std::size_t i = 0; i < mirror.sections.size(); ++i) {
    EXPECT_EQ(parsed_left.sections[i].radius_m, mirror.sections[i].radius_m);
    EXPECT_EQ(parsed_left.sections[i].cant_m, mirror.sections[i].cant_m);
    compared += 2;
  }
  // In the left-hand curve the centre lies on +y: negative curvature, same cant deficiency.
  const TrackPoint p = track_at(parsed_left, 300.0);
  EXPECT_LT(p.curvature_1_m, 0.0);
  EXPECT_NEAR(p.cant_deficiency_m, 1.5 * 25.0 * 25.0 / (9.81 * 600.0) - 0.08, kInterpolation);
  // Mirroring twice gives the route back.
  const Route twice = mirrored(left);
  for (std::size_t i = 0; i < right.sections.size(); ++i)
    EXPECT_EQ(twice.sections[i].radius_m, right.sections[i].radius_m);
  std::printf("compared %d values\n", compared + 2);
}

// Run backwards, a route is the same track seen from its other end: at distance s of the
// reversed route the track at L - s of the original with the curvature's sign changed (a
// right-hand curve is left-hand the other way) and the same cant; interpolation inside the
// transitions runs from the other end, so agreement is to interpolation rounding. Twice
// reversed, the route is the original.
TEST(Route, ReversedRouteIsTheSameTrackFromTheOtherEnd) {
  const Route forward = hand_route();
  const Route back = reversed(forward);
  EXPECT_TRUE(back.validate().empty());
  const double length = forward.total_length();
  EXPECT_NEAR(back.total_length(), length, kLengthTolerance_m);
  int compared = 1;
  // Off the boundaries (each belongs to the section that starts there, in either direction).
  for (double s = 1.25; s < length; s += 2.5) {
    const TrackPoint a = track_at(forward, length - s);
    const TrackPoint b = track_at(back, s);
    EXPECT_NEAR(b.curvature_1_m, -a.curvature_1_m, kInterpolation * 1e-3) << s;
    EXPECT_NEAR(b.cant_m, a.cant_m, kInterpolation) << s;
    EXPECT_EQ(b.speed_m_s, a.speed_m_s) << s;
    EXPECT_EQ(b.section, forward.sections.size() - 1 - a.section) << s;
    compared += 4;
  }
  const Route twice = reversed(back);
  ASSERT_EQ(twice.sections.size(), forward.sections.size());
  for (std::size_t i = 0; i < forward.sections.size(); ++i) {
    EXPECT_EQ(twice.sections[i].radius_m, forward.sections[i].radius_m) << i;
    EXPECT_EQ(twice.sections[i].cant_m, forward.sections[i].cant_m) << i;
    EXPECT_EQ(twice.sections[i].kind, forward.sections[i].kind) << i;
    compared += 3;
  }
  // A route that ends with a transition would start with one backwards.
  Route open_end = forward;
  open_end.sections.pop_back();
  EXPECT_THROW(reversed(open_end), InputError);
  std::printf("compared %d values\n", compared + 1);
}

}  // namespace
}  // namespace wheelwear::vehicle
