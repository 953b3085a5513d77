#include "wheelwear/contactgeom/sdec.hpp"

#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

void Sdec::validate() const {
  require_finite("a", a);
  require_finite("b", b);
  require_finite("psi", psi);
  require(a > 0.0, "a", a, "the semi-length must be positive (metres)");
  require(b > 0.0, "b", b, "the semi-width must be positive (metres)");
  require(std::abs(psi) < 1.0, "psi", psi, "the shape number must satisfy |psi| < 1");
}

double Sdec::c() const {
  return std::sqrt(a * b);
}

double Sdec::area() const {
  return std::numbers::pi * a * b;
}

double Sdec::leading_edge(double y) const {
  const double r = y / half_width(y);
  const double t = 1.0 - r * r;
  return t > 0.0 ? a * std::sqrt(t) : 0.0;
}

double Sdec::peak_pressure(double normal_force) const {
  return 1.5 * normal_force / area();
}

double Sdec::pressure(double x, double y, double normal_force) const {
  const double xl = leading_edge(y);
  const double t = xl * xl - x * x;
  return t > 0.0 ? peak_pressure(normal_force) / a * std::sqrt(t) : 0.0;
}

}  // namespace wheelwear::contactgeom
