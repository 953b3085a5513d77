// The normal problem of the exact theory against Hertz's closed form for a sphere on a plane
// (Johnson 1985, Sec. 4.2): a^3 = 3 N R/(4 E*), p0 = 3 N/(2 pi a^2), approach a^2/R, with
// E* = G/(1 - nu) for two elastically similar bodies of combined shear modulus G.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/normal_contact.hpp"

namespace wheelwear::tangential {
namespace {

struct Hertz {
  double a, p0, approach;
};

Hertz hertz_sphere(double radius, double force, const Material& m) {
  const double e_star = m.G / (1.0 - m.nu);
  const double a = std::cbrt(3.0 * force * radius / (4.0 * e_star));
  return {a, 3.0 * force / (2.0 * std::numbers::pi * a * a), a * a / radius};
}

// An n x n grid over [-1.25 a, 1.25 a]^2.
ElementGrid grid_around(double a, int n) {
  return {n, n, -1.25 * a, -1.25 * a, 2.5 * a / n, 2.5 * a / n};
}

// The undeformed distance of a sphere of radius R [m] on a plane, per element.
std::vector<double> sphere_gap(const ElementGrid& grid, double radius) {
  std::vector<double> h(static_cast<std::size_t>(grid.size()));
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      h[static_cast<std::size_t>(j * grid.nx + i)] =
          (grid.x(i) * grid.x(i) + grid.y(j) * grid.y(j)) / (2.0 * radius);
  return h;
}

TEST(ExactNormal, SphereReproducesHertz) {
  const Material steel{80e9, 0.28};
  const double radius = 0.2, force = 20e3;
  const Hertz hz = hertz_sphere(radius, force, steel);
  const ElementGrid grid = grid_around(hz.a, 40);
  const NormalSolution s = exact_normal(grid, sphere_gap(grid, radius), force, steel);
  ASSERT_EQ(s.status, ExactStatus::converged) << s.message;
  // The total force is imposed exactly.
  EXPECT_NEAR(s.normal_force, force, 1e-9 * force);
  // Piecewise-constant pressure on elements of a/16: measured, p0 and the approach come within
  // 0.1 % (0.4 % and 0.1 % on a/8 elements, converging with the element size); 0.5 % leaves
  // room for rounding of the iteration. The contact area is exact to one ring of elements.
  constexpr double kGrid = 0.005;
  const double p_max = *std::max_element(s.pn.begin(), s.pn.end());
  EXPECT_NEAR(p_max / hz.p0, 1.0, kGrid);
  EXPECT_NEAR(s.approach / hz.approach, 1.0, kGrid);
  const auto in_contact = std::count_if(s.pn.begin(), s.pn.end(), [](double p) { return p > 0; });
  const double area = static_cast<double>(in_contact) * grid.area();
  const double boundary = 2.0 * std::numbers::pi * hz.a * grid.dx;  // one element ring
  EXPECT_NEAR(area, std::numbers::pi * hz.a * hz.a, boundary);
  // The pressure follows p0 sqrt(1 - r^2/a^2): measured rms deviation 0.5 % of p0 (1.1 % on
  // a/8 elements); bound 1 %.
  double sum = 0.0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double r2 = (grid.x(i) * grid.x(i) + grid.y(j) * grid.y(j)) / (hz.a * hz.a);
      const double exact = r2 < 1.0 ? hz.p0 * std::sqrt(1.0 - r2) : 0.0;
      const double d = s.pn[static_cast<std::size_t>(j * grid.nx + i)] - exact;
      sum += d * d;
    }
  EXPECT_LT(std::sqrt(sum / grid.size()) / hz.p0, 0.01);
}

TEST(ExactNormal, RejectsBadInput) {
  const ElementGrid grid{10, 10, -1e-3, -1e-3, 2e-4, 2e-4};
  const std::vector<double> h(100, 0.0);
  EXPECT_THROW(exact_normal(grid, std::vector<double>(99, 0.0), 1e3, {}), InputError);
  EXPECT_THROW(exact_normal(grid, h, -1.0, {}), InputError);
  ElementGrid bad = grid;
  bad.dx = 0.0;
  EXPECT_THROW(exact_normal(bad, h, 1e3, {}), InputError);
  std::vector<double> nan_gap = h;
  nan_gap[3] = std::nan("");
  EXPECT_THROW(exact_normal(grid, nan_gap, 1e3, {}), InputError);
}

}  // namespace
}  // namespace wheelwear::tangential
