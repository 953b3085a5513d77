#pragma once
// A load collective as columns of the results file (the columns of a load-collective file,
// docs/scenes.md): written for the scene's collective, a vehicle's and a hook's, and read back
// on resume. collective_csv (vehicle_run.hpp) writes the same columns as CSV.

#include <string>
#include <vector>

#include "step_record.hpp"
#include "wheelwear/pipeline/results_file.hpp"

namespace wheelwear::pipeline::detail {

// The states as load-collective columns under `prefix` ("" or e.g. "collective/").
void add_collective(GroupRecord& g, const std::string& prefix,
                    const std::vector<WheelsetStateSpec>& states);

// The states written by add_collective in step `step` under `prefix`.
std::vector<WheelsetStateSpec> read_collective(const ResultsFile& file, int step,
                                               const std::string& prefix);

}  // namespace wheelwear::pipeline::detail
