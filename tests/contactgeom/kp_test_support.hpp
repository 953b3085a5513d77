#pragma once
// What the Kik-Piotrowski tests share: strips sampled from a gap function, and options with
// a given virtual penetration.

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/kik_piotrowski.hpp"

namespace wheelwear::contactgeom::kp_test {

constexpr double kLoad = 55e3;             // N, the reference data's wheel load
constexpr double kA = 1.0 / (2.0 * 0.46);  // 1/m: a 460 mm wheel on a straight rail

// Strips sampled from h(s) with a constant longitudinal coefficient; owns its storage.
struct Strips {
  std::vector<double> h, ax;
  GapStrips gap;
  Strips(std::function<double(double)> h_of_s, double s_lo, double s_hi, double ds, double a = kA,
         double offset = 0.0) {
    const int n = static_cast<int>(std::lround((s_hi - s_lo) / ds));
    gap.s_first = s_lo + (0.5 + offset) * ds;
    gap.ds = ds;
    for (int j = 0; j < n; ++j) {
      h.push_back(h_of_s(gap.s_first + j * ds));
      ax.push_back(a);
    }
    gap.h = h;
    gap.ax = ax;
  }
};

inline KpOptions with_epsilon(double eps) {
  KpOptions o;
  o.epsilon = eps;
  return o;
}

inline double rel(double a, double b) {
  return std::abs(a / b - 1.0);
}

// Four significant digits, for RecordProperty and test names.
inline std::string format_number(double v) {
  std::ostringstream out;
  out << std::setprecision(4) << v;
  return out.str();
}

// A gap with two wells, at s = -6 mm and at 9 mm (the second h2 higher), the lower envelope
// of two parabolas.
inline double double_well(double s, double h2) {
  const double left = 40.0 * (s + 6e-3) * (s + 6e-3);
  const double right = h2 + 400.0 * (s - 9e-3) * (s - 9e-3);
  return std::min(left, right);
}

}  // namespace wheelwear::contactgeom::kp_test
