// Reads the book of creep-force tables (data/creep_table.h5, layout of
// generators/creep_table_generator.cpp) at run time: where it is, its bytes, their SHA-256 and
// the arrays creep_table_interpolation.cpp interpolates.

#include "creep_table_data.hpp"

#include <H5Cpp.h>
#include <dlfcn.h>
#include <openssl/evp.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

namespace {

namespace fs = std::filesystem;
using detail::CreepTableBlock;
using detail::CreepTableData;

constexpr const char* kFileName = "creep_table.h5";
constexpr const char* kEnvironment = "WHEELWEAR_DATA_DIR";

// Something of this library's own, for dladdr to name the object it was linked into.
const char kAnchor = 0;

constexpr char kFix[] =
    ": set WHEELWEAR_DATA_DIR to a folder holding a good copy of creep_table.h5 (data/ of the "
    "source tree), or reinstall wheelwear (cmake --install puts it in "
    "<prefix>/share/wheelwear)";

[[noreturn]] void damaged(const fs::path& file, const std::string& what) {
  throw InputError("creep table " + file.string() + ": " + what +
                   ", so the file is damaged or not a creep table" + kFix);
}

// HDF5's error reporting (per thread: the library is thread-safe) turned from printing its
// error stack on stderr into keeping the first failure's innermost message (e.g. "truncated
// file: eof = ..."), which says more than the C++ API's exception; a damaged file is reported
// once, as an InputError.
class Hdf5Errors {
 public:
  Hdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, &Hdf5Errors::record, this);
  }
  ~Hdf5Errors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  Hdf5Errors(const Hdf5Errors&) = delete;
  Hdf5Errors& operator=(const Hdf5Errors&) = delete;

  std::string reason(const H5::Exception& e) const {
    return first_.empty() ? e.getFuncName() + ": " + e.getDetailMsg() : first_;
  }

 private:
  static herr_t innermost(unsigned n, const H5E_error2_t* error, void* out) {
    if (n == 0 && error->desc) *static_cast<std::string*>(out) = error->desc;
    return 0;
  }
  static herr_t record(hid_t stack, void* self) {
    std::string& first = static_cast<Hdf5Errors*>(self)->first_;
    if (first.empty()) H5Ewalk2(stack, H5E_WALK_UPWARD, &Hdf5Errors::innermost, &first);
    return 0;
  }

  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
  std::string first_;
};

std::string read_bytes(const fs::path& file) {
  std::error_code status;
  if (fs::exists(file, status) && !fs::is_regular_file(file, status))
    throw InputError("creep table " + file.string() + " is not a file" + kFix);
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) {
    const int error = errno;
    throw InputError("creep table " + file.string() + " cannot be opened (" + std::strerror(error) +
                     ")" + kFix);
  }
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError("creep table " + file.string() + " cannot be read" + kFix);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw InputError("creep table " + file.string() + " cannot be read" + kFix);
  return bytes;
}

std::vector<hsize_t> dims_of(const H5::DataSet& set) {
  const H5::DataSpace space = set.getSpace();
  std::vector<hsize_t> dims(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(dims.data());
  return dims;
}

std::vector<double> read_doubles(const H5::Group& group, const std::string& name) {
  const H5::DataSet set = group.openDataSet(name);
  const auto count = static_cast<std::size_t>(set.getSpace().getSimpleExtentNpoints());
  std::vector<double> data(count);
  if (count > 0) set.read(data.data(), H5::PredType::NATIVE_DOUBLE);
  return data;
}

// A scalar numeric attribute; nullopt when absent.
std::optional<double> read_number(const H5::H5Object& object, const std::string& name,
                                  const fs::path& file, const std::string& where) {
  if (!object.attrExists(name)) return std::nullopt;
  const H5::Attribute attr = object.openAttribute(name);
  if (attr.getSpace().getSimpleExtentNpoints() != 1)
    damaged(file, where + ": attribute " + name + " is not a single number");
  double value = 0.0;
  attr.read(H5::PredType::NATIVE_DOUBLE, &value);
  return value;
}

// The file's description, as the generator wrote it (a fixed-length string); empty when absent.
std::string read_description(const H5::H5File& file) {
  if (!file.attrExists("description")) return {};
  const H5::Attribute attr = file.openAttribute("description");
  const H5::StrType type = attr.getStrType();
  std::string value;
  if (type.isVariableStr()) {
    attr.read(type, value);
  } else {
    value.assign(type.getSize(), '\0');
    attr.read(type, value.data());
  }
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

// An axis must be finite and strictly increasing, or the stencils would read past it.
std::vector<double> read_axis(const H5::Group& group, const std::string& name, const fs::path& file,
                              const std::string& where) {
  std::vector<double> axis = read_doubles(group, name);
  if (axis.empty()) damaged(file, where + ": axis " + name + " is empty");
  if (axis.size() > 1000000) damaged(file, where + ": axis " + name + " has too many nodes");
  for (std::size_t i = 0; i < axis.size(); ++i) {
    if (!std::isfinite(axis[i]) || (i > 0 && !(axis[i] > axis[i - 1]))) {
      std::ostringstream what;
      what.precision(17);
      what << where << ": axis " << name << " is not finite and increasing (" << name << "[" << i
           << "] = " << axis[i] << ")";
      damaged(file, what.str());
    }
  }
  return axis;
}

std::vector<double> read_per_g(const H5::Group& group, const std::string& name, std::size_t n_g,
                               const fs::path& file, const std::string& where) {
  std::vector<double> values = read_doubles(group, name);
  if (values.size() != n_g)
    damaged(file, where + ": " + name + " has " + std::to_string(values.size()) + " values for " +
                      std::to_string(n_g) + " nodes of a_over_b");
  for (const double v : values)
    if (!std::isfinite(v)) damaged(file, where + ": " + name + " is not finite");
  return values;
}

std::vector<double> read_values(const H5::Group& group, const std::string& name,
                                const std::vector<hsize_t>& expected, const fs::path& file,
                                const std::string& where) {
  if (dims_of(group.openDataSet(name)) != expected)
    damaged(file, where + ": " + name + " is not shaped [a_over_b][psi][theta][beta]" +
                      (expected.size() == 5 ? "[r]" : ""));
  std::vector<double> values = read_doubles(group, name);
  for (const double v : values)
    if (!std::isfinite(v)) damaged(file, where + ": " + name + " holds a value that is not finite");
  return values;
}

CreepTableBlock read_block(const H5::Group& group, const fs::path& file, const std::string& where) {
  CreepTableBlock b;
  const std::optional<double> nu = read_number(group, "nu", file, where);
  const std::optional<double> grid = read_number(group, "grid", file, where);
  const std::optional<double> spin_scale = read_number(group, "spin_scale", file, where);
  const std::optional<double> aspect = read_number(group, "max_element_aspect", file, where);
  if (aspect && !(std::isfinite(*aspect) && *aspect >= 1.0))
    damaged(file, where + ": attribute max_element_aspect is not a number of at least 1");
  if (!nu || !std::isfinite(*nu)) damaged(file, where + ": attribute nu is missing or not finite");
  if (!grid || !(*grid >= 1.0 && *grid <= 1e6))
    damaged(file, where + ": attribute grid is missing or not a grid size");
  if (spin_scale && !(std::isfinite(*spin_scale) && *spin_scale > 0.0))
    damaged(file, where + ": attribute spin_scale is not positive");
  b.nu = *nu;
  b.grid = static_cast<int>(*grid);
  b.spin_scale = spin_scale.value_or(1.0);  // tables written before it was an attribute: 1
  b.max_element_aspect = aspect.value_or(0.0);
  b.a_over_b = read_axis(group, "a_over_b", file, where);
  if (!(b.a_over_b[0] > 0.0)) damaged(file, where + ": a_over_b is not positive");
  b.psi = read_axis(group, "psi", file, where);
  b.theta = read_axis(group, "theta", file, where);
  b.beta = read_axis(group, "beta", file, where);
  b.r = read_axis(group, "r", file, where);
  // Every direction of the creepages lies between the direction nodes: theta over 0 ... pi,
  // beta over -pi/2 ... pi/2 (the generator's single-node files for --reuse are no table).
  const double pi = std::numbers::pi;
  const auto spans = [](const std::vector<double>& axis, double lo, double hi) {
    return std::abs(axis.front() - lo) <= 1e-9 && std::abs(axis.back() - hi) <= 1e-9;
  };
  if (!spans(b.theta, 0.0, pi) || !spans(b.beta, -pi / 2, pi / 2))
    damaged(file,
            where + ": its direction nodes do not span theta 0 ... pi and beta -pi/2 ... pi/2");
  b.n_g = static_cast<int>(b.a_over_b.size());
  b.n_psi = static_cast<int>(b.psi.size());
  b.n_theta = static_cast<int>(b.theta.size());
  b.n_beta = static_cast<int>(b.beta.size());
  b.n_r = static_cast<int>(b.r.size());
  b.c11 = read_per_g(group, "C11", b.a_over_b.size(), file, where);
  b.c22 = read_per_g(group, "C22", b.a_over_b.size(), file, where);
  b.c23 = read_per_g(group, "C23", b.a_over_b.size(), file, where);
  const std::vector<hsize_t> dims = {b.a_over_b.size(), b.psi.size(), b.theta.size(), b.beta.size(),
                                     b.r.size()};
  const std::vector<double> fx = read_values(group, "Fx_muN", dims, file, where);
  const std::vector<double> fy = read_values(group, "Fy_muN", dims, file, where);
  // Tables written before Mz was tabulated have no Mz_muNc (0).
  b.has_mz = group.nameExists("Mz_muNc");
  const std::vector<double> mz =
      b.has_mz ? read_values(group, "Mz_muNc", dims, file, where) : std::vector<double>();
  // Fx, Fy and Mz of a node side by side, so that one interpolation reads each node's values
  // from one place.
  b.values.reserve(3 * fx.size());
  for (std::size_t i = 0; i < fx.size(); ++i) {
    b.values.push_back(static_cast<float>(fx[i]));
    b.values.push_back(static_cast<float>(fy[i]));
    b.values.push_back(b.has_mz ? static_cast<float>(mz[i]) : 0.0f);
  }
  // The full-sliding limit per direction, where the table holds it (with Mz only: the
  // correction near full sliding takes all three).
  if (b.has_mz && group.nameExists("Fx_sliding_muN")) {
    const std::vector<hsize_t> directions(dims.begin(), dims.end() - 1);
    const std::vector<double> sx = read_values(group, "Fx_sliding_muN", directions, file, where);
    const std::vector<double> sy = read_values(group, "Fy_sliding_muN", directions, file, where);
    const std::vector<double> sm = read_values(group, "Mz_sliding_muNc", directions, file, where);
    b.sliding.reserve(3 * sx.size());
    for (std::size_t i = 0; i < sx.size(); ++i)
      for (const double v : {sx[i], sy[i], sm[i]}) b.sliding.push_back(static_cast<float>(v));
  }
  b.log_a_over_b = b.a_over_b;
  for (double& g : b.log_a_over_b) g = std::log(g);
  return b;
}

std::shared_ptr<CreepTableData> read_table(const std::string& bytes, const fs::path& file) {
  auto table = std::make_shared<CreepTableData>();
  // Read from the bytes already hashed, not from the file again, so that the SHA-256 a run
  // records is the one of the data it used.
  if (bytes.empty()) damaged(file, "it is empty");
  H5::FileAccPropList access;
  access.setCore(1 << 20, false);
  if (H5Pset_file_image(access.getId(), const_cast<char*>(bytes.data()), bytes.size()) < 0)
    throw std::runtime_error("creep table " + file.string() + ": HDF5 refused its file image");
  // The core driver opens an image only under a name that is no file: one "inside" the file.
  const H5::H5File h5((file / "image").string(), H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT,
                      access);
  table->provenance = read_description(h5);
  for (hsize_t i = 0; i < h5.getNumObjs(); ++i) {
    const std::string name = h5.getObjnameByIdx(i);
    if (h5.childObjType(name) != H5O_TYPE_GROUP) continue;
    table->blocks.push_back(read_block(h5.openGroup(name), file, "group " + name));
  }
  if (table->blocks.empty()) damaged(file, "it holds no group of tables");
  std::stable_sort(table->blocks.begin(), table->blocks.end(),
                   [](const CreepTableBlock& a, const CreepTableBlock& b) { return a.nu < b.nu; });
  for (std::size_t i = 1; i < table->blocks.size(); ++i) {
    if (table->blocks[i].nu == table->blocks[i - 1].nu)
      damaged(file, "two groups tabulate nu = " + std::to_string(table->blocks[i].nu));
    // The grid, the spin scale (so what the normalised creepages mean) and psi are the first
    // group's: every group must share them. Their a/b, direction and r nodes may differ (each
    // group is interpolated on its own, then the two about nu are blended, within the creepage
    // both reach), so that a table can be refined at one nu before the others.
    const CreepTableBlock &a = table->blocks.front(), &b = table->blocks[i];
    if (a.grid != b.grid || a.max_element_aspect != b.max_element_aspect ||
        a.spin_scale != b.spin_scale || a.psi != b.psi)
      damaged(file, "its groups for nu = " + std::to_string(a.nu) + " and " + std::to_string(b.nu) +
                        " differ in their axes, grid or spin scale");
    // Between two groups the correction near full sliding needs the limits of both.
    if (a.sliding.empty() != b.sliding.empty())
      damaged(file, "one of its groups for nu = " + std::to_string(a.nu) + " and " +
                        std::to_string(b.nu) +
                        " holds the full-sliding limits (Fx_sliding_muN ...), the other not");
  }
  return table;
}

// <prefix>/share/wheelwear of the program (/proc/self/exe: dladdr names the main program by
// its argv[0], which may be relative or found on PATH) and, when this library was linked into
// a shared object, of that object.
std::vector<fs::path> installed_dirs() {
  std::vector<fs::path> dirs;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error)
    dirs.push_back((program.parent_path() / ".." / "share" / "wheelwear").lexically_normal());
  Dl_info info{};
  if (dladdr(&kAnchor, &info) != 0 && info.dli_fname && *info.dli_fname) {
    const fs::path object = fs::absolute(info.dli_fname, error);
    if (!error && fs::exists(object, error) &&
        !(!program.empty() && fs::equivalent(object, program, error))) {
      const fs::path dir = (object.parent_path() / ".." / "share" / "wheelwear").lexically_normal();
      if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
    }
  }
  return dirs;
}

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 (OpenSSL EVP_Digest) failed");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  hex.reserve(2 * size);
  for (unsigned int i = 0; i < size; ++i) {
    hex.push_back(kHex[digest[i] >> 4]);
    hex.push_back(kHex[digest[i] & 0xf]);
  }
  return hex;
}

std::string file_sha256(const std::filesystem::path& file) {
  return sha256_hex(read_bytes(file));
}

CreepTable load_creep_table(const std::filesystem::path& file) {
  const std::string bytes = read_bytes(file);
  std::shared_ptr<CreepTableData> table;
  {
    const Hdf5Errors errors;
    try {
      table = read_table(bytes, file);
    } catch (const H5::Exception& e) {
      damaged(file, "HDF5 cannot read it (" + errors.reason(e) + ")");
    }
  }
  // Absolute: what results files record must not depend on the working directory.
  std::error_code error;
  table->path = fs::absolute(file, error);
  if (error) table->path = file;
  table->sha256 = sha256_hex(bytes);
  return detail::CreepTableAccess::make(std::move(table));
}

std::filesystem::path locate_creep_table() {
  if (const char* dir = std::getenv(kEnvironment); dir && *dir) {
    const fs::path file = fs::path(dir) / kFileName;
    std::error_code error;
    if (fs::is_regular_file(file, error)) return file;
    throw InputError(std::string("creep table: WHEELWEAR_DATA_DIR = ") + dir +
                     ", but there is no file " + file.string() +
                     ": point WHEELWEAR_DATA_DIR to the folder holding "
                     "creep_table.h5 (data/ of the source tree, or <prefix>/share/wheelwear of "
                     "an installation), or unset it to use the installed table");
  }
  std::vector<fs::path> tried;
  for (const fs::path& dir : installed_dirs()) tried.push_back(dir / kFileName);
#ifdef WHEELWEAR_SOURCE_DATA_DIR
  tried.push_back(fs::path(WHEELWEAR_SOURCE_DATA_DIR) / kFileName);
#endif
  for (const fs::path& file : tried) {
    std::error_code error;
    if (fs::is_regular_file(file, error)) return file;
  }
  std::string list;
  for (const fs::path& file : tried) list += (list.empty() ? "" : ", ") + file.string();
  throw InputError("creep table: creep_table.h5 not found (WHEELWEAR_DATA_DIR is not set; tried " +
                   list +
                   "): set WHEELWEAR_DATA_DIR to the folder holding creep_table.h5 (data/ of the "
                   "source tree), or install wheelwear (cmake --install puts it in "
                   "<prefix>/share/wheelwear)");
}

const CreepTable& creep_table() {
  struct Loaded {
    std::optional<CreepTable> table;
    std::string error;
  };
  // Thread-safe initialisation of a function-local static: loaded once, on first use.
  static const Loaded loaded = [] {
    Loaded l;
    try {
      l.table = load_creep_table(locate_creep_table());
    } catch (const std::exception& e) {
      // Every failure is remembered as an input error (a missing or damaged file, or the
      // library's own failure to read it): one run never mixes results with and without it.
      l.error = e.what();
    }
    return l;
  }();
  if (!loaded.table) throw InputError(loaded.error);
  return *loaded.table;
}

std::filesystem::path creep_table_path() {
  return creep_table().path();
}

std::string creep_table_sha256() {
  return creep_table().sha256();
}

const std::filesystem::path& CreepTable::path() const {
  return data_->path;
}

const std::string& CreepTable::sha256() const {
  return data_->sha256;
}

const std::string& CreepTable::provenance() const {
  return data_->provenance;
}

}  // namespace wheelwear::tangential
