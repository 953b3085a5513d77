#include "table_hdf5.hpp"

namespace wheelwear::generators {

void write(hid_t group, const char* name, const std::vector<double>& data,
           const std::vector<hsize_t>& dims, const char* units, const char* description) {
  const std::string what = std::string("write ") + name;
  const Handle space(
      checked(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), what),
      H5Sclose);
  const Handle plist(checked(H5Pcreate(H5P_DATASET_CREATE), what), H5Pclose);
  if (dims.size() > 1) {
    std::vector<hsize_t> chunk = dims;
    chunk[0] = 1;
    checked(H5Pset_chunk(plist.get(), static_cast<int>(chunk.size()), chunk.data()), what);
    checked(H5Pset_shuffle(plist.get()), what);
    checked(H5Pset_deflate(plist.get(), 9), what);
  }
  const Handle set(checked(H5Dcreate2(group, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                      plist.get(), H5P_DEFAULT),
                           what),
                   H5Dclose);
  checked(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), what);
  write_attribute(set.get(), "units", units);
  write_attribute(set.get(), "description", description);
}

void write_attribute(hid_t object, const char* key, const std::string& value) {
  const std::string what = std::string("write the attribute ") + key;
  const Handle type(checked(H5Tcopy(H5T_C_S1), what), H5Tclose);
  checked(H5Tset_size(type.get(), value.size() + 1), what);
  const Handle scalar(checked(H5Screate(H5S_SCALAR), what), H5Sclose);
  const Handle attr(
      checked(H5Acreate2(object, key, type.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT), what),
      H5Aclose);
  checked(H5Awrite(attr.get(), type.get(), value.c_str()), what);
}

void write_attribute(hid_t object, const char* key, double value) {
  const std::string what = std::string("write the attribute ") + key;
  const Handle scalar(checked(H5Screate(H5S_SCALAR), what), H5Sclose);
  const Handle attr(
      checked(H5Acreate2(object, key, H5T_IEEE_F64LE, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
              what),
      H5Aclose);
  checked(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), what);
}

std::vector<double> read_doubles(hid_t group, const char* name) {
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) return {};
  const std::string what = std::string("read ") + name;
  const Handle set(checked(H5Dopen2(group, name, H5P_DEFAULT), what), H5Dclose);
  const Handle space(checked(H5Dget_space(set.get()), what), H5Sclose);
  std::vector<double> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  checked(H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), what);
  return out;
}

double read_number(hid_t object, const char* key, double absent) {
  if (H5Aexists(object, key) <= 0) return absent;
  const std::string what = std::string("read the attribute ") + key;
  double value = absent;
  const Handle attr(checked(H5Aopen(object, key, H5P_DEFAULT), what), H5Aclose);
  checked(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), what);
  return value;
}

}  // namespace wheelwear::generators
