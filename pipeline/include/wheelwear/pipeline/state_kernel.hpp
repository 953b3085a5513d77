#pragma once
/// The physics of one wheelset state on the current profiles: both wheels' contacts, each
/// patch's creepages, tangential solution and frictional work, and the wear it contributes to
/// its wheel. A run, a vehicle model or another executor calls it state by state; how the
/// contributions are reduced and recorded is not its business (collective_wear.hpp).

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "wheelwear/contactgeom/nadal.hpp"
#include "wheelwear/contactgeom/rail_friction.hpp"
#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/contactgeom/wheelset.hpp"
#include "wheelwear/contactgeom/wheelset_table.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/tangential/solution.hpp"
#include "wheelwear/tangential/tangential.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::pipeline {

/// Bin width of the wear grid on a wheel's arc length [m].
inline constexpr double kWearBin = 0.1e-3;

/// A patch's wear on its wheel: depth per metre running [m/m] in consecutive bins of width
/// kWearBin on the wheel profile's arc length, the first at index `first`.
struct LocalWear {
  std::size_t first = 0;
  std::vector<double> depth;

  double area() const;  ///< worn cross-section per metre running [m^2/m]
};

/// One patch of a wheel as the kernel solved it.
struct PatchOutcome {
  double normal_force = 0.0;   ///< [N]
  contactgeom::Sdec sdec;      ///< the SDEC of the patch (Eq. 13-14) [m, m, -]
  double y_wheel = 0.0;        ///< O on the wheel profile [m], + towards the flange
  double contact_angle = 0.0;  ///< [rad]
  /// False where the patch was not solved: the scene's model is hertz and the patch has no
  /// Hertz ellipse (its lateral relative curvature is not positive). Its forces, work and
  /// wear are then empty and it is counted in WheelOutcome::hertz_dropped.
  bool solved = true;
  tangential::Creepages creepages;          ///< at O
  tangential::TangentialSolution solution;  ///< forces, work, status; cell fields only if kept
  LocalWear wear;                           ///< this patch's wear per metre running
};

/// Why a wheel keeps its state from being worn. A run drops such a state whole, both wheels: one
/// wheel's contact cannot be trusted without the other's, whose loads it shares.
enum class DropReason {
  none,
  failed,     ///< no usable contact: no contact, not converged, profile end
  climbing,   ///< flange climb or past the flange (contact beyond the flange's steepest point)
  load_jump,  ///< the load falls inside a jump of the vertical force; the load is missed
  nadal,      ///< Y/Q beyond Nadal's limit (contactgeom/nadal.hpp)
};

/// One wheel of a state.
struct WheelOutcome {
  contactgeom::WheelRailStatus status = contactgeom::WheelRailStatus::no_contact;
  double dy = 0.0;              ///< this wheel's lateral shift solved at [m], + towards its flange
  double vertical_force = 0.0;  ///< sum of N cos(angle) [N]
  double lateral_force = 0.0;   ///< sum of N sin(angle) [N], + pushing the wheel to the centre
  contactgeom::LateralFit lateral_fit = contactgeom::LateralFit::not_prescribed;
  std::vector<PatchOutcome> patches;  ///< every patch, from the field side to the gauge side
                                      ///< (solved only when the status is ok)
  std::size_t contact_patches = 0;    ///< patches of the contact, whatever its status
  int hertz_dropped = 0;              ///< patches not solved for want of a Hertz ellipse
  /// Nadal's criterion with the flange friction (the scene's) and the solved patches' lateral
  /// creep forces; status ok only (else left at its default, not exceeded).
  contactgeom::NadalCheck nadal;

  /// Whether the contact gives patches to wear (status ok).
  bool usable() const;
  /// Why this wheel's state cannot be worn; failed before climbing before load_jump before
  /// nadal, one reason per wheel.
  DropReason drop_reason() const;
};

/// Both wheels of one state (0 left, 1 right).
struct StateOutcome {
  double roll = 0.0;  ///< wheelset roll [rad], + when the left wheel goes down
  std::array<WheelOutcome, 2> wheels;

  /// Whether either wheel has a drop reason: the state is not worn.
  bool dropped() const;
};

/// The fixed part of the physics: rail, track, material, contact model, tangential method and
/// wear law from a scene. Thread-safe: every member function is const.
class StateKernel {
 public:
  /// Throws InputError on a bad scene (rail profile, wear law, options).
  explicit StateKernel(const Scene& scene);

  /// The pair of `wheel` on the scene's rail in the scene's track.
  contactgeom::WheelRailPair pair(const profiles::Profile& wheel) const;

  /// The contact of the wheelset at the state's position, loads and prescribed lateral forces
  /// (the yaw enters only the creepages: states that differ only in yaw share it). With `table`
  /// (built on `track`'s profiles with contact_options()) it is interpolated there where the
  /// table answers (no prescribed lateral force, every node around it usable) and the scene's
  /// contact model is not hertz (a table keeps no Hertz ellipse); solved elsewhere.
  /// `interpolated`, where given, says which.
  contactgeom::WheelsetContact contact(const contactgeom::WheelsetOnTrack& track,
                                       const WheelsetStateSpec& state,
                                       const contactgeom::WheelsetContactTable* table = nullptr,
                                       bool* interpolated = nullptr) const;

  /// Solves and wears the patches of wheel `side` (0 left, 1 right) of `state` in `contact`
  /// (from contact()) on `wheel_profile`, whose length fixes the wear grid. With `keep_fields`
  /// each patch keeps its cells' work density and positions (work, x, y of CellFields; for
  /// T gamma maps).
  WheelOutcome wheel(const contactgeom::WheelsetContact& contact, int side,
                     const WheelsetStateSpec& state, const profiles::Profile& wheel_profile,
                     bool keep_fields = false) const;

  /// contact() and wheel() for both wheels.
  StateOutcome evaluate(const contactgeom::WheelsetOnTrack& track, const WheelsetStateSpec& state,
                        bool keep_fields = false) const;

  const Scene& scene() const { return scene_; }
  const profiles::Profile& rail() const { return *rail_; }
  /// The tangential method the scene's model and tangential_method name.
  tangential::Method method() const { return method_; }
  /// The normal problem's options from the scene (strip width, virtual penetration).
  const contactgeom::WheelRailOptions& contact_options() const { return options_; }
  /// The tangential solve's options from the scene (grid, scheme; every cell's fields kept).
  const tangential::SolveOptions& solve_options() const { return solve_options_; }
  /// The friction on the rail top and the gauge face at `state`: the state's where it gives
  /// them (a state's rail-top friction alone sets both), else the scene's.
  contactgeom::RailFriction rail_friction(const WheelsetStateSpec& state) const;
  /// The combined material of wheel and rail: shear modulus E / (2 (1 + nu)) and nu.
  tangential::Material material() const;

 private:
  Scene scene_;
  std::shared_ptr<const profiles::Profile> rail_;
  wear::WearLaw law_;
  contactgeom::WheelRailOptions options_;
  tangential::Method method_ = tangential::Method::fastsim_sdec;
  tangential::SolveOptions solve_options_;
};

/// The tangential method of a scene's contact model and tangential method: fastsim with model
/// sdec, eql, eqe, eqe-shifted, hertz gives fastsim-sdec, -eql, -eqe, -eqe-shifted, -elliptic
/// (hertz on the Hertz ellipse); best and exact (model sdec) give best and exact.
tangential::Method scene_method(tangential::ContactModel model, TangentialMethod tangential);

}  // namespace wheelwear::pipeline
