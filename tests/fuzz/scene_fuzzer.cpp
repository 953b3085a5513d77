// Fuzz target: the scene parser (pipeline/scene.hpp). Files the scene names are not read from
// disk: the collective file reads as the frozen-collective scene's
// (data/scenes/frozen_collective.csv), any other name fails as a missing file would, and
// relative names resolve against a directory that does not exist.

#include <fstream>
#include <sstream>
#include <string>

#include "fuzz_support.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace {

const std::string& default_collective() {
  static const std::string text = [] {
    std::ifstream in(WHEELWEAR_FUZZ_COLLECTIVE);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }();
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wheelwear;
  const std::string_view text = fuzz::as_text(data, size);
  const pipeline::SceneFileReader read =
      [](const std::filesystem::path& path) -> std::optional<std::string> {
    if (path.extension() == ".csv") return default_collective();
    return std::nullopt;
  };
  fuzz::expect_only_input_errors(
      [&] { pipeline::parse_scene(text, "/nonexistent-wheelwear-fuzz-base", read); });
  return 0;
}
