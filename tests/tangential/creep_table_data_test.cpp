// The book of creep-force tables as run-time data (creep_table.hpp): where it is found, its
// SHA-256, the loader on good, truncated and damaged copies, and forces bit for bit as recorded
// when the library embedded the table at build time (before it was loaded at run time).

#include <H5Cpp.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::tangential {
namespace {

namespace fs = std::filesystem;

const fs::path kShippedTable = fs::path(WHEELWEAR_SOURCE_DIR) / "data" / "creep_table.h5";

// `sha256sum data/creep_table.h5` (GNU coreutils) of the shipped table; a new table changes it.
const char kShippedSha256[] = "bddf7330b3dbf87be35a4ae7fb1240b1e9848be663ba08b930f03c617fdeef20";

struct Point {
  contactgeom::Sdec sdec;
  Creepages creepages;
  ContactLoad load;
  Material material;
  std::array<double, 3> forces;  // Fx [N], Fy [N], Mz [N m]
};

// creep_table_forces of the library with the table compiled in (its values embedded as
// single-precision literals), printed with %a: reading the file at run time must give the same
// bits. Between the two nu, psi < 0, vx < 0, tiny and large creepage, a/b away from 1. The
// first, second, third and fifth lie where the interpolation takes out the full-sliding
// limit's error (creep_table_forces): recorded again when it did (F moved by at most 0.11 % of
// mu N, Mz by 0.15 % of mu N c; against fresh exact solves they stay within 0.2 % of both). The
// fourth and sixth (at nu 0.27 and 0.25, in directions whose beta stencil reaches the new nodes)
// recorded again when the nu = 0.25 group gained beta nodes at +-75 and +-85 degrees: they moved
// by at most 0.007 % of mu N and 0.002 % of mu N c.
const Point kPoints[] = {
    {{4.25e-3, 4.25e-3, 0.6},
     {0, 0, 1.0},
     {37830, 0.35},
     {80e9, 0.25},
     {0x1.6001b2467fdddp+12, -0x1.bd5b8c86712f9p+12, -0x1.ab11dd7acbb92p+4}},
    {{6e-3, 4e-3, -0.3},
     {1e-3, -5e-4, 0.3},
     {2e4, 0.3},
     {80e9, 0.265},
     {-0x1.3760911ef16f9p+12, -0x1.2f1613ea2ce53p+10, -0x1.8193393aa5a9cp+3}},
    {{3e-3, 7e-3, 0.2},
     {-2e-3, 1e-3, -0.5},
     {5e4, 0.3},
     {80e9, 0.28},
     {0x1.654ed2fadc0c5p+12, -0x1.df10cf041bcbap+9, 0x1.332c664994378p+4}},
    {{5e-3, 5e-3, 0.0},
     {1e-5, 2e-5, 0.01},
     {2e4, 0.3},
     {80e9, 0.27},
     {-0x1.4d4331e104d2fp+6, -0x1.2a35312a01e68p+8, -0x1.47e52c986a7ecp-2}},
    {{9e-3, 3e-3, 0.45},
     {1e-4, 2e-4, -0.2},
     {3e4, 0.25},
     {80e9, 0.25},
     {-0x1.2db52ddb1ca8dp+11, 0x1.30efdd0dcf314p+12, 0x1.04c507a719d9dp+4}},
};

// The recorded values came from a portable build; a build for this CPU (-march=native, the
// project's own scripts) may contract the interpolation's products and the full-sliding limit's
// grid sums into fused multiply-adds, which moves the last bits: 1e-13 relative admits that and
// nothing a change of the data or of the interpolation would give.
constexpr double kRecordedTolerance = 1e-13;

void expect_recorded(const CreepForces& f, const Point& p) {
  EXPECT_NEAR(f.Fx, p.forces[0], kRecordedTolerance * std::abs(p.forces[0]));
  EXPECT_NEAR(f.Fy, p.forces[1], kRecordedTolerance * std::abs(p.forces[1]));
  ASSERT_TRUE(f.Mz.has_value());
  EXPECT_NEAR(*f.Mz, p.forces[2], kRecordedTolerance * std::abs(p.forces[2]));
}

void expect_bit_identical(const CreepForces& a, const CreepForces& b) {
  EXPECT_EQ(a.Fx, b.Fx);
  EXPECT_EQ(a.Fy, b.Fy);
  EXPECT_EQ(a.Mz, b.Mz);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The message of the InputError `call` throws; nullopt when it throws none.
template <class Call>
std::optional<std::string> input_error(Call call) {
  try {
    call();
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

// A fresh folder under the system's temporary one, removed with the fixture.
class CreepTableFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "wheelwear_creep_table_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  // A copy of the shipped table's first `size` bytes (all of them by default).
  fs::path copy(const std::string& name, std::size_t size = std::string::npos) const {
    std::ifstream in(kShippedTable, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << bytes.substr(0, size);
    return file;
  }

  fs::path dir_;
};

// Sets an environment variable for one scope, restoring it after.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(Sha256, KnownVectors) {
  // FIPS 180-2, Appendix B.1 ("abc"), and the empty message.
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(CreepTableData, RecordsTheShippedTablesSha256) {
  EXPECT_EQ(creep_table_sha256(), kShippedSha256);
  // The file's hash without loading it is the same.
  EXPECT_EQ(file_sha256(kShippedTable), kShippedSha256);
  EXPECT_THROW(file_sha256(kShippedTable.parent_path() / "no_such_table.h5"), InputError);
  EXPECT_EQ(creep_table_path().filename(), "creep_table.h5");
  if (!std::getenv("WHEELWEAR_DATA_DIR")) {
    // The build tree has no <prefix>/share/wheelwear: the source tree's copy.
    EXPECT_TRUE(fs::equivalent(creep_table_path(), kShippedTable)) << creep_table_path();
  }
}

TEST(CreepTableData, ForcesMatchTheRecordedValues) {
  for (const Point& p : kPoints)
    expect_recorded(creep_table_forces(p.sdec, p.creepages, p.load, p.material), p);
  const CreepTableRange range = creep_table_range();
  EXPECT_EQ(range.nu_min, 0.25);
  EXPECT_EQ(range.nu_max, 0.28);
  EXPECT_EQ(range.a_over_b_min, 0.2);
  EXPECT_EQ(range.a_over_b_max, 10.0);  // at every nu; the nu = 0.25 group reaches 25
  EXPECT_EQ(creep_table_range(0.25).a_over_b_max, 25.0);
  EXPECT_EQ(creep_table_range(0.25).r_max, 50.0);
  EXPECT_EQ(creep_table_range(0.28).r_max, 20.0);
  EXPECT_EQ(creep_table_range(0.265).a_over_b_max, 10.0);
  EXPECT_EQ(creep_table_range(0.28).a_over_b_max, 10.0);
  EXPECT_EQ(creep_table_range(0.25).a_over_b_min, 0.2);
  EXPECT_THROW(creep_table_range(std::nan("")), InputError);
  EXPECT_EQ(range.max_element_aspect, 5.0);
  EXPECT_EQ(range.psi_max, 0.8);
  EXPECT_EQ(range.r_max, 20.0);
  EXPECT_EQ(range.full_sliding_margin, 0.04);
  EXPECT_EQ(range.grid, 30);
  EXPECT_EQ(range.spin_scale, 3.0);
  EXPECT_TRUE(contains(creep_table_provenance(), "Book of creep-force tables"));
}

TEST_F(CreepTableFile, LoadsACopy) {
  const fs::path file = copy("creep_table.h5");
  const CreepTable table = load_creep_table(file);
  EXPECT_EQ(table.path(), file);
  EXPECT_EQ(table.sha256(), kShippedSha256);
  EXPECT_EQ(table.provenance(), creep_table_provenance());
  const CreepTableRange a = table.range(), b = creep_table_range();
  EXPECT_EQ(a.nu_min, b.nu_min);
  EXPECT_EQ(a.nu_max, b.nu_max);
  EXPECT_EQ(a.r_max, b.r_max);
  // The same build reads the same bits from a copy as from the shipped file.
  for (const Point& p : kPoints)
    expect_bit_identical(creep_table_forces(table, p.sdec, p.creepages, p.load, p.material),
                         creep_table_forces(p.sdec, p.creepages, p.load, p.material));
}

TEST_F(CreepTableFile, RefusesMissingTruncatedAndDamagedFiles) {
  const std::size_t size = fs::file_size(kShippedTable);
  std::vector<fs::path> bad = {dir_ / "missing.h5", copy("empty.h5", 0), copy("head.h5", 4096),
                               copy("half.h5", size / 2), copy("short.h5", size - 1)};
  // Bytes in the middle (compressed values: zlib's checksum fails) and a text file.
  const fs::path damaged = copy("damaged.h5");
  {
    std::fstream out(damaged, std::ios::binary | std::ios::in | std::ios::out);
    out.seekp(static_cast<std::streamoff>(size / 2));
    out << std::string(256, '\xff');
  }
  bad.push_back(damaged);
  std::ofstream(dir_ / "text.h5") << "not HDF5\n";
  bad.push_back(dir_ / "text.h5");
  for (const fs::path& file : bad) {
    const auto message = input_error([&] { load_creep_table(file); });
    ASSERT_TRUE(message) << file;
    EXPECT_TRUE(contains(*message, file.string())) << *message;
    EXPECT_TRUE(contains(*message, "WHEELWEAR_DATA_DIR")) << *message;
  }
}

// The grid rule's attribute: a table without it (written before the rule) reads as n x n at
// every a/b; an element aspect below 1 is refused naming the attribute.
TEST_F(CreepTableFile, ReadsTheElementAspectOfItsGrid) {
  EXPECT_EQ(load_creep_table(copy("shipped.h5")).range().max_element_aspect, 5.0);
  const auto rewrite = [&](const std::string& name, std::optional<double> aspect) {
    const fs::path file = copy(name);
    H5::H5File h5(file.string(), H5F_ACC_RDWR);
    for (const char* group : {"nu_0.25", "nu_0.28"}) {
      H5::Group g = h5.openGroup(group);
      g.removeAttr("max_element_aspect");
      if (aspect)
        g.createAttribute("max_element_aspect", H5::PredType::IEEE_F64LE, H5::DataSpace())
            .write(H5::PredType::NATIVE_DOUBLE, &*aspect);
    }
    return file;
  };
  EXPECT_EQ(load_creep_table(rewrite("square.h5", std::nullopt)).range().max_element_aspect, 0.0);
  const auto message = input_error([&] { load_creep_table(rewrite("bad.h5", 0.5)); });
  ASSERT_TRUE(message);
  EXPECT_TRUE(contains(*message, "max_element_aspect")) << *message;
}

// The grid, the extrapolation beyond r_max and the normalised creepages are shared by every
// group (their a/b nodes may differ: the shipped table's do): a group whose spin scale (so its
// normalised axes) differs is refused.
TEST_F(CreepTableFile, RefusesGroupsThatDoNotShareTheirAxes) {
  const fs::path file = copy("mixed.h5");
  {
    H5::H5File h5(file.string(), H5F_ACC_RDWR);
    H5::Group g = h5.openGroup("nu_0.28");
    g.removeAttr("spin_scale");
    const double other = 2.0;
    g.createAttribute("spin_scale", H5::PredType::IEEE_F64LE, H5::DataSpace())
        .write(H5::PredType::NATIVE_DOUBLE, &other);
  }
  const auto message = input_error([&] { load_creep_table(file); });
  ASSERT_TRUE(message);
  EXPECT_TRUE(contains(*message, "differ in their axes")) << *message;
}

// Every direction of the creepages must lie between the direction nodes: a group whose beta
// nodes stop short of pi/2 is refused (as the generator's one-node files for --reuse are).
TEST_F(CreepTableFile, RefusesDirectionNodesThatDoNotSpanEveryDirection) {
  const fs::path file = copy("short_beta.h5");
  {
    H5::H5File h5(file.string(), H5F_ACC_RDWR);
    H5::DataSet beta = h5.openGroup("nu_0.28").openDataSet("beta");
    std::vector<double> values(static_cast<std::size_t>(beta.getSpace().getSimpleExtentNpoints()));
    beta.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    values.back() -= 0.05;  // still increasing
    beta.write(values.data(), H5::PredType::NATIVE_DOUBLE);
  }
  const auto message = input_error([&] { load_creep_table(file); });
  ASSERT_TRUE(message);
  EXPECT_TRUE(contains(*message, "do not span theta 0 ... pi and beta -pi/2 ... pi/2")) << *message;
}

// A dataset of doubles of a group, with its shape.
std::vector<double> read_dataset(const H5::Group& group, const char* name,
                                 std::vector<hsize_t>* dims = nullptr) {
  const H5::DataSet set = group.openDataSet(name);
  const H5::DataSpace space = set.getSpace();
  std::vector<hsize_t> shape(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(shape.data());
  if (dims) *dims = shape;
  std::vector<double> values(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
  set.read(values.data(), H5::PredType::NATIVE_DOUBLE);
  return values;
}

// The full-sliding limits the table holds per direction node [a_over_b][psi][theta][beta] are
// full_sliding_sdec's (itself tested against the closed form of pure spin) at the node's
// direction, on the node's grid: every 7th node of both groups (11385 of 21 x 5 x 33 x 23 at
// nu = 0.25, 7166 of 16 x 5 x 33 x 19 at 0.28), which a wrong index order or a wrong
// normalisation would miss at once. The generator writes
// doubles; the same sums in the same order agree to rounding (1e-12).
TEST_F(CreepTableFile, HoldsTheFullSlidingLimitOfItsDirectionNodes) {
  const H5::H5File h5(kShippedTable.string(), H5F_ACC_RDONLY);
  const CreepTableRange range = creep_table_range();
  int compared = 0;
  for (const char* name : {"nu_0.25", "nu_0.28"}) {
    const H5::Group g = h5.openGroup(name);
    const std::vector<double> gs = read_dataset(g, "a_over_b"), psis = read_dataset(g, "psi"),
                              thetas = read_dataset(g, "theta"), betas = read_dataset(g, "beta");
    const std::vector<double> c11 = read_dataset(g, "C11"), c22 = read_dataset(g, "C22"),
                              c23 = read_dataset(g, "C23");
    std::vector<hsize_t> dims;
    const std::vector<double> sx = read_dataset(g, "Fx_sliding_muN", &dims);
    const std::vector<double> sy = read_dataset(g, "Fy_sliding_muN");
    const std::vector<double> sm = read_dataset(g, "Mz_sliding_muNc");
    ASSERT_EQ(dims, (std::vector<hsize_t>{gs.size(), psis.size(), thetas.size(), betas.size()}));
    const ContactLoad load{1e4, 0.3};
    const double mu_n = load.mu * load.N;
    for (std::size_t i = 0; i < sx.size(); i += 7) {
      const std::size_t ib = i % betas.size(), it = i / betas.size() % thetas.size(),
                        ip = i / (betas.size() * thetas.size()) % psis.size(),
                        ig = i / (betas.size() * thetas.size() * psis.size());
      const contactgeom::Sdec patch{5e-3, 5e-3 / gs[ig], psis[ip]};
      const double c = patch.c(), gc2 = 80e9 * c * c;
      const Creepages v{std::sin(thetas[it]) * std::cos(betas[ib]) * mu_n / (gc2 * c11[ig]),
                        std::sin(thetas[it]) * std::sin(betas[ib]) * mu_n / (gc2 * c22[ig]),
                        std::cos(thetas[it]) * mu_n / (range.spin_scale * gc2 * c * c23[ig])};
      const CreepForces s = full_sliding_sdec(patch, v, load, creep_table_grid(patch));
      EXPECT_NEAR(sx[i], s.Fx / mu_n, 1e-12) << name << " node " << i;
      EXPECT_NEAR(sy[i], s.Fy / mu_n, 1e-12) << name << " node " << i;
      EXPECT_NEAR(sm[i], *s.Mz / (mu_n * c), 1e-12) << name << " node " << i;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 11385 + 7166);
}

// A copy of the shipped table with its full-sliding limits removed or damaged.
class CreepTableWithoutSliding : public CreepTableFile {
 protected:
  fs::path rewritten(const std::string& name, bool damage,
                     std::vector<const char*> groups = {"nu_0.25", "nu_0.28"}) const {
    const fs::path file = copy(name);
    H5::H5File h5(file.string(), H5F_ACC_RDWR);
    for (const char* group : groups) {
      H5::Group g = h5.openGroup(group);
      for (const char* set : {"Fx_sliding_muN", "Fy_sliding_muN", "Mz_sliding_muNc"}) g.unlink(set);
      if (!damage) continue;
      const double zero[3] = {0.0, 0.0, 0.0};
      const hsize_t three = 3;
      for (const char* set : {"Fx_sliding_muN", "Fy_sliding_muN", "Mz_sliding_muNc"})
        g.createDataSet(set, H5::PredType::IEEE_F64LE, H5::DataSpace(1, &three))
            .write(zero, H5::PredType::NATIVE_DOUBLE);
    }
    return file;
  }
};

// Without the limits the table interpolates the forces alone: the same bits far from full
// sliding (small creepage), other values near it.
TEST_F(CreepTableWithoutSliding, InterpolatesTheForcesAlone) {
  const CreepTable plain = load_creep_table(rewritten("plain.h5", false));
  const contactgeom::Sdec sdec{5e-3, 5e-3 / 0.2366, 0.621};
  const ContactLoad load{2e4, 0.3};
  const Material material{80e9, 0.2542};
  const Creepages small{1e-5, -2e-6, 1e-3}, sliding{8.869e-4, -4.56e-5, 2.828e-2};
  expect_bit_identical(creep_table_forces(plain, sdec, small, load, material),
                       creep_table_forces(sdec, small, load, material));
  EXPECT_GT(std::abs(*creep_table_forces(plain, sdec, sliding, load, material).Mz -
                     *creep_table_forces(sdec, sliding, load, material).Mz),
            0.01 * load.mu * load.N * sdec.c());
}

// nu is interpolated between two groups: both hold the limits or neither.
TEST_F(CreepTableWithoutSliding, RefusesLimitsInOneGroupOnly) {
  const auto message =
      input_error([&] { load_creep_table(rewritten("one.h5", false, {"nu_0.28"})); });
  ASSERT_TRUE(message);
  EXPECT_TRUE(contains(*message, "holds the full-sliding limits")) << *message;
}

TEST_F(CreepTableWithoutSliding, RefusesLimitsOfTheWrongShape) {
  const auto message = input_error([&] { load_creep_table(rewritten("damaged.h5", true)); });
  ASSERT_TRUE(message);
  EXPECT_TRUE(contains(*message, "Fx_sliding_muN is not shaped [a_over_b][psi][theta][beta]"))
      << *message;
}

TEST_F(CreepTableFile, EnvironmentFolderWithoutTheTableIsAnError) {
  const ScopedEnvironment env("WHEELWEAR_DATA_DIR", dir_.string());
  const auto message = input_error([] { locate_creep_table(); });
  ASSERT_TRUE(message);
  EXPECT_TRUE(contains(*message, (dir_ / "creep_table.h5").string())) << *message;
  EXPECT_TRUE(contains(*message, "WHEELWEAR_DATA_DIR")) << *message;
}

TEST_F(CreepTableFile, EnvironmentFolderIsSearchedFirst) {
  copy("creep_table.h5");
  const ScopedEnvironment env("WHEELWEAR_DATA_DIR", dir_.string());
  EXPECT_EQ(locate_creep_table(), dir_ / "creep_table.h5");
}

// In a fresh process (a re-executed test binary, so that no earlier test has loaded the
// table), with WHEELWEAR_DATA_DIR set to `dir`, a folder without the table: exits 0 when every
// function that needs the table throws InputError naming the file, every time. Removes `dir`
// (exit skips the fixture's TearDown).
[[noreturn]] void use_without_the_table(const fs::path& dir) {
  setenv("WHEELWEAR_DATA_DIR", dir.c_str(), 1);
  const std::string expected = (dir / "creep_table.h5").string();
  const Point& p = kPoints[0];
  const std::optional<std::string> messages[] = {
      input_error([] { creep_table_range(); }),
      input_error([&] { creep_table_forces(p.sdec, p.creepages, p.load, p.material); }),
      input_error([&] { creep_table_covers(p.sdec, p.creepages, p.load, p.material); }),
      input_error([] { creep_table_sha256(); }),
      input_error([] { creep_table_range(); }),
  };
  int status = 0;
  for (const auto& m : messages) {
    if (!m || !contains(*m, expected)) {
      std::fprintf(stderr, "%s\n", m ? m->c_str() : "no InputError");
      status = 1;
    }
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
  std::exit(status);
}

TEST_F(CreepTableFile, FirstUseWithoutTheTableThrowsInputError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(use_without_the_table(dir_), ::testing::ExitedWithCode(0), "");
}

// In a fresh process, threads that all use the table first: exits 0 when they get the same,
// right forces (the table is loaded once, while the others wait).
[[noreturn]] void first_use_from_threads() {
  const Point& p = kPoints[1];
  std::vector<CreepForces> forces(8);
  std::vector<std::thread> threads;
  for (CreepForces& f : forces)
    threads.emplace_back([&] { f = creep_table_forces(p.sdec, p.creepages, p.load, p.material); });
  for (std::thread& t : threads) t.join();
  // All equal (bit for bit) and the recorded values (to the build's rounding).
  for (const CreepForces& f : forces) {
    if (f.Fx != forces[0].Fx || f.Fy != forces[0].Fy || f.Mz != forces[0].Mz) std::exit(1);
    if (std::abs(f.Fx - p.forces[0]) > kRecordedTolerance * std::abs(p.forces[0])) std::exit(2);
  }
  std::exit(0);
}

TEST(CreepTableData, FirstUseFromManyThreads) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(first_use_from_threads(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace wheelwear::tangential
