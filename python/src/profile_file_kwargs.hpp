#pragma once
// How profile files are read, from the Python functions' keywords (origin, taping_line_distance,
// max_drop, gauge_side, smoothing; None where not given), checked as the command line checks
// --origin, --taping-line-distance, --max-drop, --gauge-side and --smoothing, and refused in
// the same words.

#include <optional>
#include <string>

#include "profile_file_options.hpp"

namespace wheelwear::python {

struct ProfileFileKwargs {
  std::optional<std::string> origin;
  std::optional<double> taping_line_distance;
  std::optional<double> max_drop;
  std::optional<std::string> gauge_side;
  std::optional<double> smoothing;
};

/// The arguments for reading the wheel (`wheel_file`: not the standard S1002) and the rail
/// (`rail_file`: not 60E1 or UIC60). Throws InputError naming a keyword given for a standard
/// profile, which is generated, not read (max_drop and smoothing where neither is a file), or a
/// bad value.
cli::ProfileFileArgs profile_file_args(const ProfileFileKwargs& kw, bool wheel_file,
                                       bool rail_file);

}  // namespace wheelwear::python
