// Continuing a run from its results file: what the file must be for that, and the state the
// loop takes up again (profiles, the vehicle's last solve, the hook's calls).

#include <string>

#include "hook_run.hpp"
#include "stored_inputs.hpp"
#include "vehicle_record.hpp"
#include "wear_loop.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/output_lock.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/wear_run.hpp"
#include "wheelwear/profiles/wear_update.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "worn_profile.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

using detail::LoopStart;
using detail::new_profiles;
using detail::VehicleCarry;
using detail::WornProfile;

RunSummary resume_run(const fs::path& output, const RunOptions& options) {
  // Before the file is opened: opening discards a stray copy of an unfinished step, which may
  // be another run's step in progress.
  if (!fs::exists(output)) throw InputError("results file " + output.string() + ": does not exist");
  const OutputLock lock(output);
  if (!lock.warning().empty() && options.warning) options.warning(lock.warning());
  ResultsFile file = ResultsFile::open(output);
  if (file.format_version() != kFormatVersion) {
    throw InputError("results file " + output.string() + ": layout version " +
                     std::to_string(file.format_version()) + ", this program writes version " +
                     std::to_string(kFormatVersion) +
                     " (docs/results.md); it cannot continue it: start a new run with -o");
  }
  const auto directory = file.read_text("/run_info/scene_directory");
  if (!directory) {
    throw InputError("results file " + output.string() +
                     ": no /run_info/scene_directory; it was not written by wheelwear run");
  }
  const int last = file.completed_steps() - 1;
  const double step_distance = last < 0 ? -1.0 : file.read_step_array(last, "step_distance").at(0);
  if (step_distance == 0.0) {
    // A run killed while it ended (naming its last step, consolidating its step files): finish
    // that, then say it is complete. A complete file is left as it is.
    if (!file.has("/final")) file.link("/final", ResultsFile::step_group(last));
    file.consolidate();
    const bool at_limit = file.has(ResultsFile::step_group(last) + "/limits/stopped") &&
                          file.read_step_array(last, "limits/stopped").at(0) != 0.0;
    throw InputError("results file " + output.string() +
                     (at_limit ? ": the run stopped at an in-service limit ([limits] stop); "
                                 "nothing to resume (raise the limit and start a new run with -o)"
                               : ": the run is complete; nothing to resume (start a new run "
                                 "with -o)"));
  }
  const auto program = file.read_text("/run_info/program");
  if (program && *program != options.program)
    throw InputError("results file " + output.string() + ": written by " + *program + ", this is " +
                     options.program +
                     "; one run's steps come from one program: continue it with that program, "
                     "or start a new run with -o");
  const bool builtin = file.read_array("/run_info/builtin_scene").at(0) != 0.0;
  if (builtin && file.scene_text() != default_scene_text())
    throw InputError("results file " + output.string() +
                     ": it was run with another built-in scene than this program's; start a new "
                     "run with -o. Its scene is stored in the file (/scene); a run of the "
                     "built-in scene before the vehicle became it is the frozen-collective scene "
                     "that `wheelwear run --export-default-scene DIR` writes");
  const Scene scene = builtin ? default_scene()
                              : parse_scene(file.scene_text(), *directory,
                                            detail::stored_reader(file, options.resume_stored));
  if (scene.tangential == TangentialMethod::best &&
      file.root_attribute("creep_table_sha256") != tangential::creep_table_sha256()) {
    throw InputError("results file " + output.string() +
                     ": it was run with another book of creep-force tables (SHA-256 " +
                     file.root_attribute("creep_table_sha256").value_or("none") + ", now " +
                     tangential::creep_table_sha256() + " at " +
                     tangential::creep_table_path().string() +
                     "); resuming would mix the two: start a new run with -o");
  }
  detail::check_hook_allowed(scene, options);
  if (scene.vehicle_run) require_upright_route(*scene.vehicle_run, scene.lateral_arm);
  const CollectiveEvaluator evaluator(scene);
  if (last < 0) {
    // Killed before its first step was published: the run starts over from its stored scene.
    LoopStart start{0, 0.0, new_profiles(scene)};
    start.initial = start.worn;
    start.hook_directory = hook_directory(output);
    return detail::loop(scene, file.scene_text(), evaluator, file, std::move(start), *directory,
                        builtin, options);
  }
  LoopStart start{last + 1, file.read_step_array(last, "distance").at(0) + step_distance,
                  new_profiles(scene)};
  start.hook_directory = hook_directory(output);
  // A vehicle run with separate wheels written before each wheelset had profiles of its own
  // holds left and right profiles only: it cannot go on with eight.
  if (profile_layout(scene) == ProfileLayout::per_wheelset &&
      !file.has(ResultsFile::step_group(last) + "/" + start.worn.front().name))
    throw InputError("results file " + output.string() +
                     ": its wheels = \"separate\" vehicle run wears one left and one right "
                     "profile (an earlier program's layout); this program wears each wheelset's "
                     "own: start a new run with -o");
  const profiles::WearUpdateOptions update{0.0};  // as in loop()
  // A profile as step `at` recorded it.
  const auto recorded = [&](WornProfile& w, int at) {
    const auto y = file.read_step_array(at, w.name + "/y");
    const auto z = file.read_step_array(at, w.name + "/z");
    if (y.size() != z.size() || y.size() < 4)
      throw InputError("results file " + output.string() + ": step " + std::to_string(at) +
                       " holds no valid " + w.name + " profile");
    w.points.clear();
    for (std::size_t i = 0; i < y.size(); ++i) w.points.emplace_back(y[i], z[i]);
  };
  start.initial = start.worn;
  for (WornProfile& w : start.initial) recorded(w, 0);
  for (WornProfile& w : start.worn) {
    recorded(w, last);
    profiles::WearDepth depth;
    depth.y = file.read_step_array(last, w.name + "/wear_step/y");
    depth.depth = file.read_step_array(last, w.name + "/wear_step/depth");
    w.points = profiles::apply_wear(w.build(), depth, update).knot_points();
  }
  if (scene.vehicle_run) {
    VehicleCarry& carry = start.vehicle;
    carry.solved = true;
    carry.last = detail::read_vehicle_collective(file, last, *scene.vehicle_run);
    carry.depth_since_solve = file.read_step_array(last, "vehicle/depth_since_solve").at(0);
  }
  if (scene.hook) start.hook = detail::read_hook_carry(file, last, output);
  return detail::loop(scene, file.scene_text(), evaluator, file, std::move(start), *directory,
                      builtin, options);
}

}  // namespace wheelwear::pipeline
