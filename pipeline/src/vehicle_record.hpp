#pragma once
// The results file's record of a vehicle run's step: the collective the vehicle made (its
// columns in collective_record.hpp, so that a resumed run reads back exactly the states it wore
// with) and per running condition of the route the vehicle's solved state (docs/results.md,
// "Vehicle runs"). The readers rebuild what a resumed run carries on with.

#include <optional>
#include <string>
#include <vector>

#include "collective_record.hpp"
#include "step_record.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"

namespace wheelwear::pipeline::detail {

// A vehicle run's record of one step: vehicle/solved, the solve's counts and critical speed,
// vehicle/depth_since_solve (this step's included), the collective (collective/), the cases and
// the pieces.
void add_vehicle_record(GroupRecord& g, const VehicleCollective& vehicle, bool solved,
                        double depth_since_solve);

// vehicle/cases/...: per case of the route its conditions, whether its solve converged, the
// bodies' placements and per wheelset its state and the wheels' forces.
void add_vehicle_cases(GroupRecord& g, const VehicleCollective& vehicle);

// The solved cases as add_vehicle_cases recorded them in step `step` (`cases` of them): the
// fields it records, the rest left at their defaults. Throws InputError when the step holds
// another number of cases. A resumed run records them again until the vehicle's next solve and
// starts that solve from them.
std::vector<vehicle::VehicleCurving> read_vehicle_cases(const ResultsFile& file, int step,
                                                        std::size_t cases);

// vehicle/pieces/...: per time-domain piece its stretch, how its simulation went and per
// wheelset its samples and the summary of its motion (PieceRun). Nothing for a run without.
void add_vehicle_pieces(GroupRecord& g, const VehicleCollective& vehicle);

// The pieces' runs as add_vehicle_pieces recorded them in step `step` (`pieces` of them).
// Throws InputError when the step holds another number of pieces.
std::vector<PieceRun> read_vehicle_pieces(const ResultsFile& file, int step, std::size_t pieces);

// The vehicle's solve as add_vehicle_record recorded it in step `step` of `run` (its route's
// cases and pieces, their records, the collective, the counts and the critical speed): what a
// resumed run records until the vehicle's next solve and starts that solve from.
VehicleCollective read_vehicle_collective(const ResultsFile& file, int step, const VehicleRun& run);

}  // namespace wheelwear::pipeline::detail
