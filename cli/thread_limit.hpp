#pragma once
// The --threads option of the commands that run TBB-parallel work.

#include <tbb/global_control.h>

#include <cstddef>
#include <memory>

namespace wheelwear::cli {

/// Caps TBB's worker threads at `threads` while the returned object lives; no cap (all cores)
/// for 0.
inline std::unique_ptr<tbb::global_control> thread_limit(int threads) {
  if (threads <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(threads));
}

}  // namespace wheelwear::cli
