#pragma once
/// The line a vehicle runs along in a wear study: a sequence of tangents, constant curves and the
/// transitions between them, each with its cant, running speed, friction and traction; the track
/// at any distance along it; a reader of route files (TOML, docs/routes.md); and the cutting of a
/// route into the pieces a wear step solves (constant curves whole, quasi-statically; tangents
/// and transitions in short pieces, in time).
///
/// Signs follow the track frame (docs/architecture.md, "Frames and sign conventions"): a radius
/// R > 0 is a right-hand curve (its centre on -y, the left rail outer), R < 0 a left-hand one,
/// R = 0 tangent track; the cant C >= 0 raises the outer rail.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::vehicle {

/// What a section of track is.
enum class SectionKind {
  tangent,     ///< straight track: radius 0, cant 0
  transition,  ///< a clothoid from the previous section's end to its own end values
  curve,       ///< a constant radius and cant
};

/// "tangent", "transition" or "curve", as route files write it.
std::string_view section_kind_name(SectionKind kind);

/// One section of a route.
///
/// A transition is a clothoid with a linear cant ramp, the usual form of EN 13803 practice: the
/// curvature 1/R and the cant run linearly in distance from the previous section's end values
/// (radius, cant) to the transition's own `radius_m` and `cant_m`.
struct RouteSection {
  SectionKind kind = SectionKind::tangent;
  double length_m = 0.0;  ///< [m], > 0
  /// [m]; curve: signed, > 0 right-hand (left rail outer), |R| >= 100; tangent: 0; transition:
  /// the radius at its end (0 ends on tangent track), its start is the previous section's end.
  double radius_m = 0.0;
  /// Height of the outer rail above the inner [m], 0 ... 0.2; tangent: 0; transition: at its
  /// end, linear in between.
  double cant_m = 0.0;
  double speed_m_s = 0.0;        ///< running speed [m/s], (0, 100], constant over the section
  double friction_top = 0.3;     ///< coefficient of friction on the rail top (tread) [-], (0, 1]
  double friction_flange = 0.3;  ///< on the gauge face (flange), for lubrication [-], (0, 1]
  /// Longitudinal force per powered axle [N]: > 0 traction, < 0 braking, 0 coasting.
  double traction_N = 0.0;
  std::string name;  ///< free text for messages and results; may be empty

  /// Curvature [1/m]: 1 / radius_m, 0 for radius 0 (a transition's: at its end).
  double curvature() const;
};

/// Cant deficiency [m]: cant_base V^2 |kappa| / g - C, the cant a vehicle at speed V on
/// curvature kappa [1/m] would need beyond the cant C it has (EN 13803's approximation for small
/// cant angles); negative values are a cant excess. cant_base 1.5 m is the rail-centre distance
/// of standard gauge; g = 9.81 m/s^2.
double cant_deficiency(double speed_m_s, double curvature_1_m, double cant_m,
                       double cant_base_m = 1.5);

/// The cant deficiency above which Route::validate() warns [m]: about the largest that
/// EN 13803 admits at all (vehicles approved for high cant deficiency, tilting trains); a
/// conventional vehicle's limits lie lower (docs/routes.md).
inline constexpr double kCantDeficiencyWarning_m = 0.3;

/// A route: its sections in running order, the first starting at distance 0.
struct Route {
  std::string name;
  std::vector<RouteSection> sections;

  /// Sum of the sections' lengths [m].
  double total_length() const;
  /// Distance along the route at which each section starts [m]; #sections entries, the first 0.
  /// Every function of this header takes its section boundaries from here.
  std::vector<double> section_starts() const;
  /// Throws InputError naming the section (1-based number and name), the field, its value and
  /// the fix when a section breaks a rule of docs/routes.md: lengths > 0; radius 0 on tangents,
  /// |R| >= 100 m on curves, 0 or |R| >= 100 m at a transition's end; cant in 0 ... 0.2 m and 0
  /// on tangents; speed in (0, 100] m/s; frictions in (0, 1]; traction within +-5e5 N; every
  /// value finite; a transition follows another section, does not change the curve's hand, and
  /// the section after it starts where it ends; the cant never jumps between sections (nor changes
  /// rail where a curve's hand changes). Returns warnings (not errors): every section whose cant
  /// deficiency somewhere exceeds kCantDeficiencyWarning_m.
  std::vector<std::string> validate() const;
};

/// The track at one point of a route.
struct TrackPoint {
  double curvature_1_m = 0.0;      ///< signed curvature [1/m], > 0 right-hand
  double radius_m = 0.0;           ///< 1 / curvature [m], 0 where the curvature is 0
  double cant_m = 0.0;             ///< outer rail above the inner [m], >= 0
  double speed_m_s = 0.0;          ///< the section's running speed [m/s]
  double friction_top = 0.0;       ///< [-]
  double friction_flange = 0.0;    ///< [-]
  double traction_N = 0.0;         ///< per powered axle [N]
  double cant_deficiency_m = 0.0;  ///< cant_deficiency(speed, curvature, cant) [m]
  std::size_t section = 0;         ///< index into Route::sections (0-based)
  double offset_m = 0.0;           ///< distance from the section's start [m]
};

/// The track at distance `s_m` [m] from the route's start, 0 <= s_m <= total_length(). Sections
/// are half-open, [start, end): a boundary belongs to the section that starts there, the
/// route's end to the last section. In a transition the curvature and cant are linear in s
/// between the previous section's end values and the transition's own. Throws InputError for
/// an invalid route (Route::validate) or an `s_m` outside the route.
TrackPoint track_at(const Route& route, double s_m);

/// Reads a route file (TOML; keys and defaults in docs/routes.md) and validates it. Messages
/// name the file, the line, the section (1-based) and the key.
Route read_route(const std::filesystem::path& path);

/// Parses route text; `origin_name` names it in messages (a file name, "built-in route").
Route parse_route(std::string_view text, std::string_view origin_name);

/// The text of data/routes/default.toml, compiled into the library.
std::string default_route_text();

/// parse_route(default_route_text(), "built-in default route").
Route default_route();

/// The mirror image of `route` (y -> -y of the track frame): every radius changes sign, so
/// right-hand curves become left-hand ones; everything else is kept.
Route mirrored(const Route& route);

/// `route` run backwards: its sections in reverse order, every radius of the opposite sign (a
/// right-hand curve is a left-hand one to a vehicle running the other way; the outer rail keeps
/// its cant), each transition running from its own end values to those of the section before
/// it; lengths, speeds, frictions and traction kept. Throws InputError for an invalid route, or
/// one that ends with a transition (which would start the reversed route).
Route reversed(const Route& route);

/// How a wear step treats a piece of a route.
enum class PieceKind {
  constant_curve,  ///< a whole curve section: solved quasi-statically (steady curving)
  time_domain,     ///< part of a tangent or transition: simulated in time
};

/// A piece of a route for a wear step.
struct RoutePiece {
  PieceKind kind = PieceKind::time_domain;
  std::size_t section = 0;  ///< index into Route::sections
  double start_m = 0.0;     ///< distance along the route where the piece starts [m]
  double length_m = 0.0;    ///< [m], > 0
  double share = 0.0;       ///< length_m / Route::total_length(): its share of the distance
};

/// Cuts `route` into the pieces of a wear step, in running order: every curve section as one
/// constant-curve piece, every tangent and transition section into n = ceil(L / max) pieces of
/// equal length L / n <= `max_piece_length_m` [m]. The pieces cover the route once, without gap
/// or overlap: each starts where the one before ends (start_m + length_m of the one before, up to
/// rounding), and their shares sum to 1 up to rounding. Throws InputError for an invalid route,
/// a `max_piece_length_m` that is not positive and finite, or more than 1e6 pieces.
std::vector<RoutePiece> route_pieces(const Route& route, double max_piece_length_m);

}  // namespace wheelwear::vehicle
