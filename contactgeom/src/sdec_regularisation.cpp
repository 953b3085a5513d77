#include "wheelwear/contactgeom/sdec_regularisation.hpp"

#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

Sdec regularise_sdec(const PatchMeasures& m) {
  require_finite("area", m.area);
  require_finite("length", m.length);
  require_finite("width", m.width);
  require_finite("W1", m.W1);
  require_finite("W2", m.W2);
  require(m.area > 0.0, "area", m.area, "the patch area must be positive (m^2)");
  require(m.length > 0.0, "length", m.length, "the patch length must be positive (m)");
  require(m.width > 0.0, "width", m.width, "the patch width must be positive (m)");
  // W1 + W2 = W_n by definition; a mismatch means the measures do not describe one patch.
  require(std::abs(m.W1 + m.W2 - m.width) <= 1e-9 * m.width, "W1 + W2", m.W1 + m.W2,
          "must equal the patch width (W1, W2 are the extents on either side of O)");
  require(m.W1 > 0.0, "W1", m.W1, "O must lie strictly inside the patch's lateral extent");
  require(m.W2 > 0.0, "W2", m.W2, "O must lie strictly inside the patch's lateral extent");

  Sdec sdec;
  // Eq. 14: pi a b = A_n and a/b = L_n/W_n.
  sdec.a = std::sqrt(m.area * m.length / (std::numbers::pi * m.width));
  sdec.b = std::sqrt(m.area * m.width / (std::numbers::pi * m.length));
  // Eq. 13-14: psi = 2 y0*/W_n with y0* = (W1 - W2)/2.
  sdec.psi = (m.W1 - m.W2) / m.width;
  sdec.validate();
  return sdec;
}

EquivalentEllipse equivalent_ellipse(const Sdec& sdec, EllipseCentre centre) {
  sdec.validate();
  EquivalentEllipse e;
  e.a = sdec.a;
  e.b = sdec.b;
  e.y_centre = centre == EllipseCentre::at_O_prime ? sdec.y0() : 0.0;
  return e;
}

}  // namespace wheelwear::contactgeom
