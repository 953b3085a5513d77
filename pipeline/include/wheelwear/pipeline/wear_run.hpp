#pragma once
/// The wear-evolution run: evaluate the collective, step the wheel profile(s) by the wear of a
/// controlled distance, record every step durably in the results file, repeat.

#include <filesystem>
#include <functional>
#include <string>

#include "wheelwear/core/version.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/distributed_run.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline {

/// Where a run is, for progress reports.
struct RunProgress {
  int step = 0;                         ///< index of the step just written (0: the new profile)
  double distance = 0.0;                ///< running distance reached [m]
  double total_distance = 0.0;          ///< the scene's distance [m]
  std::size_t states = 0;               ///< states in the collective
  double elapsed = 0.0;                 ///< wall time of this process so far [s]
  double evaluations_per_second = 0.0;  ///< wheelset states evaluated per second so far
  DroppedStates dropped;                ///< states of this step not worn, by reason
  bool vehicle_solved = false;          ///< a vehicle run solved its vehicle on this step
  int unconverged_cases = 0;            ///< of its last solve, cases that did not converge
  int kept_cases = 0;  ///< of its last solve, cases that kept their last converged solution
};

/// How a run is driven.
struct RunOptions {
  bool overwrite = false;  ///< replace an existing output file
  /// Let a scene's co-simulation hook ([hook] command) run its program; a scene with a hook is
  /// refused without it.
  bool allow_hook = false;
  std::function<void(const RunProgress&)> progress;  ///< called after every step
  /// Called with what the user should know but does not stop the run (e.g. an output on a file
  /// system without locks, OutputLock::warning); unset: not reported.
  std::function<void(const std::string&)> warning;
  /// Resume with the inputs stored in the results file even where a file the scene names has
  /// changed since (without it such a resume is refused, naming the file).
  bool resume_stored = false;
  /// The program and version that writes the run, recorded in /run_info/program (the command
  /// line gives its version and commit).
  std::string program = std::string("wheelwear library ") + core::version();
  /// Spreads each step's states over the processes of a job (distributed_run.hpp); unset: this
  /// process evaluates them all. Not owned.
  StepDistributor* distributor = nullptr;
};

/// What a run did.
struct RunSummary {
  int steps = 0;                    ///< wear steps taken (file groups minus one)
  double distance = 0.0;            ///< [m]
  double worn_area = 0.0;           ///< worn cross-section of the (first) wheel profile [m^2]
  double elapsed = 0.0;             ///< wall time of this process [s]
  std::size_t evaluations = 0;      ///< wheelset states evaluated by this process
  std::size_t geometry_solves = 0;  ///< distinct wheel/rail contacts solved by this process
  std::size_t table_contacts = 0;   ///< of them, interpolated in the vehicle's contact tables
  std::size_t patches = 0;          ///< contact patches solved by this process
  std::size_t table_patches = 0;    ///< of them, with totals from the book of tables ("best")
  /// The frictional work of the worn distance [J] (each step's share-weighted work times its
  /// step distance), and of it the work with totals from the book of tables.
  double frictional_work = 0.0, table_work = 0.0;
  int vehicle_solves = 0;           ///< a vehicle run's solves of its vehicle by this process
  int processes = 1;                ///< processes the steps were spread over
  std::size_t gathered_bytes = 0;   ///< outcomes gathered from the other processes, all steps
  std::size_t gathered_states = 0;  ///< the states they were the outcomes of, all steps
  /// Of `elapsed`, process 0's wait for the other processes (StepDistributor::waited_seconds)
  /// and the writing of the steps to the results file [s].
  double waited = 0.0;
  double writing = 0.0;
};

/// The directory beside `output` where a co-simulation hook's calls keep their files
/// (`output` + ".hook", a step_NNNNNN directory per call).
std::filesystem::path hook_directory(const std::filesystem::path& output);

/// Runs `scene` from its new profile and writes `output` (see README, "Results file").
/// `scene_text` is recorded in the file; `scene_directory` resolves its relative file names on
/// resume (empty for the built-in scene).
RunSummary run_scene(const Scene& scene, std::string_view scene_text,
                     const std::filesystem::path& scene_directory, bool builtin_scene,
                     const std::filesystem::path& output, const RunOptions& options);

/// Runs the scene file `scene` (its text read once, recorded in the file; its relative file names
/// from its folder), or the built-in scene where `scene` is empty, into `output`.
RunSummary run_scene_file(const std::filesystem::path& scene, const std::filesystem::path& output,
                          const RunOptions& options);

/// Continues the run recorded in `output` from its last complete step; the result is identical
/// to an uninterrupted run. The scene and every file it names come from the results file
/// (/scene, /inputs), never from the disk: a file that still exists where the scene named it
/// but has changed is refused by name unless options.resume_stored. Throws InputError when the
/// file is not a run, is complete, or was written by another program version or with another
/// book of creep-force tables.
RunSummary resume_run(const std::filesystem::path& output, const RunOptions& options);

}  // namespace wheelwear::pipeline
