#include "wheelwear/tangential/exact/influence.hpp"

#include <cmath>
#include <numbers>

namespace wheelwear::tangential {

namespace {

// Primitives F(x, y) whose mixed derivative d2F/dxdy is the integrand, for the point at the
// origin and the source at (x, y): x ln(y + r) -> y^2/r^3, y ln(x + r) -> x^2/r^3,
// -r -> x y/r^3. ln(y + r) is evaluated as ln(x^2/(r - y)) for y < 0 to avoid cancellation;
// the factor in front makes each term vanish on the axis where its logarithm is singular.
double x_log_y_plus_r(double x, double y) {
  if (x == 0.0) return 0.0;
  const double r = std::hypot(x, y);
  return y >= 0.0 ? x * std::log(y + r) : x * std::log(x * x / (r - y));
}

double y_log_x_plus_r(double x, double y) {
  return x_log_y_plus_r(y, x);
}

// Corner sum F(x2, y2) - F(x1, y2) - F(x2, y1) + F(x1, y1): the integral over the rectangle.
template <typename F>
double corner_sum(F f, double x1, double x2, double y1, double y2) {
  return f(x2, y2) - f(x1, y2) - f(x2, y1) + f(x1, y1);
}

}  // namespace

InfluenceCoefficients rectangle_influence(double x1, double x2, double y1, double y2,
                                          const Material& material) {
  const double nu = material.nu;
  const double scale = 1.0 / (std::numbers::pi * material.G);
  const double lx = corner_sum(x_log_y_plus_r, x1, x2, y1, y2);  // int y^2/r^3
  const double ly = corner_sum(y_log_x_plus_r, x1, x2, y1, y2);  // int x^2/r^3
  const double lxy =
      corner_sum([](double x, double y) { return -std::hypot(x, y); }, x1, x2, y1, y2);
  InfluenceCoefficients c;
  c.xx = scale * ((1.0 - nu) * lx + ly);
  c.yy = scale * (lx + (1.0 - nu) * ly);
  c.xy = scale * nu * lxy;
  c.nn = scale * (1.0 - nu) * (lx + ly);
  return c;
}

}  // namespace wheelwear::tangential
