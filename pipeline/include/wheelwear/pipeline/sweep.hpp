#pragma once
/// A sweep: one base scene and the scene keys to vary, each run's results file, and one summary
/// table of their headline outputs (docs/sweeps.md).
///
/// The sweep file (TOML):
///
///     scene = "base.toml"          # the base scene, relative to this file
///     output_dir = "sweep_runs"    # where the runs' files and summary.csv go
///     combine = "grid"             # grid: every combination; zip: the i-th values together
///     [vary]
///     "contact.friction" = [0.25, 0.3, 0.4]
///     "time_domain.seed" = [1, 2, 3]
///
/// Each run is the base scene with its values set at the dotted keys (tables made where the base
/// has none), parsed and checked like any scene before the first run starts; its file names
/// relative to the base scene's folder.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/pipeline/process_group.hpp"
#include "wheelwear/pipeline/run_headline.hpp"
#include "wheelwear/pipeline/wear_run.hpp"

namespace wheelwear::pipeline {

struct Sweep {
  std::filesystem::path file;        ///< the sweep file
  std::filesystem::path base_scene;  ///< its base scene
  std::filesystem::path output_dir;  ///< the runs' results files and the summary
  std::vector<std::string> keys;     ///< the varied scene keys, dotted ("contact.friction")
  /// One entry per run: the value of each key as TOML source ("0.3", "\"S1002\"").
  std::vector<std::vector<std::string>> runs;
};

/// Reads a sweep file; throws InputError naming the key, its line and the fix.
Sweep read_sweep(const std::filesystem::path& file);

/// The scene text of run `index` of `sweep`: the base scene's text with that run's values.
std::string sweep_scene_text(const Sweep& sweep, std::string_view base_text, std::size_t index);

/// The results file of run `index`: output_dir/run_NNNN.h5 (from 1).
std::filesystem::path sweep_run_file(const Sweep& sweep, std::size_t index);

/// One run's row of the summary.
struct SweepRow {
  std::size_t index = 0;
  std::string status;    ///< "done", "skipped" (its file was complete already), "failed: why"
  double seconds = 0.0;  ///< wall time of this process on it
  RunHeadline headline;  ///< when it has a file with steps
  bool has_headline = false;
};

struct SweepOptions {
  /// For every run. Its callbacks are called from several runs at once (runs go in parallel)
  /// and RunProgress does not say which run: they must be thread-safe.
  RunOptions run;
  /// After each run, from the thread that ran it, serialised: the row and how many are done.
  std::function<void(const SweepRow&, std::size_t done, std::size_t total)> finished;
  /// The processes of an MPI job to spread the runs over (each every size()-th run, its own
  /// runs in parallel on its threads); process 0 then hears of the others' runs, calls
  /// `finished` for them and writes the summary. Unset: this process runs them all. Not owned.
  ProcessGroup* group = nullptr;
};

/// Runs every run of `sweep` not completed yet — a run whose file is complete is skipped, one
/// whose file is partial (no step yet, some steps, or stopped while it ended) is resumed, a file
/// that holds another scene fails its run — spread over the worker threads (one after the other
/// where the HDF5 library is not thread-safe), each run itself parallel; a failing run is
/// recorded and the others go on. Writes output_dir/summary.csv (atomically) and returns its
/// rows in run order. Throws InputError before any run starts when the base scene or a run's
/// scene is refused. Spread over the processes of options.group, only process 0 writes the
/// summary and returns every row; the others return their own runs' rows (the rest default).
std::vector<SweepRow> run_sweep(const Sweep& sweep, const SweepOptions& options);

/// The summary's columns, with units in their names (docs/sweeps.md).
std::vector<std::string> sweep_summary_columns(const Sweep& sweep);

}  // namespace wheelwear::pipeline
