#pragma once
// What every fuzz target shares: bad input must end in wheelwear::InputError, any other
// exception is a defect and is let through (libFuzzer reports it as a crash).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/types.hpp"

namespace wheelwear::fuzz {

/// The fuzzer's bytes as text.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs `parse`; InputError (the documented answer to bad input) is swallowed.
template <class Parse>
void expect_only_input_errors(Parse&& parse) {
  try {
    parse();
  } catch (const wheelwear::InputError&) {
  }
}

/// Stops the run (a crash for libFuzzer) with a message: a property of the reader failed.
[[noreturn]] inline void fail(const char* what) {
  std::fprintf(stderr, "fuzz property failed: %s\n", what);
  std::abort();
}

/// True when every coordinate is finite (only such points can be written back).
inline bool all_finite(const profiles::PointList& points) {
  return std::all_of(points.begin(), points.end(),
                     [](const auto& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); });
}

/// Largest coordinate difference between two point lists of the same size [m].
inline double max_difference(const profiles::PointList& a, const profiles::PointList& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    d = std::max({d, std::abs(a[i][0] - b[i][0]), std::abs(a[i][1] - b[i][1])});
  return d;
}

/// A file the writer produced must read back: an InputError here is a defect.
template <class Parse>
auto reread(Parse&& parse) {
  try {
    return parse();
  } catch (const wheelwear::InputError& e) {
    std::fprintf(stderr, "rereading a written profile failed: %s\n", e.what());
    std::abort();
  }
}

}  // namespace wheelwear::fuzz
