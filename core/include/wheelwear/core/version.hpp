#pragma once
/// The project's version (CMakeLists.txt's project(VERSION)).

namespace wheelwear::core {

/// "MAJOR.MINOR.PATCH".
const char* version();

}  // namespace wheelwear::core
