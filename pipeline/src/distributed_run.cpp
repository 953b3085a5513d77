#include "wheelwear/pipeline/distributed_run.hpp"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "stored_inputs.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wire.hpp"
#include "worn_profile.hpp"

namespace wheelwear::pipeline {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// What rank 0 broadcasts; every message starts with its kind.
enum class Message : std::uint64_t {
  start = 1,
  step = 2,
  finish = 3,
  prepare_route = 4,
  cases = 5,
  pieces = 6,
};

// Which process works out each task: the dearest first, each to the least loaded process (the
// lowest rank among equals), so that a few dear tasks do not meet on one process.
template <class Task>
std::vector<int> share_out(const std::vector<Task>& tasks, int processes) {
  std::vector<std::size_t> order(tasks.size());
  for (std::size_t t = 0; t < order.size(); ++t) order[t] = t;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return tasks[a].cost > tasks[b].cost; });
  std::vector<double> load(static_cast<std::size_t>(processes), 0.0);
  std::vector<int> owner(tasks.size(), 0);
  for (std::size_t t : order) {
    const auto least = std::min_element(load.begin(), load.end()) - load.begin();
    owner[t] = static_cast<int>(least);
    load[static_cast<std::size_t>(least)] += tasks[t].cost;
  }
  return owner;
}

// The tasks `owner` gives `rank`, in their order.
template <class Task>
std::vector<Task> tasks_of(const std::vector<Task>& tasks, const std::vector<int>& owner,
                           int rank) {
  std::vector<Task> mine;
  for (std::size_t t = 0; t < tasks.size(); ++t)
    if (owner[t] == rank) mine.push_back(tasks[t]);
  return mine;
}

void write_owners(detail::WireWriter& w, const std::vector<int>& owner) {
  w.u64(owner.size());
  for (int o : owner) w.i64(o);
}

std::vector<int> read_owners(detail::WireReader& r) {
  std::vector<int> owner(r.count(8));
  for (int& o : owner) o = static_cast<int>(r.i64());
  return owner;
}

// The states of each of `ranks` processes (owner: each state's), ascending.
std::vector<std::vector<std::size_t>> states_by_rank(const std::vector<int>& owner, int ranks) {
  std::vector<std::vector<std::size_t>> states(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < owner.size(); ++i)
    states[static_cast<std::size_t>(owner[i])].push_back(i);
  return states;
}

std::vector<profiles::Profile> rebuilt(const std::vector<detail::WornProfile>& templates,
                                       const std::vector<profiles::PointList>& points) {
  if (points.size() != templates.size())
    throw std::runtime_error("a step's message holds " + std::to_string(points.size()) +
                             " profiles, the scene wears " + std::to_string(templates.size()));
  std::vector<profiles::Profile> wheels;
  for (std::size_t p = 0; p < points.size(); ++p)
    wheels.push_back(profiles::Profile(points[p], templates[p].info, templates[p].curve));
  return wheels;
}

}  // namespace

Scene parse_source(const SceneSource& source) {
  if (source.builtin) return default_scene();
  std::map<std::string, std::string> files;
  for (const SceneInput& in : source.inputs) files[in.path] = in.content;
  return parse_scene(source.text, source.directory, detail::stored_files(std::move(files)));
}

void StepDistributor::start(const SceneSource& source, const Scene& scene) {
  if (started_) return;
  detail::WireWriter w;
  w.u64(static_cast<std::uint64_t>(Message::start));
  detail::write(w, source);
  // The others must solve with the same book of tables (a resumed run's is checked likewise).
  w.text(scene.tangential == TangentialMethod::best ? tangential::creep_table_sha256() : "");
  std::string message = w.take();
  group_.broadcast(message);
  started_ = true;
}

StateOutcomes StepDistributor::outcomes(const CollectiveEvaluator& evaluator,
                                        const std::vector<profiles::PointList>& points,
                                        const std::vector<const profiles::Profile*>& wheels,
                                        const std::vector<WheelsetStateSpec>& specs,
                                        bool scene_states, const ContactTables* tables) {
  busy_ = true;
  detail::WireWriter w;
  w.u64(static_cast<std::uint64_t>(Message::step));
  detail::write(w, points);
  w.flag(scene_states);
  w.flag(tables != nullptr);
  if (!scene_states) detail::write(w, specs);
  std::string message = w.take();
  group_.broadcast(message);

  const std::vector<std::vector<std::size_t>> share =
      states_by_rank(evaluator.owners(specs, group_.size()), group_.size());
  const std::vector<std::size_t>& own = share[0];
  StateOutcomes mine;
  tbb::this_task_arena::isolate([&] { mine = evaluator.outcomes(wheels, specs, own, tables); });
  const auto waiting = Clock::now();
  const std::vector<std::string> parts = group_.gather({});
  busy_ = false;  // the others are free again; what follows is this process's alone

  StateOutcomes all;
  all.states.resize(specs.size());
  all.geometry_solves = mine.geometry_solves;
  all.table_contacts = mine.table_contacts;
  for (std::size_t k = 0; k < own.size(); ++k) all.states[own[k]] = std::move(mine.states[k]);
  gathered_bytes_ = 0;
  gathered_states_ = specs.size() - own.size();
  for (int rank = 1; rank < group_.size(); ++rank) {
    const std::string& part = parts.at(static_cast<std::size_t>(rank));
    gathered_bytes_ += part.size();
    detail::WireReader r(part);
    all.geometry_solves += r.u64();
    all.table_contacts += r.u64();
    std::vector<StateOutcome> theirs = detail::read_outcomes(r);
    const std::vector<std::size_t>& which = share[static_cast<std::size_t>(rank)];
    if (theirs.size() != which.size() || !r.done())
      throw std::runtime_error("process " + std::to_string(rank) + " returned " +
                               std::to_string(theirs.size()) + " state outcomes for " +
                               std::to_string(which.size()) + " states");
    for (std::size_t k = 0; k < which.size(); ++k) all.states[which[k]] = std::move(theirs[k]);
  }
  waited_seconds_ += seconds_since(waiting);
  return all;
}

void StepDistributor::prepare_route(const std::vector<profiles::PointList>& points,
                                    std::uint64_t draw) {
  detail::WireWriter w;
  w.u64(static_cast<std::uint64_t>(Message::prepare_route));
  detail::write(w, points);
  w.u64(draw);
  std::string message = w.take();
  group_.broadcast(message);
}

template <class Result, class Task, class Compute, class Read>
std::vector<Result> StepDistributor::spread(std::uint64_t kind, const std::vector<Task>& tasks,
                                            const Compute& compute, const Read& read) {
  busy_ = true;
  const std::vector<int> owner = share_out(tasks, group_.size());
  detail::WireWriter w;
  w.u64(kind);
  detail::write(w, tasks);
  write_owners(w, owner);
  std::string message = w.take();
  group_.broadcast(message);
  // Isolated: this thread must not take up other work of the solve meanwhile (its critical-
  // speed search), which would hold every process up at the gather until it is done.
  std::vector<Result> mine;
  tbb::this_task_arena::isolate([&] { mine = compute(tasks_of(tasks, owner, 0)); });
  const auto waiting = Clock::now();
  const std::vector<std::string> parts = group_.gather({});
  busy_ = false;  // the others are free again; what follows is this process's alone
  std::vector<Result> all(tasks.size());
  for (int rank = 0; rank < group_.size(); ++rank) {
    std::vector<Result> theirs;
    if (rank == 0) {
      theirs = std::move(mine);
    } else {
      detail::WireReader r(parts.at(static_cast<std::size_t>(rank)));
      theirs = read(r);
      if (!r.done())
        throw std::runtime_error("process " + std::to_string(rank) + " sent more than its results");
    }
    const auto owned = static_cast<std::size_t>(std::count(owner.begin(), owner.end(), rank));
    if (theirs.size() != owned)
      throw std::runtime_error("process " + std::to_string(rank) + " returned " +
                               std::to_string(theirs.size()) + " results for its " +
                               std::to_string(owned) + " tasks");
    std::size_t k = 0;
    for (std::size_t t = 0; t < tasks.size(); ++t)
      if (owner[t] == rank) all[t] = std::move(theirs[k++]);
  }
  waited_seconds_ += seconds_since(waiting);
  return all;
}

std::vector<vehicle::VehicleCurving> StepDistributor::cases(const RouteSolver& solver,
                                                            const std::vector<CaseTask>& tasks) {
  RouteExecutor here;
  return spread<vehicle::VehicleCurving>(
      static_cast<std::uint64_t>(Message::cases), tasks,
      [&](const std::vector<CaseTask>& mine) { return here.cases(solver, mine); },
      [](detail::WireReader& r) { return detail::read_curvings(r); });
}

std::vector<PieceOutcome> StepDistributor::pieces(const RouteSolver& solver,
                                                  const std::vector<PieceTask>& tasks) {
  RouteExecutor here;
  return spread<PieceOutcome>(
      static_cast<std::uint64_t>(Message::pieces), tasks,
      [&](const std::vector<PieceTask>& mine) { return here.pieces(solver, mine); },
      [](detail::WireReader& r) { return detail::read_piece_outcomes(r); });
}

void StepDistributor::finish(int code) {
  if (finished_ || busy_) return;
  detail::WireWriter w;
  w.u64(static_cast<std::uint64_t>(Message::finish));
  w.i64(code);
  std::string message = w.take();
  group_.broadcast(message);
  finished_ = true;
}

namespace {

// The other processes' side of a run: what process 0's messages ask, one handler each.
class StepServer {
 public:
  explicit StepServer(ProcessGroup& group) : group_(group) {}

  // Handles messages until process 0 finishes; returns the status it finished with.
  int serve() {
    while (true) {
      std::string message;
      group_.broadcast(message);
      detail::WireReader r(message);
      const auto kind = static_cast<Message>(r.u64());
      if (kind == Message::finish) return static_cast<int>(r.i64());
      if (kind == Message::start) {
        start(r);
      } else if (kind == Message::step && evaluator_) {
        step(r);
      } else if (kind == Message::prepare_route && evaluator_ && scene_->vehicle_run) {
        prepare_route(r);
      } else if (kind == Message::cases && solver_) {
        const std::vector<CaseTask> tasks = detail::read_case_tasks(r);
        answer(tasks, r,
               [&](const std::vector<CaseTask>& mine) { return here_.cases(*solver_, mine); });
      } else if (kind == Message::pieces && solver_) {
        const std::vector<PieceTask> tasks = detail::read_piece_tasks(r);
        answer(tasks, r,
               [&](const std::vector<PieceTask>& mine) { return here_.pieces(*solver_, mine); });
      } else {
        throw std::runtime_error("unexpected message from process 0 (kind " +
                                 std::to_string(static_cast<std::uint64_t>(kind)) + ")");
      }
    }
  }

 private:
  void start(detail::WireReader& r) {
    scene_ = parse_source(detail::read_scene_source(r));
    const std::string table = r.text();
    if (!table.empty() && table != tangential::creep_table_sha256())
      throw InputError("creep table " + tangential::creep_table_path().string() + " (SHA-256 " +
                       tangential::creep_table_sha256() + ") is not process 0's (" + table +
                       "): every process of the job must read the same book of tables; point "
                       "WHEELWEAR_DATA_DIR to it");
    evaluator_ = std::make_unique<CollectiveEvaluator>(*scene_);
    templates_ = detail::new_profiles(*scene_);
  }

  // This process's share of a step's states.
  void step(detail::WireReader& r) {
    const std::vector<profiles::Profile> wheels = rebuilt(templates_, detail::read_point_lists(r));
    const bool scene_states = r.flag();
    // The tables of this step's vehicle solve, on the same profiles (prepare_route).
    const bool on_tables = r.flag();
    if (on_tables && !solver_)
      throw std::runtime_error(
          "process 0 evaluates a step on the vehicle's contact tables, and "
          "this process has built none");
    const std::vector<WheelsetStateSpec> sent =
        scene_states ? std::vector<WheelsetStateSpec>{} : detail::read_specs(r);
    const std::vector<WheelsetStateSpec>& specs = scene_states ? scene_->states : sent;
    const std::vector<std::size_t> mine =
        states_by_rank(evaluator_->owners(specs, group_.size()),
                       group_.size())[static_cast<std::size_t>(group_.rank())];
    const StateOutcomes outcomes = evaluator_->outcomes(
        detail::pointers_to(wheels), specs, mine, on_tables ? &solver_->contact_tables() : nullptr);
    detail::WireWriter w;
    w.u64(outcomes.geometry_solves);
    w.u64(outcomes.table_contacts);
    detail::write(w, outcomes.states);
    group_.gather(w.bytes());
  }

  // The solver of a vehicle solve on its profiles.
  void prepare_route(detail::WireReader& r) {
    // The profiles outlive the solver, whose contact models refer to them.
    solver_.reset();
    route_wheels_ = rebuilt(templates_, detail::read_point_lists(r));
    const std::uint64_t draw = r.u64();
    solver_ = std::make_unique<RouteSolver>(*scene_->vehicle_run, evaluator_->kernel(),
                                            detail::pointers_to(route_wheels_), draw);
  }

  // This process's share of `tasks` (by the owners `r` holds next), worked out with `compute`,
  // to process 0.
  template <class Task, class Compute>
  void answer(const std::vector<Task>& tasks, detail::WireReader& r, const Compute& compute) {
    const std::vector<int> owner = read_owners(r);
    if (owner.size() != tasks.size())
      throw std::runtime_error("a message from process 0 gives " + std::to_string(owner.size()) +
                               " owners for " + std::to_string(tasks.size()) + " tasks");
    detail::WireWriter w;
    detail::write(w, compute(tasks_of(tasks, owner, group_.rank())));
    group_.gather(w.bytes());
  }

  ProcessGroup& group_;
  std::optional<Scene> scene_;
  std::unique_ptr<CollectiveEvaluator> evaluator_;
  std::vector<detail::WornProfile> templates_;
  std::vector<profiles::Profile> route_wheels_;  // a vehicle solve's, while it lasts
  std::unique_ptr<RouteSolver> solver_;
  RouteExecutor here_;
};

}  // namespace

int serve_steps(ProcessGroup& group) {
  return StepServer(group).serve();
}

}  // namespace wheelwear::pipeline
