#pragma once
// The HDF5 calls of the table generators: datasets of doubles and attributes written with every
// call checked (a failed write throws instead of leaving a damaged table), and read back.

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace wheelwear::generators {

/// An HDF5 identifier or status, or std::runtime_error naming `what` where the call failed.
template <class Id>
Id checked(Id id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5 failed to " + what);
  return id;
}

/// Closes an HDF5 object when it leaves scope (on the error paths too).
class Handle {
 public:
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), close_(closer) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  /// Closes now, so that a failure to flush is seen.
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    checked(close_(id), what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// A dataset of doubles of shape `dims` (chunked by its first axis and compressed when it has
/// more than one), with the attributes "units" and "description".
void write(hid_t group, const char* name, const std::vector<double>& data,
           const std::vector<hsize_t>& dims, const char* units, const char* description);

/// A string or double attribute of a file, group or dataset.
void write_attribute(hid_t object, const char* key, const std::string& value);
void write_attribute(hid_t object, const char* key, double value);

/// A dataset of doubles, or empty when it is missing.
std::vector<double> read_doubles(hid_t group, const char* name);

/// A double attribute, or `absent` when it is missing.
double read_number(hid_t object, const char* key, double absent);

}  // namespace wheelwear::generators
