// The wheelwear command-line tool: one subcommand per stage of the wear chain.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "build_commit.hpp"
#include "commands.hpp"
#include "job.hpp"
#include "wheelwear/core/input_error.hpp"

namespace {

// Says what stopped the command: process 0 (or a lone process) always; another process of an
// MPI job only for a failure of its own share of the work (every process parses the same
// command line, and one message is enough).
void say(const char* what, const char* message) {
  const wheelwear::cli::Job& job = wheelwear::cli::job();
  std::string line;
  if (job.leader())
    line = std::string("wheelwear: ") + what + ": " + message + '\n';
  else if (job.working())
    line = std::string("wheelwear: ") + what + " (process " + std::to_string(job.rank()) + " of " +
           std::to_string(job.size()) + "): " + message + '\n';
  // One write: an MPI launcher forwards a process's output in the pieces it was written in,
  // and may put its own report of an abort between them.
  std::cerr << line << std::flush;
}

int run_command_line(int argc, char** argv) {
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
      if (wheelwear::cli::job().leader())
        std::cerr << "wheelwear: unknown command '" << command
                  << "'; run `wheelwear --help` for the list of commands\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version end the parse with success; every other parse error is bad usage.
    if (error.get_exit_code() == 0) return wheelwear::cli::job().leader() ? app.exit(error) : 0;
    if (wheelwear::cli::job().leader())
      std::cerr << "wheelwear: error: " << error.what()
                << "\nRun with --help for more information.\n";
    return 2;
  } catch (const wheelwear::InputError& error) {
    say("error", error.what());
    return 2;
  } catch (const wheelwear::IoError& error) {
    say("error", error.what());
    return 4;
  } catch (const std::exception& error) {
    say("failed", error.what());
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  wheelwear::cli::Job& job = wheelwear::cli::job();
  job.join(argc, argv);
  // In an MPI job only `run` and `sweep` share their work; another command is process 0's.
  const std::string command = argc > 1 ? argv[1] : "";
  if (!job.leader() && command != "run" && command != "sweep") return job.end(0);
  job.prepare(command);
  int code = run_command_line(argc, argv);
  if (job.owes_service()) {  // process 0's run, whatever this parse gave
    try {
      code = job.serve();
    } catch (const std::exception& error) {
      say("failed", error.what());
      code = 3;
    }
  }
  return job.end(code);
}
