#pragma once
// The one rule for every file a command writes: an existing file is replaced only with
// --overwrite, and no folder is created for it (docs/cli.md).

#include <filesystem>
#include <string>
#include <system_error>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::cli {

/// Throws InputError naming `flag` when `path` exists and `overwrite` is false, or when its
/// folder does not exist. An empty path (no output asked for) passes.
inline void refuse_existing(const std::string& path, const char* flag, bool overwrite) {
  if (path.empty()) return;
  const std::filesystem::path file(path);
  std::error_code ignored;
  if (!overwrite && std::filesystem::exists(file, ignored))
    throw InputError(std::string(flag) + " " + path +
                     ": the file exists; pass --overwrite to replace it");
  const std::filesystem::path folder =
      file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder, ignored))
    throw InputError(std::string(flag) + " " + path + ": the folder " + folder.string() +
                     " does not exist; create it or choose another path");
}

/// Makes folder `dir` for a command's files where it is not there yet; its parent must exist.
/// Throws InputError naming `flag` otherwise.
inline void make_output_folder(const std::filesystem::path& dir, const char* flag) {
  std::error_code ignored;
  if (std::filesystem::is_directory(dir, ignored)) return;
  const std::filesystem::path parent =
      dir.has_parent_path() ? dir.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ignored))
    throw InputError(std::string(flag) + " " + dir.string() + ": the folder " + parent.string() +
                     " does not exist; create it or choose another folder");
  std::filesystem::create_directory(dir);
}

}  // namespace wheelwear::cli
