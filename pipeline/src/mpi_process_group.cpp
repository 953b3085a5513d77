// The program's only MPI code: a ProcessGroup over MPI_COMM_WORLD (built with WHEELWEAR_MPI).

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "wheelwear/pipeline/process_group.hpp"

namespace wheelwear::pipeline {

namespace {

// Messages go in pieces MPI's int counts can hold.
constexpr std::uint64_t kPiece = 1U << 30;

// Whether an MPI launcher started this process: Open MPI's mpirun, a PMI or PMIx launcher
// (MPICH's, Slurm's srun). A plain command line never initialises MPI.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

class MpiGroup final : public ProcessGroup {
 public:
  MpiGroup(int& argc, char**& argv) {
    // Only the main thread calls MPI; TBB's threads never do.
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (provided < MPI_THREAD_FUNNELED) {
      if (rank_ == 0)
        std::fprintf(stderr,
                     "wheelwear: error: this MPI library does not allow a threaded program "
                     "(MPI_THREAD_FUNNELED); build wheelwear with one that does (Open MPI does)\n");
      MPI_Abort(MPI_COMM_WORLD, 3);
    }
  }
  ~MpiGroup() override { MPI_Finalize(); }
  MpiGroup(const MpiGroup&) = delete;
  MpiGroup& operator=(const MpiGroup&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void broadcast(std::string& bytes) override {
    std::uint64_t length = bytes.size();
    MPI_Bcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    bytes.resize(length);
    for (std::uint64_t at = 0; at < length; at += kPiece)
      MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(kPiece, length - at)), MPI_BYTE, 0,
                MPI_COMM_WORLD);
  }

  std::vector<std::string> gather(const std::string& bytes) override {
    const std::uint64_t length = bytes.size();
    std::vector<std::uint64_t> lengths(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
    MPI_Gather(&length, 1, MPI_UINT64_T, lengths.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    std::uint64_t total = 0;
    for (std::uint64_t l : lengths) total += l;
    MPI_Bcast(&total, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    if (total < INT_MAX) return gather_at_once(bytes, lengths, total);
    return gather_in_pieces(bytes, lengths);
  }

  [[noreturn]] void abort(int code) override {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);  // MPI_Abort does not return; should it, the process still ends
  }

 private:
  // All of it in one MPI_Gatherv, which the library can arrange as a tree.
  std::vector<std::string> gather_at_once(const std::string& bytes,
                                          const std::vector<std::uint64_t>& lengths,
                                          std::uint64_t total) {
    std::string all(rank_ == 0 ? total : 0, '\0');
    std::vector<int> counts, offsets;
    int at = 0;
    for (std::uint64_t l : lengths) {
      counts.push_back(static_cast<int>(l));
      offsets.push_back(at);
      at += static_cast<int>(l);
    }
    MPI_Gatherv(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, all.data(), counts.data(),
                offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
    std::vector<std::string> parts;
    for (std::size_t r = 0; r < lengths.size(); ++r)
      parts.push_back(all.substr(static_cast<std::size_t>(offsets[r]), lengths[r]));
    return parts;
  }

  // More than an int can count: each process's bytes to rank 0 in turn, in pieces.
  std::vector<std::string> gather_in_pieces(const std::string& bytes,
                                            const std::vector<std::uint64_t>& lengths) {
    std::vector<std::string> parts;
    if (rank_ != 0) {
      for (std::uint64_t at = 0; at < bytes.size(); at += kPiece)
        MPI_Send(bytes.data() + at,
                 static_cast<int>(std::min<std::uint64_t>(kPiece, bytes.size() - at)), MPI_BYTE, 0,
                 0, MPI_COMM_WORLD);
      return parts;
    }
    parts.push_back(bytes);
    for (int r = 1; r < size_; ++r) {
      std::string part(lengths[static_cast<std::size_t>(r)], '\0');
      for (std::uint64_t at = 0; at < part.size(); at += kPiece)
        MPI_Recv(part.data() + at,
                 static_cast<int>(std::min<std::uint64_t>(kPiece, part.size() - at)), MPI_BYTE, r,
                 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      parts.push_back(std::move(part));
    }
    return parts;
  }

  int rank_ = 0;
  int size_ = 1;
};

}  // namespace

bool mpi_built() {
  return true;
}

std::unique_ptr<ProcessGroup> join_mpi_job(int& argc, char**& argv) {
  if (!launched_by_mpi()) return nullptr;
  return std::make_unique<MpiGroup>(argc, argv);
}

}  // namespace wheelwear::pipeline
