#pragma once
/// The wheel profile parameters of EN 15313: flange height Sh, flange thickness Sd and qR.

#include <string>
#include <vector>

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
  double Sh = 0.0;  ///< flange height: flange tip below the running circle [m]
  double Sd = 0.0;  ///< flange thickness: internal face to the flange face, sd_height from the
                    ///< running circle [m]
  double qR = 0.0;  ///< flange face slope measure: lateral distance from the qR point to the Sd
                    ///< point [m]
  Point internal_face =
      Point::Zero();  ///< the internal face (internal_face.hpp) at the flange tip's height [m]
  Point running_circle =
      Point::Zero();  ///< profile point taping_line_offset from the internal face [m]
  Point flange_tip = Point::Zero();  ///< lowest point of the flange (largest z) [m]
  Point sd_point = Point::Zero();    ///< flange face point of the Sd measurement [m]
  Point qr_point = Point::Zero();    ///< flange face point qr_height from the tip [m]
};

/// Sh, Sd and qR of a wheel profile (EN 15313, as the standard defines them; frame of
/// profile.hpp). The internal face is internal_face()'s: the steep back-face points, else the
/// profile's origin convention. Throws InputError for rails or profiles without a measurable
/// flange.
WheelParameters wheel_parameters(const Profile& wheel, const WheelParameterOptions& options = {});

/// In-service limits of a wheel's flange on standard gauge [m]. Wear thins the flange (Sd falls),
/// lowers the tread (Sh rises) and sharpens the flange face (qR falls), so only these three
/// bounds can be reached by wear.
struct WheelLimits {
  double Sd_min = 0.0;  ///< least flange thickness
  double Sh_max = 0.0;  ///< largest flange height
  double qR_min = 0.0;  ///< least qR
};

/// The smallest wheel diameter EN 15313's in-service limits cover [m].
inline constexpr double kSmallestStandardWheel = 0.330;

/// EN 15313's in-service limits for a wheel of nominal diameter `diameter` [m] (the same figures
/// are the TSI LOC&PAS limits, Commission Regulation (EU) No 1302/2014, 4.2.3.5.2.2): Sd at least
/// 22 mm for D >= 840 mm, 25 mm for 760 < D < 840 mm and 27.5 mm for 330 <= D <= 760 mm; Sh at
/// most 36 mm and qR at least 6.5 mm for every diameter. Throws InputError below 330 mm or for a
/// diameter that is not finite.
WheelLimits in_service_limits(double diameter);

/// The limits `parameters` has reached, one phrase each ("Sd 21.950 mm <= 22.000 mm"); empty when
/// none. A NaN limit is not watched; a NaN parameter (a profile worn past its reference points,
/// where it cannot be measured) has reached its limit.
std::vector<std::string> limits_reached(const WheelParameters& parameters,
                                        const WheelLimits& limits);

}  // namespace wheelwear::profiles
