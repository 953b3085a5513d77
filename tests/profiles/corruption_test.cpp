// Seeded random corruption of real profile files: the loader either succeeds with a finite
// profile or throws InputError, never anything else.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <typeinfo>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::profiles {
namespace {

using testing::read_text;

// One random change of the text; `what` says which, for the failure message.
std::string corrupt(const std::string& text, std::mt19937& random, std::string& what) {
  std::string out = text;
  auto pick = [&](std::size_t n) {
    return n == 0 ? std::size_t{0} : std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
  };
  auto line_start = [&](std::size_t at) {
    const auto p = out.rfind('\n', at);
    return p == std::string::npos ? std::size_t{0} : p + 1;
  };
  const char* numbers[] = {"nan",    "-inf", "1e308", "-", "+",   ".",
                           "1e-320", "0",    "99999", "",  "1,5", "0x10"};
  switch (pick(9)) {
    case 0: {  // flip some bytes
      const std::size_t n = 1 + pick(8);
      for (std::size_t k = 0; k < n && !out.empty(); ++k)
        out[pick(out.size())] = static_cast<char>(random() & 0xff);
      what = "flipped " + std::to_string(n) + " bytes";
      break;
    }
    case 1: {  // truncate anywhere
      const std::size_t at = pick(out.size() + 1);
      out.resize(at);
      what = "truncated at byte " + std::to_string(at);
      break;
    }
    case 2: {  // delete a line
      const std::size_t start = line_start(pick(out.size()));
      const std::size_t end = out.find('\n', start);
      out.erase(start, end == std::string::npos ? std::string::npos : end - start + 1);
      what = "deleted the line at byte " + std::to_string(start);
      break;
    }
    case 3: {  // duplicate a block of lines
      const std::size_t start = line_start(pick(out.size()));
      const std::size_t length = std::min(out.size() - start, 40 + pick(400));
      out.insert(start, out.substr(start, length));
      what = "duplicated " + std::to_string(length) + " bytes at " + std::to_string(start);
      break;
    }
    case 4: {  // replace a number-like token
      const std::size_t at = out.find_first_of("0123456789", pick(out.size()));
      if (at == std::string::npos) break;
      const std::size_t end = out.find_first_of(" \t\n,;", at);
      const char* replacement = numbers[pick(std::size(numbers))];
      out.replace(at, (end == std::string::npos ? out.size() : end) - at, replacement);
      what = std::string("replaced a number by \"") + replacement + "\"";
      break;
    }
    case 5: {  // swap two lines
      const std::size_t a = line_start(pick(out.size())), b = line_start(pick(out.size()));
      const std::size_t ae = out.find('\n', a), be = out.find('\n', b);
      if (ae == std::string::npos || be == std::string::npos || a == b) break;
      std::string la = out.substr(a, ae - a), lb = out.substr(b, be - b);
      if (a < b) {
        out.replace(b, be - b, la);
        out.replace(a, ae - a, lb);
      } else {
        out.replace(a, ae - a, lb);
        out.replace(b, be - b, la);
      }
      what = "swapped two lines";
      break;
    }
    case 6: {  // insert a random row of numbers
      std::uniform_real_distribution<double> value(-1e3, 1e3);
      const std::size_t at = line_start(pick(out.size()));
      const std::string row =
          std::to_string(value(random)) + " " + std::to_string(value(random)) + "\n";
      out.insert(at, row);
      what = "inserted the row " + row;
      break;
    }
    case 7: {  // a burst of binary noise
      const std::size_t at = pick(out.size() + 1), n = 1 + pick(64);
      std::string noise(n, '\0');
      for (char& c : noise) c = static_cast<char>(random() & 0xff);
      out.insert(at, noise);
      what = "inserted " + std::to_string(n) + " random bytes";
      break;
    }
    default: {  // scale a stretch of numbers (a unit slip in part of the file)
      const std::size_t start = line_start(pick(out.size()));
      std::string tail = out.substr(start);
      std::string scaled;
      std::size_t lines = 0;
      for (std::size_t i = 0; i < tail.size() && lines < 30; ++i) {
        scaled += tail[i];
        if (tail[i] == '\n') ++lines;
        if (tail[i] == '.' && lines % 2 == 0) scaled += "0";
      }
      out = out.substr(0, start) + scaled + tail.substr(std::min(tail.size(), scaled.size()));
      what = "rescaled numbers after byte " + std::to_string(start);
      break;
    }
  }
  return out;
}

TEST(Corruption, NeverCrashesTheLoader) {
  const auto dir = testing::scratch_dir();
  struct Source {
    std::string name;
    std::string text;
    Body body;
  };
  const std::vector<Source> sources = {
      {"wheel.prw", read_text(testing::contact_wheel_file()), Body::wheel},
      {"rail.prr", read_text(testing::contact_rail_file()), Body::rail},
      {"wheel.whl", read_text(testing::measured_wheel_file()), Body::wheel},
      {"rail.ban", read_text(testing::measured_rail_file()), Body::rail},
      {"wheel.csv", format_csv(s1002_points({.point_spacing = 0.4e-3}), {}), Body::wheel},
  };
  std::mt19937 random(20240601);
  int accepted = 0, rejected = 0;
  for (const Source& source : sources) {
    for (int trial = 0; trial < 60; ++trial) {
      std::string what;
      std::string text = corrupt(source.text, random, what);
      if (trial % 3 == 0) {
        std::string second;
        text = corrupt(text, random, second);
        what += "; then " + second;
      }
      const auto path = dir / source.name;
      testing::write_text(path, text);
      LoadOptions options;
      options.read.body = source.body;
      try {
        const LoadedProfile loaded = load_profile(path, options);
        for (double s = 0.0; s <= loaded.profile.length(); s += 1e-3) {
          ASSERT_TRUE(std::isfinite(loaded.profile.position(s)[1])) << source.name << ": " << what;
          ASSERT_TRUE(std::isfinite(loaded.profile.curvature(s))) << source.name << ": " << what;
        }
        if (source.body == Body::wheel) {
          try {
            wheel_parameters(loaded.profile);
          } catch (const InputError&) {
            // a damaged flange may have no measurable Sd: a clear error is the right outcome
          }
        }
        ++accepted;
      } catch (const InputError&) {
        ++rejected;
      } catch (const std::exception& e) {
        FAIL() << source.name << " after \"" << what << "\": " << typeid(e).name() << ": "
               << e.what();
      }
    }
  }
  // Both outcomes occur, so the test exercised the accepting and the rejecting paths.
  EXPECT_GT(accepted, 20);
  EXPECT_GT(rejected, 20);
  std::printf("random corruption: %d accepted, %d rejected with InputError\n", accepted, rejected);
}

}  // namespace
}  // namespace wheelwear::profiles
