#pragma once
// A co-simulation hook: an outside program (typically a commercial multibody code's batch run)
// that makes each step's load collective from the current wheel and rail profiles. The run
// writes the profiles to files, runs the program without a shell, and reads the collective it
// wrote (the extended collective format of docs/scenes.md).

#include <filesystem>
#include <string>
#include <vector>

#include "wheelwear/profiles/types.hpp"

namespace wheelwear::pipeline {

/// The file format the hook is given the profiles in.
enum class HookProfileFormat { csv, simpack, miniprof };

/// The scene's [hook] table.
struct CosimulationHook {
  /// The program and its arguments, run without a shell; the placeholders {wheel},
  /// {wheel_left}, {wheel_right}, {rail}, {collective}, {step}, {distance_m} and {directory}
  /// are replaced in every argument (hook_placeholders()).
  std::vector<std::string> command;
  /// The hook is called again once the deepest wear since its last call reaches this [m];
  /// 0: at every step.
  double resolve_depth = 0.0;
  double timeout = 3600.0;  ///< longest run of one call [s]; the program is killed beyond it
  HookProfileFormat profile_format = HookProfileFormat::csv;
  /// Where the program runs: the scene's directory (relative names in its arguments are taken
  /// from there, as the scene's own); empty: the current one.
  std::filesystem::path working_directory;
  int line = 0;  ///< the scene line of [hook] command, for messages
};

/// The arguments joined by spaces, for messages and records.
std::string hook_command_line(const std::vector<std::string>& arguments);

/// The placeholders a hook's arguments may name, each with what it stands for.
const std::vector<std::pair<std::string, std::string>>& hook_placeholders();

/// Throws InputError when `command` is empty, names an unknown {placeholder}, or does not name
/// {collective} (the program must be told where to write).
void validate_hook_command(const std::vector<std::string>& command);

/// What one call of the hook gave.
struct HookCall {
  std::vector<std::string> arguments;  ///< the command as run, placeholders replaced
  std::string collective;              ///< the collective file the program wrote (its text)
  std::string log;                     ///< its standard output and error (the last 64 KiB)
  double seconds = 0.0;                ///< wall time of the call
};

/// The profiles of one call: the wheel(s) and the rail, as the run holds them [m].
struct HookProfiles {
  profiles::PointList wheel_left;
  profiles::PointList wheel_right;  ///< the same as wheel_left when the wheels are shared
  profiles::PointList rail;
};

/// Writes the profiles into `directory` (created; an earlier call's collective there removed),
/// runs the hook in its working directory and returns what it wrote. The program runs in a
/// process group of its own; an interrupt of the run (SIGINT, SIGTERM, SIGHUP) kills that group
/// and then ends the run as the signal would, so no program outlives its run. Throws InputError
/// naming the command and the cause when the program cannot be started, exits with a non-zero
/// status or a signal, runs past its timeout (it is killed), or writes no collective; the log's
/// last lines are in the message.
HookCall call_hook(const CosimulationHook& hook, const std::filesystem::path& directory, int step,
                   double distance, const HookProfiles& profiles);

}  // namespace wheelwear::pipeline
