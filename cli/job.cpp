#include "job.hpp"

namespace wheelwear::cli {

Job& job() {
  static Job instance;
  return instance;
}

void Job::join(int& argc, char**& argv) {
  group_ = pipeline::join_mpi_job(argc, argv);
}

void Job::prepare(const std::string& command) {
  if (!group_ || group_->size() < 2 || command != "run") return;
  if (leader())
    distributor_ = std::make_unique<pipeline::StepDistributor>(*group_);
  else
    must_serve_ = true;
}

int Job::serve() {
  served_ = true;
  serving_ = true;
  served_code_ = pipeline::serve_steps(*group_);
  serving_ = false;
  return served_code_;
}

int Job::end(int code) {
  if (serving_ && code != 0) group_->abort(code);  // process 0 waits for this one's share
  if (distributor_) {
    if (distributor_->busy()) group_->abort(code);  // the others wait inside the step
    distributor_->finish(code);
    distributor_.reset();
  }
  group_.reset();  // finalises MPI
  return code != 0 ? code : served_code_;
}

}  // namespace wheelwear::cli
