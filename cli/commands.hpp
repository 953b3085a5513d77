#pragma once
/// The wheelwear subcommands. Each lives in its own file and registers itself on the app.

namespace CLI {
class App;
}

namespace wheelwear::cli {

/// `wheelwear creep`: creep forces of one SDEC patch with any tangential method.
void add_creep_command(CLI::App& app);

/// `wheelwear contact`: contact patches of one wheel on its rail.
void add_contact_command(CLI::App& app);

/// `wheelwear wear`: wear of one wheel position per patch, mapped onto the wheel profile.
void add_wear_command(CLI::App& app);

/// `wheelwear profile`: generate, read, clean, resample and summarise wheel/rail profiles.
void add_profile_command(CLI::App& app);

/// `wheelwear curving`: quasi-static curving of a vehicle in a constant curve.
void add_curving_command(CLI::App& app);

/// `wheelwear route`: the vehicle on its route without wear, and the collective it makes.
void add_route_command(CLI::App& app);

/// `wheelwear run`: the wear-evolution run of a scene, written to an HDF5 results file.
void add_run_command(CLI::App& app);

/// `wheelwear sweep`: the runs of a base scene with some keys varied, and their summary.
void add_sweep_command(CLI::App& app);

}  // namespace wheelwear::cli
