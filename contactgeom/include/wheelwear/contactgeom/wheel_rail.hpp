#pragma once
/// One wheel on its rail: from the wheelset's position to the non-elliptic contact patches,
/// their SDEC regions and Hertz comparators (the chain of CONTACT's wheel/rail module, with
/// the Kik-Piotrowski normal problem).

#include <optional>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/hertz.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/contactgeom/patch_measures.hpp"
#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::contactgeom {

/// A wheel profile on a wheel and a rail profile on a rail, placed in a track. Both profiles
/// are in their own frames (profiles::Profile: y towards the field side, z down); the rail
/// profile already carries its inclination.
struct WheelRailPair {
  profiles::Profile wheel;
  profiles::Profile rail;
  double gauge = 1.435;           ///< track gauge [m], measured `gauge_depth` below the top
  double gauge_depth = 0.014;     ///< [m]
  double back_to_back = 1.360;    ///< distance between the wheels' flange backs [m]
  double wheel_radius = 0.46;     ///< rolling radius at the wheel profile's y = 0 [m]
  double flange_back_y = 0.0;     ///< flange back in the wheel profile's frame [m]
  double youngs_modulus = 200e9;  ///< E of wheel and rail [Pa]
  double poisson = 0.25;          ///< nu of wheel and rail [-]

  /// A pair with the flange back at the wheel profile's internal face (profiles::internal_face:
  /// its steep back-face points, else its origin convention).
  WheelRailPair(profiles::Profile wheel_profile, profiles::Profile rail_profile);
  void validate() const;  ///< throws InputError naming a bad field
};

/// Where the wheelset is, for this wheel.
struct WheelsetPose {
  double dy = 0.0;  ///< lateral shift from the centred position, + towards this wheel's flange [m]
  /// Roll of the wheel profile about its taping point [rad], |roll| < 0.1: + turns the profile's
  /// +y (field side) down (+z), z' - z_tape = sin(roll) y + cos(roll) (z - z_tape). The rolling
  /// radius of a material point, its distance from the axle, does not change.
  double roll = 0.0;
  double yaw = 0.0;  ///< yaw angle [rad]; enters the creepages, not the patch shape
};

/// The plane a patch's strips are solved in (docs/normal-contact.md, "The contact plane").
enum class ContactPlane {
  /// The tangent plane at O, each strip's gap the vertical one times the plane's cosine (Kik &
  /// Piotrowski's reduction).
  initial_point,
  /// CONTACT's planar contact (its wheel/rail module, D = 2): inclined by the rail's contact angle
  /// averaged over the interpenetration (weights: penetration^(5/2)), both profiles turned into
  /// it, the wheel at its rigid approach; the gap along the plane's normal.
  weighted,
};

/// The names scenes and the command line give them.
inline constexpr core::NameTable<ContactPlane, 2> kContactPlaneNames = {{
    {ContactPlane::initial_point, "initial-point"},
    {ContactPlane::weighted, "weighted"},
}};

/// Numerical options of the wheel/rail contact.
struct WheelRailOptions {
  /// The plane each patch's strips are solved in.
  ContactPlane contact_plane = ContactPlane::initial_point;
  double strip_width = 0.1e-3;  ///< lateral sampling of the gap [m] (patch strips are this wide
                                ///< divided by cos(contact angle))
  /// Coarse scan that finds where contact is possible [m]; between two of its points the gap is
  /// sampled also where their slopes lead into a dip whose tangents cross within the margin (a
  /// steep flank's dip, narrower than the spacing).
  double scan_spacing = 1e-3;
  /// Gaps more than this above the minimum cannot touch [m]. The gap is sampled first where it
  /// lies within min(0.3 mm, this) of its minimum and again to this margin when the approach
  /// comes within 0.1 mm of that.
  double scan_margin = 2e-3;
  /// Prescribed vertical force: the iteration stops when |Fz/Fz_target - 1| <= load_tolerance,
  /// in (0, 0.01], with Fz the strip-wise WheelRailContact::vertical_force, and the status is
  /// not_converged when the final Fz misses this. The single-region fast path solves the
  /// Kik-Piotrowski load problem for a first guess (to 1e-4 on N, or this if looser) and then
  /// corrects the approach to this; kp.load_tolerance is not used by the wheel/rail solves.
  double load_tolerance = 1e-9;
  double max_contact_angle = 1.35;  ///< steeper contact is reported as flange climb [rad]
  /// Prescribed lateral force (solve_wheel_rail_lateral): stop when |Fy/Fz - target/Fz| is
  /// below this.
  double lateral_tolerance = 1e-6;
  /// Patches with a contact angle above this are flange contact [rad] (solve_wheel_rail_lateral):
  /// S1002 on 60E1 touches its tread below 0.13 rad and its flange root above 0.28 rad.
  double flange_angle = 0.2;
  /// Kik-Piotrowski options (virtual penetration 0.55; KpPenetration::hertz_calibrated for
  /// each patch's own, accurate on slender flange patches).
  KpOptions kp;
  void validate() const;
};

/// One contact patch: its strips, measures, SDEC and the quantities at O.
struct WheelRailPatch {
  KpPatch kp;              ///< the Kik-Piotrowski strips (s: lateral, + towards the gauge side)
  PatchMeasures measures;  ///< area, length, width, W1, W2 in the contact plane
  Sdec sdec;               ///< Eq. 13-14 regularisation
  /// Hertz ellipse from the curvatures at O at the same normal force (a patch of a blend: at
  /// description_load(), its p0 and normal_force scaled by the share); none where the lateral
  /// relative curvature is not positive.
  std::optional<HertzSolution> hertz;
  double y_wheel = 0.0;  ///< O on the (unrolled) wheel profile, from its origin, + towards the
                         ///< flange [m]
  double y_rail = 0.0;   ///< O on the rail profile, from its origin, + towards the gauge side [m]
  double s_wheel = 0.0;  ///< arc length of O on the wheel profile [m]
  double contact_angle = 0.0;  ///< angle of the contact plane to the track plane [rad]
  /// The contact angle as CONTACT reports it [rad] (its wheel/rail module's planar contact, at
  /// the weighted centre of the interpenetration): the rail's contact angle averaged over the
  /// patch's rigid interpenetration, weighted by the penetration to the power 5/2 (its square
  /// integrated along x under the wheel's sag); contact_angle is O's. The table's patches carry
  /// O's.
  double contact_angle_centre = 0.0;
  /// Inclination of the planar contact the patch was solved in [rad]: contact_angle_centre with
  /// ContactPlane::weighted, contact_angle with ContactPlane::initial_point
  /// (WheelRailOptions::contact_plane). The strips' s, the measures and the gap along the contact
  /// normal are this plane's.
  double plane_angle = 0.0;
  /// The rigid vertical interpenetration of the undeformed surfaces at O [m]: how far the
  /// wheel's rigid approach reaches below its surface there (a planar gap turned into the
  /// plane depends on it, as the wheel moves down, not along the plane's normal).
  double rigid_penetration = 0.0;
  double rolling_radius = 0.0;  ///< wheel radius at O: its material point's distance from the
                                ///< axle [m], which a roll does not change
  double normal_force = 0.0;    ///< [N]
  /// The patch's share of WheelRailContact::vertical_force: its strips' line loads projected
  /// with the contact angle gamma(s) at each strip, sum q(s) ds cos(gamma(s)) [N]. Equal to
  /// normal_force cos(contact_angle) only where the rail's slope is the same across the patch.
  double vertical_force = 0.0;
  /// The patch's share of WheelRailContact::lateral_force, sum q(s) ds sin(gamma(s)) [N], + towards
  /// the gauge side.
  double lateral_force = 0.0;
  double pmax = 0.0;  ///< [Pa]
  /// 1 for a contact of its own. Where two basins of the gap are between one contact and two,
  /// the contact is blended from both descriptions (the basins cut apart, and one patch over
  /// both), each patch with its share of the blend, the shares of a contact's descriptions
  /// summing to 1; so is a cut between two samples of the gap (its piece ending at either). Its
  /// pressures and forces above are already scaled by the share, its shape is that of its
  /// description. The tangential problem is the description's: solved at description_load()
  /// and its creep forces, frictional work and wear weighted by the share (a patch solved at the
  /// scaled load would keep its full linear creep force, and a blend would count it twice).
  double share = 1.0;
};

/// The normal load of the patch's own description, normal_force / share [N]: its tangential
/// problem is solved at this load, and the outcome weighted by the share.
inline double description_load(const WheelRailPatch& patch) {
  return patch.normal_force / patch.share;
}

/// Outcome of a wheel/rail contact evaluation. Where several apply, the first of load_jump,
/// not_converged, profile_end, flange_climb, past_flange is reported (a load_jump's message
/// also says when its contact is past the flange).
enum class WheelRailStatus {
  ok,
  no_contact,
  flange_climb,  ///< a contact angle exceeds WheelRailOptions::max_contact_angle
  not_converged,
  load_jump,    ///< the load falls inside a jump of the vertical force against the approach
                ///< (regions merge); the nearer side is reported and the vertical force misses
                ///< the load
  profile_end,  ///< the contact reaches the end of a profile: the profiles are too short
  /// A loaded patch's O lies on the wheel's flange beyond the flank's steepest point, towards the
  /// flange tip: tip-wards of every point of the active flank (taping line to flange tip) whose
  /// slope is within 0.02 rad of the flank's largest (kFlangeSlopeTolerance,
  /// contactgeom/src/wheel_rail_gap.hpp). The contact angle falls as the wheel moves on: the
  /// flange climbs its rail or has passed it.
  past_flange,
};

/// All patches of one wheel on its rail.
struct WheelRailContact {
  WheelRailStatus status = WheelRailStatus::no_contact;
  std::string message;                  ///< why, when status != ok
  std::vector<WheelRailPatch> patches;  ///< ordered from the field side to the gauge side
  /// Sum of the patches' vertical_force: every strip's line load projected with the contact
  /// angle at that strip, sum q(s) ds cos(gamma(s)) [N]; the prescribed load meets this.
  double vertical_force = 0.0;
  /// Sum of the patches' lateral_force, sum q(s) ds sin(gamma(s)) [N], + pushes the wheel towards
  /// the gauge side (track centre), as flange contact does.
  double lateral_force = 0.0;
  double approach = 0.0;  ///< vertical approach beyond first touch [m]
};

/// Solves the normal contact of the wheel under a prescribed vertical force Fz [N] > 0.
WheelRailContact solve_wheel_rail(const WheelRailPair& pair, const WheelsetPose& pose,
                                  double vertical_force, const WheelRailOptions& options = {});

/// Where the undeformed surfaces of a wheel and its rail first touch: the minimum of the vertical
/// gap z_rail - z_wheel over the rail-frame lateral coordinate (both profiles in their own z,
/// the wheel rolled about its taping point), sampled every options.strip_width and refined by a
/// parabola through the lowest sample and its neighbours.
struct WheelRailTouch {
  bool found = false;  ///< false where the profiles do not overlap laterally
  double gap = 0.0;    ///< minimum vertical gap [m]: how far the wheel moves down (+z)
                       ///< from the profiles' common datum to touch its rail
  /// Where the wheel of a wheelset rests [m]: `gap`, unless a minimum of the gap on a flank so
  /// steep that the roll hardly lifts the wheel off it (for a 0.46 m wheel on standard gauge:
  /// from about 0.9 rad, fully from 1.16 rad, fading again from 1.26 rad to none at atan(D/r) =
  /// 1.273 rad) lies within an elastic approach (50 um) of the touch; then smaller (the minima
  /// sharing the load as equal Hertzian springs, the wheel sinks less than into one), so that the
  /// wheelset's roll (solve_wheelset puts each wheel at this depth) moves continuously as the
  /// flank's minimum overtakes the tread's. first_touch, without a wheelset: `gap`.
  double resting_gap = 0.0;
  double y_rail = 0.0;          ///< touch point on the rail profile, + towards the gauge side [m]
  double y_wheel = 0.0;         ///< touch point on the wheel profile, + towards the flange [m]
  double contact_angle = 0.0;   ///< as WheelRailPatch::contact_angle [rad]
  double rolling_radius = 0.0;  ///< wheel radius at the touch point [m]
};

/// The first touch of the undeformed surfaces at `pose` (no load); throws InputError on bad input.
WheelRailTouch first_touch(const WheelRailPair& pair, const WheelsetPose& pose,
                           const WheelRailOptions& options = {});

/// The name of a status ("ok", "no contact", ...).
const char* status_name(WheelRailStatus status);

/// Whether a contact of this status has patches carrying the load: ok, load_jump, flange_climb
/// and past_flange (the wheel touches its rail); not no_contact, not_converged, profile_end.
bool carries_load(WheelRailStatus status);

}  // namespace wheelwear::contactgeom
