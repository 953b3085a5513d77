#pragma once
// Runs the wheelwear executable from a test and captures what it prints.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>

namespace wheelwear::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `WHEELWEAR_EXE <arguments>` through the shell (arguments are passed as written).
inline CommandResult run_wheelwear(const std::string& arguments) {
  const auto err_path = std::filesystem::temp_directory_path() /
                        ("wheelwear_test_stderr_" + std::to_string(::getpid()));
  const std::string command =
      std::string(WHEELWEAR_EXE) + " " + arguments + " 2>" + err_path.string();
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_path);
  std::stringstream text;
  text << err.rdbuf();
  result.err = text.str();
  std::filesystem::remove(err_path);
  return result;
}

/// The number after "key": in a flat JSON text, if present.
inline std::optional<double> json_number(const std::string& json, const std::string& key) {
  const std::regex pattern("\"" + key + "\": (-?[0-9.eE+-]+)");
  std::smatch match;
  if (!std::regex_search(json, match, pattern)) return std::nullopt;
  return std::stod(match[1].str());
}

}  // namespace wheelwear::testing
