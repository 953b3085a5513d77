#include "wheelwear/tangential/exact/sdec_fit.hpp"

#include <cmath>

#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::tangential {

SdecNoSlipCoefficients exact_no_slip_coefficients(double a_over_b, double psi,
                                                  const Material& material,
                                                  const SdecGridOptions& options) {
  const double a = 4.25e-3, b = a / a_over_b, c = std::sqrt(a * b), creep = 1e-6;
  const ContactLoad load{1e4, 1e6};  // friction large enough that nothing slips
  const contactgeom::Sdec patch{a, b, psi};
  const ExactSolution fx = exact_sdec(patch, {creep, 0, 0}, load, material, options);
  const ExactSolution fy = exact_sdec(patch, {0, creep, 0}, load, material, options);
  const ExactSolution fs = exact_sdec(patch, {0, 0, creep / c}, load, material, options);
  SdecNoSlipCoefficients out;
  for (const ExactSolution* s : {&fx, &fy, &fs})
    out.clean = out.clean && s->status == ExactStatus::converged && s->slip_elements == 0;
  const double gc2 = material.G * c * c * creep;
  out.c11 = -fx.forces.Fx / gc2;
  out.c22 = -fy.forces.Fy / gc2;
  out.c23 = -fs.forces.Fy / gc2;
  out.c13 = -fs.forces.Fx / gc2;
  return out;
}

SdecCoefficientFit fit_sdec_coefficients(double a_over_b, const Material& material,
                                         const SdecGridOptions& options,
                                         std::span<const double> psis) {
  SdecCoefficientFit fit;
  fit.at_zero = exact_no_slip_coefficients(a_over_b, 0.0, material, options);
  fit.clean = fit.at_zero.clean;
  const SdecNoSlipCoefficients& base = fit.at_zero;
  double s2 = 0.0, s4 = 0.0;
  for (const double psi : psis) {
    const SdecNoSlipCoefficients l = exact_no_slip_coefficients(a_over_b, psi, material, options);
    fit.clean = fit.clean && l.clean;
    fit.k13 -= l.c13 * psi;
    fit.b11 += (l.c11 - base.c11) * psi * psi;
    fit.b22 += (l.c22 - base.c22) * psi * psi;
    fit.b23 += (l.c23 - base.c23) * psi * psi;
    s2 += psi * psi;
    s4 += psi * psi * psi * psi;
  }
  fit.k13 /= s2;
  fit.b11 /= s4;
  fit.b22 /= s4;
  fit.b23 /= s4;
  return fit;
}

}  // namespace wheelwear::tangential
