#include "wheelwear/tangential/sdec_coefficients.hpp"

#include <algorithm>
#include <array>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/kalker_coefficients.hpp"

namespace wheelwear::tangential {

namespace {

struct SdecExtra {
  double k13, b11, b22, b23;
};

// K13, B11, B22, B23 from Kalker's exact theory for several nu (kGeneratedNu), rows a/b = 0.1
// ... 1.0 then b/a = 0.9 ... 0.1, written by generators/sdec_table_generator.cpp (the same values
// as data/sdec_coefficients.csv, whose header states the method).
#include "sdec_coefficients_table.inc"

// Liu, Fu & Bruni 2022, Table 1 (nu = 0.25): rows a/b = 0.1 ... 1.0.
constexpr std::array<SdecExtra, 10> kWide = {{
    {8.88, 0.029, 0.037, 0.006},
    {6.33, 0.056, 0.065, 0.019},
    {5.23, 0.080, 0.082, 0.030},
    {4.59, 0.097, 0.093, 0.038},
    {4.16, 0.115, 0.100, 0.044},
    {3.86, 0.121, 0.103, 0.048},
    {3.63, 0.123, 0.102, 0.051},
    {3.45, 0.119, 0.097, 0.051},
    {3.30, 0.123, 0.096, 0.055},
    {3.18, 0.143, 0.109, 0.063},
}};

// Table 1 rows b/a = 0.1 ... 1.0 (printed as g = 1/0.1 ... 1/0.9 and 1.0).
constexpr std::array<SdecExtra, 10> kSlender = {{
    {2.30, 0.080, 0.050, 0.088},
    {2.29, 0.107, 0.064, 0.080},
    {2.38, 0.121, 0.075, 0.072},
    {2.51, 0.123, 0.077, 0.070},
    {2.60, 0.134, 0.091, 0.066},
    {2.73, 0.131, 0.089, 0.065},
    {2.84, 0.145, 0.105, 0.071},
    {2.95, 0.132, 0.098, 0.063},
    {3.07, 0.139, 0.104, 0.064},
    {3.18, 0.143, 0.109, 0.063},
}};

SdecExtra interpolate(const std::array<SdecExtra, 10>& rows, double r) {
  const double position = std::clamp(r * 10.0 - 1.0, 0.0, 9.0);
  const auto lower = std::min(static_cast<std::size_t>(position), std::size_t{8});
  const double w = position - static_cast<double>(lower);
  const SdecExtra& p = rows[lower];
  const SdecExtra& q = rows[lower + 1];
  return {(1 - w) * p.k13 + w * q.k13, (1 - w) * p.b11 + w * q.b11, (1 - w) * p.b22 + w * q.b22,
          (1 - w) * p.b23 + w * q.b23};
}

// The generated row for table nu index v at a/b (interpolated in a/b or b/a like Table 1).
SdecExtra generated(std::size_t v, double a_over_b) {
  std::array<SdecExtra, 10> wide{}, slender{};
  const auto& rows = kGeneratedRows[v];
  for (std::size_t k = 0; k < 10; ++k) wide[k] = rows[k];
  for (std::size_t k = 0; k < 9; ++k) slender[k] = rows[18 - k];
  slender[9] = rows[9];
  return a_over_b <= 1.0 ? interpolate(wide, a_over_b) : interpolate(slender, 1.0 / a_over_b);
}

// Natural cubic spline through (kGeneratedNu[v], value[v]) evaluated at nu.
double spline_in_nu(const std::array<double, kGeneratedNu.size()>& value, double nu) {
  constexpr std::size_t n = kGeneratedNu.size();
  const auto& x = kGeneratedNu;
  // Second derivatives m (m[0] = m[n-1] = 0) from the tridiagonal system (Thomas algorithm).
  std::array<double, n> m{}, c{}, d{};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    const double rhs = 6.0 * ((value[i + 1] - value[i]) / h1 - (value[i] - value[i - 1]) / h0);
    const double diag = 2.0 * (h0 + h1) - (i > 1 ? h0 * c[i - 1] : 0.0);
    c[i] = h1 / diag;
    d[i] = (rhs - (i > 1 ? h0 * d[i - 1] : 0.0)) / diag;
  }
  for (std::size_t i = n - 2; i >= 1; --i) m[i] = d[i] - c[i] * m[i + 1];
  std::size_t k = 0;
  while (k + 2 < n && nu > x[k + 1]) ++k;
  const double h = x[k + 1] - x[k], t = (nu - x[k]) / h, u = 1.0 - t;
  return u * value[k] + t * value[k + 1] +
         h * h / 6.0 * ((u * u * u - u) * m[k] + (t * t * t - t) * m[k + 1]);
}

// The exact theory's K13, B11, B22, B23 at (a/b, nu): a spline in nu through the generated
// rows.
SdecExtra generated_at(double a_over_b, double nu) {
  std::array<double, kGeneratedNu.size()> k13{}, b11{}, b22{}, b23{};
  for (std::size_t v = 0; v < kGeneratedNu.size(); ++v) {
    const SdecExtra e = generated(v, a_over_b);
    k13[v] = e.k13;
    b11[v] = e.b11;
    b22[v] = e.b22;
    b23[v] = e.b23;
  }
  return {spline_in_nu(k13, nu), spline_in_nu(b11, nu), spline_in_nu(b22, nu),
          spline_in_nu(b23, nu)};
}

}  // namespace

SdecTableRow sdec_table_row(double a_over_b, double nu, CoefficientFlags* flags) {
  const KalkerCoefficients kalker = kalker_coefficients(a_over_b, nu);
  const bool outside = a_over_b < 0.1 || a_over_b > 10.0;
  const SdecExtra extra =
      a_over_b <= 1.0 ? interpolate(kWide, a_over_b) : interpolate(kSlender, 1.0 / a_over_b);
  SdecTableRow row{kalker.c11, kalker.c22, kalker.c23, extra.k13, extra.b11, extra.b22, extra.b23};
  if (nu != 0.25) {
    // Table 1 carried to nu with the exact theory's change between 0.25 and nu: K13 by its
    // ratio, the B's (small differences of nearly equal coefficients) by their difference, so
    // that the generated grid's own bias at 0.25 cancels and nu = 0.25 gives Table 1 exactly.
    const SdecExtra at = generated_at(a_over_b, nu);
    const SdecExtra base = generated_at(a_over_b, 0.25);
    row.k13 *= at.k13 / base.k13;
    row.b11 += at.b11 - base.b11;
    row.b22 += at.b22 - base.b22;
    row.b23 += at.b23 - base.b23;
  }
  if (flags) {
    flags->kalker_extrapolated = kalker.extrapolated;
    flags->sdec_held = outside;
  }
  return row;
}

SdecCoefficients sdec_coefficients(const contactgeom::Sdec& sdec, double nu) {
  sdec.validate();
  SdecCoefficients out;
  out.row = sdec_table_row(sdec.ellipticity(), nu, &out.flags);
  const double psi2 = sdec.psi * sdec.psi;
  out.c11s = out.row.c11 + out.row.b11 * psi2;
  out.c13s = -out.row.k13 * sdec.psi;
  out.c22s = out.row.c22 + out.row.b22 * psi2;
  out.c23s = out.row.c23 + out.row.b23 * psi2;
  return out;
}

}  // namespace wheelwear::tangential
