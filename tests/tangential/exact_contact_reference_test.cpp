// Non-linear creep forces against Kalker's exact theory as computed by CONTACT:
// - SDEC patches under pure spin (tests/data/contact/b_pure_spin_mx80.csv: sets b1, g = 1,
//   psi = 0.6, phi = 0.2 ... 1.6 1/m, and b2, phi = 1 1/m, psi = -0.8 ... 0.8; p0 = 1000 MPa,
//   mu = 0.35, G = 80 GPa, nu = 0.25), with the prescribed SDEC pressure;
// - S1002/UIC60 wheel/rail patches (d_wheelrail_*_dx0.2.csv, y_ws = -8 ... 10 mm), with the
//   normal problem solved from the undeformed distance;
// forces, element counts and frictional power (which checks the slip field). Also the
// catalogue those files are read through (support/contact_cases.hpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/contact_cases.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::tangential {
namespace {

namespace contact = testing::contact;

// On CONTACT's own grid the forces agree to the printed digits: CONTACT's 6-digit element
// tractions and the two programs' stopping tests (1e-7 and 1e-6 relative).
constexpr double kSameGrid = 2e-5;  // [mu N]
// The adhesion/slip boundary may move by an element where |p| is within rounding of the bound.
constexpr double kSlipBoundaryElements = 2;
// CONTACT prints the frictional power with 4 digits.
constexpr double kPrintedPower = 1e-3;  // [relative]
// 40 x 40 against CONTACT's 80 x 80: measured 0.6 % of mu N; CONTACT's own 80 x 80 ->
// 120 x 120 change is 0.36 % (README section 4).
constexpr double kCoarseGrid = 0.01;  // [mu N]

ExactSolution solve(const contact::PureSpinCase& c, int n) {
  SdecGridOptions options;
  options.nx = n;
  options.ny = n;
  return exact_sdec(c.patch, c.creepages, c.load, c.material, options);
}

// On CONTACT's own grid (80 x 80 over 1.02 times the patch, the same element centres, the
// same discrete equations, including CONTACT's dx/6 offset of the spin slip) the forces must
// agree to kSameGrid. Three cases, for run time.
TEST(ExactVersusContact, SameGridReproducesContactsDiscreteSolution) {
  int checked = 0;
  for (const contact::PureSpinCase& c : contact::pure_spin_cases()) {
    const double phi = c.creepages.phi, psi = c.patch.psi;
    const bool selected =
        (phi == 0.2 && psi == 0.6) || (phi == 1.0 && psi == -0.8) || (phi == 1.6 && psi == 0.6);
    if (!selected) continue;
    ++checked;
    const ExactSolution s = solve(c, c.mx);
    ASSERT_EQ(s.status, ExactStatus::converged) << s.message;
    EXPECT_NEAR(s.forces.Fx / c.mu_N(), c.Fx_muN, kSameGrid) << "phi " << phi;
    EXPECT_NEAR(s.forces.Fy / c.mu_N(), c.Fy_muN, kSameGrid) << "phi " << phi;
    EXPECT_EQ(s.contact_elements, c.contact_elements);
    EXPECT_NEAR(s.slip_elements, c.slip_elements, kSlipBoundaryElements) << "phi " << phi;
    // The same prescribed pressure over the same elements (CONTACT's sum printed to 1 mN).
    EXPECT_NEAR(s.normal_force, c.discrete_normal_force, 1e-5 * c.load.N);
    // Frictional power at V = 1 m/s: sum |p| |s| dA V, dissipated (CONTACT: negative).
    const double speed = 1.0;
    EXPECT_NEAR(s.frictional_work * speed, -c.frictional_power,
                kPrintedPower * std::abs(c.frictional_power))
        << "phi " << phi;
  }
  EXPECT_EQ(checked, 3);
}

// The same on CONTACT's refinement grid (120 x 120, b_pure_spin_refine_mx120.csv), for the
// case phi = 1 1/m: the agreement does not depend on the grid.
TEST(ExactVersusContact, SameFineGridReproducesContactsDiscreteSolution) {
  int checked = 0;
  for (const contact::PureSpinCase& c : contact::pure_spin_cases(contact::kPureSpinRefineMx120)) {
    if (c.creepages.phi != 1.0) continue;
    ++checked;
    const ExactSolution s = solve(c, c.mx);
    ASSERT_EQ(s.status, ExactStatus::converged) << s.message;
    EXPECT_NEAR(s.forces.Fx / c.mu_N(), c.Fx_muN, kSameGrid);
    EXPECT_NEAR(s.forces.Fy / c.mu_N(), c.Fy_muN, kSameGrid);
    EXPECT_EQ(s.contact_elements, c.contact_elements);
    EXPECT_NEAR(s.slip_elements, c.slip_elements, kSlipBoundaryElements);
  }
  EXPECT_EQ(checked, 1);
}

// All 18 cases on a 40 x 40 grid: within kCoarseGrid of CONTACT's 80 x 80 values.
TEST(ExactVersusContact, CoarseGridIsWithinOnePercentOfMuN) {
  double worst = 0.0;
  std::size_t compared = 0;
  for (const contact::PureSpinCase& c : contact::pure_spin_cases()) {
    const ExactSolution s = solve(c, 40);
    ASSERT_EQ(s.status, ExactStatus::converged) << s.message;
    const double dx = std::abs(s.forces.Fx / c.mu_N() - c.Fx_muN);
    const double dy = std::abs(s.forces.Fy / c.mu_N() - c.Fy_muN);
    EXPECT_LT(dx, kCoarseGrid) << "set " << c.set << " phi " << c.creepages.phi << " psi "
                               << c.patch.psi;
    EXPECT_LT(dy, kCoarseGrid) << "set " << c.set << " phi " << c.creepages.phi << " psi "
                               << c.patch.psi;
    worst = std::max({worst, dx, dy});
    ++compared;
  }
  EXPECT_EQ(compared, contact::kPureSpinCases);
  RecordProperty("worst_over_muN", std::to_string(worst));
}

// The undeformed distance of a wheel/rail patch on CONTACT's grid (element centres at
// multiples of dx and ds from the contact reference point): CONTACT's minimum per grid row
// h(s) plus the wheel's curvature along x projected on the contact normal,
// cos(delta) x^2/(2 r0) with the nominal rolling radius r0 = 460 mm (the rail is straight
// along x). Rows outside the patch are kept out of contact.
struct UndeformedDistance {
  ElementGrid grid;
  std::vector<double> h;
};

UndeformedDistance undeformed_distance(const contact::WheelRailCase& patch) {
  constexpr double kNominalRadius = 0.460;
  const double dx = patch.dx, ds = patch.ds;
  const double cos_delta = std::cos(patch.delta_cp);
  std::map<long, double> h_row;  // row index s/ds -> minimum undeformed distance [m]
  double x_max = 0.0;
  for (const contact::WheelRailRow& r : patch.rows) {
    h_row[std::lround(r.s / ds)] = r.h_min;
    x_max = std::max(x_max, r.x_lead);
  }
  const long first = h_row.begin()->first - 2, last = h_row.rbegin()->first + 2;
  const int half = static_cast<int>(std::lround(x_max / dx)) + 3;
  UndeformedDistance c;
  c.grid = {2 * half + 1,
            static_cast<int>(last - first + 1),
            -(half + 0.5) * dx,
            (static_cast<double>(first) - 0.5) * ds,
            dx,
            ds};
  c.h.resize(static_cast<std::size_t>(c.grid.size()));
  for (int j = 0; j < c.grid.ny; ++j) {
    const auto row = h_row.find(first + j);
    for (int i = 0; i < c.grid.nx; ++i) {
      const double x = c.grid.x(i);
      c.h[static_cast<std::size_t>(j * c.grid.nx + i)] =
          row == h_row.end() ? 1.0 : row->second + cos_delta * x * x / (2.0 * kNominalRadius);
    }
  }
  return c;
}

// CONTACT's creepages (of body 1 against body 2, at the contact reference point) and normal
// force give its forces on body 1 (FX, FS, Kalker's convention) within 1 % of mu N. The
// undeformed distance above is reconstructed, not CONTACT's own: the wheel radius varies over
// the patch by the profile height (< 1 % of r0), and the planar projection is crude in the
// flange contact at delta = 1.2 rad (y_ws = -8: measured 0.4 % of mu N; elsewhere <= 0.02 %).
TEST(ExactVersusContact, WheelRailPatchesFromTheUndeformedDistance) {
  constexpr double kReconstructedGap = 0.01;  // [mu N], see above
  // Contact area: the same elements up to boundary ones (0.6 % at the flange root y_ws = -6,
  // <= 0.2 % elsewhere).
  constexpr double kBoundaryElements = 0.01;  // [relative]
  // Frictional power: the slip field too; 0.45 % off in the flange contact, <= 0.15 % elsewhere.
  constexpr double kPower = 0.01;  // [relative]
  double worst = 0.0;
  std::size_t compared = 0;
  for (const contact::WheelRailCase& patch : contact::wheel_rail_cases()) {
    const UndeformedDistance c = undeformed_distance(patch);
    const ContactLoad load{patch.FN, patch.mu};
    const ExactSolution s = exact_rolling(c.grid, c.h, patch.creepages, load, patch.material);
    ASSERT_EQ(s.status, ExactStatus::converged) << s.message;
    const double mun = load.mu * load.N;
    const double dx = std::abs(s.forces.Fx - patch.FX) / mun;
    const double ds = std::abs(s.forces.Fy - patch.FS) / mun;
    EXPECT_LT(dx, kReconstructedGap) << "y_ws " << patch.y_ws_mm;
    EXPECT_LT(ds, kReconstructedGap) << "y_ws " << patch.y_ws_mm;
    EXPECT_NEAR(s.contact_elements, patch.contact_elements,
                kBoundaryElements * patch.contact_elements)
        << "y_ws " << patch.y_ws_mm;
    // CONTACT's power is negative (dissipated), at the rolling speed VELOC.
    EXPECT_NEAR(s.frictional_work * patch.speed, -patch.frictional_power,
                kPower * std::abs(patch.frictional_power))
        << "y_ws " << patch.y_ws_mm;
    worst = std::max({worst, dx, ds});
    ++compared;
  }
  EXPECT_EQ(compared, contact::kWheelRailCases);
  RecordProperty("worst_over_muN", std::to_string(worst));
}

// The catalogue holds what the README lists, file by file, and the files agree where they
// overlap: the refinement files repeat the 80 x 80 cases' parameters (and, for the linear
// coefficients, their values).
TEST(ContactCatalogue, EveryFileHoldsTheCasesTheReadmeLists) {
  const auto coefficients = contact::linear_coefficient_cases();
  ASSERT_EQ(coefficients.size(), contact::kLinearCoefficientCases);
  std::set<std::string> labels;
  std::map<std::pair<std::string, double>, const contact::LinearCoefficientCase*> by_patch;
  for (const auto& c : coefficients) {
    labels.insert(c.g_label);
    by_patch[{c.g_label, c.patch.psi}] = &c;
    EXPECT_EQ(c.mx, 80);
    EXPECT_LE(c.max_slip_elements, 1) << c.g_label;  // the no-slip linear theory
  }
  // 10 ellipticities, each with 9 distinct psi.
  EXPECT_EQ(labels.size(), 10u);
  EXPECT_EQ(by_patch.size(), contact::kLinearCoefficientCases);

  const auto fits = contact::linear_fit_cases();
  ASSERT_EQ(fits.size(), contact::kLinearFitCases);
  for (const auto& f : fits) {
    EXPECT_EQ(labels.count(f.g_label), 1u) << f.g_label;
    EXPECT_EQ(f.psi_count, 9) << f.g_label;
  }

  const auto refinements = contact::linear_refinement_cases();
  ASSERT_EQ(refinements.size(), contact::kLinearRefinementCases);
  std::size_t matched = 0;
  for (const auto& r : refinements) {
    const auto it = by_patch.find({r.g_label, r.psi});
    ASSERT_NE(it, by_patch.end()) << r.g_label << " psi " << r.psi;
    const contact::LinearCoefficientCase& c = *it->second;
    EXPECT_EQ(r.coarse.mx, 80);
    EXPECT_GT(r.fine.mx * r.fine.my, 80 * 80);
    // The same digits in both files.
    EXPECT_EQ(r.coarse.c11s, c.c11s);
    EXPECT_EQ(r.coarse.c13s, c.c13s);
    EXPECT_EQ(r.coarse.c22s, c.c22s);
    EXPECT_EQ(r.coarse.c23s, c.c23s);
    ++matched;
  }
  EXPECT_EQ(matched, contact::kLinearRefinementCases);

  const auto spin = contact::pure_spin_cases();
  ASSERT_EQ(spin.size(), contact::kPureSpinCases);
  EXPECT_EQ(std::count_if(spin.begin(), spin.end(), [](const auto& c) { return c.set == "b1"; }),
            9);
  EXPECT_EQ(contact::pure_spin_cases_with_spin().size(), contact::kPureSpinCasesWithSpin);
  // The 120 x 120 cases are b1's at the same spin; README section 4: Fx/(mu N) moves by
  // <= 0.36 % and Fy/(mu N) by <= 0.34 % from 80 x 80.
  std::size_t refined = 0;
  for (const auto& fine : contact::pure_spin_cases(contact::kPureSpinRefineMx120)) {
    const auto coarse = std::find_if(spin.begin(), spin.end(), [&](const auto& c) {
      return c.set == fine.set && c.creepages.phi == fine.creepages.phi &&
             c.patch.psi == fine.patch.psi;
    });
    ASSERT_NE(coarse, spin.end()) << "phi " << fine.creepages.phi;
    EXPECT_EQ(fine.patch.a, coarse->patch.a);
    EXPECT_EQ(fine.patch.b, coarse->patch.b);
    EXPECT_EQ(fine.load.N, coarse->load.N);
    EXPECT_EQ(fine.mx, 120);
    EXPECT_NEAR(coarse->Fx_muN / fine.Fx_muN, 1.0, 0.0036) << "phi " << fine.creepages.phi;
    EXPECT_NEAR(coarse->Fy_muN / fine.Fy_muN, 1.0, 0.0034) << "phi " << fine.creepages.phi;
    ++refined;
  }
  EXPECT_EQ(refined, contact::kPureSpinRefineCases);

  const auto wheel_rail = contact::wheel_rail_cases();
  ASSERT_EQ(wheel_rail.size(), contact::kWheelRailCases);
  std::size_t rows = 0;
  for (std::size_t k = 0; k < wheel_rail.size(); ++k) {
    EXPECT_EQ(wheel_rail[k].y_ws_mm, -8 + 2 * static_cast<int>(k));  // y_ws = -8, -6, ..., 10
    EXPECT_NEAR(wheel_rail[k].dx, 0.2e-3, 1e-12);
    rows += wheel_rail[k].rows.size();
  }
  EXPECT_EQ(rows, contact::kWheelRailRows);
  const auto fine = contact::wheel_rail_cases(contact::kWheelRailDx01);
  ASSERT_EQ(fine.size(), contact::kWheelRailFineCases);
  EXPECT_EQ(fine[0].y_ws_mm, 0);
  EXPECT_NEAR(fine[0].dx, 0.1e-3, 1e-12);
  EXPECT_EQ(fine[0].rows.size(), contact::kWheelRailFineRows);
}

// A missing file, one with a case too few, a cell that is not a number and a row that lost
// a cell are refused with a message naming the file, so no test can pass on fewer cases.
TEST(ContactCatalogue, RefusesAMissingShortOrMalformedFile) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "wheelwear_contact_catalogue";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<std::string> lines;
  {
    std::ifstream in(contact::contact_directory() + "/" + std::string(contact::kPureSpinMx80.name));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  ASSERT_EQ(lines.size(), contact::kPureSpinCases + 1);  // with the header
  const auto write = [&](const std::vector<std::string>& content) {
    std::ofstream out(dir / std::string(contact::kPureSpinMx80.name));
    for (const std::string& line : content) out << line << "\n";
  };
  const auto refusal = [&]() -> std::string {
    try {
      contact::pure_spin_cases(contact::kPureSpinMx80, dir.string());
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "accepted";
  };

  EXPECT_NE(refusal().find("cannot open"), std::string::npos);  // missing

  write(lines);  // the file as it is: accepted
  EXPECT_EQ(refusal(), "accepted");
  EXPECT_EQ(contact::pure_spin_cases(contact::kPureSpinMx80, dir.string()).size(),
            contact::kPureSpinCases);

  write({lines.begin(), lines.end() - 1});  // a case too few
  EXPECT_NE(refusal().find("holds 17 data rows, expected 18"), std::string::npos) << refusal();
  write({lines.front()});  // the header alone
  EXPECT_NE(refusal().find("holds 0 data rows"), std::string::npos) << refusal();

  std::vector<std::string> malformed = lines;
  malformed[3].replace(malformed[3].find(",0.35,"), 6, ",0.3x,");  // mu
  write(malformed);
  EXPECT_NE(refusal().find("mu: '0.3x' is not a number"), std::string::npos) << refusal();

  std::vector<std::string> truncated = lines;
  truncated[5].erase(truncated[5].rfind(','));
  write(truncated);
  EXPECT_NE(refusal().find("row 5 has"), std::string::npos) << refusal();

  // Every message names the file.
  EXPECT_NE(refusal().find(contact::kPureSpinMx80.name), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wheelwear::tangential
