#include "wheelwear/pipeline/results_file.hpp"

#include <H5Cpp.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <system_error>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kCompressAbove = 4096;   // elements
constexpr std::size_t kChunkElements = 65536;  // about 512 kB per chunk

// A step's six digits: "000012", its link's name in /steps.
std::string step_digits(int step) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d", step);
  return name;
}

// A step's own file while the run goes on: "000012.h5".
std::string step_file_name(int step) {
  return step_digits(step) + ".h5";
}

fs::path partial_path(const fs::path& path) {
  fs::path partial = path;
  partial += ".partial";
  return partial;
}

// Flushes a file's data, or a directory's entries, to the disk.
void sync_to_disk(const fs::path& path, bool directory) {
  const int fd = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
  if (fd < 0) throw std::system_error(errno, std::generic_category(), "open " + path.string());
  const int status = ::fsync(fd);
  ::close(fd);
  if (status != 0)
    throw std::system_error(errno, std::generic_category(), "fsync " + path.string());
}

// Replaces `path` by `partial` atomically and makes the rename itself durable.
void publish(const fs::path& partial, const fs::path& path) {
  sync_to_disk(partial, false);
  fs::rename(partial, path);
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  sync_to_disk(directory, true);
}

// Text as variable-length UTF-8 strings: h5py reads attributes as str (datasets as bytes that
// .asstr() decodes), where fixed-length ASCII attributes came back as bytes.
H5::StrType utf8_text() {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  return type;
}

void write_string_attribute(H5::H5Object& object, const std::string& name,
                            const std::string& value) {
  const H5::StrType type = utf8_text();
  H5::Attribute attribute = object.createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
  attribute.write(type, value);
}

void write_int_attribute(H5::H5Object& object, const std::string& name, int value) {
  if (object.attrExists(name)) object.removeAttr(name);
  H5::Attribute attribute =
      object.createAttribute(name, H5::PredType::NATIVE_INT, H5::DataSpace(H5S_SCALAR));
  attribute.write(H5::PredType::NATIVE_INT, &value);
}

// Creates the intermediate groups of "a/b/c" below `root` and returns the last one's path.
std::string ensure_parents(H5::H5File& file, const std::string& root, const std::string& name) {
  std::string path = root;
  std::size_t start = 0;
  for (std::size_t slash = name.find('/'); slash != std::string::npos;
       slash = name.find('/', start)) {
    path += '/';
    path.append(name, start, slash - start);
    if (!file.nameExists(path)) file.createGroup(path);
    start = slash + 1;
  }
  path += '/';
  path.append(name, start);
  return path;
}

void write_text(H5::H5File& file, const std::string& path, const std::string& text,
                const std::string& description) {
  const H5::StrType type = utf8_text();
  H5::DataSet data = file.createDataSet(path, type, H5::DataSpace(H5S_SCALAR));
  data.write(text, type);
  // Every dataset carries units; a text has none to give.
  write_string_attribute(data, "units", "text");
  write_string_attribute(data, "description", description);
}

void write_group(H5::H5File& file, const std::string& root, const GroupRecord& group) {
  if (!file.nameExists(root)) file.createGroup(root);
  for (const ArrayRecord& array : group.arrays) {
    std::size_t count = 1;
    std::vector<hsize_t> dims;
    for (std::size_t extent : array.shape) {
      dims.push_back(extent);
      count *= extent;
    }
    require(count == array.values.size(), array.name, static_cast<double>(array.values.size()),
            "values do not match the dataset's shape");
    const H5::DataSpace space = dims.empty()
                                    ? H5::DataSpace(H5S_SCALAR)
                                    : H5::DataSpace(static_cast<int>(dims.size()), dims.data());
    // Large arrays are chunked and compressed: per-state summaries and maps shrink severalfold,
    // and every step's copy of the file is cheaper.
    H5::DSetCreatPropList properties;
    if (dims.size() >= 1 && count >= kCompressAbove) {
      std::vector<hsize_t> chunk = dims;
      std::size_t chunk_count = count;
      for (std::size_t d = 0; d < chunk.size() && chunk_count > kChunkElements; ++d) {
        const hsize_t keep = std::max<hsize_t>(1, chunk[d] * kChunkElements / chunk_count);
        chunk_count = chunk_count / chunk[d] * keep;
        chunk[d] = keep;
      }
      properties.setChunk(static_cast<int>(chunk.size()), chunk.data());
      properties.setShuffle();
      properties.setDeflate(4);
    }
    H5::DataSet data;
    if (array.integer) {
      const std::int64_t fill = -1;
      properties.setFillValue(H5::PredType::NATIVE_INT64, &fill);
      std::vector<std::int64_t> integers(count, fill);
      for (std::size_t i = 0; i < count; ++i) {
        const double v = array.values[i];
        if (std::isnan(v)) continue;
        require(v == std::round(v) && std::abs(v) < 9e15, array.name, v,
                "an integer dataset takes integral values");
        integers[i] = static_cast<std::int64_t>(v);
      }
      data = file.createDataSet(ensure_parents(file, root, array.name), H5::PredType::STD_I64LE,
                                space, properties);
      if (count > 0) data.write(integers.data(), H5::PredType::NATIVE_INT64);
    } else {
      data = file.createDataSet(ensure_parents(file, root, array.name), H5::PredType::NATIVE_DOUBLE,
                                space, properties);
      if (count > 0) data.write(array.values.data(), H5::PredType::NATIVE_DOUBLE);
    }
    write_string_attribute(data, "units", array.units);
    write_string_attribute(data, "description", array.description);
  }
  for (const TextRecord& text : group.texts)
    write_text(file, ensure_parents(file, root, text.name), text.text, text.description);
  for (const BytesRecord& record : group.bytes) {
    const hsize_t size = record.bytes.size();
    H5::DataSet data = file.createDataSet(ensure_parents(file, root, record.name),
                                          H5::PredType::NATIVE_UINT8, H5::DataSpace(1, &size));
    if (size > 0) data.write(record.bytes.data(), H5::PredType::NATIVE_UINT8);
    write_string_attribute(data, "units", "bytes");
    write_string_attribute(data, "description", record.description);
    for (const auto& [name, value] : record.attributes) write_string_attribute(data, name, value);
  }
}

// Writes a new file by `write` as `path`'s partial copy and publishes it; on any failure the
// copy is removed and `path` is left as it was ("cannot <verb> <path>" for HDF5's errors).
template <class Write>
void write_new_atomically(const fs::path& path, const char* verb, Write write) {
  const fs::path partial = partial_path(path);
  try {
    {
      H5::H5File file(partial.string(), H5F_ACC_TRUNC);
      write(file);
      file.close();
    }
    publish(partial, path);
  } catch (const H5::Exception& error) {
    fs::remove(partial);
    throw IoError(std::string("cannot ") + verb + " " + path.string() + ": " +
                  error.getDetailMsg());
  } catch (...) {
    fs::remove(partial);
    throw;
  }
}

// Runs `change` on a copy of `path` and publishes the copy.
template <class Change>
void change_atomically(const fs::path& path, Change change) {
  const fs::path partial = partial_path(path);
  try {
    fs::copy_file(path, partial, fs::copy_options::overwrite_existing);
    {
      H5::H5File file(partial.string(), H5F_ACC_RDWR);
      change(file);
      file.close();
    }
    publish(partial, path);
  } catch (const H5::Exception& error) {
    // H5::Exception is not a std::exception: translate it, naming the file.
    fs::remove(partial);
    throw IoError("cannot update " + path.string() + ": " + error.getDetailMsg());
  } catch (...) {
    fs::remove(partial);  // FILE keeps its last published state
    throw;
  }
}

}  // namespace

ResultsFile::ResultsFile(fs::path path, std::string scene_text, int completed_steps)
    : path_(std::move(path)),
      scene_text_(std::move(scene_text)),
      completed_steps_(completed_steps) {}

std::string ResultsFile::step_group(int step) {
  return "/steps/" + step_digits(step);
}

ResultsFile ResultsFile::create(const fs::path& path, std::string_view scene_text, bool overwrite,
                                const GroupRecord& load_collective,
                                const std::map<std::string, std::string>& root_attributes,
                                const GroupRecord& run_info, const GroupRecord& inputs) {
  if (fs::exists(path) && !overwrite) {
    throw InputError("output " + path.string() +
                     ": the file exists; choose another name or pass --overwrite to replace it");
  }
  write_new_atomically(path, "create", [&](H5::H5File& file) {
    write_text(file, "/scene", std::string(scene_text), "the scene this run was made from (TOML)");
    H5::Group root = file.openGroup("/");
    write_int_attribute(root, "format_version", kFormatVersion);
    for (const auto& [name, value] : root_attributes) write_string_attribute(root, name, value);
    if (!load_collective.arrays.empty() || !load_collective.texts.empty())
      write_group(file, "/load_collective", load_collective);
    H5::Group steps = file.createGroup("/steps");
    write_int_attribute(steps, "completed_steps", 0);
    if (!run_info.arrays.empty() || !run_info.texts.empty())
      write_group(file, "/run_info", run_info);
    if (!inputs.bytes.empty()) write_group(file, "/inputs", inputs);
  });
  // The step files of an earlier run under this name belong to the file just replaced.
  fs::remove_all(steps_directory(path));
  return ResultsFile(path, std::string(scene_text), 0);
}

ResultsFile ResultsFile::open(const fs::path& path) {
  if (!fs::exists(path)) throw InputError("results file " + path.string() + ": does not exist");
  // A stray copy from a run killed mid-step holds an unfinished step: it is discarded, and so
  // are step files written but not yet linked.
  fs::remove(partial_path(path));
  ResultsFile file = read(path);
  const fs::path directory = steps_directory(path);
  if (fs::is_directory(directory)) {
    for (int k = file.completed_steps();; ++k) {
      const fs::path stray = directory / step_file_name(k);
      fs::remove(partial_path(stray));
      if (!fs::remove(stray)) break;
    }
  }
  return file;
}

fs::path ResultsFile::steps_directory(const fs::path& path) {
  fs::path directory = path;
  directory += ".steps";
  return directory;
}

void ResultsFile::append_step(const GroupRecord& step) {
  const int index = completed_steps_;
  const fs::path directory = steps_directory(path_);
  const std::string name = step_file_name(index);
  fs::create_directories(directory);
  write_new_atomically(directory / name, "write",
                       [&](H5::H5File& file) { write_group(file, "/step", step); });
  // The link's file name is relative: HDF5 looks for it beside FILE, wherever FILE is read from.
  const std::string linked = (directory.filename() / name).string();
  change_atomically(path_, [&](H5::H5File& file) {
    H5::Group steps = file.openGroup("/steps");
    if (H5Lcreate_external(linked.c_str(), "/step", steps.getId(), step_digits(index).c_str(),
                           H5P_DEFAULT, H5P_DEFAULT) < 0)
      throw IoError("cannot link " + linked + " into " + path_.string());
    write_int_attribute(steps, "completed_steps", index + 1);
  });
  completed_steps_ = index + 1;
}

namespace {

// Whether `name` in `group` is an external link; its info in `info`.
bool is_external(const H5::Group& group, const std::string& name, H5L_info_t& info) {
  return H5Lget_info(group.getId(), name.c_str(), &info, H5P_DEFAULT) >= 0 &&
         info.type == H5L_TYPE_EXTERNAL;
}

// The file an external link of `group` points to, resolved as HDF5 resolves it: beside `main`
// when relative. Empty for a link of another kind.
fs::path link_target(const H5::Group& group, const std::string& name, const fs::path& main) {
  H5L_info_t info;
  if (!is_external(group, name, info)) return {};
  std::vector<char> value(info.u.val_size);
  const char* file_name = nullptr;
  const char* object = nullptr;
  if (H5Lget_val(group.getId(), name.c_str(), value.data(), value.size(), H5P_DEFAULT) < 0 ||
      H5Lunpack_elink_val(value.data(), value.size(), nullptr, &file_name, &object) < 0)
    throw IoError("cannot read the link of step " + name + " in " + main.string());
  const fs::path target(file_name);
  return target.is_absolute() ? target : main.parent_path() / target;
}

}  // namespace

bool ResultsFile::has_linked_steps() const {
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    const H5::Group steps = file.openGroup("/steps");
    H5L_info_t info;
    for (int k = 0; k < completed_steps_; ++k)
      if (is_external(steps, step_digits(k), info)) return true;
  } catch (const H5::Exception&) {
  }
  return false;
}

void ResultsFile::consolidate() {
  if (!has_linked_steps()) {
    fs::remove_all(steps_directory(path_));  // left by a kill after the last consolidation
    return;
  }
  // The folders the links point to: FILE.steps, or that of FILE's earlier name when a renamed
  // file was resumed.
  std::vector<fs::path> folders;
  change_atomically(path_, [&](H5::H5File& file) {
    const H5::Group steps = file.openGroup("/steps");
    for (int k = 0; k < completed_steps_; ++k) {
      const std::string name = step_digits(k);
      const fs::path source = link_target(steps, name, path_);
      if (source.empty()) continue;
      H5::H5File step_file(source.string(), H5F_ACC_RDONLY);
      if (H5Ldelete(steps.getId(), name.c_str(), H5P_DEFAULT) < 0 ||
          H5Ocopy(step_file.getId(), "/step", steps.getId(), name.c_str(), H5P_DEFAULT,
                  H5P_DEFAULT) < 0)
        throw IoError("cannot copy step " + name + " into " + path_.string());
      if (std::find(folders.begin(), folders.end(), source.parent_path()) == folders.end())
        folders.push_back(source.parent_path());
    }
  });
  // Only step folders, by their name: a link can point anywhere.
  folders.push_back(steps_directory(path_));
  for (const fs::path& folder : folders)
    if (folder.extension() == ".steps") fs::remove_all(folder);
}

void ResultsFile::link(const std::string& link, const std::string& target) {
  change_atomically(path_, [&](H5::H5File& file) {
    if (file.nameExists(link)) file.unlink(link);
    file.link(H5L_TYPE_SOFT, target, link);
  });
}

void ResultsFile::write_run_info(const GroupRecord& info) {
  change_atomically(path_, [&](H5::H5File& file) {
    if (file.nameExists("/run_info")) file.unlink("/run_info");
    write_group(file, "/run_info", info);
  });
}

}  // namespace wheelwear::pipeline
