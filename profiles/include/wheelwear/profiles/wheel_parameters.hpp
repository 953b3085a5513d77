#pragma once
/// The wheel profile parameters of EN 15313: flange height Sh, flange thickness Sd and qR.

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Reference distances of the EN 15313 measurements.
struct WheelParameterOptions {
  /// Running circle (taping line) distance from the internal face of the wheel [m] (EN 13715,
  /// EN 15313: 70 mm).
  double taping_line_offset = 0.070;
  /// Sd is measured this far from the running circle towards the flange tip [m] (EN 15313:
  /// 10 mm).
  double sd_height = 0.010;
  /// qR runs from the Sd point to the flange-face point this far from the flange tip [m]
  /// (EN 15313: 2 mm).
  double qr_height = 0.002;

  /// Throws InputError unless all are finite and > 0.
  void validate() const;
};

/// EN 15313 wheel parameters and the points they were measured between [m].
struct WheelParameters {
  double Sh = 0.0;      ///< flange height: flange tip below the running circle [m]
  double Sd = 0.0;      ///< flange thickness: internal face to the flange face, sd_height from the
                        ///< running circle [m]
  double qR = 0.0;      ///< flange face slope measure: lateral distance from the qR point to the Sd
                        ///< point [m]
  Point internal_face;  ///< the internal face (internal_face.hpp) at the flange tip's height [m]
  Point running_circle;  ///< profile point taping_line_offset from the internal face [m]
  Point flange_tip;      ///< lowest point of the flange (largest z) [m]
  Point sd_point;        ///< flange face point of the Sd measurement [m]
  Point qr_point;        ///< flange face point qr_height from the tip [m]
};

/// Sh, Sd and qR of a wheel profile (EN 15313, as the standard defines them; frame of
/// profile.hpp). The internal face is internal_face()'s: the steep back-face points, else the
/// profile's origin convention. Throws InputError for rails or profiles without a measurable
/// flange.
WheelParameters wheel_parameters(const Profile& wheel, const WheelParameterOptions& options = {});

}  // namespace wheelwear::profiles
