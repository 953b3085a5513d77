#pragma once
// The results file's layout of what a run computes: per-step scalars and arrays, per-state
// summaries and T gamma maps from the kernel's outcomes, the collective and the run's
// information (docs/results.md). The physics knows nothing of it.

#include <filesystem>
#include <string>
#include <vector>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"

namespace wheelwear::pipeline::detail {

ArrayRecord scalar(std::string name, double value, std::string units, std::string description);
ArrayRecord vector(std::string name, std::vector<double> values, std::string units,
                   std::string description);

// states/...: per state and wheel, and per state, wheel and patch (shape [states, 2, P], P the
// largest patch count of the step, NaN where a wheel has fewer patches).
void add_state_summaries(GroupRecord& g, const std::vector<StateOutcome>& states);

// tgamma/...: every patch's cells, shape [states, 2, P, ny, nx], NaN where there is no patch.
void add_tgamma_maps(GroupRecord& g, const std::vector<StateOutcome>& states, int nx, int ny);

// NAME/cumulative_wear/ (the depth worn since step 0 along the step-0 profile's normal, on its
// arc-length grid of 0.1 mm) and NAME/radius_change/ (r(y) - r(y) at step 0 on a fixed 0.1 mm
// lateral grid) of the profile `current`, worn from `original`.
void add_wear_measures(GroupRecord& g, const std::string& name, const profiles::Profile& original,
                       const profiles::Profile& current);

// equivalent_conicity and delta_r/ of the wheelset the profiles make (left, right), or with
// eight profiles (each wheelset its own) wheelset 1's there and each one's under wheelsets/K/.
void add_conicity(GroupRecord& g, const CollectiveEvaluator& evaluator,
                  const std::vector<profiles::Profile>& wheels);

// The states as the run resolved them (from the scene, a CSV or an HDF5 file).
GroupRecord collective_record(const Scene& scene);

// /run_info: host, time, threads, timings (the only place they appear).
GroupRecord run_info(const std::filesystem::path& scene_directory, bool builtin, double elapsed,
                     std::size_t evaluations, int resumed_from, const std::string& program);

}  // namespace wheelwear::pipeline::detail
