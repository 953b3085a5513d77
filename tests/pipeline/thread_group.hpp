#pragma once
// A ProcessGroup of threads in this process, for testing what a run spread over an MPI job
// does without MPI: the same collective calls, with the bytes handed over in memory.

#include <barrier>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "wheelwear/pipeline/process_group.hpp"

namespace wheelwear::pipeline {

// What the threads of a group share.
struct ThreadGroupShared {
  explicit ThreadGroupShared(int processes)
      : size(processes), sync(processes), parts(static_cast<std::size_t>(processes)) {}
  int size;
  std::barrier<> sync;
  std::string broadcast;
  std::vector<std::string> parts;
};

class ThreadGroup final : public ProcessGroup {
 public:
  ThreadGroup(std::shared_ptr<ThreadGroupShared> shared, int rank)
      : shared_(std::move(shared)), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return shared_->size; }
  void broadcast(std::string& bytes) override {
    if (rank_ == 0) shared_->broadcast = bytes;
    shared_->sync.arrive_and_wait();
    if (rank_ != 0) bytes = shared_->broadcast;
    shared_->sync.arrive_and_wait();
  }
  std::vector<std::string> gather(const std::string& bytes) override {
    shared_->parts[static_cast<std::size_t>(rank_)] = bytes;
    shared_->sync.arrive_and_wait();
    std::vector<std::string> all;
    if (rank_ == 0) all = shared_->parts;
    shared_->sync.arrive_and_wait();
    return all;
  }
  [[noreturn]] void abort(int /*code*/) override { std::abort(); }

 private:
  std::shared_ptr<ThreadGroupShared> shared_;
  int rank_;
};

// Runs `leader` as process 0 of a group of `size` threads and `other` as each of the others;
// returns once all have. `leader` must not throw (the others would wait for it for ever).
inline void run_thread_group(int size, const std::function<void(ProcessGroup&)>& leader,
                             const std::function<void(ProcessGroup&)>& other) {
  auto shared = std::make_shared<ThreadGroupShared>(size);
  std::vector<std::thread> threads;
  for (int rank = 1; rank < size; ++rank)
    threads.emplace_back([&, rank] {
      ThreadGroup group(shared, rank);
      other(group);
    });
  ThreadGroup group(shared, 0);
  leader(group);
  for (std::thread& t : threads) t.join();
}

}  // namespace wheelwear::pipeline
