#pragma once
/// A contact look-up table of a rigid wheelset on its track, as multibody codes build them: both
/// wheels' contacts solved once on a grid of lateral shifts and wheel loads, then interpolated.
///
/// What is tabulated. The wheelset's geometry depends on its lateral shift dy alone (the roll
/// puts both undeformed wheels on their rails; the yaw enters the creepages, not the patch shape:
/// WheelsetPose), and each wheel's patches on its vertical force Fz. Each node (dy_i, Fz_j) holds
/// the roll, both wheels' poses and their patches from solve_wheelset. Patches are stored per
/// unit of the wheel's vertical force (normal, vertical and lateral forces divided by it) and
/// their sizes (SDEC a and b) per cube root of it, the Hertzian scaling, so that the load
/// dimension interpolates a non-Hertzian patch's change of shape with load rather than its size.
///
/// Interpolation. Linear in dy and in log(Fz) between the four surrounding nodes. Patches of two
/// nodes are paired in order from the field side to the gauge side, choosing the pairing that
/// keeps their contact points on the rail closest; a patch without a partner (a second contact
/// that appears between two nodes) enters with its forces scaled by its weight and its sizes by
/// the cube root of it, so the wheel's forces stay continuous as a contact appears (along dy and
/// along Fz; inside a cell the pairing in dy follows the load-blended contact points, and may
/// change with the load where two patches are equally near). Each node's
/// vertical shares sum to 1, so the interpolated patches carry exactly the requested Fz.
/// Outside the loads tabulated, the end level's shares and shapes are scaled.
///
/// Contacts past the flange or climbing (WheelRailStatus::past_flange, flange_climb) are
/// tabulated with their status, which the interpolated contact carries where all its weighted
/// nodes climb (the one the direct solve would report first of theirs). Where a wheel has
/// passed its flange throughout an interval the table is not refined: the curving accepts no
/// balance there and the wear does not wear such contacts (climbing); the time-domain
/// simulation, which may pass through them, gets their forces interpolated between nodes 0.1 mm
/// apart (half the initial spacing), the lateral force within 1 % of the load on new S1002.
///
/// Where the table does not answer. A shift outside the table, a surrounding node at which a
/// wheel does not carry its load (no contact, the profile's end, a roll or load that did not
/// converge), or a cell whose nodes disagree on whether a wheel climbs (the onset of the climb,
/// refined to the finest spacing along dy) returns nothing: the caller evaluates the contact
/// directly there, with its own statuses.
///
/// The interpolated patches carry the quantities a vehicle model needs (normal, vertical and
/// lateral force, contact angle, rolling radius, SDEC, contact points, pmax); their strips,
/// measures and Hertz ellipse are left empty.

#include <cstddef>
#include <optional>
#include <vector>

#include "wheelwear/contactgeom/wheelset.hpp"

namespace wheelwear::contactgeom {

/// The grid of a table. Shifts start on a uniform grid and are refined by halving where the
/// interpolation misses: an interval's midpoint is solved, and where its interpolated contact
/// differs from the solved one at any load level by more than a tolerance, both halves are
/// refined in turn, as long as the halves are at least dy_step_min wide (12.5 um with the
/// defaults). An interval between two nodes that do not answer is not checked: the table does
/// not answer there, and the caller's direct evaluation does. Nor is one past the flange (above).
struct WheelsetTableOptions {
  double dy_max = 16e-3;       ///< the table covers shifts in [-dy_max, dy_max] [m]
  double dy_step = 0.2e-3;     ///< spacing of the initial shifts [m]
  double dy_step_min = 10e-6;  ///< finest spacing refinement reaches [m]
  /// Largest miss of a wheel's lateral force per unit vertical force (sum of the patches'
  /// lateral_force / Fz) at a midpoint [-].
  double lateral_tolerance = 1e-3;
  /// Largest miss of a wheel's load-weighted rolling radius at a midpoint [m]: 1 um is a
  /// longitudinal creepage of 2e-6 on a 0.46 m wheel.
  double radius_tolerance = 1e-6;
  double load_min = 10e3;    ///< smallest tabulated vertical force of a wheel [N]
  double load_max = 200e3;   ///< largest [N]
  double load_ratio = 1.25;  ///< largest ratio of successive load levels (> 1)
  void validate() const;     ///< throws InputError naming a bad field
};

/// One patch of a node, per unit of its wheel's vertical force.
struct TablePatch {
  double normal = 0.0;    ///< N / Fz [-]
  double vertical = 0.0;  ///< vertical_force / Fz [-]
  double lateral = 0.0;   ///< lateral_force / Fz [-]
  double a = 0.0;         ///< SDEC a / Fz^(1/3) [m N^-1/3]
  double b = 0.0;         ///< SDEC b / Fz^(1/3) [m N^-1/3]
  double psi = 0.0;       ///< SDEC shape number [-]
  double pmax = 0.0;      ///< pmax / Fz^(1/3) [Pa N^-1/3]
  double contact_angle = 0.0;
  double rolling_radius = 0.0;
  double y_wheel = 0.0, y_rail = 0.0, s_wheel = 0.0;
  double share = 1.0;  ///< WheelRailPatch::share: its weight in a blend of descriptions [-]
};

/// One wheel at one node.
struct TableWheel {
  WheelRailStatus status = WheelRailStatus::no_contact;
  std::vector<TablePatch> patches;  ///< from the field side to the gauge side
};

/// One node of the grid.
struct TableNode {
  bool usable = false;  ///< the roll converged and both wheels carry their load
  double roll = 0.0, centre_height = 0.0;
  double left_dy = 0.0, right_dy = 0.0;  ///< the per-wheel poses' dy
  TableWheel left, right;
};

/// Whether the wheelset's two wheels and rails are alike (profiles, radii, track geometry,
/// material), so that its contact at -dy is the one at dy with the wheels swapped.
bool mirror_symmetric(const WheelsetOnTrack& track);

/// Both wheels' contacts of one wheelset, tabulated over dy and Fz. A mirror-symmetric
/// wheelset is solved over dy >= 0 only and mirrored.
class WheelsetContactTable {
 public:
  /// Solves every node (in parallel; the table does not depend on the number of threads).
  /// Throws InputError on bad input.
  WheelsetContactTable(const WheelsetOnTrack& track, const WheelRailOptions& options,
                       const WheelsetTableOptions& grid = {});

  /// The interpolated contact of `state` (its dy and yaw and both vertical forces; a prescribed
  /// lateral force is not tabulated and gives nothing), or nothing where the table does not
  /// answer (see above).
  std::optional<WheelsetContact> contact(const WheelsetState& state) const;

  const WheelsetTableOptions& grid() const { return grid_; }
  const std::vector<double>& shifts() const { return shifts_; }  ///< node shifts, increasing [m]
  const std::vector<double>& loads() const { return loads_; }    ///< load levels, increasing [N]
  std::size_t unusable_nodes() const;                            ///< nodes that do not answer
  int contact_solves() const { return contact_solves_; }         ///< spent building the table

 private:
  const TableNode& node(std::size_t shift, std::size_t level) const { return nodes_[shift][level]; }

  WheelsetTableOptions grid_;
  std::vector<double> shifts_;                 ///< the nodes' dy, increasing [m]
  std::vector<double> loads_;                  ///< the load levels [N], increasing
  std::vector<std::vector<TableNode>> nodes_;  ///< per shift, per load level
  int contact_solves_ = 0;
};

}  // namespace wheelwear::contactgeom
