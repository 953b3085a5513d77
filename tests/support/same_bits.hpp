#pragma once
// Bit-for-bit equality of two arrays of doubles: for determinism and exact round trips, where
// even -0.0 against 0.0 or two NaN payloads must count as different.

#include <cstring>
#include <vector>

namespace wheelwear::testing {

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace wheelwear::testing
