#pragma once
// What a test reads from a refusal: the message of the InputError a call throws.

#include <functional>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::testing {

/// The message of the InputError `call` throws, or "no InputError" when it throws none.
inline std::string error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

/// Whether `text` contains `part`.
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace wheelwear::testing
