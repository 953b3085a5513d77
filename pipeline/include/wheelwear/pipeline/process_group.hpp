#pragma once
/// The processes of one job that share its work: an MPI job's (mpirun, Slurm's srun) in a build
/// with WHEELWEAR_MPI. Everything MPI is behind this interface, in one translation unit
/// (pipeline/src/mpi_process_group.cpp); the rest of the program speaks bytes.

#include <memory>
#include <string>
#include <vector>

namespace wheelwear::pipeline {

/// Collective operations among the processes of a job, called by every process in the same
/// order (as MPI's collectives are). Rank 0 leads: it reads, writes and reports.
class ProcessGroup {
 public:
  virtual ~ProcessGroup() = default;
  virtual int rank() const = 0;  ///< this process, 0 ... size() - 1
  virtual int size() const = 0;  ///< processes in the job
  /// Rank 0's `bytes` to every process: elsewhere `bytes` is replaced by them.
  virtual void broadcast(std::string& bytes) = 0;
  /// Every process's `bytes` to rank 0, in rank order (rank 0's own first); empty elsewhere.
  virtual std::vector<std::string> gather(const std::string& bytes) = 0;
  /// Ends every process of the job with exit status `code`, at once: for an error one process
  /// met while the others wait for it (after it has said what went wrong).
  [[noreturn]] virtual void abort(int code) = 0;
};

/// Whether this program was built with MPI (WHEELWEAR_MPI).
bool mpi_built();

/// Joins the MPI job this process was started in, or returns null: in a build without MPI, or
/// when no MPI launcher started the process (a plain command line never initialises MPI). MPI is
/// finalised when the group is destroyed.
std::unique_ptr<ProcessGroup> join_mpi_job(int& argc, char**& argv);

}  // namespace wheelwear::pipeline
