#include "hook_run.hpp"

#include <cstdio>
#include <string>

#include "load_collective.hpp"
#include "vehicle_record.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline::detail {
namespace fs = std::filesystem;

void check_hook_allowed(const Scene& scene, const RunOptions& options) {
  if (!scene.hook || options.allow_hook) return;
  throw InputError("scene line " + std::to_string(scene.hook->line) +
                   ": [hook] command runs the program `" + hook_command_line(scene.hook->command) +
                   "` during the run; pass --allow-hook to let the run start it");
}

std::optional<HookCall> update_hook(const CosimulationHook& hook, const fs::path& directory,
                                    int step, double distance, bool at_end,
                                    const profiles::PointList& wheel_left,
                                    const profiles::PointList& wheel_right,
                                    const profiles::Profile& rail, HookCarry& carry) {
  if (carry.called && (at_end || carry.depth_since_call < hook.resolve_depth)) return std::nullopt;
  char name[32];
  std::snprintf(name, sizeof name, "step_%06d", step);
  HookCall call = call_hook(hook, directory / name, step, distance,
                            {wheel_left, wheel_right, rail.knot_points()});
  const std::string source = "the hook's collective of step " + std::to_string(step) + " (" +
                             (directory / name / "collective.csv").string() + ")";
  std::vector<WheelsetStateSpec> states = read_collective_csv(call.collective, source);
  double total = 0.0;
  for (const WheelsetStateSpec& state : states) total += state.weight;
  if (states.empty() || !(total > 0.0))
    throw InputError(source +
                     ": no state with a weight > 0; the program must write at least "
                     "one state (docs/scenes.md, load collective columns)");
  carry.states = std::move(states);
  carry.depth_since_call = 0.0;
  carry.called = true;
  return call;
}

void add_hook_record(GroupRecord& g, const std::optional<HookCall>& call, const HookCarry& carry,
                     double depth_after) {
  g.arrays.push_back(as_integer(
      scalar("hook/called", call ? 1.0 : 0.0, "1", "1 when the hook made this step's collective")));
  g.arrays.push_back(scalar("hook/depth_since_call", depth_after, "m",
                            "deepest wear since the hook's last call, this step's included "
                            "(an upper bound: the steps' deepest increments summed)"));
  if (call) {
    g.texts.push_back({"hook/command", hook_command_line(call->arguments),
                       "the command as run, placeholders replaced"});
    g.texts.push_back(
        {"hook/output", call->collective, "the collective file the program wrote, as it wrote it"});
    g.texts.push_back(
        {"hook/log", call->log, "the program's standard output and error (the last 64 KiB)"});
    g.arrays.push_back(scalar("hook/seconds", call->seconds, "s", "wall time of the hook's call"));
  }
  add_collective(g, "collective/", carry.states);
}

HookCarry read_hook_carry(const ResultsFile& file, int last, const fs::path& output) {
  int called = last;
  while (called > 0 && file.read_step_array(called, "hook/called").at(0) == 0.0) --called;
  const auto written = file.read_text(ResultsFile::step_group(called) + "/hook/output");
  if (!written)
    throw InputError("results file " + output.string() + ": step " + std::to_string(called) +
                     " holds no hook/output to resume from");
  HookCarry carry;
  carry.called = true;
  carry.states =
      read_collective_csv(*written, "the hook's collective of step " + std::to_string(called) +
                                        " in " + output.string());
  carry.depth_since_call = file.read_step_array(last, "hook/depth_since_call").at(0);
  return carry;
}

}  // namespace wheelwear::pipeline::detail
