#pragma once
// A run's co-simulation hook from step to step: when its program is called, the states it carries
// between calls, the step's record (docs/results.md, "Runs with a co-simulation hook") and what a
// resumed run reads back.

#include <filesystem>
#include <optional>
#include <vector>

#include "wheelwear/pipeline/cosimulation_hook.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/wear_run.hpp"
#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::pipeline::detail {

// What a run with a hook carries from step to step: the collective of its last call.
struct HookCarry {
  bool called = false;  // a call has been made (or read back on resume)
  std::vector<WheelsetStateSpec> states;
  double depth_since_call = 0.0;  // deepest wear since the last call [m], an upper bound
};

// Refuses a scene whose hook the run was not allowed to start.
void check_hook_allowed(const Scene& scene, const RunOptions& options);

// Calls `hook` on the step's profiles (the wheels' points, the rail) when the wear since its last
// call reaches its depth (at every step for depth 0), but not at a step that ends the run
// (`at_end`), which only records. Its files go to a step_NNNNNN directory in `directory`.
// Returns the call, if one was made.
std::optional<HookCall> update_hook(const CosimulationHook& hook,
                                    const std::filesystem::path& directory, int step,
                                    double distance, bool at_end,
                                    const profiles::PointList& wheel_left,
                                    const profiles::PointList& wheel_right,
                                    const profiles::Profile& rail, HookCarry& carry);

// hook/...: whether the step called the program, the depth since its call (`depth_after`, this
// step's wear included), the call's command, output, log and time, and the states it carries.
void add_hook_record(GroupRecord& g, const std::optional<HookCall>& call, const HookCarry& carry,
                     double depth_after);

// What a run resumed after step `last` of `file` (the results file `output`) carries: the last
// call's collective as the program wrote it (the step records' columns leave out creepages a
// hook may give directly) and the depth since that call.
HookCarry read_hook_carry(const ResultsFile& file, int last, const std::filesystem::path& output);

}  // namespace wheelwear::pipeline::detail
