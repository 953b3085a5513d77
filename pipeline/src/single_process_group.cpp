// A build without MPI (WHEELWEAR_MPI off): every job is this one process.

#include "wheelwear/pipeline/process_group.hpp"

namespace wheelwear::pipeline {

bool mpi_built() {
  return false;
}

std::unique_ptr<ProcessGroup> join_mpi_job(int& /*argc*/, char**& /*argv*/) {
  return nullptr;
}

}  // namespace wheelwear::pipeline
