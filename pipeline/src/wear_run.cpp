#include "wheelwear/pipeline/wear_run.hpp"

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <optional>

#include "hook_run.hpp"
#include "step_record.hpp"
#include "stored_inputs.hpp"
#include "vehicle_record.hpp"
#include "wear_increment.hpp"
#include "wear_loop.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/output_lock.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/profiles/wear_update.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "worn_profile.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

namespace {

using detail::new_profiles;
using detail::scalar;
using detail::vector;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Clock = std::chrono::steady_clock;

using detail::LoopStart;
using detail::VehicleCarry;
using detail::WornProfile;

// Solves the vehicle again when the wear since its last solve reaches the scene's depth (at
// every step for depth 0), at wear step `step`. Returns whether it solved.
// Its cases and time-domain pieces are spread over the job's processes where the run has a
// distributor.
bool update_vehicle(const VehicleRun& run, const StateKernel& kernel,
                    const std::vector<WornProfile>& worn,
                    const std::vector<const profiles::Profile*>& wheels, int step,
                    StepDistributor* distributor, VehicleCarry& carry) {
  if (carry.solved && carry.depth_since_solve < run.resolve_depth) return false;
  const auto draw = static_cast<std::uint64_t>(step);
  if (distributor) distributor->prepare_route(detail::points_of(worn), draw);
  carry.last = solve_vehicle_collective(run, kernel, wheels, carry.solved ? &carry.last : nullptr,
                                        draw, distributor);
  carry.depth_since_solve = 0.0;
  carry.solved = true;
  return true;
}

// What each counter of DroppedStates means, for the results file.
std::string dropped_description(const std::string& name) {
  const bool weight = name.size() > 7 && name.compare(name.size() - 7, 7, "_weight") == 0;
  const std::string base = weight ? name.substr(0, name.size() - 7) : name;
  std::string what;
  if (base == "failed_contacts")
    what = "wheel contacts without a usable contact (no contact, not converged, profile end)";
  if (base == "climbing_contacts")
    what = "wheel contacts in flange climb or past the flange (beyond its steepest point)";
  if (base == "nadal_contacts") what = "wheel contacts with Y/Q beyond Nadal's limit";
  if (base == "load_jump_contacts")
    what = "wheel contacts whose load falls in a jump of the vertical force";
  if (base == "dropped_patches")
    return weight ? "share of the running distance of the states not worn (dropped whole)"
                  : "contact patches of both wheels of the states not worn (dropped whole)";
  return weight ? "share of the running distance of the states with " + what +
                      " (each state once), not worn"
                : what + "; their states are not worn";
}

// EN 15313's parameters of a wheel profile; NaN for a profile worn past their reference points.
profiles::WheelParameters measured_parameters(const profiles::Profile& wheel) {
  try {
    return profiles::wheel_parameters(wheel);
  } catch (const InputError&) {
    profiles::WheelParameters none;
    none.Sh = none.Sd = none.qR = kNaN;
    return none;
  }
}

// The evaluation of `specs` on `wheels` (built from `worn`), spread over the job's processes
// where the run has a distributor; the same bits either way.
CollectiveWear evaluate_step(const CollectiveEvaluator& evaluator,
                             const std::vector<WornProfile>& worn,
                             const std::vector<const profiles::Profile*>& wheels,
                             const std::vector<WheelsetStateSpec>& specs, bool scene_states,
                             const ContactTables* tables, StepDistributor* distributor) {
  if (!distributor) return evaluator.evaluate(wheels, specs, tables);
  return evaluator.reduce(wheels, specs,
                          distributor->outcomes(evaluator, detail::points_of(worn), wheels, specs,
                                                scene_states, tables));
}

// The SHA-256 of the book of creep-force tables the run uses. A run with tangential_method
// best cannot go without it (creep_table_sha256 throws, naming where it looked); the other
// methods do not read it, so the file found is hashed without loading it, and a missing table
// is recorded, not fatal.
std::string table_hash(const Scene& scene) {
  if (scene.tangential == TangentialMethod::best) return tangential::creep_table_sha256();
  try {
    return tangential::file_sha256(tangential::locate_creep_table());
  } catch (const InputError&) {
    return "none";  // the reason names this machine's paths, which the file must not hold
  }
}

// A run's vehicle file against its scene (vehicle_scene_differences), once as the run starts;
// a resumed run, like its scene's warnings, says it no more. `radius`: the nominal radius of the
// run's new wheel profiles.
void warn_of_vehicle_differences(const Scene& scene, double radius, const RunOptions& options) {
  if (!options.warning || !scene.vehicle_run || scene.vehicle_run->vehicle_file.empty()) return;
  for (const std::string& w : vehicle_scene_differences(
           scene.vehicle_run->vehicle, "vehicle file " + scene.vehicle_run->vehicle_file, scene,
           radius, std::nullopt))
    options.warning(w);
}

}  // namespace

RunSummary detail::loop(const Scene& scene, std::string_view scene_text,
                        const CollectiveEvaluator& evaluator, ResultsFile& file, LoopStart start,
                        const fs::path& scene_directory, bool builtin, const RunOptions& options) {
  const auto t0 = Clock::now();
  RunSummary summary;
  if (options.distributor) {
    options.distributor->start({builtin, std::string(scene_text), scene_directory, scene.inputs},
                               scene);
    summary.processes = options.distributor->processes();
  }
  int step = start.step;
  double distance = start.distance;
  std::vector<WornProfile> worn = std::move(start.worn);
  std::vector<profiles::Profile> originals;
  for (const WornProfile& w : start.initial) originals.push_back(w.build());
  VehicleCarry carry = std::move(start.vehicle);
  detail::HookCarry hook = std::move(start.hook);
  // The depth arrives smoothed (detail::smoothed): the update adds no smoothing of its own.
  const profiles::WearUpdateOptions update{0.0};
  // The nominal diameter is the new wheel's: a worn profile keeps its nominal radius.
  const profiles::WheelLimits limits = scene.limits.resolve(2.0 * worn.front().info.nominal_radius);
  while (true) {
    std::vector<profiles::Profile> wheels;
    for (const WornProfile& w : worn) wheels.push_back(w.build());
    const std::vector<const profiles::Profile*> pointers = detail::pointers_to(wheels);
    bool vehicle_solved = false;
    if (scene.vehicle_run) {
      vehicle_solved = update_vehicle(*scene.vehicle_run, evaluator.kernel(), worn, pointers, step,
                                      options.distributor, carry);
      if (vehicle_solved) ++summary.vehicle_solves;
    }
    // The profiles' in-service parameters and limits, known before the step's states: a step
    // that ends the run (its distance run, or a limit that stops it) only records.
    std::vector<profiles::WheelParameters> parameters;
    std::vector<std::size_t> limits_reached;  // per profile
    bool reached = false;
    for (const profiles::Profile& wheel : wheels) {
      parameters.push_back(measured_parameters(wheel));
      limits_reached.push_back(profiles::limits_reached(parameters.back(), limits).size());
      reached = reached || limits_reached.back() > 0;
    }
    const double remaining = scene.distance - distance;
    const bool run_through = remaining <= 1e-9 * scene.distance;
    const bool stop = scene.limits.stop && reached && !run_through;
    std::optional<HookCall> hook_call;
    if (scene.hook)
      hook_call = detail::update_hook(*scene.hook, start.hook_directory, step, distance,
                                      run_through || stop, worn.front().points, worn.back().points,
                                      evaluator.kernel().rail(), hook);
    const std::vector<WheelsetStateSpec>& specs = scene.vehicle_run ? carry.last.states
                                                  : scene.hook      ? hook.states
                                                                    : scene.states;
    // The vehicle's tables hold this step's profiles only where it was solved at this step.
    const ContactTables* tables =
        vehicle_solved && scene.vehicle_run->wear_from_table ? &carry.last.contact_tables : nullptr;
    const CollectiveWear cw =
        evaluate_step(evaluator, worn, pointers, specs, !scene.vehicle_run && !scene.hook, tables,
                      options.distributor);
    carry.last.contact_tables.clear();  // the profiles change at the end of the step
    if (options.distributor) {
      summary.gathered_bytes += options.distributor->gathered_bytes();
      summary.gathered_states += options.distributor->gathered_states();
    }
    summary.evaluations += specs.size();
    summary.geometry_solves += cw.geometry_solves;
    summary.table_contacts += cw.table_contacts;

    std::vector<wear::WearDistribution> smooth_rate;
    for (const auto& r : cw.rate)
      smooth_rate.push_back(detail::smoothed(r, scene.smoothing_length));
    // Step control: the distance that keeps the deepest increment below max_depth_step.
    double peak = 0.0;
    for (const auto& r : smooth_rate)
      for (double d : r.depth) peak = std::max(peak, d);

    double step_distance = 0.0;
    if (!run_through && !stop) {
      step_distance = std::min(scene.step_distance, remaining);
      if (peak > 0.0) step_distance = std::min(step_distance, scene.max_depth_step / peak);
    }

    GroupRecord g;
    g.arrays.push_back(scalar("distance", distance, "m", "running distance at this step"));
    g.arrays.push_back(scalar("step_distance", step_distance, "m",
                              "distance of the wear increment taken from here (0: the end)"));
    for (const auto& [name, value] : cw.dropped.named()) {
      ArrayRecord r = scalar(name, value, "1", dropped_description(name));
      r.integer = !name.ends_with("_weight");  // a count, not a share
      g.arrays.push_back(std::move(r));
    }
    g.arrays.push_back(scalar("limits/Sd_min", limits.Sd_min, "m", "least flange thickness"));
    g.arrays.push_back(scalar("limits/Sh_max", limits.Sh_max, "m", "largest flange height"));
    g.arrays.push_back(scalar("limits/qR_min", limits.qR_min, "m", "least qR"));
    g.arrays.push_back(
        as_integer(scalar("limits/stopped", stop ? 1.0 : 0.0, "1",
                          "1 when the run ends here because a profile reached a limit")));
    g.arrays.push_back(as_integer(
        scalar("patches", static_cast<double>(cw.patches), "1", "contact patches solved")));
    g.arrays.push_back(as_integer(
        scalar("table_contacts", static_cast<double>(cw.table_contacts), "1",
               "wheelset contacts interpolated in the vehicle's contact tables of this step "
               "([vehicle] wear_from_table) instead of solved")));
    g.arrays.push_back(
        as_integer(scalar("table_patches", static_cast<double>(cw.table_patches), "1",
                          "of them, with totals from the book of tables "
                          "(tangential_method = best)")));
    g.arrays.push_back(scalar(
        "table_work_share", cw.frictional_work > 0.0 ? cw.table_work / cw.frictional_work : 0.0,
        "1", "share of the step's frictional work on patches with totals from the book of tables"));
    g.arrays.push_back(
        as_integer(scalar("unconverged_patches", static_cast<double>(cw.unconverged_patches), "1",
                          "exact solves (tangential_method = exact) stopped at their "
                          "iteration cap; their last iterate is used")));
    g.arrays.push_back(
        as_integer(scalar("hertz_dropped", static_cast<double>(cw.hertz_dropped), "1",
                          "patches not solved nor worn: the contact model is hertz and they "
                          "have no Hertz ellipse (lateral relative curvature not positive)")));
    std::vector<profiles::WearDepth> increments;
    for (std::size_t p = 0; p < worn.size(); ++p) {
      const std::string& n = worn[p].name;
      std::vector<double> y, z;
      for (const auto& point : worn[p].points) {
        y.push_back(point.x());
        z.push_back(point.y());
      }
      g.arrays.push_back(vector(n + "/y", y, "m",
                                "profile points, lateral: profile frame, + towards the field "
                                "side, 0 at the taping line"));
      g.arrays.push_back(vector(n + "/z", z, "m", "profile points, vertical (+ down)"));
      g.arrays.push_back(scalar(n + "/Sh", parameters[p].Sh, "m", "flange height (EN 15313)"));
      g.arrays.push_back(scalar(n + "/Sd", parameters[p].Sd, "m", "flange thickness (EN 15313)"));
      g.arrays.push_back(
          scalar(n + "/qR", parameters[p].qR, "m", "flange slope measure qR (EN 15313)"));
      g.arrays.push_back(
          as_integer(scalar(n + "/limits_reached", static_cast<double>(limits_reached[p]), "1",
                            "in-service limits (limits/) this profile has reached: Sd, Sh, qR")));
      detail::add_wear_measures(g, n, originals[p], wheels[p]);
      const wear::WearDistribution& rate = cw.rate[p];
      std::vector<double> s(rate.depth.size()), ys(rate.depth.size());
      for (std::size_t k = 0; k < s.size(); ++k) {
        s[k] = rate.s(k);
        ys[k] = wheels[p].position(s[k]).x();
      }
      g.arrays.push_back(
          vector(n + "/wear_rate/s", s, "m", "bin centre, arc length on the profile"));
      g.arrays.push_back(vector(n + "/wear_rate/y", ys, "m",
                                "bin centre, lateral position in the profile frame (+ towards the "
                                "field side, 0 at the taping line)"));
      g.arrays.push_back(
          vector(n + "/wear_rate/depth", rate.depth, "m/m",
                 "worn depth per metre running, weighted over the collective (unsmoothed)"));
      increments.push_back(detail::depth_on_y(wheels[p], smooth_rate[p], step_distance));
      g.arrays.push_back(vector(n + "/wear_step/y", increments.back().y, "m",
                                "lateral positions of the step's wear depth (profile frame, + "
                                "towards the field side)"));
      g.arrays.push_back(
          vector(n + "/wear_step/depth", increments.back().depth, "m",
                 "wear depth of the step (smoothed wear rate times the step distance)"));
    }
    detail::add_conicity(g, evaluator, wheels);
    if (scene.vehicle_run) {
      const double depth_after = carry.depth_since_solve + peak * step_distance;
      detail::add_vehicle_record(g, carry.last, vehicle_solved, depth_after);
      carry.depth_since_solve = depth_after;
    }
    if (scene.hook) {
      const double depth_after = hook.depth_since_call + peak * step_distance;
      detail::add_hook_record(g, hook_call, hook, depth_after);
      hook.depth_since_call = depth_after;
    }
    if (scene.state_summaries) detail::add_state_summaries(g, cw.states);
    if (scene.tgamma_maps) detail::add_tgamma_maps(g, cw.states, scene.grid_nx, scene.grid_ny);
    const auto writing = Clock::now();
    file.append_step(g);
    summary.writing += std::chrono::duration<double>(Clock::now() - writing).count();

    summary.steps = step;
    summary.distance = distance;
    summary.patches += cw.patches;
    summary.table_patches += cw.table_patches;
    if (options.progress) {
      RunProgress p;
      p.step = step;
      p.distance = distance;
      p.total_distance = scene.distance;
      p.states = specs.size();
      p.vehicle_solved = vehicle_solved;
      p.unconverged_cases = scene.vehicle_run ? carry.last.unconverged : 0;
      p.kept_cases = scene.vehicle_run ? carry.last.kept : 0;
      p.elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
      p.evaluations_per_second = static_cast<double>(summary.evaluations) / p.elapsed;
      p.dropped = cw.dropped;
      options.progress(p);
    }
    summary.frictional_work += cw.frictional_work * step_distance;
    summary.table_work += cw.table_work * step_distance;
    if (step_distance == 0.0) break;
    for (std::size_t p = 0; p < worn.size(); ++p) {
      summary.worn_area += p == 0 ? smooth_rate[p].area() * step_distance : 0.0;
      worn[p].points = profiles::apply_wear(wheels[p], increments[p], update).knot_points();
    }
    distance += step_distance;
    ++step;
  }
  summary.elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  if (options.distributor) summary.waited = options.distributor->waited_seconds();
  file.write_run_info(detail::run_info(scene_directory, builtin, summary.elapsed,
                                       summary.evaluations, start.step == 0 ? -1 : start.step - 1,
                                       options.program));
  // The run is over: its last step (the final profiles) gets a fixed name while the file is
  // still small, and its step files become part of the one results file.
  file.link("/final", ResultsFile::step_group(step));
  file.consolidate();
  return summary;
}

std::vector<WornProfile> detail::new_profiles(const Scene& scene) {
  const profiles::Profile initial =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  WornProfile w{"wheel", initial.info(), initial.curve_options(), initial.knot_points()};
  // The profile is re-interpolated through its knots: smoothing was applied once, on reading.
  w.curve.smoothing_length = 0.0;
  std::vector<WornProfile> worn;
  for (const std::string& name : profile_names(profile_layout(scene))) {
    worn.push_back(w);
    worn.back().name = name;
  }
  return worn;
}

fs::path hook_directory(const fs::path& output) {
  fs::path d = output;
  d += ".hook";
  return d;
}

RunSummary run_scene(const Scene& scene, std::string_view scene_text,
                     const fs::path& scene_directory, bool builtin_scene, const fs::path& output,
                     const RunOptions& options) {
  if (options.warning)
    for (const std::string& w : scene.warnings) options.warning(w);
  // Everything that can fail on input fails before the file is created.
  detail::check_hook_allowed(scene, options);
  if (scene.vehicle_run) require_upright_route(*scene.vehicle_run, scene.lateral_arm);
  const CollectiveEvaluator evaluator(scene);
  LoopStart start{0, 0.0, new_profiles(scene)};
  warn_of_vehicle_differences(scene, start.worn.front().info.nominal_radius, options);
  start.initial = start.worn;
  start.hook_directory = hook_directory(output);
  for (const WornProfile& w : start.worn) evaluator.pair(w.build());
  const OutputLock lock(output);
  if (!lock.warning().empty() && options.warning) options.warning(lock.warning());
  // The run information goes in with the scene, so that a run killed before its first step
  // can be resumed from the start.
  ResultsFile file = ResultsFile::create(
      output, scene_text, options.overwrite, detail::collective_record(scene),
      {{"creep_table_sha256", table_hash(scene)}},
      detail::run_info(scene_directory, builtin_scene, 0.0, 0, -1, options.program),
      detail::stored_inputs(scene));
  return detail::loop(scene, scene_text, evaluator, file, std::move(start), scene_directory,
                      builtin_scene, options);
}

RunSummary run_scene_file(const fs::path& scene, const fs::path& output,
                          const RunOptions& options) {
  if (scene.empty())
    return run_scene(default_scene(), default_scene_text(), {}, true, output, options);
  if (!fs::is_regular_file(scene)) throw InputError("scene " + scene.string() + ": no such file");
  const std::string text = core::read_text_file(scene);
  // Absolute: the files it names are recorded by the paths a resumed run looks them up by.
  const fs::path folder = fs::absolute(scene).parent_path();
  Scene parsed;
  try {
    parsed = parse_scene(text, folder);
  } catch (const InputError& error) {
    throw InputError(scene.string() + ": " + error.what());
  }
  return run_scene(parsed, text, folder, false, output, options);
}

}  // namespace wheelwear::pipeline
