#include "stored_inputs.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/creep_table.hpp"

namespace wheelwear::pipeline::detail {

GroupRecord stored_inputs(const Scene& scene) {
  GroupRecord group;
  for (std::size_t i = 0; i < scene.inputs.size(); ++i) {
    const SceneInput& in = scene.inputs[i];
    std::string name = std::to_string(i);
    if (name.size() < 2) name.insert(0, 1, '0');  // 00, 01, ...: sorted as read
    group.bytes.push_back(
        {name,
         in.content,
         "a file the scene names, as the run read it (its bytes)",
         {{"key", in.key}, {"path", in.path}, {"sha256", tangential::sha256_hex(in.content)}}});
  }
  return group;
}

SceneFileReader stored_files(std::map<std::string, std::string> files) {
  auto stored = std::make_shared<const std::map<std::string, std::string>>(std::move(files));
  return [stored](const std::filesystem::path& path) -> std::optional<std::string> {
    const auto it = stored->find(path.string());
    if (it == stored->end()) return std::nullopt;
    return it->second;
  };
}

SceneFileReader stored_reader(const ResultsFile& file, bool resume_stored) {
  std::map<std::string, std::string> stored;
  std::string changed;
  for (BytesRecord& in : file.read_bytes("/inputs")) {
    const std::string& path = in.attributes["path"];
    const std::optional<std::string> now = read_scene_file_from_disk(path);
    if (now && tangential::sha256_hex(*now) != in.attributes["sha256"])
      changed += "\n  " + path + " (" + in.attributes["key"] + ")";
    stored[path] = std::move(in.bytes);
  }
  if (!changed.empty() && !resume_stored)
    throw InputError("results file " + file.path().string() +
                     ": these files the scene names have changed since the run started:" + changed +
                     "\nthe run goes on only with the inputs it started with: resume with "
                     "--resume-stored to use the copies stored in the results file, or start a "
                     "new run with -o");
  return stored_files(std::move(stored));
}

}  // namespace wheelwear::pipeline::detail
