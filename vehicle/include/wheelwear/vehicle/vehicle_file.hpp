#pragma once
/// Vehicle files: a vehicle's parameters in TOML, a unit in every key, and the built-in default
/// (the Manchester benchmark passenger coach, data/vehicles/default.toml; its sources in
/// docs/vehicle_parameters.md).

#include <filesystem>
#include <string_view>

#include "wheelwear/vehicle/vehicle.hpp"

namespace wheelwear::vehicle {

/// Parses a vehicle file's text; `document` names it in messages ("vehicle file x.toml"). Every
/// problem (TOML syntax, unknown or missing key, wrong type, a value out of range) throws
/// InputError naming the key and its line.
Vehicle parse_vehicle(std::string_view text, std::string_view document);

/// Reads and parses the vehicle file `path`.
Vehicle read_vehicle(const std::filesystem::path& path);

/// The built-in default vehicle's text (data/vehicles/default.toml).
std::string_view default_vehicle_text();
/// The built-in default vehicle.
Vehicle default_vehicle();

}  // namespace wheelwear::vehicle
