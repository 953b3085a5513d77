// `wheelwear profile`: placeholder registration until the profiles module lands.

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace wheelwear::cli {

void add_profile_command(CLI::App& app) { (void)app; }

}  // namespace wheelwear::cli
