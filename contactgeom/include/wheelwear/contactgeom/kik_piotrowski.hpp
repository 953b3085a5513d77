#pragma once
/// Non-Hertzian normal contact by the Kik-Piotrowski method with virtual penetration
/// (Piotrowski & Kik 2008, VSD 46:27-48; Kik & Piotrowski 1996, Proc. 2nd Mini Conference on
/// Contact Mechanics and Wear of Rail/Wheel Systems, Budapest), on strips across the lateral
/// contact coordinate s. The gap is taken symmetric in x about each strip's centre (no yaw);
/// the yaw extension EKP (Liu, Bruni & Vollebregt 2016), which shifts the strips along x, is
/// not modelled.
///
/// The method, for one contact region with gap minimum h_O at s_O and local approach
/// delta_k = delta - h_O:
/// 1. the patch is the region where the undeformed surfaces, brought together by the *virtual*
///    penetration eps*delta_k, interpenetrate: per strip the leading edge is
///    x_l(s) = sqrt((eps delta_k - (h(s) - h_O)) / A(s)) and the trailing edge -x_l(s);
/// 2. along x the pressure is semi-elliptic: p(x, s) = p_O sqrt(x_l(s)^2 - x^2) / x_l(s_O);
/// 3. the full approach delta_k is imposed only at O (the point of largest interpenetration):
///    delta_k = 1/(pi E*) int int p / r dA (Boussinesq), which gives
///    p_O = pi E* delta_k x_l(s_O) / I1 and N_k = pi E* delta_k I2 / I1 with
///    I1 = int int sqrt(x_l^2 - x^2) / sqrt(x^2 + (s - s_O)^2) dx ds, I2 = int pi/2 x_l^2 ds.
/// With KpPenetration::hertz_calibrated step 1 takes two factors of the patch's own instead of
/// eps: strips touch below eps_s delta_k, and x_l(s)^2 = eps_x (eps_s delta_k - (h(s) - h_O)) /
/// (eps_s A(s)); steps 2 and 3 are unchanged.
/// Cross-checks of these formulas: (a) for a quadratic gap and eps = 1/2 they reduce exactly to
/// Hertz's circular contact (N = 4/3 E* a delta, p_O = 3N/(2 pi a^2)), derived in
/// kik_piotrowski.cpp and tested; (b) they agree with the public Python implementation of the
/// paper (R. Skrypnyk, github.com/bytebunny/piotrowski-kik_model, function maxPressure, which
/// cites the paper's Eq. 13: load = pi E delta/(2(1 - nu^2)) I2/I1, pmax = load x_l(s_O)/I2,
/// i.e. E* = E/(2(1 - nu^2)) for identical materials); (c) the abstract of the paper: pressure
/// semi-elliptic along the rolling direction, patch from virtual penetration, normal pressure
/// from the contact condition at the geometrical point of contact. eps = 0.55 is the paper's
/// recommended value (eps = 1/2 is exact for the circle; elongated Hertz ellipses need more).
///
/// Several contact regions (e.g. tread and flange): the regions are the separate runs of strips
/// where the undeformed surfaces interpenetrate at the rigid approach delta (h(s) < delta).
/// Each run k is a KP problem of its own with its own minimum h_O,k, local approach
/// delta_k = delta - h_O,k and load N_k = pi E* delta_k I2,k / I1,k; the total load
/// N = sum N_k fixes the common rigid approach delta. A run can thus carry a patch made of
/// several pieces if its gap has several minima; they share the reference point O of the run.
/// When a rise in the gap between two runs sinks below delta the runs merge, the number of
/// patches changes and N(delta) drops there (the shallower lobe loses its own contact point):
/// a load in that window has two solutions and solve_kp_load returns the one its iteration
/// reaches. Everywhere else N(delta) is continuous and, in every case tested, rising.

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "wheelwear/core/enum_names.hpp"

namespace wheelwear::contactgeom {

/// The undeformed distance of a contact, sampled on uniform strips across the lateral contact
/// coordinate s: h(x, s) ~ h(s) + A(s) x^2 near x = 0.
struct GapStrips {
  double s_first = 0.0;  ///< s of the first strip's centre [m]; +s points to the gauge side
  double ds = 0.0;       ///< strip width [m], > 0
  /// #strips gap at x = 0 [m]; any datum (it may be negative where the surfaces overlap);
  /// +inf marks strips without potential contact. Not NaN, not -inf.
  std::span<const double> h;
  /// #strips longitudinal gap coefficient A(s) [1/m], > 0: half the second derivative of the
  /// gap along x. For a wheel of rolling radius R_w(s) on a straight rail, 1/(2 R_w(s)).
  std::span<const double> ax;

  std::size_t size() const { return h.size(); }
  double s(std::size_t j) const { return s_first + static_cast<double>(j) * ds; }  ///< [m]
  /// Throws InputError naming the first bad field (sizes, ds, NaN or -inf gap, A <= 0).
  void validate() const;
};

/// How the virtual penetration is chosen.
enum class KpPenetration {
  /// One factor eps for both directions (Piotrowski & Kik 2008): KpOptions::epsilon.
  fixed,
  /// Per patch, the factors Hertz's ellipse has for the patch's own curvature ratio: laterally
  /// eps_s delta_k decides which strips touch, along x eps_x delta_k sets the strips' length,
  /// with eps_x + eps_s = 1 (hertz_penetration.hpp). The lateral curvature is the secant one of
  /// the run's interpenetration (all its pieces), B = 16 L^3 / (9 (int g ds)^2) with
  /// g = L - (h - h_O) > 0 at the lateral level L = eps_s delta_k (B itself for a parabola),
  /// and eps_s follows from B/A(s_O) by three fixed-point steps from 1/2. For a quadratic gap
  /// the patch and the pressure are Hertz's, to the strip model (7e-4 with 80 strips across); a
  /// fixed eps is right only for one axis ratio (1/2 for a circle), and on slender flange
  /// patches (B/A = 100, a/b = 18: eps_x 0.77, eps_s 0.23) 0.55 makes them 1.5 times too wide
  /// and 15 % too short. docs/normal-contact.md compares both with CONTACT.
  hertz_calibrated,
};

/// The names scenes and the command line give the two (the normal method).
inline constexpr core::NameTable<KpPenetration, 2> kNormalMethodNames = {{
    {KpPenetration::fixed, "kik-piotrowski"},
    {KpPenetration::hertz_calibrated, "hertz-calibrated"},
}};

/// Options of the Kik-Piotrowski solver.
struct KpOptions {
  /// Virtual penetration factor eps [-] in (0, 1] (Piotrowski & Kik 2008 recommend 0.55), used
  /// with KpPenetration::fixed.
  double epsilon = 0.55;
  KpPenetration penetration = KpPenetration::fixed;
  /// Prescribed load: the iteration stops when |N/N_target - 1| <= load_tolerance, in (0, 0.01],
  /// and the status is converged if and only if the result's N meets this. (The wheel/rail
  /// solves use WheelRailOptions::load_tolerance instead, the same test on Fz.)
  double load_tolerance = 1e-10;
  /// Prescribed load: at most this many evaluations of N(delta) (bracketing included).
  int max_evaluations = 60;

  void validate() const;  ///< throws InputError on a bad option
};

/// One strip of a patch: semi-elliptic pressure between the edges -x_lead and +x_lead.
struct KpStrip {
  double s = 0.0;       ///< lateral position of the strip centre [m]
  double x_lead = 0.0;  ///< leading edge [m] >= 0; the trailing edge is -x_lead; 0: no contact
  double p_peak = 0.0;  ///< pressure at x = 0 [Pa]
  /// A strip out of contact between two pieces of a patch: how far its gap stays above the
  /// virtual penetration level, over A(s), times KpPatch::stretch: the x_lead^2 it lacks [m^2].
  /// 0 in contact (or not known: strips built by hand); the solver gives every strip out of
  /// contact a positive one, the smallest double where the gap is just at the level.
  double opening = 0.0;
  /// Pressure p(x) = p_peak sqrt(1 - x^2/x_lead^2) [Pa] at x [m]; 0 outside the strip's edges.
  double pressure(double x) const;
  /// Normal line load int p dx = pi/2 p_peak x_lead [N/m].
  double line_load() const;
};

/// One contact patch (one interpenetration region) of the Kik-Piotrowski solution.
struct KpPatch {
  /// Strips from the first to the last one in contact, in increasing s; interior strips with
  /// x_lead = 0 are gaps between pieces of the patch.
  std::vector<KpStrip> strips;
  double ds = 0.0;        ///< strip width [m]
  double s_O = 0.0;       ///< initial contact point O: gap minimum (parabola fit) [m]
  double h_O = 0.0;       ///< gap at O [m], same datum as GapStrips::h
  double approach = 0.0;  ///< local approach delta_k = delta - h_O [m]
  /// Lateral virtual penetration eps_s delta_k [m] (eps_s = eps with a fixed factor): strips
  /// with h - h_O below it touch.
  double virtual_penetration = 0.0;
  /// Ratio eps_x / eps_s of the longitudinal to the lateral factor (1 with a fixed factor): a
  /// strip's x_lead^2 is this times (virtual_penetration - (h - h_O)) / A(s).
  double stretch = 1.0;
  double x_lead_O = 0.0;      ///< leading edge at O, sqrt(eps_x delta_k / A(s_O)) [m]
  double normal_force = 0.0;  ///< N_k [N]
  double p_O = 0.0;           ///< pressure at O [Pa]
  double pmax = 0.0;          ///< largest pressure, max(p_O, strip centres) [Pa]
  /// The KpStrip::opening of the strip just before the first and just after the last of
  /// `strips` [m^2], > 0: where the patch's lateral edges lie between strips. A strip beyond
  /// the patch's run of interpenetration counts as lying at the rigid approach. NaN: not known
  /// (a patch built by hand).
  double opening_before = std::numeric_limits<double>::quiet_NaN();
  double opening_after = std::numeric_limits<double>::quiet_NaN();
};

/// Outcome of a Kik-Piotrowski solve.
enum class KpStatus {
  converged,      ///< the prescribed load or approach is met
  no_contact,     ///< nothing touches (approach below the gap minimum, zero load, no finite gap)
  not_converged,  ///< the load iteration stopped early (see message); the result is the best
};

/// Kik-Piotrowski solution: all patches at one rigid approach.
struct KpResult {
  KpStatus status = KpStatus::no_contact;
  std::string message;           ///< why, when status != converged
  double approach = 0.0;         ///< rigid approach delta [m], same datum as GapStrips::h
  double normal_force = 0.0;     ///< total N [N]
  double pmax = 0.0;             ///< largest pressure over all patches [Pa]
  int evaluations = 0;           ///< evaluations of N(delta) made
  std::vector<KpPatch> patches;  ///< in increasing s
};

/// Solves the normal problem for a prescribed total normal force N [N] >= 0 (N = 0: no_contact).
/// E_star: combined modulus [Pa] > 0 (combined_modulus). The approach delta solves
/// (N(delta)/N)^(2/3) - 1 = 0, which is nearly linear in delta (Hertz: N ~ delta^(3/2)): secant
/// steps from KP's closed form for the gap's local curvatures until the root is met or
/// bracketed, then regula falsi with the Anderson-Bjorck modification, safeguarded by
/// bisection, until |N(delta)/N - 1| <= options.load_tolerance. Typically 3 to 5 evaluations
/// of N(delta), each one pass over the strips.
/// Throws InputError on bad input.
KpResult solve_kp_load(const GapStrips& gap, double E_star, double N,
                       const KpOptions& options = {});

/// As solve_kp_load, reusing the storage of `result` (no allocation once its capacity suffices).
void solve_kp_load(const GapStrips& gap, double E_star, double N, const KpOptions& options,
                   KpResult& result);

/// Solves the normal problem for a prescribed rigid approach delta [m] (same datum as h): the
/// surfaces interpenetrate by delta - h(s). delta at or below min h gives no_contact.
KpResult solve_kp_approach(const GapStrips& gap, double E_star, double delta,
                           const KpOptions& options = {});

/// As solve_kp_approach, reusing the storage of `result` (no allocation once its capacity
/// suffices): for callers that iterate on the approach themselves.
void solve_kp_approach(const GapStrips& gap, double E_star, double delta, const KpOptions& options,
                       KpResult& result);

}  // namespace wheelwear::contactgeom
