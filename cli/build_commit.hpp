#pragma once
// The git commit the program was built from (cmake/build_commit.cmake writes its definition).

namespace wheelwear::cli {

const char* build_commit();

}  // namespace wheelwear::cli
