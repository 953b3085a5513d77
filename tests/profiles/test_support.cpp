#include "test_support.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace wheelwear::profiles::testing {

std::filesystem::path data_path(const std::string& relative) {
  return std::filesystem::path(WHEELWEAR_TEST_DATA) / relative;
}

std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const auto dir = std::filesystem::temp_directory_path() / "wheelwear_profiles_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::filesystem::path contact_wheel_file() {
  return data_path("contact/profiles/MBench_S1002_v3.prw");
}
std::filesystem::path contact_rail_file() {
  return data_path("contact/profiles/MBench_UIC60_v3.prr");
}
std::filesystem::path measured_wheel_file() {
  return data_path("measured/Car7216_0001r.whl");
}
std::filesystem::path measured_rail_file() {
  return data_path("measured/avg_HR.BAN");
}

}  // namespace wheelwear::profiles::testing
