// `wheelwear run`: the wear-evolution run of a scene (the built-in default when none is given).

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "build_commit.hpp"
#include "commands.hpp"
#include "job.hpp"
#include "json_writer.hpp"
#include "output_path.hpp"
#include "stop_message.hpp"
#include "thread_limit.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/run_headline.hpp"
#include "wheelwear/pipeline/wear_run.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::cli {

namespace {

struct RunArgs {
  std::string scene;
  std::string output;
  std::string resume;
  bool resume_stored = false;
  int threads = 0;
  bool overwrite = false;
  bool allow_hook = false;
  bool quiet = false;
  bool json = false;
  std::string export_default;
};

std::string duration(double seconds) {
  char text[32];
  if (seconds < 120)
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  else
    std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
  return text;
}

// "  (12 % of the distance not worn: 3 climbing, 1 Nadal)" for the progress line.
std::string dropped_note(const pipeline::DroppedStates& d) {
  char share[32];
  std::snprintf(share, sizeof share, "%.2g", 100.0 * d.dropped_patches_weight);
  std::string note = "  (" + std::string(share) + " % of the distance not worn:";
  const std::pair<int, const char*> reasons[] = {{d.failed_contacts, "failed"},
                                                 {d.climbing_contacts, "climbing"},
                                                 {d.load_jump_contacts, "load jump"},
                                                 {d.nadal_contacts, "Nadal"}};
  const char* separator = " ";
  for (const auto& [count, name] : reasons)
    if (count > 0) {
      note += separator + std::to_string(count) + " " + name;
      separator = ", ";
    }
  return note + ")";
}

// Progress on stderr: one redrawn line on a terminal, one line per step otherwise.
void show_progress(const pipeline::RunProgress& p) {
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  const double done = p.total_distance > 0.0 ? p.distance / p.total_distance : 1.0;
  const int width = 24;
  const int filled = static_cast<int>(done * width + 0.5);
  const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                          std::string(static_cast<std::size_t>(width - filled), '.');
  // ETA from the distance rate so far; the step lengths vary, the distance is what remains.
  const double eta = done > 0.0 ? p.elapsed * (1.0 - done) / done : 0.0;
  std::string vehicle;
  if (p.vehicle_solved) {
    vehicle = "  vehicle solved";
    if (p.unconverged_cases > 0)
      vehicle += " (" + std::to_string(p.unconverged_cases) +
                 " conditions not converged, last iterate used)";
    if (p.kept_cases > 0)
      vehicle +=
          " (" + std::to_string(p.kept_cases) + " conditions kept their last converged solution)";
  }
  std::fprintf(stderr, "%s[%s] step %d  %.1f / %.1f km  %.0f states/s  ETA %s%s%s%s",
               tty ? "\r" : "", bar.c_str(), p.step, p.distance / 1e3, p.total_distance / 1e3,
               p.evaluations_per_second, done >= 1.0 ? "0 s" : duration(eta).c_str(),
               vehicle.c_str(),
               p.dropped.dropped_patches_weight > 0.0 ? dropped_note(p.dropped).c_str() : "",
               tty ? "   " : "\n");
  if (tty && done >= 1.0) std::fputc('\n', stderr);
  std::fflush(stderr);
}

void report(const RunArgs& args, const std::string& output, const pipeline::RunSummary& s) {
  const pipeline::ResultsFile file = pipeline::ResultsFile::read(output);
  const pipeline::RunHeadline h = pipeline::read_headline(file);
  const int last = h.steps;
  const std::string& wheel = h.wheel;
  auto at = [&](int step, const std::string& name) {
    return file.read_step_array(step, name).at(0);
  };
  const double rate = s.elapsed > 0.0 ? static_cast<double>(s.evaluations) / s.elapsed : 0.0;
  const std::map<std::string, double>& dropped = h.dropped;
  const bool stopped = h.stopped_at_limit;
  if (args.json) {
    JsonObject o;
    o.add("output", output)
        .add("steps", last)
        .add("distance", h.distance)
        .add("Sh_start", h.Sh_start)
        .add("Sh_end", h.Sh_end)
        .add("Sd_start", h.Sd_start)
        .add("Sd_end", h.Sd_end)
        .add("qR_start", h.qR_start)
        .add("qR_end", h.qR_end)
        .add("conicity_start", h.conicity_start)
        .add("conicity_end", h.conicity_end)
        .add("worn_area", s.worn_area)
        .add("elapsed", s.elapsed)
        .add("evaluations", static_cast<double>(s.evaluations))
        .add("states_steps_per_second", rate)
        .add("geometry_solves", static_cast<double>(s.geometry_solves))
        .add("table_contacts", static_cast<double>(s.table_contacts))
        .add("patches", static_cast<double>(s.patches))
        .add("table_patches", static_cast<double>(s.table_patches))
        .add("table_work_share", s.frictional_work > 0.0 ? s.table_work / s.frictional_work : 0.0)
        .add("processes", s.processes)
        .add("gathered_bytes", static_cast<double>(s.gathered_bytes))
        .add("waited_seconds", s.waited)
        .add("writing_seconds", s.writing)
        .add("limit_reached", h.limit_reached)
        .add("limit_step", h.limit_step)
        .add("stopped_at_limit", stopped);
    for (const auto& [name, unused] : pipeline::DroppedStates{}.named())
      o.add(name, dropped.at(name));
    std::cout << o.str() << '\n';
    return;
  }
  std::printf("wrote %s: %d wear steps, %.1f km\n", output.c_str(), last,
              at(last, "distance") / 1e3);
  // The change in its own column, to the micrometre: a short run's change is far below the
  // values' last digit.
  // With a profile per wheel, the first one's (the group it is stored in).
  std::printf("  %-22s %10s %10s %12s\n", wheel == "wheel" ? "" : wheel.c_str(), "start", "end",
              "change");
  for (const char* name : {"Sh", "Sd", "qR"}) {
    const double start = at(0, wheel + "/" + name) * 1e3, end = at(last, wheel + "/" + name) * 1e3;
    std::printf("  %-22s %10.3f %10.3f %+12.4f\n", (std::string(name) + " [mm]").c_str(), start,
                end, end - start);
  }
  const double conicity_start = at(0, "equivalent_conicity");
  const double conicity_end = at(last, "equivalent_conicity");
  std::printf("  %-22s %10.4f %10.4f %+12.4f\n", "conicity (3 mm)", conicity_start, conicity_end,
              conicity_end - conicity_start);
  std::printf("  %zu state evaluations in %.1f s (%.0f states/s, %zu contact geometries",
              s.evaluations, s.elapsed, rate, s.geometry_solves);
  if (s.table_contacts > 0)
    std::printf(", %zu of them from the vehicle's contact tables", s.table_contacts);
  std::printf(")\n");
  if (s.processes > 1)
    std::printf(
        "  spread over %d processes: %.1f MB of outcomes gathered by process 0 (%.0f bytes per "
        "state); it waited %.1f s for the others, wrote for %.1f s\n",
        s.processes, static_cast<double>(s.gathered_bytes) / 1e6,
        static_cast<double>(s.gathered_bytes) /
            static_cast<double>(std::max<std::size_t>(1, s.gathered_states)),
        s.waited, s.writing);
  if (dropped.at("dropped_patches_weight") > 0.0) {
    std::printf(
        "  %.2f %% of the distance not worn (states dropped whole): %.0f failed, %.0f "
        "climbing, %.0f load-jump, %.0f Nadal contacts over all steps\n",
        100.0 * dropped.at("dropped_patches_weight"), dropped.at("failed_contacts"),
        dropped.at("climbing_contacts"), dropped.at("load_jump_contacts"),
        dropped.at("nadal_contacts"));
  }
  if (s.table_patches > 0) {
    std::printf(
        "  %zu of %zu patches with totals from the book of tables (best), %.2f %% of the "
        "frictional work\n",
        s.table_patches, s.patches,
        s.frictional_work > 0.0 ? 100.0 * s.table_work / s.frictional_work : 0.0);
  }
  if (h.limit_step >= 0) {
    std::printf("  in-service limit (EN 15313) reached at step %d, %.1f km: %s%s\n", h.limit_step,
                at(h.limit_step, "distance") / 1e3, h.limit_reached.c_str(),
                stopped ? "; the run stopped there ([limits] stop)" : "");
  }
  std::printf("plots: scripts/plot_run.py %s\n", output.c_str());
}

void run(const RunArgs& args) {
  Job& job = cli::job();
  if (!args.export_default.empty()) {
    if (!job.leader()) return;
    const std::filesystem::path dir(args.export_default);
    make_output_folder(dir, "--export-default-scene");
    const std::array files{
        std::pair{"default.toml", pipeline::default_scene_text()},
        std::pair{"frozen_collective.toml", pipeline::frozen_collective_text()},
        std::pair{"frozen_collective.csv", pipeline::frozen_collective_states_text()}};
    // Every name checked before any is written: a refusal leaves the folder as it was.
    for (const auto& [name, text] : files) {
      if (std::filesystem::exists(dir / name) && !args.overwrite) {
        throw InputError("--export-default-scene: " + (dir / name).string() +
                         " exists; pass --overwrite to replace it");
      }
    }
    for (const auto& [name, text] : files) core::write_file_atomically(dir / name, text);
    std::cout << "wrote " << (dir / "default.toml").string()
              << " (the built-in vehicle on the built-in route) and frozen_collective.toml with "
                 "its load collective (the earlier built-in scene, for comparison); run it with: "
                 "wheelwear run "
              << (dir / "default.toml").string() << " -o run.h5\n";
    return;
  }
  const auto threads = thread_limit(args.threads);
  // In an MPI job the other processes serve process 0's steps (with this --threads), and
  // process 0 ends their service whatever happens next (Job::prepare, Job::end).
  if (!job.leader()) {
    job.serve();
    return;
  }
  pipeline::RunOptions options;
  options.distributor = job.distributor();
  options.program = program_identity();
  options.overwrite = args.overwrite;
  options.allow_hook = args.allow_hook;
  options.resume_stored = args.resume_stored;
  const bool quiet = args.quiet;
  options.progress = [quiet](const pipeline::RunProgress& p) {
    StopMessage::steps_written();
    if (!quiet) show_progress(p);
  };
  options.warning = [](const std::string& text) {
    std::fprintf(stderr, "wheelwear: warning: %s\n", text.c_str());
  };

  if (args.resume_stored && args.resume.empty())
    throw InputError("--resume-stored: it goes with --resume FILE (a new run reads its inputs)");
  if (!args.resume.empty()) {
    if (!args.scene.empty() || !args.output.empty()) {
      throw InputError("--resume " + args.resume +
                       ": the scene and the output come from that file; give neither SCENE nor -o");
    }
    const StopMessage stop_message(args.resume);
    StopMessage::steps_written();  // what the file holds stays resumable
    report(args, args.resume, pipeline::resume_run(args.resume, options));
    return;
  }
  if (args.output.empty()) throw InputError("-o: give the results file to write, e.g. -o run.h5");
  const StopMessage stop_message(args.output);
  const pipeline::RunSummary summary = pipeline::run_scene_file(args.scene, args.output, options);
  report(args, args.output, summary);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Wear-evolution run of a scene: evaluate every wheelset state of the load collective, wear\n"
      "the wheel profile step by step, record everything in one HDF5 file.\n"
      "Without SCENE the built-in default scene runs: the Manchester benchmark coach on a 100 km\n"
      "mixed line, solved again on the worn profiles at every step, a new S1002 wheel on 60E1\n"
      "1:40 worn over 10^5 km (about a minute on two cores); `wheelwear run\n"
      "--export-default-scene DIR` writes it out to start from, with the frozen-collective scene\n"
      "(1000 hand-set states, for comparison).\n"
      "Each step is published atomically: a killed run keeps every finished step and continues\n"
      "with --resume. Plots: scripts/plot_run.py FILE.\n"
      "A scene (TOML, docs/scenes.md; every key has its unit in its name): [wheel] and [rail]\n"
      "profiles, [contact] model and friction, [wear] law, [run] distance_m and step sizes, and\n"
      "the states that wear the wheel: a [load_collective] (inline or a CSV file), or a\n"
      "[vehicle] on a [route] whose own states the run solves on the current profiles.\n"
      "Examples:\n"
      "  wheelwear run -o run.h5                            the built-in scene, 10^5 km\n"
      "  wheelwear run data/scenes/vehicle_route.toml -o vehicle.h5 --threads 2\n"
      "  wheelwear run --resume run.h5                      continue a killed run\n"
      "  mpirun -np 8 wheelwear run scene.toml -o run.h5   over 8 processes (a build with\n"
      "                                                     WHEELWEAR_MPI; the same file,\n"
      "                                                     docs/cluster.md)");
  CLI::Option* scene =
      cmd->add_option("scene", args->scene, "scene file (TOML); the built-in default when omitted");
  cmd->add_option("-o,--output", args->output, "results file to write (HDF5)");
  CLI::Option* resume =
      cmd->add_option("--resume", args->resume,
                      "continue the run recorded in this results file from its last step");
  // The other processes of an MPI job read no file: process 0 sends them the scene, so they
  // need not see its file system.
  if (job().leader()) {
    scene->check(CLI::ExistingFile);
    resume->check(CLI::ExistingFile);
  }
  cmd->add_flag("--resume-stored", args->resume_stored,
                "with --resume: go on with the inputs stored in the results file although a file "
                "the scene names has changed since the run started (refused without it)");
  cmd->add_option("--threads", args->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing output file");
  cmd->add_flag("--allow-hook", args->allow_hook,
                "let the scene's co-simulation hook ([hook] command) run its program at its steps "
                "(with --resume too); its files go to OUTPUT.hook/ (docs/scenes.md)");
  cmd->add_flag("-q,--quiet", args->quiet, "no progress on stderr");
  cmd->add_flag("--json", args->json, "print the summary as JSON");
  cmd->add_option("--export-default-scene", args->export_default,
                  "write the built-in scene (default.toml) and the frozen-collective scene "
                  "(frozen_collective.toml, frozen_collective.csv) into this directory and exit");
  cmd->callback([args] { run(*args); });
}

}  // namespace wheelwear::cli
