#pragma once
/// A run's steps spread over the processes of a job (process_group.hpp). Rank 0 runs the run as
/// one process would: it reads the scene, writes the results file and reports progress. At every
/// step it sends the current profiles (and the step's states, where they are not the scene's own)
/// to the other processes; each evaluates the states of its share (CollectiveEvaluator::owners)
/// with TBB, and rank 0 gathers their outcomes and reduces all of them in the collective's order,
/// exactly as a single process does. A vehicle solve's quasi-static cases and time-domain pieces
/// are spread likewise, one by one. The results file is therefore bit-identical to the
/// single-process run's for any number of processes (on the same build and CPU), and a run started
/// with one number of processes resumes with any other.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/process_group.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/types.hpp"

namespace wheelwear::pipeline {

/// What a scene was read from: enough for another process to parse the identical scene without
/// reading any file (the run's /scene and /inputs).
struct SceneSource {
  bool builtin = false;             ///< the built-in scene (text and inputs unused)
  std::string text;                 ///< the scene file's text
  std::filesystem::path directory;  ///< its folder, against which its file names resolve
  std::vector<SceneInput> inputs;   ///< the files it names, with their bytes
};

/// The scene of `source`, parsed from its text and stored files only.
Scene parse_source(const SceneSource& source);

/// Rank 0's side: hands each step's states (and a vehicle solve's cases and pieces) out and
/// gathers their outcomes.
class StepDistributor final : public RouteExecutor {
 public:
  explicit StepDistributor(ProcessGroup& group) : group_(group) {}

  /// Sends the run's scene (`scene`, parsed from `source`) to the other processes, which build
  /// their evaluator from it and check that they read the same book of creep-force tables.
  /// Once, before the first step.
  void start(const SceneSource& source, const Scene& scene);
  /// The outcomes of every state of `specs` on the profiles `wheels` (built from `points`, as the
  /// other processes rebuild them), each process evaluating its share. `scene_states`: `specs`
  /// are the scene's own collective, which the other processes hold already. `tables`: process
  /// 0's tables of the vehicle solved on these profiles (prepare_route); the others evaluate on
  /// the tables they built there.
  StateOutcomes outcomes(const CollectiveEvaluator& evaluator,
                         const std::vector<profiles::PointList>& points,
                         const std::vector<const profiles::Profile*>& wheels,
                         const std::vector<WheelsetStateSpec>& specs, bool scene_states,
                         const ContactTables* tables = nullptr);
  /// Before a vehicle solve: the other processes build the same RouteSolver on the profiles of
  /// `points` for `draw` (their contact tables) while process 0 builds its own.
  void prepare_route(const std::vector<profiles::PointList>& points, std::uint64_t draw);
  /// The vehicle solve's cases and pieces (RouteExecutor) spread over the processes, after
  /// prepare_route on the same profiles: the dearest tasks first (CaseTask::cost,
  /// PieceTask::cost), each to the least loaded process; results in the tasks' order.
  std::vector<vehicle::VehicleCurving> cases(const RouteSolver& solver,
                                             const std::vector<CaseTask>& tasks) override;
  std::vector<PieceOutcome> pieces(const RouteSolver& solver,
                                   const std::vector<PieceTask>& tasks) override;
  /// Ends the other processes' service; they exit with `code`. Idempotent.
  void finish(int code);

  /// Whether a step's exchange is under way (then the others wait inside it, and only
  /// ProcessGroup::abort can end them).
  bool busy() const { return busy_; }
  bool started() const { return started_; }
  int processes() const { return group_.size(); }
  /// Bytes of state outcomes gathered from the other processes at the last step (a vehicle
  /// solve's cases and pieces not counted).
  std::size_t gathered_bytes() const { return gathered_bytes_; }
  /// The states whose outcomes they were.
  std::size_t gathered_states() const { return gathered_states_; }
  /// Wall time process 0 has spent, over all steps, from finishing its own share of an exchange
  /// to holding everyone's results [s]: the others' longer shares (imbalance) and the
  /// communication.
  double waited_seconds() const { return waited_seconds_; }

 private:
  // Deals `tasks` out (message `kind`), computes process 0's share with `compute`, gathers the
  // others' (`read` from their bytes) and returns all results in the tasks' order.
  template <class Result, class Task, class Compute, class Read>
  std::vector<Result> spread(std::uint64_t kind, const std::vector<Task>& tasks,
                             const Compute& compute, const Read& read);

  ProcessGroup& group_;
  bool started_ = false;
  bool finished_ = false;
  bool busy_ = false;
  std::size_t gathered_bytes_ = 0;
  std::size_t gathered_states_ = 0;
  double waited_seconds_ = 0.0;
};

/// The other processes' side: evaluates their share of every step rank 0's StepDistributor
/// sends, until it finishes; returns the exit status rank 0 ended with.
int serve_steps(ProcessGroup& group);

}  // namespace wheelwear::pipeline
