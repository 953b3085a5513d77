#include "wheelwear/wear/sdec_coefficients.hpp"

#include <algorithm>
#include <array>

#include "wheelwear/input_error.hpp"
#include "wheelwear/wear/kalker_coefficients.hpp"

namespace wheelwear::wear {

namespace {

struct SdecExtra {
  double k13, b11, b22, b23;
};

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

}  // namespace

SdecTableRow sdec_table_row(double a_over_b, double nu, CoefficientFlags* flags) {
  const KalkerCoefficients kalker = kalker_coefficients(a_over_b, nu);
  const bool outside = a_over_b < 0.1 || a_over_b > 10.0;
  const SdecExtra extra =
      a_over_b <= 1.0 ? interpolate(kWide, a_over_b) : interpolate(kSlender, 1.0 / a_over_b);
  SdecTableRow row{kalker.c11, kalker.c22, kalker.c23, extra.k13, extra.b11, extra.b22, extra.b23};
  const bool other_nu = nu != 0.25;
  if (other_nu) {
    const KalkerCoefficients at_table_nu = kalker_coefficients(a_over_b, 0.25);
    const double r11 = kalker.c11 / at_table_nu.c11;
    row.k13 *= r11;
    row.b11 *= r11;
    row.b22 *= kalker.c22 / at_table_nu.c22;
    row.b23 *= kalker.c23 / at_table_nu.c23;
  }
  if (flags) {
    flags->kalker_extrapolated = kalker.extrapolated;
    flags->sdec_held = outside;
    flags->sdec_nu_approximated = other_nu;
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

}  // namespace wheelwear::wear
