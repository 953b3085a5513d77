#pragma once
/// The HDF5 results file of a run, written step by step and published atomically.
///
/// HDF5 1.10 does not survive a crash in the middle of a write, so every change goes to a
/// copy (`FILE.partial`), is flushed to disk, and replaces FILE by rename(2), which is atomic:
/// a killed run leaves FILE as it was after the last completed step.
///
/// While a run goes on, each step is a file of its own, `FILE.steps/NNNNNN.h5` (its group
/// `/step`), written and renamed into place; FILE links it as `/steps/NNNNNN` by an HDF5
/// external link, and that change of the small FILE (copied and renamed as above) commits the
/// step. So a step costs its own size, not the whole file's, and a reader (h5py too) sees
/// `/steps/NNNNNN/...` through the links. When the run ends, consolidate() copies every step into
/// FILE (one more atomic replacement) and removes FILE.steps: a finished run is one file.
///
/// Layout (every dataset carries string attributes `units` and `description`; docs/results.md
/// is the full description):
///   /                 attribute `format_version` (kFormatVersion) and the root attributes
///                     the run passes (e.g. `creep_table_sha256`)
///   /scene            the scene text (TOML)
///   /load_collective  the wheelset states of the run, one dataset per quantity
///   /inputs/NN        the files the scene names, their bytes (attributes key, path, sha256)
///   /steps            attribute `completed_steps`
///   /steps/NNNNNN/... the arrays of step NNNNNN (six digits)
///   /final            a soft link to the last step of a finished run (its final profiles)
///   /run_info/...     timings and host information, the only place they appear

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::pipeline {

/// Version of the file's layout, the root attribute `format_version`: bumped by every change
/// of the layout, each listed in docs/results.md. 2: root attribute, per-patch datasets of
/// shape (states, 2, P), every patch worn, `hertz_dropped` per step, `creep_table_sha256`.
/// 3: states dropped whole by reason (`failed_contacts` ... `dropped_patches` and their
/// `_weight`s replace `failed_contacts`, `failed_weight`), per-state `drop_reason`, Nadal's
/// `nadal_delta`, `Y_over_Q`, `nadal_limit`, status 6 past the flange, strip-wise forces.
inline constexpr int kFormatVersion = 6;

/// One dataset: values in row-major order with their shape ({} for a scalar, {n}, {rows, cols}).
struct ArrayRecord {
  std::string name;                ///< path below the group it is written to, e.g. "wheel/y"
  std::vector<double> values;      ///< row-major
  std::vector<std::size_t> shape;  ///< empty for a scalar
  std::string units;               ///< SI units, "1" for dimensionless
  std::string description;         ///< one line for a reader of the file
  /// Stored as 64-bit integers (counts, flags, statuses, indices), NaN as -1, the dataset's fill
  /// value; every value must be integral.
  bool integer = false;
};

/// The record with its values stored as integers (ArrayRecord::integer).
inline ArrayRecord as_integer(ArrayRecord record) {
  record.integer = true;
  return record;
}

/// One text dataset (for names and labels).
struct TextRecord {
  std::string name;
  std::string text;
  std::string description;
};

/// One byte string (a stored input file), a 1-D uint8 dataset with text attributes.
struct BytesRecord {
  std::string name;
  std::string bytes;
  std::string description;
  std::map<std::string, std::string> attributes;
};

/// What one group of the file holds.
struct GroupRecord {
  std::vector<ArrayRecord> arrays;
  std::vector<TextRecord> texts;
  std::vector<BytesRecord> bytes;
};

/// Durable, step-by-step writer and reader of a results file.
class ResultsFile {
 public:
  /// Creates FILE with the scene text, the group /load_collective (the states as the run
  /// resolved them), the first /run_info (if given), the group /inputs (the files the scene
  /// names, if any) and no steps. Throws InputError if FILE exists and `overwrite` is false;
  /// the existing file is then left untouched.
  static ResultsFile create(const std::filesystem::path& path, std::string_view scene_text,
                            bool overwrite, const GroupRecord& load_collective = {},
                            const std::map<std::string, std::string>& root_attributes = {},
                            const GroupRecord& run_info = {}, const GroupRecord& inputs = {});
  /// Opens an existing results file to continue it (resume): a stray FILE.partial of a killed
  /// run is discarded. Throws InputError when the file is missing or is not a results file.
  static ResultsFile open(const std::filesystem::path& path);
  /// Opens a results file to read it, touching nothing (safe while a run is writing it).
  static ResultsFile read(const std::filesystem::path& path);

  /// Publishes step `completed_steps()` atomically: writes its own file, then links it.
  void append_step(const GroupRecord& step);
  /// Copies every linked step into FILE and removes the step folders the links point to
  /// (FILE.steps, or the folder of FILE's name when a renamed file was resumed); the file reads
  /// the same before and after. Nothing to copy for a file without linked steps.
  void consolidate();
  /// Whether some step is still an external link to its own file (a run not yet consolidated).
  bool has_linked_steps() const;
  /// Makes `link` (e.g. "/final") a soft link to the object `target` ("/steps/000012"),
  /// replacing an earlier link of that name, atomically.
  void link(const std::string& link, const std::string& target);
  /// Publishes the /run_info group atomically (replacing an earlier one).
  void write_run_info(const GroupRecord& info);

  int completed_steps() const { return completed_steps_; }
  const std::string& scene_text() const { return scene_text_; }
  const std::filesystem::path& path() const { return path_; }

  /// Reads a dataset (as row-major doubles) of step `step`; throws InputError when missing.
  std::vector<double> read_step_array(int step, const std::string& name) const;
  /// Reads any dataset by its full path (e.g. "/steps/000003/wheel/y"); InputError when missing.
  std::vector<double> read_array(const std::string& full_path) const;
  /// Whether the file holds an object at `full_path`.
  bool has(const std::string& full_path) const;
  /// The numeric datasets of step `step`, as names below its group ("wheel/y"), sorted.
  std::vector<std::string> step_array_names(int step) const;
  /// The numeric datasets below the group `group` ("/load_collective"), as names below it,
  /// sorted; InputError when the group is missing.
  std::vector<std::string> array_names(const std::string& group) const;
  /// The root attribute `format_version`; 1 for files written before it was there.
  int format_version() const;
  /// A text attribute of the root group; std::nullopt when missing.
  std::optional<std::string> root_attribute(const std::string& name) const;
  /// Reads a text dataset by its full path; std::nullopt when missing.
  std::optional<std::string> read_text(const std::string& full_path) const;
  /// The byte strings directly below `group` ("/inputs"), by name, with their text attributes;
  /// none when the group is missing.
  std::vector<BytesRecord> read_bytes(const std::string& group) const;

  /// The group name of a step: "/steps/000012".
  static std::string step_group(int step);
  /// The folder of a running file's step files: FILE + ".steps".
  static std::filesystem::path steps_directory(const std::filesystem::path& path);

 private:
  ResultsFile(std::filesystem::path path, std::string scene_text, int completed_steps);
  std::filesystem::path path_;
  std::string scene_text_;
  int completed_steps_ = 0;
};

}  // namespace wheelwear::pipeline
