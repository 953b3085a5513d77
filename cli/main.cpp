// The wheelwear command-line tool: one subcommand per stage of the wear chain.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "build_commit.hpp"
#include "commands.hpp"
#include "wheelwear/core/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "wheelwear: railway wheel profile wear prediction with non-elliptic (SDEC) contact.\n"
      "All inputs and outputs are SI (m, N, Pa, 1/m) unless a flag says otherwise.\n"
      "Run `wheelwear COMMAND --help` for the options of a command."};
  app.set_version_flag("--version", wheelwear::cli::program_identity());
  app.require_subcommand(1);
  // A repeated option takes its last value, as in most command-line tools (scripts append
  // overrides).
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.fallthrough(false);
  wheelwear::cli::add_creep_command(app);
  wheelwear::cli::add_contact_command(app);
  wheelwear::cli::add_wear_command(app);
  wheelwear::cli::add_profile_command(app);
  wheelwear::cli::add_run_command(app);
  wheelwear::cli::add_sweep_command(app);
  wheelwear::cli::add_curving_command(app);
  wheelwear::cli::add_route_command(app);
  // CLI11 answers `wheelwear nosuch --help` with the main help and success; a misspelt
  // command must fail instead, so scripts notice.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string command = argv[1];
    const auto known =
        app.get_subcommands([&command](const CLI::App* sub) { return sub->get_name() == command; });
    if (known.empty()) {
      std::cerr << "wheelwear: unknown command '" << command
                << "'; run `wheelwear --help` for the list of commands\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version end the parse with success; every other parse error is bad usage.
    if (error.get_exit_code() == 0) return app.exit(error);
    std::cerr << "wheelwear: error: " << error.what()
              << "\nRun with --help for more information.\n";
    return 2;
  } catch (const wheelwear::InputError& error) {
    std::cerr << "wheelwear: error: " << error.what() << '\n';
    return 2;
  } catch (const wheelwear::IoError& error) {
    std::cerr << "wheelwear: error: " << error.what() << '\n';
    return 4;
  } catch (const std::exception& error) {
    std::cerr << "wheelwear: failed: " << error.what() << '\n';
    return 3;
  }
  return 0;
}
