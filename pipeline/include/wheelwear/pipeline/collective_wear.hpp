#pragma once
/// One evaluation of a load collective on the current wheel profiles: every state's contacts,
/// their tangential solutions and wear, reduced to a wear rate across each worn profile.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/wear/wear_distribution.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::pipeline {

/// Patches recorded per wheel and state (tread, flange root, flange), from the field side.
inline constexpr int kPatchSlots = 3;

/// Per state, wheel (0 left, 1 right) and patch slot: what the results file records. Arrays
/// are row-major [state][wheel][slot]; slots without a patch hold NaN.
struct StateSummaries {
  std::size_t states = 0;
  std::vector<double> status;   ///< [state][wheel]: code of contactgeom::WheelRailStatus
  std::vector<double> patches;  ///< [state][wheel]: number of patches
  std::vector<double> dy;       ///< [state][wheel]: this wheel's lateral shift solved at [m]
  std::vector<double> roll;     ///< [state]: wheelset roll [rad] (contactgeom::WheelsetContact)
  std::vector<double> vertical_force;  ///< [state][wheel]: sum of N cos(angle) [N]
  std::vector<double> lateral_force;   ///< [state][wheel]: sum of N sin(angle) [N]
  std::vector<double> lateral_fit;     ///< [state][wheel]: code of contactgeom::LateralFit
  std::vector<double> normal_force, a, b, psi, y_wheel, contact_angle, vx, vy, phi, Fx, Fy,
      frictional_work, worn_area;  ///< [state][wheel][slot]: N, m, m, -, m, rad, -, -, 1/m, N, N,
                                   ///< N (J/m), m^2/m
  /// [state][wheel][slot]: 1 where the totals came from the book of tables (tangential_method
  /// "best"), 0 where not.
  std::vector<double> from_table;
};

/// T gamma maps: per state, wheel and slot the nx*ny cells of FASTSIM's grid (strip by strip),
/// frictional work density per metre rolled [J/m^2/m]; NaN where there is no patch.
struct TgammaMaps {
  int nx = 0, ny = 0;
  std::vector<double> work;  ///< [state][wheel][slot][ny][nx]
  std::vector<double> x, y;  ///< cell centres relative to O [m], same layout
};

/// The result of one evaluation.
struct CollectiveWear {
  /// Wear rate of each worn profile (one when the wheels share a profile, else left, right):
  /// the distance-weighted mean over the collective of the depth per metre running [m/m], on a
  /// 0.1 mm grid of the profile's arc length.
  std::vector<wear::WearDistribution> rate;
  StateSummaries summaries;         ///< filled when the scene asks for them
  std::optional<TgammaMaps> maps;   ///< filled when the scene asks for them
  int failed_contacts = 0;          ///< wheel contacts without usable patches (skipped)
  double failed_weight = 0.0;       ///< their share of the running distance (of the two wheels)
  std::size_t geometry_solves = 0;  ///< distinct wheel/rail contacts solved (after reuse)
  std::size_t patches = 0;          ///< patches solved
  std::size_t table_patches = 0;    ///< of them, with totals from the book of tables ("best")
  /// Exact solves ("exact") that stopped at their iteration cap; their last iterate is used.
  std::size_t unconverged_patches = 0;
};

/// The fixed part of a run: rail, track, models, law, collective. Evaluations are
/// deterministic: the same profiles give bit-identical results for any number of threads.
class CollectiveEvaluator {
 public:
  /// Resolves the scene's rail profile and wear law; throws InputError on a bad scene.
  /// `reuse_geometry` solves the contact of states with the same position and loads once (the
  /// results are identical either way; off only to measure what the reuse saves).
  explicit CollectiveEvaluator(const Scene& scene, bool reuse_geometry = true);

  /// Evaluates the collective on `wheels` (one profile worn by both wheels, or left and right).
  /// Every worn profile must have the taping line at y = 0 (as profiles from
  /// profiles::wheel_profile do). TBB-parallel over contacts and states.
  CollectiveWear evaluate(const std::vector<const profiles::Profile*>& wheels) const;

  const Scene& scene() const { return scene_; }
  const profiles::Profile& rail() const { return *rail_; }
  /// The pair of `wheel` on the scene's rail in the scene's track.
  contactgeom::WheelRailPair pair(const profiles::Profile& wheel) const;

 private:
  Scene scene_;
  std::shared_ptr<const profiles::Profile> rail_;
  wear::WearLaw law_;
  contactgeom::WheelRailOptions options_;
  bool reuse_geometry_ = true;
};

}  // namespace wheelwear::pipeline
