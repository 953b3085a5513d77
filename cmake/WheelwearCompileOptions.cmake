# Compile options shared by every wheelwear target, attached through an interface target
# so that no global flags are edited.
add_library(wheelwear_compile_options INTERFACE)
add_library(wheelwear::compile_options ALIAS wheelwear_compile_options)
target_compile_options(wheelwear_compile_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  # Value types are built from their leading members, the rest keeping their defaults.
  -Wno-missing-field-initializers
  # errno is never read; without it sqrt can be vectorised.
  -fno-math-errno)
if(WHEELWEAR_NATIVE)
  target_compile_options(wheelwear_compile_options INTERFACE -march=native)
endif()
if(WHEELWEAR_SANITIZE)
  target_compile_options(wheelwear_compile_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  target_link_options(wheelwear_compile_options INTERFACE -fsanitize=address,undefined)
endif()
# Not installed: the package must not hand the project's warnings, -march=native or the
# sanitizers to its consumers (wheelwear_module links it only inside the build tree).

# wheelwear_module(NAME SOURCES ... DEPS ...): one static library per module, with its public
# headers under NAME/include and a namespaced alias wheelwear::NAME. Every module joins the
# umbrella target wheelwear::wheelwear (cmake/WheelwearInstall.cmake).
function(wheelwear_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(wheelwear_${name} STATIC ${ARG_SOURCES})
  add_library(wheelwear::${name} ALIAS wheelwear_${name})
  set_target_properties(wheelwear_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(wheelwear_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # The public headers are C++20, so consumers must compile as C++20 at least.
  target_compile_features(wheelwear_${name} PUBLIC cxx_std_20)
  # PUBLIC but build-tree only: the project's programs, tests and fuzz targets inherit the
  # warnings, the architecture and the sanitizer/fuzzer instrumentation (an instrumented library
  # must be linked with the sanitizer runtimes), while the exported targets carry none of it.
  target_link_libraries(wheelwear_${name}
    PUBLIC ${ARG_PUBLIC_DEPS} $<BUILD_INTERFACE:wheelwear_compile_options>
    PRIVATE ${ARG_PRIVATE_DEPS})
  # Eigen's core header costs 2-3 s in every file that includes it (profiles/types.hpp, so every
  # module but core); compiled once per module instead.
  if(NOT name STREQUAL "core")
    target_precompile_headers(wheelwear_${name} PRIVATE <Eigen/Core> <string> <vector>)
  endif()
  set_property(GLOBAL APPEND PROPERTY WHEELWEAR_MODULES wheelwear_${name})
  install(TARGETS wheelwear_${name} EXPORT wheelwearTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
