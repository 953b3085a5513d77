// `wheelwear sweep`: the runs of a base scene with some of its keys varied, and their summary.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "build_commit.hpp"
#include "commands.hpp"
#include "job.hpp"
#include "json_writer.hpp"
#include "stop_message.hpp"
#include "thread_limit.hpp"
#include "wheelwear/pipeline/sweep.hpp"

namespace wheelwear::cli {

namespace {

struct SweepArgs {
  std::string file;
  int threads = 0;
  bool quiet = false;
  bool json = false;
};

std::string values_of(const pipeline::Sweep& sweep, std::size_t index) {
  std::string out;
  for (std::size_t k = 0; k < sweep.keys.size(); ++k)
    out += (k ? ", " : "") + sweep.keys[k] + " = " + sweep.runs[index][k];
  return out;
}

void sweep(const SweepArgs& args) {
  const pipeline::Sweep sweep = pipeline::read_sweep(args.file);
  const auto threads = thread_limit(args.threads);
  const Job& job = cli::job();
  // In an MPI job the other processes run their share quietly: process 0 speaks for the job.
  const std::optional<StopMessage> stop_message =
      job.leader()
          ? std::optional<StopMessage>(
                std::in_place,
                StopMessage::Texts{"; the finished runs are in " + sweep.output_dir.string() +
                                       "; continue with: wheelwear sweep " + args.file +
                                       " (complete runs are skipped, partial ones resumed)\n",
                                   "; continue with: wheelwear sweep " + args.file + "\n"})
          : std::nullopt;
  StopMessage::steps_written();
  pipeline::SweepOptions options;
  options.group = job.group();
  options.run.program = program_identity();
  options.run.warning = [](const std::string& text) {
    std::fprintf(stderr, "wheelwear: warning: %s\n", text.c_str());
  };
  if (!args.quiet && job.leader()) {
    std::fprintf(stderr, "sweep: %zu runs into %s%s\n", sweep.runs.size(),
                 sweep.output_dir.string().c_str(),
                 job.size() > 1 ? (", spread over " + std::to_string(job.size()) +
                                   " processes (the others' runs reported when all are done)")
                                      .c_str()
                                : "");
    options.finished = [&sweep](const pipeline::SweepRow& row, std::size_t done,
                                std::size_t total) {
      std::fprintf(stderr, "[%zu/%zu] run %zu (%s): %s in %.1f s\n", done, total, row.index + 1,
                   values_of(sweep, row.index).c_str(), row.status.c_str(), row.seconds);
    };
  }
  const std::vector<pipeline::SweepRow> rows = pipeline::run_sweep(sweep, options);
  if (!job.leader()) return;
  std::size_t failed = 0;
  for (const pipeline::SweepRow& row : rows) failed += row.status.rfind("failed", 0) == 0;
  const std::string summary = (sweep.output_dir / "summary.csv").string();
  if (args.json) {
    std::vector<std::string> runs;
    for (const pipeline::SweepRow& row : rows)
      runs.push_back(JsonObject()
                         .add("run", static_cast<int>(row.index + 1))
                         .add("file", pipeline::sweep_run_file(sweep, row.index).string())
                         .add("status", row.status)
                         .str());
    std::cout << JsonObject()
                     .add("summary", summary)
                     .add("runs_failed", static_cast<int>(failed))
                     .add_raw("runs", json_array(runs))
                     .str()
              << '\n';
  } else {
    std::printf("wrote %s: %zu runs, %zu failed\n", summary.c_str(), rows.size(), failed);
  }
  if (failed > 0)
    throw std::runtime_error(std::to_string(failed) + " of " + std::to_string(rows.size()) +
                             " runs failed (their status in " + summary + ")");
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "The runs of one base scene with some of its keys varied, each into its own results file,\n"
      "and one summary table of their headline outputs (summary.csv: Sd, Sh, qR and conicity\n"
      "after the distance, their change and the worn area per 10^5 km, the distance not worn).\n"
      "The sweep file (TOML; docs/sweeps.md):\n"
      "  scene = \"base.toml\"          # the base scene, relative to this file\n"
      "  output_dir = \"sweep_runs\"    # run_0001.h5 ... and summary.csv go here\n"
      "  combine = \"grid\"             # grid: every combination; zip: i-th values together\n"
      "  [vary]\n"
      "  \"contact.friction\" = [0.25, 0.3, 0.4]\n"
      "  \"time_domain.seed\" = [1, 2, 3]\n"
      "Runs go in parallel, each itself parallel; under mpirun (a build with WHEELWEAR_MPI,\n"
      "docs/cluster.md) they are spread over the processes too. Run it again after a stop:\n"
      "complete runs are skipped, partial ones resumed. A failing run is recorded; the others\n"
      "go on, and the command then exits with status 3.");
  cmd->add_option("sweep", args->file, "sweep file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--threads", args->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("-q,--quiet", args->quiet, "no progress on stderr");
  cmd->add_flag("--json", args->json, "print the summary file and each run's status as JSON");
  cmd->callback([args] { sweep(*args); });
}

}  // namespace wheelwear::cli
