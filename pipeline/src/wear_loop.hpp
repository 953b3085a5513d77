#pragma once
// The wear-evolution loop a run starts (wear_run.cpp) and a resumed run continues
// (wear_run_resume.cpp), and what it starts from.

#include <filesystem>
#include <string_view>
#include <vector>

#include "hook_run.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/pipeline/wear_run.hpp"
#include "worn_profile.hpp"

namespace wheelwear::pipeline::detail {

// What a vehicle run carries from step to step: its last solve (the collective, and where each
// case's bodies were, to start the next solve from).
struct VehicleCarry {
  bool solved = false;  // a solve has been made (or read back on resume)
  VehicleCollective last;
  double depth_since_solve = 0.0;  // deepest wear since the last solve [m], an upper bound
};

// Where the loop starts: a new run at step 0 or a resumed one.
struct LoopStart {
  int step = 0;
  double distance = 0.0;
  std::vector<WornProfile> worn;
  std::vector<WornProfile> initial;  // the profiles at step 0, which the wear is measured from
  VehicleCarry vehicle;
  HookCarry hook;
  std::filesystem::path hook_directory;  // the hook's files, a directory per call
};

// Runs the wear steps from `start` to the scene's distance (or a limit), appending each to
// `file`.
RunSummary loop(const Scene& scene, std::string_view scene_text,
                const CollectiveEvaluator& evaluator, ResultsFile& file, LoopStart start,
                const std::filesystem::path& scene_directory, bool builtin,
                const RunOptions& options);

}  // namespace wheelwear::pipeline::detail
