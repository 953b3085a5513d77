// A route: its sections' checks, the track at any distance, and its pieces for wear steps.

#include "wheelwear/vehicle/route.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "route_checks.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/vehicle/free_wheelset.hpp"

namespace wheelwear::vehicle {

namespace {

constexpr double kMinRadius_m = 100.0;  // |R| below: not a main line's curve
constexpr double kMaxCant_m = 0.2;      // about EN 13803's largest cant
using detail::kMaxSpeed_m_s;
constexpr double kMaxTraction_N = 5e5;       // twice a 25 t axle's weight: beyond any adhesion
constexpr std::size_t kMaxPieces = 1000000;  // route_pieces: a longer list is a wrong unit
// Where two sections join, their radii agree to 1e-9 relative and their cants to 1e-9 m: room
// for the rounding of values computed elsewhere, far below any track tolerance.
constexpr double kJoinRelative = 1e-9;
constexpr double kJoinCant_m = 1e-9;

using detail::in_quotes;
using detail::number_text;
using detail::section_label;

// The curvature and cant where a section starts or ends.
struct Ends {
  double curvature_1_m = 0.0;
  double cant_m = 0.0;
};

Ends end_of(const RouteSection& section) {
  if (section.kind == SectionKind::tangent) return {};
  return {section.curvature(), section.cant_m};
}

// A transition starts where the section before it ends; other sections start at their own
// values. The first section cannot be a transition (validate refuses it; here it would start on
// tangent track).
Ends start_of(const Route& route, std::size_t i) {
  const RouteSection& section = route.sections[i];
  if (section.kind != SectionKind::transition) return end_of(section);
  if (i == 0) return {};
  return end_of(route.sections[i - 1]);
}

// The cant with the side of its raised rail: negative where the right rail is the outer one
// (left-hand curves), so a reverse curve's cants of one height still differ.
double sided_cant(const Ends& ends) {
  return ends.curvature_1_m < 0.0 ? -ends.cant_m : ends.cant_m;
}

double radius_of(double curvature) {
  return curvature == 0.0 ? 0.0 : 1.0 / curvature;
}

std::string radius_text(double curvature) {
  return curvature == 0.0 ? std::string("0 (tangent)") : number_text(radius_of(curvature)) + " m";
}

bool radii_agree(double r1, double r2) {
  return std::abs(r1 - r2) <= kJoinRelative * std::max(std::abs(r1), std::abs(r2));
}

// The rules of Route::validate; `label(i)` says where section i is ("route \"x\": section 3
// (\"R500\")", or with the file and line). Returns the warnings.
}  // namespace

namespace detail {

std::string number_text(double v) {
  return core::format_number(v);
}

std::string in_quotes(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  out += text;
  out += '"';
  return out;
}

std::vector<std::string> check_route(const Route& route,
                                     const std::function<std::string(std::size_t)>& label) {
  if (route.sections.empty()) {
    throw InputError("route " + in_quotes(route.name) +
                     ": no sections; give at least one [[section]] with kind and length_m");
  }
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < route.sections.size(); ++i) {
    const RouteSection& s = route.sections[i];
    const auto fail = [&](std::string_view key, double value, const std::string& rule) {
      throw InputError(label(i) + ": " + std::string(key) + " = " + number_text(value) + ": " +
                       rule);
    };
    const std::string kind(section_kind_name(s.kind));
    if (!(std::isfinite(s.length_m) && s.length_m > 0.0))
      fail("length_m", s.length_m, "the section's length must be a finite number > 0 (m)");
    if (!(std::isfinite(s.speed_m_s) && s.speed_m_s > 0.0 && s.speed_m_s <= kMaxSpeed_m_s))
      fail("speed_m_s", s.speed_m_s,
           "the running speed must lie in (0, 100] m/s; give speed_m_s in the section or in "
           "[route]");
    if (!(std::isfinite(s.friction_top) && s.friction_top > 0.0 && s.friction_top <= 1.0))
      fail("friction", s.friction_top, "the rail top's coefficient of friction must lie in (0, 1]");
    if (!(std::isfinite(s.friction_flange) && s.friction_flange > 0.0 && s.friction_flange <= 1.0))
      fail("friction_flange", s.friction_flange,
           "the gauge face's coefficient of friction must lie in (0, 1] (lubricated about 0.1)");
    if (!(std::isfinite(s.traction_N) && std::abs(s.traction_N) <= kMaxTraction_N))
      fail("traction_N", s.traction_N,
           "the longitudinal force per powered axle must lie in [-5e5, 5e5] N (+ traction, - "
           "braking)");
    if (!std::isfinite(s.radius_m)) fail("radius_m", s.radius_m, "must be a finite number (m)");
    if (!(std::isfinite(s.cant_m) && s.cant_m >= 0.0 && s.cant_m <= kMaxCant_m))
      fail("cant_m", s.cant_m, "the outer rail's height above the inner must lie in [0, 0.2] m");
    switch (s.kind) {
      case SectionKind::tangent:
        if (s.radius_m != 0.0)
          fail("radius_m", s.radius_m,
               "tangent track has radius 0; give kind = \"curve\" for a curve");
        if (s.cant_m != 0.0)
          fail("cant_m", s.cant_m,
               "tangent track has no cant; give cant_m = 0, or kind = \"curve\" or \"transition\"");
        break;
      case SectionKind::curve:
        if (std::abs(s.radius_m) < kMinRadius_m)
          fail("radius_m", s.radius_m,
               "a curve's |R| must be at least 100 m (> 0 right-hand, < 0 left-hand); give "
               "kind = \"tangent\" for straight track");
        break;
      case SectionKind::transition:
        if (s.radius_m != 0.0 && std::abs(s.radius_m) < kMinRadius_m)
          fail("radius_m", s.radius_m,
               "a transition's end radius must be 0 (tangent) or at least 100 m in magnitude");
        if (s.radius_m == 0.0 && s.cant_m != 0.0)
          fail("cant_m", s.cant_m,
               "a transition that ends on tangent track (radius_m = 0) ends with cant_m = 0");
        if (i == 0)
          throw InputError(label(i) +
                           ": kind = \"transition\" starts where the section before it ends, and "
                           "this is the first section; begin with a tangent or a curve");
        break;
    }
    const Ends start = start_of(route, i);
    const Ends end = end_of(s);
    if (s.kind == SectionKind::transition && start.curvature_1_m * end.curvature_1_m < 0.0) {
      throw InputError(label(i) + ": radius_m = " + number_text(s.radius_m) +
                       ": a transition keeps the curve's hand (it starts at radius " +
                       radius_text(start.curvature_1_m) +
                       "); a reverse curve takes two transitions, one to radius_m = 0 and one "
                       "from it");
    }
    if (i > 0 && s.kind != SectionKind::transition) {
      const RouteSection& before = route.sections[i - 1];
      const Ends joint = end_of(before);
      const std::string before_label =
          "section " + std::to_string(i) +
          (before.name.empty() ? "" : " (" + in_quotes(before.name) + ")");
      if (before.kind == SectionKind::transition &&
          (!radii_agree(radius_of(joint.curvature_1_m), radius_of(start.curvature_1_m)) ||
           std::abs(joint.cant_m - start.cant_m) > kJoinCant_m)) {
        throw InputError(label(i) + ": kind = " + in_quotes(kind) + " starts at radius " +
                         radius_text(start.curvature_1_m) + ", cant " + number_text(start.cant_m) +
                         " m, but the transition before it (" + before_label + ") ends at radius " +
                         radius_text(joint.curvature_1_m) + ", cant " + number_text(joint.cant_m) +
                         " m; a transition joins the sections on both sides: give it radius_m = " +
                         number_text(s.kind == SectionKind::tangent ? 0.0 : s.radius_m) +
                         " and cant_m = " + number_text(start.cant_m));
      }
      if (std::abs(sided_cant(joint) - sided_cant(start)) > kJoinCant_m) {
        const bool other_rail = sided_cant(joint) * sided_cant(start) < 0.0;
        throw InputError(label(i) + ": cant_m = " + number_text(start.cant_m) +
                         ": the cant jumps from " + number_text(joint.cant_m) +
                         " m at the end of " + before_label +
                         (other_rail ? " (on the other rail: the curve's hand changes)" : "") +
                         "; join the two with kind = \"transition\" sections (a cant ramps "
                         "linearly, through 0 where the hand changes)");
      }
    }
    // The cant deficiency is linear in s along a transition (curvature and cant both are, at
    // one speed), so its largest value lies at an end.
    const double deficiency =
        std::max(cant_deficiency(s.speed_m_s, start.curvature_1_m, start.cant_m),
                 cant_deficiency(s.speed_m_s, end.curvature_1_m, end.cant_m));
    if (deficiency > kCantDeficiencyWarning_m) {
      warnings.push_back(label(i) + ": cant deficiency " + number_text(deficiency) +
                         " m at speed_m_s = " + number_text(s.speed_m_s) +
                         " exceeds 0.3 m, about the largest EN 13803 admits (tilting trains); "
                         "lower the speed or raise the cant");
    }
  }
  return warnings;
}

std::string section_label(const RouteSection& section, std::size_t i) {
  return "section " + std::to_string(i + 1) +
         (section.name.empty() ? "" : " (" + in_quotes(section.name) + ")");
}

}  // namespace detail

std::string_view section_kind_name(SectionKind kind) {
  switch (kind) {
    case SectionKind::tangent:
      return "tangent";
    case SectionKind::transition:
      return "transition";
    case SectionKind::curve:
      return "curve";
  }
  return "?";
}

double RouteSection::curvature() const {
  return radius_m == 0.0 ? 0.0 : 1.0 / radius_m;
}

double cant_deficiency(double speed_m_s, double curvature_1_m, double cant_m, double cant_base_m) {
  return cant_base_m * speed_m_s * speed_m_s * std::abs(curvature_1_m) / kGravity - cant_m;
}

double Route::total_length() const {
  double total = 0.0;
  for (const RouteSection& s : sections) total += s.length_m;
  return total;
}

std::vector<double> Route::section_starts() const {
  std::vector<double> starts;
  starts.reserve(sections.size());
  double s = 0.0;
  for (const RouteSection& section : sections) {
    starts.push_back(s);
    s += section.length_m;
  }
  return starts;
}

std::vector<std::string> Route::validate() const {
  return detail::check_route(*this, [this](std::size_t i) {
    return "route " + in_quotes(name) + ": " + section_label(sections[i], i);
  });
}

TrackPoint track_at(const Route& route, double s_m) {
  route.validate();
  const double total = route.total_length();
  if (!(std::isfinite(s_m) && s_m >= 0.0 && s_m <= total)) {
    throw InputError("track_at: s = " + number_text(s_m) + " m lies outside route " +
                     in_quotes(route.name) + ", which runs from 0 to " + number_text(total) + " m");
  }
  const std::vector<double> starts = route.section_starts();
  // The last section that starts at or before s: boundaries belong to the section after them.
  const auto after = std::upper_bound(starts.begin(), starts.end(), s_m);
  const auto i = static_cast<std::size_t>(after - starts.begin()) - 1;
  const RouteSection& section = route.sections[i];
  const double end_of_section = i + 1 < starts.size() ? starts[i + 1] : total;

  TrackPoint p;
  p.section = i;
  p.offset_m = s_m - starts[i];
  p.speed_m_s = section.speed_m_s;
  p.friction_top = section.friction_top;
  p.friction_flange = section.friction_flange;
  p.traction_N = section.traction_N;
  switch (section.kind) {
    case SectionKind::tangent:
      break;
    case SectionKind::curve:
      p.curvature_1_m = section.curvature();
      p.radius_m = section.radius_m;
      p.cant_m = section.cant_m;
      break;
    case SectionKind::transition: {
      // Clothoid with a linear cant ramp: curvature and cant linear in distance.
      const Ends a = start_of(route, i);
      const Ends b = end_of(section);
      const double t = std::clamp(p.offset_m / (end_of_section - starts[i]), 0.0, 1.0);
      p.curvature_1_m = a.curvature_1_m + t * (b.curvature_1_m - a.curvature_1_m);
      p.cant_m = a.cant_m + t * (b.cant_m - a.cant_m);
      p.radius_m = radius_of(p.curvature_1_m);
      break;
    }
  }
  p.cant_deficiency_m = cant_deficiency(p.speed_m_s, p.curvature_1_m, p.cant_m);
  return p;
}

Route mirrored(const Route& route) {
  Route mirror = route;
  for (RouteSection& s : mirror.sections)
    if (s.radius_m != 0.0) s.radius_m = -s.radius_m;
  return mirror;
}

Route reversed(const Route& route) {
  route.validate();
  if (!route.sections.empty() && route.sections.back().kind == SectionKind::transition) {
    throw InputError("route " + in_quotes(route.name) + ": " +
                     section_label(route.sections.back(), route.sections.size() - 1) +
                     ": the route ends with a transition, which would start it run backwards; "
                     "end it with a tangent or a curve");
  }
  Route back;
  back.name = route.name;
  for (std::size_t i = route.sections.size(); i-- > 0;) {
    RouteSection s = route.sections[i];
    if (s.kind == SectionKind::transition) {
      // Backwards a transition ends where it started: at the section before it (validate
      // ensures there is one).
      const RouteSection& before = route.sections[i - 1];
      const bool tangent = before.kind == SectionKind::tangent;
      s.radius_m = tangent ? 0.0 : before.radius_m;
      s.cant_m = tangent ? 0.0 : before.cant_m;
    }
    if (s.radius_m != 0.0) s.radius_m = -s.radius_m;
    back.sections.push_back(std::move(s));
  }
  return back;
}

std::vector<RoutePiece> route_pieces(const Route& route, double max_piece_length_m) {
  route.validate();
  if (!(std::isfinite(max_piece_length_m) && max_piece_length_m > 0.0)) {
    throw InputError("route_pieces: max_piece_length_m = " + number_text(max_piece_length_m) +
                     ": the longest time-domain piece must be a finite length > 0 (m)");
  }
  const std::vector<double> starts = route.section_starts();
  const double total = route.total_length();
  const std::size_t n = route.sections.size();
  const auto end_of_section = [&](std::size_t i) { return i + 1 < n ? starts[i + 1] : total; };

  // The fewest equal pieces no longer than the maximum: ceil(L / max), one less when that is
  // enough after rounding.
  std::vector<std::size_t> counts(n, 1);
  double count = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (route.sections[i].kind == SectionKind::curve) {
      count += 1.0;
      continue;
    }
    const double length = end_of_section(i) - starts[i];
    const double ratio = length / max_piece_length_m;
    if (!(ratio <= static_cast<double>(kMaxPieces))) {
      count = std::numeric_limits<double>::infinity();
      break;
    }
    std::size_t pieces = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(ratio)));
    if (pieces > 1 && length / static_cast<double>(pieces - 1) <= max_piece_length_m) --pieces;
    counts[i] = pieces;
    count += static_cast<double>(pieces);
  }
  if (!(count <= static_cast<double>(kMaxPieces))) {
    throw InputError("route_pieces: max_piece_length_m = " + number_text(max_piece_length_m) +
                     " cuts route " + in_quotes(route.name) + " (" + number_text(total) +
                     " m) into more than 1e6 pieces; give a longer max_piece_length_m");
  }

  std::vector<RoutePiece> pieces;
  pieces.reserve(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < n; ++i) {
    const double a = starts[i];
    const double b = end_of_section(i);
    const PieceKind kind = route.sections[i].kind == SectionKind::curve ? PieceKind::constant_curve
                                                                        : PieceKind::time_domain;
    const std::size_t m = counts[i];
    for (std::size_t k = 0; k < m; ++k) {
      const double from = a + (b - a) * static_cast<double>(k) / static_cast<double>(m);
      const double to =
          k + 1 == m ? b : a + (b - a) * static_cast<double>(k + 1) / static_cast<double>(m);
      pieces.push_back({kind, i, from, to - from, (to - from) / total});
    }
  }
  return pieces;
}

}  // namespace wheelwear::vehicle
