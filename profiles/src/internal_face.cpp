#include "wheelwear/profiles/internal_face.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::profiles {

namespace {

constexpr double kSampling = 0.1e-3;  // [m]

// Arc length of the flange tip: a wheel profile's largest z (the flange reaches below the tread
// and the field-side chamfer), sampled; enough to bound the back face, in any lateral origin.
double tip_arc_length(const Profile& wheel) {
  double s_tip = 0.0, z_tip = wheel.position(0.0)[1];
  for (double s = 0.0; s <= wheel.length(); s += kSampling) {
    const double z = wheel.position(s)[1];
    if (z > z_tip) {
      z_tip = z;
      s_tip = s;
    }
  }
  return s_tip;
}

}  // namespace

InternalFace internal_face(const Profile& wheel) {
  if (wheel.body() != Body::wheel)
    throw InputError("profile " + wheel.info().name + " is a rail: it has no internal face");
  const double s_tip = tip_arc_length(wheel);
  const double steep = std::sin(kBackFaceSteepness);
  std::vector<double> ys;
  double z_lo = INFINITY, z_hi = -INFINITY;
  for (double s = 0.0; s < s_tip; s += kSampling) {
    if (std::abs(wheel.tangent(s)[0]) > steep) continue;
    const Point p = wheel.position(s);
    ys.push_back(p[0]);
    z_lo = std::min(z_lo, p[1]);
    z_hi = std::max(z_hi, p[1]);
  }
  InternalFace face;
  if (!ys.empty() && z_hi - z_lo >= kMinBackFaceHeight) {
    std::nth_element(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(ys.size() / 2), ys.end());
    face.y = ys[ys.size() / 2];
    face.measured = true;
    face.how = "measured: the median of the steep back-face points over " +
               core::format_mm(z_hi - z_lo, 2) + " of height, at y = " + core::format_mm(face.y, 2);
    return face;
  }
  const double distance = wheel.info().taping_line_distance;
  face.y = -distance;
  face.how = "by convention: the profile has no steep back face (it starts at y = " +
             core::format_mm(wheel.position(0.0)[0], 2) + "), so the face lies " +
             core::format_mm(distance, 2) + " from the taping line at y = 0";
  return face;
}

}  // namespace wheelwear::profiles
