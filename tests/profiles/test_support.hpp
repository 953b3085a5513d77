#pragma once
// Shared by the profiles tests: test data paths, scratch folders, small text files.

#include <filesystem>
#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles::testing {

/// Absolute path of a file under tests/data.
std::filesystem::path data_path(const std::string& relative);

/// A fresh, empty scratch folder for the running test (removed at the start of the next run).
std::filesystem::path scratch_dir();

/// Writes `content` to `path` (plain write; the tests build their inputs with it).
void write_text(const std::filesystem::path& path, const std::string& content);

/// The whole file as a string.
std::string read_text(const std::filesystem::path& path);

/// CONTACT's S1002 wheel file and UIC60 rail file (tests/data/contact/profiles).
std::filesystem::path contact_wheel_file();
std::filesystem::path contact_rail_file();
/// The measured MiniProf wheel and rail (tests/data/measured).
std::filesystem::path measured_wheel_file();
std::filesystem::path measured_rail_file();

/// Runs `f` and returns the message of the InputError it throws, or "no error".
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace wheelwear::profiles::testing
