// Reading a results file: ResultsFile's read-only members (results_file.cpp writes).

#include <H5Cpp.h>

#include <optional>
#include <string>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/results_file.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

namespace {

// Why HDF5 failed, in its own words: the most specific message of its error stack ("truncated
// file: eof = ...", "file signature not found"), which the C++ exception's "H5Fopen failed"
// leaves out; the exception's message where the stack holds none.
std::string hdf5_reason(const H5::Exception& error) {
  std::string deepest;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
        if (n == 0 && e->desc) *static_cast<std::string*>(data) = e->desc;
        return 0;
      },
      &deepest);
  if (deepest.empty()) return error.getDetailMsg();
  // One line: some descriptions carry line breaks (messages and CSV summaries are line-based).
  for (char& c : deepest)
    if (c == '\n' || c == '\r') c = ' ';
  while (!deepest.empty() && deepest.back() == ' ') deepest.pop_back();
  return deepest;
}

// The message for a file HDF5 cannot read at all.
std::string unreadable(const fs::path& path, const H5::Exception& error) {
  return "results file " + path.string() + ": unreadable HDF5 (" + hdf5_reason(error) +
         "): the file is damaged or was copied incompletely (a run that is killed keeps its "
         "file readable); copy it again, or start a new run with -o";
}

int read_int_attribute(const H5::H5Object& object, const std::string& name) {
  int value = 0;
  object.openAttribute(name).read(H5::PredType::NATIVE_INT, &value);
  return value;
}

// The numeric datasets below `group`, as paths relative to it ("wheel/y"). Walks the groups
// with the C++ API, which is the same in HDF5 1.10 and later.
void collect_numeric_datasets(const H5::Group& group, const std::string& prefix,
                              std::vector<std::string>& names) {
  for (hsize_t i = 0; i < group.getNumObjs(); ++i) {
    const std::string name = group.getObjnameByIdx(i);
    const H5G_obj_t type = group.getObjTypeByIdx(i);
    if (type == H5G_GROUP) {
      collect_numeric_datasets(group.openGroup(name), prefix + name + "/", names);
    } else if (type == H5G_DATASET && group.openDataSet(name).getTypeClass() != H5T_STRING) {
      names.push_back(prefix + name);
    }
  }
}

}  // namespace

ResultsFile ResultsFile::read(const fs::path& path) {
  if (!fs::exists(path)) throw InputError("results file " + path.string() + ": does not exist");
  if (fs::is_directory(path))
    throw InputError("results file " + path.string() + ": is a folder, not a results file");
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path.string(), H5F_ACC_RDONLY);
    if (!file.nameExists("/scene") || !file.nameExists("/steps"))
      throw InputError("results file " + path.string() + ": not a wheelwear results file");
    H5::DataSet scene = file.openDataSet("/scene");
    std::string text;
    scene.read(text, scene.getStrType());
    const int steps = read_int_attribute(file.openGroup("/steps"), "completed_steps");
    return ResultsFile(path, text, steps);
  } catch (const H5::Exception& error) {
    throw InputError(unreadable(path, error));
  }
}

std::vector<double> ResultsFile::read_step_array(int step, const std::string& name) const {
  return read_array(step_group(step) + "/" + name);
}

std::vector<double> ResultsFile::read_array(const std::string& full) const {
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    if (!file.nameExists(full)) throw InputError("results file: no dataset " + full);
    H5::DataSet data = file.openDataSet(full);
    const H5::DataSpace space = data.getSpace();
    std::vector<double> values(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
    if (!values.empty()) data.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    return values;
  } catch (const H5::Exception& error) {
    throw InputError("results file " + path_.string() + ": cannot read " + full + " (" +
                     hdf5_reason(error) + ")");
  }
}

bool ResultsFile::has(const std::string& full) const {
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    return file.nameExists(full);
  } catch (const H5::Exception&) {
    return false;  // a missing intermediate group
  }
}

std::vector<std::string> ResultsFile::step_array_names(int step) const {
  return array_names(step_group(step));
}

std::vector<std::string> ResultsFile::array_names(const std::string& group) const {
  std::vector<std::string> names;
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    if (!file.nameExists(group)) throw InputError("results file: no group " + group);
    collect_numeric_datasets(file.openGroup(group), "", names);
  } catch (const H5::Exception& error) {
    throw InputError("results file " + path_.string() + ": cannot list " + group + " (" +
                     hdf5_reason(error) + ")");
  }
  std::sort(names.begin(), names.end());
  return names;
}

int ResultsFile::format_version() const {
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    const H5::Group root = file.openGroup("/");
    return root.attrExists("format_version") ? read_int_attribute(root, "format_version") : 1;
  } catch (const H5::Exception& error) {
    throw InputError(unreadable(path_, error));
  }
}

std::optional<std::string> ResultsFile::root_attribute(const std::string& name) const {
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    const H5::Group root = file.openGroup("/");
    if (!root.attrExists(name)) return std::nullopt;
    const H5::Attribute attribute = root.openAttribute(name);
    std::string value;
    attribute.read(attribute.getStrType(), value);
    return value;
  } catch (const H5::Exception& error) {
    throw InputError("results file " + path_.string() + ": cannot read attribute " + name + " (" +
                     hdf5_reason(error) + ")");
  }
}

std::optional<std::string> ResultsFile::read_text(const std::string& full) const {
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    if (!file.nameExists(full)) return std::nullopt;
    std::string text;
    const H5::DataSet data = file.openDataSet(full);
    data.read(text, data.getStrType());
    return text;
  } catch (const H5::Exception& error) {
    throw InputError("results file " + path_.string() + ": cannot read " + full + " (" +
                     hdf5_reason(error) + ")");
  }
}

std::vector<BytesRecord> ResultsFile::read_bytes(const std::string& group) const {
  std::vector<BytesRecord> records;
  try {
    H5::Exception::dontPrint();
    H5::H5File file(path_.string(), H5F_ACC_RDONLY);
    if (!file.nameExists(group)) return records;
    const H5::Group g = file.openGroup(group);
    for (hsize_t i = 0; i < g.getNumObjs(); ++i) {
      const std::string name = g.getObjnameByIdx(i);
      if (g.getObjTypeByIdx(i) != H5G_DATASET) continue;
      const H5::DataSet data = g.openDataSet(name);
      if (data.getTypeClass() != H5T_INTEGER) continue;
      BytesRecord record;
      record.name = name;
      record.bytes.resize(static_cast<std::size_t>(data.getSpace().getSimpleExtentNpoints()));
      if (!record.bytes.empty()) data.read(record.bytes.data(), H5::PredType::NATIVE_UINT8);
      for (int a = 0; a < data.getNumAttrs(); ++a) {
        const H5::Attribute attribute = data.openAttribute(static_cast<unsigned>(a));
        if (attribute.getTypeClass() != H5T_STRING) continue;
        std::string value;
        attribute.read(attribute.getStrType(), value);
        if (attribute.getName() == "description")
          record.description = value;
        else
          record.attributes[attribute.getName()] = value;
      }
      records.push_back(std::move(record));
    }
  } catch (const H5::Exception& error) {
    throw InputError("results file " + path_.string() + ": cannot read " + group + " (" +
                     hdf5_reason(error) + ")");
  }
  return records;
}

}  // namespace wheelwear::pipeline
