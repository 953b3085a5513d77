// Patch measures on shapes with closed forms, and the fast strip path against Boost.Geometry.

#include "wheelwear/contactgeom/patch_measures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "wheelwear/contactgeom/hertz.hpp"
#include "wheelwear/contactgeom/sdec_regularisation.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;

PatchRing rectangle(double x0, double x1, double y0, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Ellipse centred at (xc, yc) as a regular n-gon inscribed in it.
PatchRing ellipse(double a, double b, double xc, double yc, int n) {
  PatchRing ring;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    ring.emplace_back(xc + a * std::cos(t), yc + b * std::sin(t));
  }
  return ring;
}

TEST(PatchMeasures, RectangleIsExact) {
  // 12 mm x 4 mm, O at y = 1 mm: W1 = 3 - 1 = 2 mm, W2 = 1 - (-1) = 2 mm... offset to 0.5 mm.
  const PatchMeasures m = measure_polygons({rectangle(-6e-3, 6e-3, -1e-3, 3e-3)}, 0.5e-3);
  EXPECT_NEAR(m.area, 48e-6, 1e-18);
  EXPECT_NEAR(m.length, 12e-3, 1e-15);
  EXPECT_NEAR(m.width, 4e-3, 1e-15);
  EXPECT_NEAR(m.centroid_x, 0.0, 1e-15);
  EXPECT_NEAR(m.centroid_y, 1e-3, 1e-15);
  EXPECT_NEAR(m.W1, 2.5e-3, 1e-15);
  EXPECT_NEAR(m.W2, 1.5e-3, 1e-15);
}

TEST(PatchMeasures, OrientationDoesNotMatter) {
  PatchRing cw = rectangle(0.0, 2.0, 0.0, 1.0);
  std::reverse(cw.begin(), cw.end());
  EXPECT_NEAR(measure_polygons({cw}, 0.5).area, 2.0, 1e-15);
}

TEST(PatchMeasures, EllipseMatchesClosedForm) {
  // Inscribed n-gon: area (n/2) a b sin(2 pi/n) exactly, -> pi a b with relative error
  // (2 pi/n)^2/6; n = 2000 gives 1.6e-6. Extents are exact at the vertices t = 0, pi/2, ...
  const double a = 6e-3, b = 4e-3;
  const int n = 2000;
  const PatchMeasures m = measure_polygons({ellipse(a, b, 1e-3, -2e-3, n)}, -3e-3);
  EXPECT_NEAR(m.area, 0.5 * n * a * b * std::sin(2.0 * kPi / n), 1e-18);
  EXPECT_LT(std::abs(m.area / (kPi * a * b) - 1.0), 2e-6);
  EXPECT_NEAR(m.length, 2.0 * a, 1e-15);
  EXPECT_NEAR(m.width, 2.0 * b, 1e-15);
  EXPECT_NEAR(m.centroid_x, 1e-3, 1e-15);
  EXPECT_NEAR(m.centroid_y, -2e-3, 1e-15);
  EXPECT_NEAR(m.W1, 5e-3, 1e-15);  // from O at -3 mm to the top at +2 mm
  EXPECT_NEAR(m.W2, 3e-3, 1e-15);
}

TEST(PatchMeasures, TwoDisjointPiecesCombine) {
  // Area-weighted centroid, union of extents.
  const PatchMeasures m =
      measure_polygons({rectangle(-1.0, 1.0, 0.0, 1.0), rectangle(-2.0, 2.0, 3.0, 4.0)}, 0.5);
  EXPECT_NEAR(m.area, 6.0, 1e-14);
  EXPECT_NEAR(m.centroid_y, (2.0 * 0.5 + 4.0 * 3.5) / 6.0, 1e-14);
  EXPECT_NEAR(m.length, 4.0, 1e-14);
  EXPECT_NEAR(m.width, 4.0, 1e-14);
  EXPECT_NEAR(m.W1, 3.5, 1e-14);
  EXPECT_NEAR(m.W2, 0.5, 1e-14);
}

KpPatch staircase_patch() {
  // A lopsided patch with a gap strip inside: two pieces.
  KpPatch p;
  p.ds = 1e-4;
  p.s_O = 2.2e-4;
  const double xl[] = {1e-3, 2e-3, 3e-3, 3e-3, 2.5e-3, 0.0, 1e-3, 0.5e-3};
  for (int j = 0; j < 8; ++j) p.strips.push_back({j * 1e-4, xl[j], 1e9 * xl[j]});
  return p;
}

TEST(PatchMeasures, StripPathEqualsBoostGeometryOnTheOutline) {
  const KpPatch p = staircase_patch();
  const std::vector<PatchRing> outline = patch_outline(p);
  ASSERT_EQ(outline.size(), 2u);
  const PatchMeasures fast = measure_patch(p);
  const PatchMeasures ref = measure_polygons(outline, p.s_O);
  // Same sums in a different order: rounding only.
  EXPECT_NEAR(fast.area, ref.area, 1e-20);
  EXPECT_NEAR(fast.area, 2e-4 * (1 + 2 + 3 + 3 + 2.5 + 1 + 0.5) * 1e-3, 1e-20);
  EXPECT_NEAR(fast.length, ref.length, 1e-16);
  EXPECT_NEAR(fast.centroid_x, ref.centroid_x, 1e-16);
  EXPECT_NEAR(fast.centroid_y, ref.centroid_y, 1e-16);
  // The edges: the staircase ends half a strip beyond the outer strips' centres (8e-4 wide);
  // measure_patch extrapolates x_lead^2 to zero from the two outer strips on each side:
  // (1e-3)^2 / ((2e-3)^2 - (1e-3)^2) = 1/3 of a strip below the first, and
  // (0.5e-3)^2 / ((1e-3)^2 - (0.5e-3)^2) = 1/3 of a strip beyond the last.
  const double third = 1e-4 / 3.0;
  EXPECT_NEAR(ref.width, 8e-4, 1e-16);
  EXPECT_NEAR(fast.width, 7e-4 + 2.0 * third, 1e-16);
  EXPECT_NEAR(fast.W1, 7e-4 + third - 2.2e-4, 1e-16);
  EXPECT_NEAR(fast.W2, 2.2e-4 + third, 1e-16);
}

// A parabolic gap (x_lead^2 = c (L^2 - s^2)) on strips 0.1 mm wide, its half-width L growing
// across three strips: the measured width follows 2 L continuously, where the staircase jumps
// by a strip each time one comes into contact.
TEST(PatchMeasures, WidthIsContinuousAsStripsComeIntoContact) {
  const double ds = 1e-4;
  double previous = 0.0;
  int compared = 0;
  for (int step = 0; step <= 300; ++step) {
    const double L = 0.21e-3 + step * 1e-6;  // 0.21 ... 0.51 mm: strips at 0.3, 0.4, 0.5 mm enter
    KpPatch p;
    p.ds = ds;
    p.s_O = 0.0;
    for (int k = -6; k <= 6; ++k) {
      const double s = k * ds;
      const double x = L * L > s * s ? 3.0 * std::sqrt(L * L - s * s) : 0.0;
      p.strips.push_back({s, x, 1e9 * x});
    }
    const PatchMeasures m = measure_patch(p);
    // The chord of a parabola through its two outer strips reaches beyond its root, most just
    // after a strip has come into contact: 0.343 ds each side at worst over this sweep; 0.375 ds
    // each side bounds it (the staircase's error reaches a whole strip).
    EXPECT_NEAR(m.width, 2.0 * L, 0.75 * ds) << "L " << L;
    // Continuous: a 1 um step of L moves the width by about 2 um; a strip entering would jump
    // it by 0.1 mm (the staircase) — 10 um bounds the slope of the extrapolation's root.
    if (step > 0) {
      EXPECT_LT(std::abs(m.width - previous), 10e-6) << "L " << L;
    }
    previous = m.width;
    ++compared;
  }
  EXPECT_EQ(compared, 301);
}

// The same parabolic gap with the openings the solver gives the strips out of contact (the
// x_lead^2 they lack, inside the list and beyond its ends): the edge is where x_lead^2, linear
// between the outer strip and the one beyond, falls to zero. As a strip leaves, its reach falls
// to 0 and the next strip's reaches a whole strip, so the width is continuous at both ends of
// every strip, and the chord of the parabola between two strips misses its root by at most
// ds/4 · (ds / L) here (0.05 ds): bound 0.15 ds each side.
TEST(PatchMeasures, WidthFollowsTheOpeningsBeyondTheEdges) {
  const double ds = 1e-4;
  double previous = 0.0;
  int compared = 0;
  for (int step = 0; step <= 300; ++step) {
    const double L = 0.21e-3 + step * 1e-6;
    const auto x2 = [L](double s) { return 9.0 * (L * L - s * s); };
    KpPatch p;
    p.ds = ds;
    p.s_O = 0.0;
    const int n = static_cast<int>(std::floor(L / ds * (1.0 - 1e-12)));
    for (int k = -n; k <= n; ++k) p.strips.push_back({k * ds, std::sqrt(x2(k * ds)), 1e9});
    p.opening_before = -x2(-(n + 1) * ds);
    p.opening_after = -x2((n + 1) * ds);
    const PatchMeasures m = measure_patch(p);
    EXPECT_NEAR(m.width, 2.0 * L, 0.3 * ds) << "L " << L;
    if (step > 0) {
      EXPECT_LT(std::abs(m.width - previous), 5e-6) << "L " << L;
      ++compared;
    }
    previous = m.width;
  }
  EXPECT_EQ(compared, 300);
}

// A worn tread's patch: a main piece around O and, four strips out of contact away, a band of
// one strip that comes into contact and leaves it. Its reach enters the width with the share
// d / (d + r), d its x_lead^2, r the largest opening of the strips between: nothing as it
// vanishes, all of it as the opening closes (the strips would join), so the width moves
// continuously where the staircase jumps by the five strips.
TEST(PatchMeasures, AnOuterBandEntersTheWidthContinuously) {
  const double ds = 1e-4;
  const auto patch = [ds](double band_x_lead, double opening) {
    KpPatch p;
    p.ds = ds;
    p.s_O = 0.0;
    for (int k = -3; k <= 3; ++k) {
      const double x = 1e-3 * (4.0 - std::abs(k));  // the main piece, x_lead^2 not parabolic
      p.strips.push_back({k * ds, x, 1e9 * x});
    }
    for (int k = 4; k <= 7; ++k) p.strips.push_back({k * ds, 0.0, 0.0, opening});
    p.strips.push_back({8 * ds, band_x_lead, 1e9 * band_x_lead});
    return p;
  };
  KpPatch main_only = patch(1.0, 0.0);
  main_only.strips.resize(7);
  // Symmetric, its edges a third of a strip beyond the outer strips: (1/(4 - 1)) ds.
  const double main_width = measure_patch(main_only).width;
  EXPECT_NEAR(main_width, (6.0 + 2.0 / 3.0) * ds, 1e-15);
  const double r = 4e-8;  // opening [m^2]: an x_lead 0.2 mm short of touching
  // With the band, the strip beyond the main piece's gauge-side edge is known: x_lead^2 taken
  // linear from the outer strip's (1e-3)^2 to its -r (the field side keeps its third).
  const double field_edge = (3.0 + 1.0 / 3.0) * ds;
  const double main_edge = (3.0 + 1e-6 / (1e-6 + r)) * ds;
  const double band_edge = 8.5 * ds;  // a lone strip reaches half a strip
  double previous = field_edge + main_edge;
  int compared = 0;
  for (int step = 1; step <= 100; ++step) {
    const double x = 0.5e-3 * step / 100.0;  // the band's x_lead: 5 um ... 0.5 mm
    const double w = measure_patch(patch(x, r)).width;
    const double share = x * x / (x * x + r);
    EXPECT_NEAR(w, main_edge + share * (band_edge - main_edge) + field_edge, 1e-15);
    // Continuous: d(share)/dx peaks at 3.25 per mm (x = sqrt(r/3)); times the band's reach of
    // 0.52 mm and a step of 5 um, 8.4 um, where the staircase jumps by the whole 0.52 mm.
    EXPECT_LT(std::abs(w - previous), 10e-6) << "x_lead " << x;
    previous = w;
    ++compared;
  }
  EXPECT_EQ(compared, 100);
  // An unknown opening (0: strips built by hand, or a patch interpolated from a table) keeps the
  // whole staircase extent, as before.
  EXPECT_NEAR(measure_patch(patch(1e-4, 0.0)).width, field_edge + band_edge, 1e-15);
}

// O blended between two bands (blended_minimum.hpp) can lie in the strips out of contact
// between them. The extent then still reaches half a strip beyond O on its far side, so that
// O lies inside the SDEC (a run of the example scene stopped on W1 < 0 here).
TEST(PatchMeasures, OBetweenTwoBandsStaysInsideThePatch) {
  const double ds = 1e-4;
  KpPatch p;
  p.ds = ds;
  p.s_O = 0.5 * ds;  // in the middle of the two strips out of contact
  for (int k = -3; k <= 3; ++k) {
    const double x = k == 0 || k == 1 ? 0.0 : 1e-3;
    p.strips.push_back({k * ds, x, 1e9 * x, x > 0.0 ? 0.0 : 1e-5});  // 10 x the bands x_lead^2
  }
  const PatchMeasures m = measure_patch(p);
  EXPECT_GE(m.W1, 0.5 * ds);
  EXPECT_GE(m.W2, 0.5 * ds);
  const Sdec sdec = regularise_sdec(m);
  EXPECT_LT(std::abs(sdec.psi), 1.0);
}

TEST(PatchMeasures, RejectsDegenerateInput) {
  EXPECT_THROW(measure_polygons({}, 0.0), InputError);
  EXPECT_THROW(measure_polygons({{{0.0, 0.0}, {1.0, 0.0}}}, 0.0), InputError);
  EXPECT_THROW(measure_polygons({{{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}}}, 0.0), InputError);
  // Self-intersecting bow tie.
  EXPECT_THROW(measure_polygons({{{0.0, 0.0}, {1.0, 1.0}, {1.0, 0.0}, {0.0, 1.0}}}, 0.5),
               InputError);
  KpPatch empty;
  empty.ds = 1e-4;
  empty.strips.push_back({0.0, 0.0, 0.0});
  EXPECT_THROW(measure_patch(empty), InputError);
}

}  // namespace
}  // namespace wheelwear::contactgeom
