#pragma once
// The command-line options that say how profile files are read (the origin of a wheel file, the
// taping line distance, the share of points cleaning may drop), shared by the commands that
// take profile files.

#include <optional>
#include <string>

#include "wheelwear/profiles/profile_source.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace wheelwear::cli {

struct ProfileFileArgs {
  std::string origin = "auto";
  std::optional<double> taping_line_distance;
  double max_drop = profiles::ProfileFileOptions{}.max_drop_fraction;
  std::string gauge_side = "auto";
  double smoothing = profiles::ProfileFileOptions{}.smoothing_length;
  CLI::Option* origin_option = nullptr;
  CLI::Option* taping_line_distance_option = nullptr;
  CLI::Option* max_drop_option = nullptr;
  CLI::Option* gauge_side_option = nullptr;
  CLI::Option* smoothing_option = nullptr;

  /// The options as given; throws InputError on a bad value.
  profiles::ProfileFileOptions options() const;
  /// Refuses the file options given for a standard profile (S1002, 60E1), which has no file:
  /// --origin, --taping-line-distance, --max-drop for the wheel, --gauge-side, --max-drop for
  /// the rail, --smoothing for both.
  void refuse_for_standard(bool standard_wheel, bool standard_rail) const;
};

/// Adds --origin, --taping-line-distance, --max-drop, --gauge-side and --smoothing to `cmd`.
void add_profile_file_options(CLI::App* cmd, ProfileFileArgs& args);

}  // namespace wheelwear::cli
