#pragma once
// The reference results computed with CONTACT (tests/data/contact, described in its README) as
// typed records in SI units. Every file is read by one loader, which knows how many cases the
// file holds and throws, naming the file, row and column, when the file is missing, has too few
// or too many rows, or a cell that is absent or not a number. The files' units (mm, N/mm, 1/mm,
// MPa, ...) are converted here and nowhere else.

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "support/contact_file_reader.hpp"
#include "support/csv_table.hpp"
#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::testing::contact {

// --- What every CONTACT run shares (README sections 2 and 3) --------------------------------

/// GG1 = GG2 = 80 000 N/mm^2, POISS1 = POISS2 = 0.25.
inline constexpr tangential::Material kMaterial{80e9, 0.25};
/// FSTAT = FKIN = 0.35 in every set.
inline constexpr double kFriction = 0.35;

/// The SDEC patches of the SDEC sets: c = sqrt(ab) = 4.25 mm, of ellipticity a/b and shape psi.
inline contactgeom::Sdec reference_patch(double a_over_b, double psi) {
  const double c = 4.25e-3;
  return {c * std::sqrt(a_over_b), c / std::sqrt(a_over_b), psi};
}

/// Their load: p0 = 1000 MPa, N = 2 pi a b p0 / 3, and kFriction.
inline tangential::ContactLoad reference_load(const contactgeom::Sdec& patch) {
  return {1000e6 * 2.0 * std::acos(-1.0) * patch.a * patch.b / 3.0, kFriction};
}

// --- The files and how many cases each holds -----------------------------------------------

/// a_linear_coeffs_mx80.csv: 10 ellipticities x 9 shape numbers psi = -0.8 ... 0.8.
inline constexpr std::size_t kLinearCoefficientCases = 90;
/// a_linear_fit_mx80.csv: one row per ellipticity.
inline constexpr std::size_t kLinearFitCases = 10;
/// a_linear_refinement_check.csv: 5 ellipticities x 3 psi on 120 x 120, and 3 psi each on
/// 160 x 80 (b/a = 0.1) and 120 x 80 (b/a = 0.3).
inline constexpr std::size_t kLinearRefinementCases = 21;
/// b_pure_spin_mx80.csv: b1 (psi = 0.6, phi = 0, 0.2, ..., 1.6 1/m) and b2 (phi = 1 1/m,
/// psi = -0.8 ... 0.8), 9 each.
inline constexpr std::size_t kPureSpinCases = 18;
/// Those of b_pure_spin_mx80.csv with spin: all but b1's phi = 0.
inline constexpr std::size_t kPureSpinCasesWithSpin = 17;
/// b_pure_spin_refine_mx120.csv: b1 at phi = 0.4, 1.0, 1.6 1/m.
inline constexpr std::size_t kPureSpinRefineCases = 3;
/// d_wheelrail_patches_dx0.2.csv: y_ws = -8, -6, ..., 10 mm, one patch each; its rows file
/// holds their 462 grid rows.
inline constexpr std::size_t kWheelRailCases = 10;
inline constexpr std::size_t kWheelRailRows = 462;
/// d_wheelrail_patches_dx0.1.csv: y_ws = 0 on 0.1 mm elements, 195 grid rows.
inline constexpr std::size_t kWheelRailFineCases = 1;
inline constexpr std::size_t kWheelRailFineRows = 195;

inline constexpr ContactFile kLinearCoeffsMx80{"a_linear_coeffs_mx80.csv", kLinearCoefficientCases};
inline constexpr ContactFile kLinearFitMx80{"a_linear_fit_mx80.csv", kLinearFitCases};
inline constexpr ContactFile kLinearRefinementCheck{"a_linear_refinement_check.csv",
                                                    kLinearRefinementCases};
inline constexpr ContactFile kPureSpinMx80{"b_pure_spin_mx80.csv", kPureSpinCases};
inline constexpr ContactFile kPureSpinRefineMx120{"b_pure_spin_refine_mx120.csv",
                                                  kPureSpinRefineCases};

/// A wheel/rail set: its patch file and its file of grid rows.
struct WheelRailFiles {
  ContactFile patches, rows;
};

inline constexpr WheelRailFiles kWheelRailDx02{{"d_wheelrail_patches_dx0.2.csv", kWheelRailCases},
                                               {"d_wheelrail_rows_dx0.2.csv", kWheelRailRows}};
inline constexpr WheelRailFiles kWheelRailDx01{
    {"d_wheelrail_patches_dx0.1.csv", kWheelRailFineCases},
    {"d_wheelrail_rows_dx0.1.csv", kWheelRailFineRows}};

/// tests/data/contact.
inline std::string contact_directory() {
  return test_data("contact");
}

// --- The records ---------------------------------------------------------------------------

/// CONTACT's linear-theory coefficients of one SDEC patch (Eq. 9 of Liu, Fu & Bruni 2022),
/// each from one solve with a tiny creepage from zero, 80 x 80 elements.
struct LinearCoefficientCase {
  std::string g_label;            ///< Kalker's row label: "0.5", or "1/0.7" for b/a = 0.7
  double ellipticity = 0.0;       ///< a/b, exact from the label (the file's column is rounded)
  contactgeom::Sdec patch;        ///< a, b [m], psi
  double y0 = 0.0;                ///< psi*b, the offset of O' from O [m]
  tangential::ContactLoad load;   ///< analytic N of p0 = 1000 MPa [N], mu
  tangential::Material material;  ///< G = 80 GPa, nu = 0.25
  double dv = 0.0;                ///< the creepage step dvx = dvy [-]
  double dphi = 0.0;              ///< the spin step [1/m]
  double c11s = 0, c12s = 0, c13s = 0, c21s = 0, c22s = 0, c23s = 0;  ///< [-]
  int max_slip_elements = 0;       ///< at most 1: the result is the no-slip theory
  double discrete_area_ratio = 0;  ///< contact elements x dx dy / (pi a b)
  int mx = 0, my = 0;              ///< CONTACT's grid
  double dx = 0.0, dy = 0.0;       ///< its element size [m]
};

/// CONTACT's coefficients of one ellipticity at psi = 0 and fitted over psi, with Table 1 of
/// Liu, Fu & Bruni (2022) as printed there.
struct LinearFitCase {
  std::string g_label;
  double ellipticity = 0.0;                               ///< a/b, exact from the label
  int psi_count = 0;                                      ///< shape numbers the fits use
  double c11 = 0, c22 = 0, c23 = 0;                       ///< CONTACT at psi = 0
  double k13 = 0, b11 = 0, b22 = 0, b23 = 0;              ///< CONTACT's least-squares fits over psi
  double kalker_c11 = 0, kalker_c22 = 0, kalker_c23 = 0;  ///< Kalker's table, nu = 0.25
  double paper_k13 = 0, paper_b11 = 0, paper_b22 = 0, paper_b23 = 0;  ///< Table 1 itself
};

/// The linear coefficients of one patch on 80 x 80 and on a finer grid.
struct LinearRefinementCase {
  struct Coefficients {
    int mx = 0, my = 0;
    double c11s = 0, c12s = 0, c13s = 0, c21s = 0, c22s = 0, c23s = 0;
  };
  std::string g_label;
  double ellipticity = 0.0;  ///< a/b, exact from the label
  double psi = 0.0;
  Coefficients coarse, fine;
};

/// One SDEC case of set b: pure spin at O, the SDEC pressure prescribed, 80 x 80 elements
/// (120 x 120 in the refinement file).
struct PureSpinCase {
  std::string set;                  ///< "b1" (phi varied) or "b2" (psi varied)
  std::string g_label;              ///< "1.0"
  contactgeom::Sdec patch;          ///< a, b [m], psi
  double y0 = 0.0;                  ///< psi*b [m]
  tangential::Creepages creepages;  ///< at O: vx = vy = 0, phi [1/m]
  double vx_at_Oprime = 0.0;        ///< vx - phi*y0, the creepage at O' [-]
  tangential::ContactLoad load;     ///< analytic N of p0 = 1000 MPa [N], mu
  tangential::Material material;    ///< G = 80 GPa, nu = 0.25
  double Fx = 0.0, Fy = 0.0;        ///< CONTACT's forces on body 1 (Kalker's convention) [N]
  /// The same over mu N, to 6 digits (the columns in N have 4 decimals).
  double Fx_muN = 0.0, Fy_muN = 0.0;
  double discrete_normal_force = 0.0;  ///< the prescribed pressure summed over elements [N]
  int contact_elements = 0, adhesion_elements = 0, slip_elements = 0;
  double frictional_power = 0.0;  ///< at V = 1 m/s [W]; negative: dissipated
  int mx = 0, my = 0;
  double dx = 0.0, dy = 0.0;  ///< element size [m]

  double mu_N() const { return load.mu * load.N; }
};

/// One grid row (fixed s) of a wheel/rail patch.
struct WheelRailRow {
  double s = 0.0;                      ///< from the contact reference point, like y_r [m]
  double x_trail = 0.0, x_lead = 0.0;  ///< [m]
  int elements = 0;
  double pn_line = 0, px_line = 0, ps_line = 0;  ///< line loads [N/m]
  double h_min = 0.0;                            ///< least undeformed distance in the row [m]
  double frictional_power = 0.0;                 ///< per unit lateral width [W/m], positive
};

/// One wheel/rail case of set d (S1002 on UIC60, Fz = 55 kN): its single patch and the patch's
/// grid rows. Forces are on the rail (body 1) in the patch's (x, s, n) frame.
struct WheelRailCase {
  int y_ws_mm = 0;                  ///< the case's name: lateral wheelset position in mm
  double y_ws = 0.0;                ///< the same [m]; negative: the left wheel towards its flange
  double z_ws = 0.0;                ///< [m]
  double ycp_r = 0.0, zcp_r = 0.0;  ///< contact reference point on the rail profile [m]
  double ycp_w = 0.0, zcp_w = 0.0;  ///< and on the wheel profile [m]
  double delta_cp = 0.0;            ///< contact angle [rad]
  double speed = 0.0;               ///< VELOC [m/s]
  /// CONTACT's creepages at its reference point (not at O: O lies s_icp from it), phi [1/m].
  tangential::Creepages creepages;
  tangential::Material material;  ///< G = 80 GPa, nu = 0.25
  double mu = kFriction;
  double FN = 0.0, FX = 0.0, FS = 0.0;  ///< [N]
  /// The wheel's total forces in the track frame (FY_tr_total, FZ_tr_total) [N]: FZ = the
  /// prescribed 55 kN; FY < 0 for the left wheel's flange contact.
  double FY_track = 0.0, FZ_track = 0.0;
  double MN = 0.0;                ///< spin moment [N m]
  double frictional_power = 0.0;  ///< [W]; negative: dissipated
  double p_max = 0.0;             ///< [Pa]
  int contact_elements = 0, adhesion_elements = 0, slip_elements = 0;
  double dx = 0.0, ds = 0.0;                ///< element size [m]
  double area = 0.0;                        ///< contact elements x dx ds [m^2]
  double x_min = 0, x_max = 0, length = 0;  ///< extent in x [m]
  double s_min = 0, s_max = 0, width = 0;   ///< extent in s from the reference point [m]
  double s_icp = 0.0;                       ///< the initial contact point O [m]
  double w_pos = 0.0, w_neg = 0.0;          ///< s_max - s_icp, s_icp - s_min [m]
  double psi_equiv = 0.0;                   ///< (w_pos - w_neg)/width (Eq. 14)
  double a_equiv = 0.0, b_equiv = 0.0;      ///< Eq. 14 [m]
  double max_lateral_gap = 0.0;             ///< > 0 where CONTACT merged regions [m]
  std::vector<WheelRailRow> rows;           ///< the patch's grid rows, s increasing
};

/// a_linear_coeffs_mx80.csv: the 90 patches with their linear coefficients.
inline std::vector<LinearCoefficientCase> linear_coefficient_cases(
    const std::string& directory = contact_directory()) {
  const detail::Reader in(kLinearCoeffsMx80, directory);
  std::vector<LinearCoefficientCase> cases;
  for (std::size_t k = 0; k < in.rows(); ++k) {
    LinearCoefficientCase c;
    c.g_label = in.text(k, "g_label");
    c.ellipticity = in.ellipticity(k);
    c.patch = {detail::mm(in.number(k, "a_mm")), detail::mm(in.number(k, "b_mm")),
               in.number(k, "psi")};
    c.y0 = detail::mm(in.number(k, "y0_mm"));
    c.load = {in.number(k, "N_N"), kFriction};
    c.material = kMaterial;
    c.dv = in.number(k, "dvx_dvy");
    c.dphi = in.number(k, "dphi_per_m");
    c.c11s = in.number(k, "C11s");
    c.c12s = in.number(k, "C12s");
    c.c13s = in.number(k, "C13s");
    c.c21s = in.number(k, "C21s");
    c.c22s = in.number(k, "C22s");
    c.c23s = in.number(k, "C23s");
    c.max_slip_elements = in.count(k, "max_slip_elements");
    c.discrete_area_ratio = in.number(k, "discrete_area_ratio");
    c.mx = in.count(k, "mx");
    c.my = in.count(k, "my");
    c.dx = detail::mm(in.number(k, "dx_mm"));
    c.dy = detail::mm(in.number(k, "dy_mm"));
    cases.push_back(c);
  }
  return cases;
}

/// a_linear_fit_mx80.csv: the 10 ellipticities' fits, with Table 1 of the paper.
inline std::vector<LinearFitCase> linear_fit_cases(
    const std::string& directory = contact_directory()) {
  const detail::Reader in(kLinearFitMx80, directory);
  std::vector<LinearFitCase> cases;
  for (std::size_t k = 0; k < in.rows(); ++k) {
    LinearFitCase c;
    c.g_label = in.text(k, "g_label");
    c.ellipticity = in.ellipticity(k);
    c.psi_count = in.count(k, "n_psi");
    c.c11 = in.number(k, "C11_psi0");
    c.c22 = in.number(k, "C22_psi0");
    c.c23 = in.number(k, "C23_psi0");
    c.k13 = in.number(k, "K13_fit");
    c.b11 = in.number(k, "B11_fit");
    c.b22 = in.number(k, "B22_fit");
    c.b23 = in.number(k, "B23_fit");
    c.kalker_c11 = in.number(k, "C11_kalker");
    c.kalker_c22 = in.number(k, "C22_kalker");
    c.kalker_c23 = in.number(k, "C23_kalker");
    c.paper_k13 = in.number(k, "K13_paper");
    c.paper_b11 = in.number(k, "B11_paper");
    c.paper_b22 = in.number(k, "B22_paper");
    c.paper_b23 = in.number(k, "B23_paper");
    cases.push_back(c);
  }
  return cases;
}

/// a_linear_refinement_check.csv: the 21 patches on 80 x 80 and on a finer grid.
inline std::vector<LinearRefinementCase> linear_refinement_cases(
    const std::string& directory = contact_directory()) {
  const detail::Reader in(kLinearRefinementCheck, directory);
  // "120x80" -> mx = 120, my = 80.
  const auto grid = [&in](std::size_t k, const std::string& column) {
    const std::string& cell = in.text(k, column);
    const std::size_t x = cell.find('x');
    std::size_t used_x = 0, used_y = 0;
    int mx = 0, my = 0;
    try {
      mx = std::stoi(cell.substr(0, x), &used_x);
      my = std::stoi(cell.substr(x + 1), &used_y);
    } catch (const std::exception&) {
      used_x = 0;
    }
    if (x == std::string::npos || used_x != x || used_y != cell.size() - x - 1 || mx <= 0 ||
        my <= 0)
      in.fail("row " + std::to_string(k + 1) + ", " + column + ": '" + cell + "' is not a grid");
    return std::pair{mx, my};
  };
  const auto coefficients = [&in](std::size_t k, const std::string& suffix) {
    LinearRefinementCase::Coefficients c;
    c.c11s = in.number(k, "C11s_" + suffix);
    c.c12s = in.number(k, "C12s_" + suffix);
    c.c13s = in.number(k, "C13s_" + suffix);
    c.c21s = in.number(k, "C21s_" + suffix);
    c.c22s = in.number(k, "C22s_" + suffix);
    c.c23s = in.number(k, "C23s_" + suffix);
    return c;
  };
  std::vector<LinearRefinementCase> cases;
  for (std::size_t k = 0; k < in.rows(); ++k) {
    LinearRefinementCase c;
    c.g_label = in.text(k, "g_label");
    c.ellipticity = in.ellipticity(k);
    c.psi = in.number(k, "psi");
    c.coarse = coefficients(k, "coarse");
    c.fine = coefficients(k, "fine");
    std::tie(c.coarse.mx, c.coarse.my) = grid(k, "mx_my_coarse");
    std::tie(c.fine.mx, c.fine.my) = grid(k, "mx_my_fine");
    cases.push_back(c);
  }
  return cases;
}

/// Set b: every case of `file` (kPureSpinMx80: 18, kPureSpinRefineMx120: 3).
inline std::vector<PureSpinCase> pure_spin_cases(
    const ContactFile& file = kPureSpinMx80, const std::string& directory = contact_directory()) {
  const detail::Reader in(file, directory);
  std::vector<PureSpinCase> cases;
  for (std::size_t k = 0; k < in.rows(); ++k) {
    PureSpinCase c;
    c.set = in.text(k, "set");
    if (c.set != "b1" && c.set != "b2") in.fail("row " + std::to_string(k + 1) + ": set " + c.set);
    c.g_label = in.text(k, "g_label");
    c.patch = {detail::mm(in.number(k, "a_mm")), detail::mm(in.number(k, "b_mm")),
               in.number(k, "psi")};
    c.y0 = detail::mm(in.number(k, "y0_mm"));
    c.creepages = {in.number(k, "vx_at_O"), in.number(k, "vy_at_O"), in.number(k, "phi_per_m")};
    c.vx_at_Oprime = in.number(k, "vx_at_Oprime");
    c.load = {in.number(k, "N_N"), in.number(k, "mu")};
    c.material = kMaterial;
    c.Fx = in.number(k, "Fx_N");
    c.Fy = in.number(k, "Fy_N");
    c.Fx_muN = in.number(k, "Fx_over_muN");
    c.Fy_muN = in.number(k, "Fy_over_muN");
    c.discrete_normal_force = in.number(k, "FNsum_discrete_N");
    c.contact_elements = in.count(k, "n_contact");
    c.adhesion_elements = in.count(k, "n_adhesion");
    c.slip_elements = in.count(k, "n_slip");
    c.frictional_power = in.number(k, "fric_power_W_at_V1m_s");
    c.mx = in.count(k, "mx");
    c.my = in.count(k, "my");
    c.dx = detail::mm(in.number(k, "dx_mm"));
    c.dy = detail::mm(in.number(k, "dy_mm"));
    cases.push_back(c);
  }
  return cases;
}

/// The 17 cases of b_pure_spin_mx80.csv with spin (phi > 0), in the file's order.
inline std::vector<PureSpinCase> pure_spin_cases_with_spin(
    const std::string& directory = contact_directory()) {
  std::vector<PureSpinCase> cases;
  for (PureSpinCase& c : pure_spin_cases(kPureSpinMx80, directory))
    if (c.creepages.phi != 0.0) cases.push_back(std::move(c));
  if (cases.size() != kPureSpinCasesWithSpin)
    throw std::runtime_error("CONTACT reference " + std::string(kPureSpinMx80.name) + ": " +
                             std::to_string(cases.size()) + " cases with spin, expected " +
                             std::to_string(kPureSpinCasesWithSpin));
  return cases;
}

/// Set d: the cases of `files` (kWheelRailDx02: 10, kWheelRailDx01: 1), each with its rows.
inline std::vector<WheelRailCase> wheel_rail_cases(
    const WheelRailFiles& files = kWheelRailDx02,
    const std::string& directory = contact_directory()) {
  const detail::Reader in(files.patches, directory);
  std::vector<WheelRailCase> cases;
  for (std::size_t k = 0; k < in.rows(); ++k) {
    // Every case of the set gave exactly one patch (README, section 5).
    if (in.count(k, "npatch") != 1 || in.count(k, "patch") != 1)
      in.fail("row " + std::to_string(k + 1) + ": not the single patch of its case");
    WheelRailCase c;
    c.y_ws_mm = in.count(k, "y_ws_mm");
    c.y_ws = detail::mm(in.number(k, "y_ws_mm"));
    c.z_ws = detail::mm(in.number(k, "z_ws_mm"));
    c.ycp_r = detail::mm(in.number(k, "ycp_r_mm"));
    c.zcp_r = detail::mm(in.number(k, "zcp_r_mm"));
    c.ycp_w = detail::mm(in.number(k, "ycp_w_mm"));
    c.zcp_w = detail::mm(in.number(k, "zcp_w_mm"));
    c.delta_cp = in.number(k, "delta_cp_rad");
    c.speed = detail::mm(in.number(k, "veloc_mm_s"));
    c.creepages = {in.number(k, "cksi"), in.number(k, "ceta"),
                   detail::per_mm(in.number(k, "cphi_per_mm"))};
    c.material = kMaterial;
    c.FN = in.number(k, "FN_N");
    c.FX = in.number(k, "FX_N");
    c.FS = in.number(k, "FS_N");
    c.FY_track = in.number(k, "FY_tr_total_N");
    c.FZ_track = in.number(k, "FZ_tr_total_N");
    c.MN = detail::n_mm(in.number(k, "MN_Nmm"));
    c.frictional_power = in.number(k, "fric_power_W");
    c.p_max = detail::mpa(in.number(k, "pmax_MPa"));
    c.contact_elements = in.count(k, "n_contact");
    c.adhesion_elements = in.count(k, "n_adhesion");
    c.slip_elements = in.count(k, "n_slip");
    c.dx = detail::mm(in.number(k, "dx_mm"));
    c.ds = detail::mm(in.number(k, "ds_mm"));
    c.area = detail::mm2(in.number(k, "area_mm2"));
    c.x_min = detail::mm(in.number(k, "x_min_mm"));
    c.x_max = detail::mm(in.number(k, "x_max_mm"));
    c.length = detail::mm(in.number(k, "length_x_mm"));
    c.s_min = detail::mm(in.number(k, "s_min_mm"));
    c.s_max = detail::mm(in.number(k, "s_max_mm"));
    c.width = detail::mm(in.number(k, "width_s_mm"));
    c.s_icp = detail::mm(in.number(k, "s_icp_mm"));
    c.w_pos = detail::mm(in.number(k, "W_pos_mm"));
    c.w_neg = detail::mm(in.number(k, "W_neg_mm"));
    c.psi_equiv = in.number(k, "psi_equiv");
    c.a_equiv = detail::mm(in.number(k, "a_equiv_mm"));
    c.b_equiv = detail::mm(in.number(k, "b_equiv_mm"));
    c.max_lateral_gap = detail::mm(in.number(k, "max_lateral_gap_mm"));
    cases.push_back(c);
  }

  // Each row belongs to the case of its y_ws (named as in the patch file), in increasing s.
  const detail::Reader rows(files.rows, directory);
  for (std::size_t k = 0; k < rows.rows(); ++k) {
    const int y_ws_mm = rows.count(k, "y_ws_mm");
    WheelRailCase* owner = nullptr;
    for (WheelRailCase& c : cases)
      if (c.y_ws_mm == y_ws_mm) owner = &c;
    if (!owner || rows.count(k, "patch") != 1)
      rows.fail("row " + std::to_string(k + 1) + ": no patch y_ws = " + std::to_string(y_ws_mm));
    WheelRailRow r;
    r.s = detail::mm(rows.number(k, "s_mm"));
    r.x_trail = detail::mm(rows.number(k, "x_trail_mm"));
    r.x_lead = detail::mm(rows.number(k, "x_lead_mm"));
    r.elements = rows.count(k, "n_elements");
    r.pn_line = detail::per_mm(rows.number(k, "pn_line_load_N_per_mm"));
    r.px_line = detail::per_mm(rows.number(k, "px_line_N_per_mm"));
    r.ps_line = detail::per_mm(rows.number(k, "ps_line_N_per_mm"));
    r.h_min = detail::mm(rows.number(k, "h_min_row_mm"));
    r.frictional_power = detail::per_mm(rows.number(k, "fric_power_W_per_mm"));
    if (!owner->rows.empty() && r.s <= owner->rows.back().s)
      rows.fail("row " + std::to_string(k + 1) + ": s does not increase");
    owner->rows.push_back(r);
  }
  for (const WheelRailCase& c : cases)
    if (c.rows.empty()) rows.fail("no rows for y_ws = " + std::to_string(c.y_ws_mm));
  return cases;
}

}  // namespace wheelwear::testing::contact
