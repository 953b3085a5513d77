#pragma once
// The quasi-static curving the front ends ask for (`wheelwear curving`, the Python module's
// curving()): the scene's profiles, a vehicle, a constant curve, its checks and the solve.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "wheelwear/vehicle/quasi_static_curving.hpp"

namespace wheelwear::cli {

struct CurvingRequest {
  std::string scene;    ///< scene file for profiles, track and contact; empty: the built-in
  std::string vehicle;  ///< vehicle file; empty: the scene's [vehicle], else the built-in coach
  double radius = 0.0;  ///< [m], + right-hand, 0 tangent
  double cant = 0.0;    ///< [m], >= 0
  double speed = 0.0;   ///< [m/s], > 0
  std::optional<double> friction;  ///< top of rail and flange alike; default the scene's
  double traction = 0.0;           ///< per powered axle [N], + traction
  bool contact_table = false;      ///< interpolate the contacts from a table built first
};

/// What the contact table cost, when one was built.
struct TableReport {
  std::size_t shifts = 0, load_levels = 0;
  int contact_solves = 0;
  double seconds = 0.0;
};

struct CurvingAnswer {
  vehicle::SteadyCurve curve;
  vehicle::VehicleCurving curving;
  std::optional<TableReport> table;
  /// The scene's warnings (what reading its profile files noticed, ...) and where the vehicle
  /// file and the scene disagree (pipeline::vehicle_scene_differences).
  std::vector<std::string> warnings;
};

/// Throws InputError for a bad curve or file, naming the option and the fix.
CurvingAnswer solve_curving(const CurvingRequest& request);

}  // namespace wheelwear::cli
