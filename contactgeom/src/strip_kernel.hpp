#pragma once
// Inline kernels of the strip influence integrals (strip_influence.hpp documents the integrals
// and their accuracy). They live in a header so that the Kik-Piotrowski load loop, which calls
// them once per strip and evaluation, can inline them.

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace wheelwear::contactgeom::detail {

// Natural logarithm of a positive normal double to ~1e-13 relative, without a library call:
// x = 2^e f with f in [sqrt(1/2), sqrt(2)), ln x = e ln 2 + 2 atanh(s), s = (f - 1)/(f + 1),
// |s| <= 0.1716, and atanh(s) = s (1 + s^2/3 + s^4/5 + ...) truncated after s^12/13 (the first
// omitted term is below 4e-13). Falls back to std::log outside the normal range.
inline double fast_log(double x) {
  if (!(x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max())) {
    return std::log(x);
  }
  std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  int exponent = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
  double f = std::bit_cast<double>(bits);  // in [1, 2)
  if (f > std::numbers::sqrt2) {
    f *= 0.5;
    ++exponent;
  }
  const double s = (f - 1.0) / (f + 1.0);
  const double s2 = s * s;
  const double series =
      1.0 +
      s2 * (1.0 / 3.0 +
            s2 * (1.0 / 5.0 +
                  s2 * (1.0 / 7.0 + s2 * (1.0 / 9.0 + s2 * (1.0 / 11.0 + s2 * (1.0 / 13.0))))));
  return exponent * std::numbers::ln2 + 2.0 * s * series;
}

// Coefficients of K - E = (pi/2) sum_{n>=1} q_n^2 (2n/(2n-1)) m^n with q_n = (2n-1)!!/(2n)!!
// (from the Maclaurin series of K and E, Abramowitz & Stegun 1964, 17.3.11-17.3.12).
inline constexpr int kSeriesTerms = 16;
constexpr std::array<double, kSeriesTerms> k_minus_e_series_coefficients() {
  std::array<double, kSeriesTerms> coeff{};
  double q = 1.0;
  for (int n = 1; n <= kSeriesTerms; ++n) {
    q *= (2.0 * n - 1.0) / (2.0 * n);
    coeff[n - 1] = q * q * (2.0 * n) / (2.0 * n - 1.0);
  }
  return coeff;
}
inline constexpr std::array<double, kSeriesTerms> kKMinusESeries = k_minus_e_series_coefficients();

// K(k) - E(k) from m = k^2 and m1 = k'^2 = 1 - m, both given so that neither is formed from
// the other with cancellation.
inline double k_minus_e(double m, double m1) {
  if (m <= 0.1) {
    // Truncation: the first omitted term is below 0.1^16 times the leading one.
    double sum = kKMinusESeries[kSeriesTerms - 1];
    for (int n = kSeriesTerms - 2; n >= 0; --n) sum = sum * m + kKMinusESeries[n];
    return 0.5 * std::numbers::pi * m * sum;
  }
  // Hastings' polynomial approximations of K and E in m1 with their logarithmic terms
  // (Abramowitz & Stegun 1964, 17.3.34 and 17.3.36, each |error| <= 2e-8), subtracted
  // coefficient by coefficient. K - E >= pi/4 * 0.1 here, so the relative error is below 2e-7
  // by those bounds; the two errors largely cancel, and 1.4e-8 is the largest measured
  // (elliptic_integrals_test).
  constexpr double p0 = 1.38629436112 - 1.0;
  constexpr double p1 = 0.09666344259 - 0.44325141463;
  constexpr double p2 = 0.03590092383 - 0.06260601220;
  constexpr double p3 = 0.03742563713 - 0.04757383546;
  constexpr double p4 = 0.01451196212 - 0.01736506451;
  constexpr double q0 = 0.5;
  constexpr double q1 = 0.12498593597 - 0.24998368310;
  constexpr double q2 = 0.06880248576 - 0.09200180037;
  constexpr double q3 = 0.03328355346 - 0.04069697526;
  constexpr double q4 = 0.00441787012 - 0.00526449639;
  const double poly = p0 + m1 * (p1 + m1 * (p2 + m1 * (p3 + m1 * p4)));
  const double log_poly = q0 + m1 * (q1 + m1 * (q2 + m1 * (q3 + m1 * q4)));
  return poly - fast_log(m1) * log_poly;
}

// L(c, y) = 2 sqrt(c^2 + y^2) (K(k) - E(k)), k^2 = c^2/(c^2 + y^2), for c > 0, y != 0.
// Lengths are patch-sized (1e-9 ... 1 m), far from over- or underflow, so no hypot scaling.
inline double line_kernel(double c, double y) {
  const double r2 = c * c + y * y;
  const double inv_r2 = 1.0 / r2;
  return 2.0 * std::sqrt(r2) * k_minus_e(c * c * inv_r2, y * y * inv_r2);
}

// 4-point Gauss-Legendre on [lo, hi] (Abramowitz & Stegun 1964, Table 25.4).
template <class F>
double gauss4(F&& f, double lo, double hi) {
  constexpr double node[2] = {0.3399810435848562648, 0.8611363115940525752};
  constexpr double weight[2] = {0.6521451548625461426, 0.3478548451374538574};
  const double mid = 0.5 * (lo + hi);
  const double half = 0.5 * (hi - lo);
  double sum = 0.0;
  for (int i = 0; i < 2; ++i) {
    const double d = half * node[i];
    sum += weight[i] * (f(mid - d) + f(mid + d));
  }
  return half * sum;
}

// G(u) = int_0^u L(c, t) dt for u >= 0, c > 0.
// Near the field point, with tau = t/c, L/(2c) = ln(4/tau) - 1 + tau^2/4 ln(4/tau)
// + tau^4 (5/128 - 3/64 ln(4/tau)) + O(tau^6 ln tau) (from K and E's expansions in k',
// DLMF 19.12.1-19.12.2; the tau^4 coefficients were confirmed against 50-digit values). For
// u <= c/8 this series is integrated in closed form; the omitted terms are below 1e-8 of G.
// Otherwise the log singularity 2c (ln(4c/t) - 1) is integrated exactly on [0, min(u, c/2)]
// and the remainder by 4-point Gauss-Legendre on pieces halving towards 0 until the first is
// below c/16; beyond c/2, L itself on pieces growing by 1.5, which keeps its log singularity
// at 0 and its branch points at +-ic at least five half-lengths from each piece's centre.
inline double integral_from_zero(double c, double u) {
  if (u <= 0.0) return 0.0;
  if (u <= 0.125 * c) {
    const double U = u / c;
    const double l = fast_log(4.0 / U);
    const double U2 = U * U;
    // int_0^U tau^n ln(4/tau) dtau = U^(n+1)/(n+1) (ln(4/U) + 1/(n+1)).
    const double series = U * l + U2 * U / 12.0 * (l + 1.0 / 3.0) -
                          3.0 / 320.0 * U2 * U2 * U * (l + 0.2) + 1.0 / 128.0 * U2 * U2 * U;
    return 2.0 * c * c * series;
  }
  const double u_singular = std::fmin(u, 0.5 * c);
  auto remainder = [c](double t) {
    return line_kernel(c, t) - 2.0 * c * (fast_log(4.0 * c / t) - 1.0);
  };
  double sum = 2.0 * c * u_singular * fast_log(4.0 * c / u_singular);
  double hi = u_singular;
  for (int piece = 0; piece < 4 && hi > 0.0625 * c; ++piece) {
    sum += gauss4(remainder, 0.5 * hi, hi);
    hi *= 0.5;
  }
  sum += gauss4(remainder, 0.0, hi);
  auto line = [c](double t) { return line_kernel(c, t); };
  double lo = u_singular;
  // At most 120 pieces (a factor 1.5^120 = 1e21 in t): beyond, the tail ~ pi c^2/(2t) is
  // negligible for any strip a contact patch can have.
  for (int piece = 0; piece < 120 && lo < u; ++piece) {
    const double next = std::fmin(1.5 * lo, u);
    sum += gauss4(line, lo, next);
    lo = next;
  }
  return sum;
}

// S(c, y1, y2) = int_{y1}^{y2} L(c, y) dy; see strip_influence.hpp for the rules and accuracy.
inline double strip_kernel(double c, double y1, double y2) {
  if (c <= 0.0 || !(y2 > y1)) return 0.0;
  if (y1 < 0.0 && y2 > 0.0) {
    // The strip holds the field point; L is even in y.
    return integral_from_zero(c, -y1) + integral_from_zero(c, y2);
  }
  // Fold the strip onto y >= 0: [near, far] with 0 <= near < far.
  const double near = y1 >= 0.0 ? y1 : -y2;
  const double far = y1 >= 0.0 ? y2 : -y1;
  const double width = far - near;
  if (near < 2.0 * width) {
    return integral_from_zero(c, far) - integral_from_zero(c, near);
  }
  const double mid = 0.5 * (near + far);
  if (near < 4.0 * width) {
    // 3-point Gauss-Legendre: nodes 0, +-sqrt(3/5), weights 8/9, 5/9.
    const double d = 0.5 * width * 0.7745966692414833770;
    return 0.5 * width *
           (8.0 / 9.0 * line_kernel(c, mid) +
            5.0 / 9.0 * (line_kernel(c, mid - d) + line_kernel(c, mid + d)));
  }
  if (near < 8.0 * width) {
    // 2-point Gauss-Legendre: nodes +-1/sqrt(3), weights 1.
    const double d = 0.5 * width * 0.5773502691896257645;
    return 0.5 * width * (line_kernel(c, mid - d) + line_kernel(c, mid + d));
  }
  return width * line_kernel(c, mid);
}

}  // namespace wheelwear::contactgeom::detail
