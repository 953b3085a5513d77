#pragma once
/// Resolves the wheel and rail profiles a user names: a standard profile or a file.

#include <optional>
#include <string>
#include <vector>

#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/profiles/profile_loader.hpp"

namespace wheelwear::profiles {

/// How the profile files a user names are read (the standard profiles ignore it): the choices
/// of LoadOptions a scene or a command line can make.
struct ProfileFileOptions {
  WheelOrigin origin = WheelOrigin::automatic;  ///< wheels: the file's lateral origin
  /// Wheels: taping line from the internal face [m] for an internal-face origin; default the
  /// file's header where it states one, else 70 mm (EN 13715).
  std::optional<double> taping_line_distance;
  double max_drop_fraction = 0.2;  ///< share of points cleaning may discard (CleaningOptions)
  /// The fit's smoothing length [m] (CurveOptions::smoothing_length; LoadOptions' default):
  /// longer for a record whose surface is wavy on the scale of a millimetre, whose contact
  /// point then jumps between the waves.
  double smoothing_length = LoadOptions{}.curve.smoothing_length;
  /// Rails: where the file has its gauge face on its lateral axis (OrientationOptions::mirror_y:
  /// automatic, keep = the smaller values, flip = the larger ones).
  Mirror rail_gauge_side = Mirror::automatic;
  /// The file's bytes where they were read before (a scene's stored input): parsed instead of
  /// reading the file again, the path naming it in messages and giving its format.
  std::optional<std::string> text;

  /// LoadOptions for a file of `body`, with these choices.
  LoadOptions load_options(Body body) const;
};

/// The longest smoothing length a profile file's fit may be given [m]: longer would round the
/// flange tip (radius 12 mm in EN 13715) and the rail's gauge corner.
inline constexpr double kMaxSmoothingLength = 5e-3;

/// Nominal rolling radius [m] when neither the user nor the file states one.
inline constexpr double kDefaultWheelRadius = 0.46;

/// "S1002" (generated, EN 13715 defaults) or a wheel profile file. The nominal radius (the
/// rolling radius at the taping line, Profile::info().nominal_radius) is `radius` where given,
/// else half the diameter a file's header states, else kDefaultWheelRadius.
/// A file's loading warnings (LoadedProfile::cleaning.warnings) are appended to `warnings`
/// where given.
profiles::Profile wheel_profile(const std::string& spec, std::optional<double> radius,
                                const ProfileFileOptions& files = {},
                                std::vector<std::string>* warnings = nullptr);

/// "60E1" (generated, EN 15302 arcs) or a profile file, inclined by `inclination` [rad] towards
/// the track centre. Without an inclination the built-in rail is inclined 1:40 and a file is
/// taken as it is (rail files usually carry their inclination).
profiles::Profile rail_profile(const std::string& spec, std::optional<double> inclination,
                               const ProfileFileOptions& files = {},
                               std::vector<std::string>* warnings = nullptr);

/// Default inclination applied to a rail spec: atan(1/40) for the built-in 60E1, 0 for files.
double default_inclination(const std::string& spec);

}  // namespace wheelwear::profiles
