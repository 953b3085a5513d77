#include "wheelwear/tangential/creep_types.hpp"

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

void Material::validate() const {
  require_finite("G", G);
  require_finite("nu", nu);
  require(G > 0.0, "G", G, "the combined shear modulus must be positive (Pa)");
  require(nu >= 0.0 && nu <= 0.5, "nu", nu, "Poisson's ratio must lie in [0, 0.5]");
}

void ContactLoad::validate() const {
  require_finite("N", N);
  require_finite("mu", mu);
  require(N > 0.0, "N", N, "the normal force must be positive (newtons)");
  require(mu > 0.0, "mu", mu, "the friction coefficient must be positive");
}

std::string CoefficientFlags::describe() const {
  std::string text;
  auto add = [&text](const char* what) {
    if (!text.empty()) text += "; ";
    text += what;
  };
  if (kalker_extrapolated) add("a/b outside Kalker's table (0.1...10): asymptotic C11, C22, C23");
  if (sdec_held) add("a/b outside Table 1 (0.1...10): SDEC coefficients of the end row");
  return text;
}

}  // namespace wheelwear::tangential
