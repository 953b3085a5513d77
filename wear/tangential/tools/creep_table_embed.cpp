// Build step: writes the creep-force table of data/creep_table.h5 (written by
// generators/creep_table_generator.cpp) as C++ arrays (wear/src/creep_table_data.hpp), so that the
// library needs no data file at run time. Numbers are written as hexadecimal literals (exact;
// the tabulated values rounded to single precision).
// Usage: wheelwear_creep_table_embed TABLE.h5 OUTPUT.cpp; without TABLE.h5 (the argument "-")
// an empty table is written.

#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::vector<double> read(hid_t group, const char* name) {
  const hid_t set = H5Dopen2(group, name, H5P_DEFAULT);
  if (set < 0) throw std::runtime_error(std::string("missing dataset ") + name);
  const hid_t space = H5Dget_space(set);
  const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<double> data(count);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Sclose(space);
  H5Dclose(set);
  return data;
}

double read_double_attribute(hid_t object, const char* name) {
  double value = 0;
  const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
  H5Aread(attr, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  return value;
}

std::string read_string_attribute(hid_t object, const char* name) {
  const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  std::string value(H5Tget_size(type), '\0');
  H5Aread(attr, type, value.data());
  H5Tclose(type);
  H5Aclose(attr);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

void array(std::ostream& out, const std::string& name, const std::vector<double>& v) {
  out << "const double " << name << "[] = {";
  char buffer[40];
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%a", v[i]);
    out << (i % 6 == 0 ? "\n  " : " ") << buffer << ',';
  }
  out << "\n};\n";
}

// The tabulated values in single precision: its 6e-8 relative rounding is far below the
// interpolation's error (1e-3 of mu N) and halves the library's size.
void float_array(std::ostream& out, const std::string& name, const std::vector<double>& v) {
  out << "const float " << name << "[] = {";
  char buffer[40];
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%af", static_cast<double>(static_cast<float>(v[i])));
    out << (i % 8 == 0 ? "\n  " : " ") << buffer << ',';
  }
  out << "\n};\n";
}

herr_t collect(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: wheelwear_creep_table_embed TABLE.h5|- OUTPUT.cpp\n";
    return 2;
  }
  const std::string input = argv[1];
  std::ofstream out(argv[2]);
  out << "// Generated from " << input << " by wear/tools/creep_table_embed.cpp. Do not edit.\n"
      << "#include \"creep_table_data.hpp\"\n\nnamespace wheelwear::tangential::detail {\nnamespace {\n";
  std::vector<std::string> blocks;
  std::string description;
  if (input != "-") {
    try {
      const hid_t file = H5Fopen(input.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      if (file < 0) throw std::runtime_error("cannot open " + input);
      description = read_string_attribute(file, "description");
      std::vector<std::string> names;
      H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names);
      for (const std::string& name : names) {
        const hid_t group = H5Gopen2(file, name.c_str(), H5P_DEFAULT);
        const std::string p = "b" + std::to_string(blocks.size()) + "_";
        for (const char* set : {"a_over_b", "psi", "theta", "beta", "r", "C11", "C22", "C23"})
          array(out, p + set, read(group, set));
        // Fx, Fy and Mz of a node side by side, so that one interpolation reads each node's
        // values from one place. Tables written before Mz was tabulated have no Mz_muNc (0).
        const std::vector<double> fx = read(group, "Fx_muN"), fy = read(group, "Fy_muN");
        const bool has_mz = H5Lexists(group, "Mz_muNc", H5P_DEFAULT) > 0;
        const std::vector<double> mz = has_mz ? read(group, "Mz_muNc") : std::vector<double>();
        std::vector<double> values;
        values.reserve(3 * fx.size());
        for (std::size_t i = 0; i < fx.size(); ++i) {
          values.push_back(fx[i]);
          values.push_back(fy[i]);
          values.push_back(has_mz ? mz[i] : 0.0);
        }
        float_array(out, p + "values", values);
        std::vector<double> log_g = read(group, "a_over_b");
        for (double& g : log_g) g = std::log(g);
        array(out, p + "log_a_over_b", log_g);
        std::ostringstream block;
        block.precision(17);
        block << "{" << read_double_attribute(group, "nu") << ", "
              << static_cast<int>(read_double_attribute(group, "grid")) << ", "
              << (H5Aexists(group, "spin_scale") > 0 ? read_double_attribute(group, "spin_scale")
                                                     : 1.0)
              << ", " << read(group, "a_over_b").size() << ", " << read(group, "psi").size() << ", "
              << read(group, "theta").size() << ", " << read(group, "beta").size() << ", "
              << read(group, "r").size() << ", " << p << "a_over_b, " << p << "psi, " << p
              << "theta, " << p << "beta, " << p << "r, " << p << "C11, " << p << "C22, " << p
              << "C23, " << p << "values, " << (has_mz ? "true" : "false") << ", " << p
              << "log_a_over_b}";
        blocks.push_back(block.str());
        H5Gclose(group);
      }
      H5Fclose(file);
    } catch (const std::exception& e) {
      std::cerr << "creep_table_embed: " << e.what() << '\n';
      return 1;
    }
  }
  out << "const CreepTableBlock kBlocks[] = {\n";
  for (const auto& b : blocks) out << "  " << b << ",\n";
  if (blocks.empty())
    out << "  {0.0, 0, 1.0, 0, 0, 0, 0, 0, nullptr, nullptr, nullptr, nullptr, "
           "nullptr, nullptr, nullptr, nullptr, nullptr, false, nullptr},\n";
  out << "};\n}  // namespace\n\n"
      << "const CreepTableBlock* const kCreepTableBlocks = kBlocks;\n"
      << "const int kCreepTableBlockCount = " << blocks.size() << ";\n"
      << "const char* const kCreepTableProvenance = R\"table(" << description << ")table\";\n\n"
      << "}  // namespace wheelwear::tangential::detail\n";
  return out ? 0 : 1;
}
