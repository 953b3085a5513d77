#pragma once
// The bytes a step's work travels in between the processes of a job (distributed_run.cpp): the
// scene's source, the profiles and states of a step, the states' outcomes. Doubles travel as
// their bits, so that what arrives is bit-identical to what was sent; the layout is this build's
// own (both ends run the same program), checked only for truncation.

#include <cstdint>
#include <string>
#include <vector>

#include "wheelwear/pipeline/distributed_run.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/types.hpp"

namespace wheelwear::pipeline::detail {

// Appends values to a byte string.
class WireWriter {
 public:
  void u64(std::uint64_t v);
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v);
  void flag(bool v) { u64(v ? 1 : 0); }
  void text(const std::string& v);
  void doubles(const std::vector<double>& v);

  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads values back in the order they were written; std::runtime_error when the bytes end early.
class WireReader {
 public:
  explicit WireReader(const std::string& bytes) : bytes_(bytes) {}
  std::uint64_t u64();
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64();
  bool flag() { return u64() != 0; }
  std::string text();
  std::vector<double> doubles();
  std::size_t count(std::size_t bytes_each);  // a length, checked against what is left
  bool done() const { return at_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

void write(WireWriter& w, const SceneSource& source);
SceneSource read_scene_source(WireReader& r);

void write(WireWriter& w, const std::vector<profiles::PointList>& profiles);
std::vector<profiles::PointList> read_point_lists(WireReader& r);

void write(WireWriter& w, const std::vector<WheelsetStateSpec>& specs);
std::vector<WheelsetStateSpec> read_specs(WireReader& r);

// Everything of an outcome the reduction and the step's records use: the exact solver's whole
// solution (TangentialSolution::exact) stays with the process that computed it.
void write(WireWriter& w, const std::vector<StateOutcome>& states);
std::vector<StateOutcome> read_outcomes(WireReader& r);

void write(WireWriter& w, const std::vector<CaseTask>& tasks);
std::vector<CaseTask> read_case_tasks(WireReader& r);

// What the results file records of a case's solution (vehicle_record.cpp) and a resumed run
// restores, which is all a run uses of it, and its scalars besides: not its contact patches.
void write(WireWriter& w, const std::vector<vehicle::VehicleCurving>& curvings);
std::vector<vehicle::VehicleCurving> read_curvings(WireReader& r);

void write(WireWriter& w, const std::vector<PieceTask>& tasks);
std::vector<PieceTask> read_piece_tasks(WireReader& r);

void write(WireWriter& w, const std::vector<PieceOutcome>& outcomes);
std::vector<PieceOutcome> read_piece_outcomes(WireReader& r);

}  // namespace wheelwear::pipeline::detail
