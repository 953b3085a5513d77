#include "scene_files.hpp"

#include <algorithm>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::pipeline {

std::optional<std::string> read_scene_file_from_disk(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) return std::nullopt;
  return core::read_file_bytes(path);
}

namespace detail {

SceneFiles::SceneFiles(std::filesystem::path base, SceneFileReader read)
    : base_(std::move(base)), read_(read ? std::move(read) : read_scene_file_from_disk) {}

std::filesystem::path SceneFiles::resolve(const std::string& name) const {
  const std::filesystem::path p(name);
  return p.is_absolute() || base_.empty() ? p : base_ / p;
}

std::optional<std::string> SceneFiles::read(const std::string& key,
                                            const std::filesystem::path& file, bool text) {
  const std::string path = file.string();
  const auto same = [&](const SceneInput& in) { return in.path == path; };
  if (const auto it = std::find_if(kept_.begin(), kept_.end(), same); it != kept_.end())
    return it->content;
  std::optional<std::string> content = read_(file);
  if (!content) return content;
  if (text) {
    if (content->empty()) throw InputError(key + " = " + path + ": the file is empty");
    try {
      core::check_text(*content, path);
    } catch (const InputError&) {
      throw InputError(key + " = " + path +
                       ": binary data, not a text file; give the text file this key expects");
    }
  }
  kept_.push_back({key, path, *content});
  return content;
}

}  // namespace detail
}  // namespace wheelwear::pipeline
