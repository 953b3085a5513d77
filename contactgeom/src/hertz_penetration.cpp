#include "hertz_penetration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "wheelwear/contactgeom/hertz.hpp"

namespace wheelwear::contactgeom::detail {
namespace {

constexpr double kLogRatioLimit = 13.8;  // ln(1e6)
constexpr std::size_t kNodes = 1105;     // 0.025 apart in ln(B/A)
constexpr double kStep = 2.0 * kLogRatioLimit / (kNodes - 1);

// eps_x on the nodes ln(B/A) = -limit + i step. Hertz's semi-axes scale with the approach and
// the curvatures alike, so any approach and modulus give the same factor.
std::array<double, kNodes> build_table() {
  std::array<double, kNodes> table{};
  for (std::size_t i = 0; i < kNodes; ++i) {
    const double ratio = std::exp(-kLogRatioLimit + static_cast<double>(i) * kStep);
    const HertzSolution h = hertz_from_approach(1.0, ratio, 1.0, 1.0);
    table[i] = h.a * h.a / h.delta;
  }
  return table;
}

}  // namespace

double hertz_penetration_x(double curvature_ratio) {
  static const std::array<double, kNodes> table = build_table();
  // Not above 0 (or NaN): the flattest end, as for the smallest ratio.
  const double log_ratio = curvature_ratio > 0.0 ? std::log(curvature_ratio) : -kLogRatioLimit;
  const double t =
      (std::clamp(log_ratio, -kLogRatioLimit, kLogRatioLimit) + kLogRatioLimit) / kStep;
  const auto i = std::min(static_cast<std::size_t>(t), kNodes - 2);
  const double f = t - static_cast<double>(i);
  return table[i] + f * (table[i + 1] - table[i]);
}

}  // namespace wheelwear::contactgeom::detail
