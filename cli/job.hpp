#pragma once
// The job this process belongs to: alone, or one process of an MPI job (mpirun, srun), where
// `run` and `sweep` share their work and process 0 alone reads, writes and reports.

#include <memory>
#include <string>

#include "wheelwear/pipeline/distributed_run.hpp"
#include "wheelwear/pipeline/process_group.hpp"

namespace wheelwear::cli {

class Job {
 public:
  /// Joins the MPI job that started the process, if one did (pipeline::join_mpi_job).
  void join(int& argc, char**& argv);

  /// The group of processes; null when this process runs alone.
  pipeline::ProcessGroup* group() const { return group_.get(); }
  int rank() const { return group_ ? group_->rank() : 0; }
  int size() const { return group_ ? group_->size() : 1; }
  /// Process 0, or the only one: it reads and writes files and talks to the user.
  bool leader() const { return rank() == 0; }

  /// Before the command line is parsed: in a job of several processes, a `run` makes process 0
  /// the distributor of its steps and the others their servers, whatever the parse gives (so
  /// that process 0 can always release them, even after a parse error of its own).
  void prepare(const std::string& command);
  /// Process 0 of a `run` over several processes: the distributor of its steps. Null elsewhere.
  pipeline::StepDistributor* distributor() const { return distributor_.get(); }
  /// The other processes of a `run`: serves process 0's steps, returns its exit status.
  int serve();
  /// Whether this process still has to serve a `run` (its command line did not reach the run).
  bool owes_service() const { return must_serve_ && !served_; }
  /// Whether this process has work in hand for the job (a serving process, or process 0 with a
  /// distributor): an error here must end the others too.
  bool working() const { return serving_ || distributor_ != nullptr; }

  /// Ends this process's part with exit status `code`: process 0 releases the processes serving
  /// its steps (or, in the middle of a step's exchange, aborts the job); a serving process
  /// that failed aborts the job, which waits for it. Returns the status to exit with (a serving
  /// process's: process 0's).
  int end(int code);

 private:
  std::unique_ptr<pipeline::ProcessGroup> group_;
  std::unique_ptr<pipeline::StepDistributor> distributor_;
  bool must_serve_ = false;
  bool serving_ = false;
  bool served_ = false;
  int served_code_ = 0;  // the status process 0 ended the service with
};

/// This process's job.
Job& job();

}  // namespace wheelwear::cli
