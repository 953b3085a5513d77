#pragma once
// The files a scene names, stored in the results file (/inputs) and read back on resume, so
// that a resumed run depends on nothing the file does not hold (docs/results.md).

#include <map>
#include <string>

#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline::detail {

// The scene's files as the run read them (Scene::inputs), each with its key, path and SHA-256.
GroupRecord stored_inputs(const Scene& scene);

// A reader of the scene's files from `files` (path -> bytes): a file not among them is not
// there.
SceneFileReader stored_files(std::map<std::string, std::string> files);

// A reader of the scene's files from their copies in `file`. Throws InputError naming every
// file still on disk where the scene named it whose bytes have changed since, unless
// `resume_stored`.
SceneFileReader stored_reader(const ResultsFile& file, bool resume_stored);

}  // namespace wheelwear::pipeline::detail
