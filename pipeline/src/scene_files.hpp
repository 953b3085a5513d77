#pragma once
// The files a scene names, read through the scene's reader once each and kept (Scene::inputs),
// so that a run depends on nothing it has not stored.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline::detail {

class SceneFiles {
 public:
  // Relative names are taken from `base`; `read` empty: read_scene_file_from_disk.
  SceneFiles(std::filesystem::path base, SceneFileReader read);

  const std::filesystem::path& base() const { return base_; }

  // `name` taken relative to the scene's folder unless it is absolute or the folder is empty.
  std::filesystem::path resolve(const std::string& name) const;

  // The bytes of `file`, kept under `key` (a file read twice is kept once); none when there is
  // no such file. A `text` file that is empty or binary is refused naming the key.
  std::optional<std::string> read(const std::string& key, const std::filesystem::path& file,
                                  bool text = true);

  std::vector<SceneInput> take() { return std::move(kept_); }

 private:
  std::filesystem::path base_;
  SceneFileReader read_;
  std::vector<SceneInput> kept_;
};

}  // namespace wheelwear::pipeline::detail
