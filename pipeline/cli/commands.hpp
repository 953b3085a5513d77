#pragma once
/// The wheelwear subcommands. Each lives in its own file and registers itself on the app.

namespace CLI {
class App;
}

namespace wheelwear::cli {

/// `wheelwear creep`: creep forces of one SDEC patch with any tangential method.
void add_creep_command(CLI::App& app);

/// `wheelwear profile`: generate, read, clean, resample and summarise wheel/rail profiles.
void add_profile_command(CLI::App& app);

}  // namespace wheelwear::cli
