#pragma once
// The load collective's columns, shared by inline scene states, CSV and HDF5 files.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline::detail {

/// One named value of a state (a CSV cell, a TOML key, an HDF5 dataset element).
struct StateField {
  std::string name;
  double number = 0.0;
  std::string text;  // the label only
};

/// Sets `field` on `state`; throws InputError naming `where` when the name is unknown or the
/// value impossible.
void set_state_field(WheelsetStateSpec& state, const StateField& field, const std::string& where);

/// Checks a complete state (loads given, creepages complete); `where` names it in messages.
void finish_state(WheelsetStateSpec& state, const std::string& where);

/// Whether `name` is a state's column or key.
bool is_state_field(std::string_view name);

/// The names a state accepts, for messages.
std::string state_field_names();

/// States from a CSV text: a header of column names, one state per line, '#' comments; an empty
/// cell leaves an optional column unset.
std::vector<WheelsetStateSpec> read_collective_csv(std::string_view text,
                                                   const std::string& file_name);

/// Whether a column's value in an HDF5 collective is given: NaN is not, nor is -1 in the
/// `wheelset` column (the results file's integer fill value).
bool value_given(std::string_view column, double value);

/// States from an HDF5 file's bytes (`image`; `file_name` names it in messages): one 1-D
/// dataset per column (same names) in `group`.
std::vector<WheelsetStateSpec> read_collective_hdf5(const std::string& image,
                                                    const std::string& file_name,
                                                    const std::string& group);

}  // namespace wheelwear::pipeline::detail
