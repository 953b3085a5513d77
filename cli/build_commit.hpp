#pragma once
// The git commit the program was built from (cmake/build_commit.cmake writes its definition).

#include <string>

#include "wheelwear/core/version.hpp"

namespace wheelwear::cli {

const char* build_commit();

/// "wheelwear VERSION (commit COMMIT)": what --version prints and every run records.
inline std::string program_identity() {
  return std::string("wheelwear ") + core::version() + " (commit " + build_commit() + ")";
}

}  // namespace wheelwear::cli
