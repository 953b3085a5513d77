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
  CLI::Option* origin_option = nullptr;
  CLI::Option* taping_line_distance_option = nullptr;

  /// The options as given; throws InputError on a bad value.
  profiles::ProfileFileOptions options() const;
  /// Whether a wheel-file option (--origin, --taping-line-distance) was given.
  bool wheel_file_option_given() const;
};

/// Adds --origin, --taping-line-distance, --max-drop and --gauge-side to `cmd`.
void add_profile_file_options(CLI::App* cmd, ProfileFileArgs& args);

}  // namespace wheelwear::cli
