// Where frictional work lands across a wheel/rail patch: the chain (Kik-Piotrowski patch ->
// SDEC -> FASTSIM-SDEC), the elliptic models and the project's exact chain (wheel_rail_exact)
// against Kalker's exact theory as CONTACT computes it (its wheel/rail module, set d of
// tests/data/contact: frictional power per unit lateral width, row by row, S1002 on UIC60 at
// Fz = 55 kN).

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "support/contact_cases.hpp"
#include "support/reference_profiles.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/tangential/exact/exact_fields.hpp"
#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"
#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::wear {

// The patches these tests wear are solved by the tangential library.
using namespace wheelwear::tangential;
namespace {

using testing::benchmark_pair;
namespace contact = testing::contact;

// Lateral centroid and peak of a distribution of frictional power over lateral positions.
struct Location {
  double centroid = 0.0, peak = 0.0;
};

Location locate(const std::map<double, double>& power) {
  double sum = 0.0, moment = 0.0, best = -1.0;
  Location out;
  for (const auto& [s, p] : power) {
    sum += p;
    moment += p * s;
    if (p > best) {
      best = p;
      out.peak = s;
    }
  }
  out.centroid = moment / sum;
  return out;
}

// Frictional power per unit lateral width [W/m] of a solution's cells, strip by strip, against
// the strip's lateral position from O [m].
std::map<double, double> power_per_width(const CellFields& f, double speed) {
  std::map<double, double> power;
  for (int j = 0; j < f.ny; ++j) {
    double line = 0.0;
    for (int i = 0; i < f.nx; ++i) line += f.work[static_cast<std::size_t>(j) * f.nx + i] * f.dx[j];
    power[f.strip_y[static_cast<std::size_t>(j)]] = line * speed;
  }
  return power;
}

// Our model's frictional power per unit lateral width [W/m] against the lateral position
// from O [m], for the creepages CONTACT used (moved from its reference point to O).
std::map<double, double> model_power(ContactModel model, const contactgeom::WheelRailPatch& p,
                                     const Creepages& at_O, double speed) {
  std::optional<contactgeom::Sdec> hertz;
  if (p.hertz) hertz = contactgeom::Sdec{p.hertz->a, p.hertz->b, 0.0};
  const ModelPatch mp = model_patch(model, p.sdec, hertz);
  SolveOptions options;
  options.fastsim.nx = options.fastsim.ny = 80;
  options.fastsim.cell_fields = true;
  const TangentialSolution s =
      solve_patch(mp.method, mp.region, at_O, {p.normal_force, 0.35}, {80e9, 0.25}, options);
  return power_per_width(*s.fields, speed);
}

// The exact chain's frictional power per unit lateral width [W/m] against the lateral
// position from O [m]: Kalker's exact theory on the patch's undeformed distance
// (wheel_rail_exact, in O's contact plane), its elements as cells (exact_fields.hpp).
std::map<double, double> exact_power(const contactgeom::WheelRailPair& pair,
                                     const contactgeom::WheelsetPose& pose,
                                     const contactgeom::WheelRailPatch& p, const Creepages& at_O,
                                     double speed) {
  WheelRailExactOptions grid;
  grid.nx = grid.ny = 80;
  grid.margin = 2.5;  // the exact patch at y_ws = -2 reaches twice the strips' width
  const WheelRailExactSolution e = wheel_rail_exact(pair, pose, p, at_O, 0.35, grid);
  EXPECT_EQ(e.rolling.status, ExactStatus::converged) << e.rolling.message;
  return power_per_width(*exact_tangential_solution(e.rolling, at_O).fields, speed);
}

TEST(WearVersusContact, FrictionalWorkLandsWhereExactTheoryPutsIt) {
  const contactgeom::WheelRailPair& pair = benchmark_pair();
  std::map<ContactModel, double> total_error;
  std::size_t compared = 0;
  for (const contact::WheelRailCase& c : contact::wheel_rail_cases()) {
    const int y_ws = c.y_ws_mm;
    contactgeom::WheelsetPose pose;
    pose.dy = -c.y_ws;
    const auto geometry = contactgeom::solve_wheel_rail(pair, pose, 55e3);
    ASSERT_EQ(geometry.patches.size(), 1u);
    const auto& p = geometry.patches[0];
    // CONTACT's creepages are at its reference point; O lies s_icp from it, and the rigid
    // slip vx - phi*y moves vx there.
    const Creepages at_O{c.creepages.vx - c.creepages.phi * c.s_icp, c.creepages.vy,
                         c.creepages.phi};
    std::map<double, double> reference;  // lateral position from O [m] -> W/m
    for (const contact::WheelRailRow& r : c.rows) reference[r.s - c.s_icp] = r.frictional_power;
    const Location ref = locate(reference);
    const double speed = c.speed;
    std::map<ContactModel, double> error;  // |centroid - CONTACT's| [m]
    for (ContactModel m : kContactModels) {
      if (m == ContactModel::hertz && !p.hertz) continue;
      const Location ours = locate(model_power(m, p, at_O, speed));
      error[m] = std::abs(ours.centroid - ref.centroid);
      total_error[m] += error[m];
      std::printf("y_ws %5.1f %-12s centroid %7.3f mm (CONTACT %7.3f)  peak %7.3f mm (%7.3f)\n",
                  static_cast<double>(y_ws), std::string(model_name(m)).c_str(),
                  ours.centroid * 1e3, ref.centroid * 1e3, ours.peak * 1e3, ref.peak * 1e3);
    }
    // The exact chain, the reference `wear --exact` gives where no CONTACT result exists (wide
    // conformal patches): within half of CONTACT's 0.2 mm element at every position (measured
    // at most 0.031 mm, y_ws = 0 included), though its plane is O's and CONTACT's its
    // reference point's.
    const Location exact = locate(exact_power(pair, pose, p, at_O, speed));
    std::printf("y_ws %5.1f %-12s centroid %7.3f mm (CONTACT %7.3f)  peak %7.3f mm (%7.3f)\n",
                static_cast<double>(y_ws), "exact", exact.centroid * 1e3, ref.centroid * 1e3,
                exact.peak * 1e3, ref.peak * 1e3);
    EXPECT_LT(std::abs(exact.centroid - ref.centroid), 0.1e-3) << "y_ws " << y_ws;
    // The goal: the SDEC chain within 1 mm of exact theory. At y_ws = 0 the patch is 19.5 mm
    // wide over an almost flat gap and CONTACT's work peaks at its far gauge-side end, 11 mm
    // from O, which no single SDEC reproduces: 2 mm there.
    constexpr double kGoal = 1.0e-3, kWideFlatPatch = 2.0e-3;  // [m]
    EXPECT_LT(error[ContactModel::sdec], y_ws == 0 ? kWideFlatPatch : kGoal) << "y_ws " << y_ws;
    // On the tread (y_ws >= 0) the SDEC places the work better than the ellipses at O.
    if (y_ws >= 0) {
      EXPECT_LT(error[ContactModel::sdec], error[ContactModel::eqe]) << "y_ws " << y_ws;
      EXPECT_LT(error[ContactModel::sdec], error[ContactModel::hertz]) << "y_ws " << y_ws;
    }
    ++compared;
  }
  EXPECT_EQ(compared, contact::kWheelRailCases);
  for (const auto& [m, e] : total_error) {
    RecordProperty(std::string("mean_centroid_error_mm_") + std::string(model_name(m)),
                   std::to_string(e / static_cast<double>(compared) * 1e3));
  }
}

}  // namespace
}  // namespace wheelwear::wear
