#include "wheelwear/contactgeom/wheelset_table.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

namespace {

constexpr std::size_t kMaxPatches = 8;

// A contact reported as climbing its rail or past its flange.
bool climbs(WheelRailStatus s) {
  return s == WheelRailStatus::flange_climb || s == WheelRailStatus::past_flange;
}

// A wheel that carries its load: normally, in a load jump (the nearer side), or with its
// contact reported as climbing or past the flange (the contact is solved all the same, and the
// status travels with the interpolated contact).
bool answers(WheelRailStatus status) {
  return status == WheelRailStatus::ok || status == WheelRailStatus::load_jump || climbs(status);
}

// The patch with its forces multiplied by `forces` and its sizes (SDEC a and b, and pmax) by
// `sizes`: the Hertzian scaling with the load, sizes by its cube root, serves to store a patch
// per unit load, to scale it back, and to fade in a patch without a partner.
TablePatch rescaled(TablePatch p, double forces, double sizes) {
  p.normal *= forces;
  p.vertical *= forces;
  p.lateral *= forces;
  p.a *= sizes;
  p.b *= sizes;
  p.pmax *= sizes;
  return p;
}

// A wheel's patches per unit of its vertical force. The node's own vertical force is the
// divisor (it misses the load only in a load jump), so the vertical shares sum to 1.
TableWheel tabulate(const WheelRailContact& contact) {
  TableWheel w;
  w.status = contact.status;
  if (!answers(contact.status) || !(contact.vertical_force > 0.0)) return w;
  const double Fz = contact.vertical_force;
  for (const WheelRailPatch& p : contact.patches) {
    const TablePatch solved{
        p.normal_force,  p.vertical_force, p.lateral_force, p.sdec.a, p.sdec.b,  p.sdec.psi, p.pmax,
        p.contact_angle, p.rolling_radius, p.y_wheel,       p.y_rail, p.s_wheel, p.share};
    w.patches.push_back(rescaled(solved, 1.0 / Fz, 1.0 / std::cbrt(Fz)));
  }
  return w;
}

TablePatch mix(const TablePatch& p, double wp, const TablePatch& q, double wq) {
  TablePatch m;
  m.normal = wp * p.normal + wq * q.normal;
  m.vertical = wp * p.vertical + wq * q.vertical;
  m.lateral = wp * p.lateral + wq * q.lateral;
  m.a = wp * p.a + wq * q.a;
  m.b = wp * p.b + wq * q.b;
  m.psi = wp * p.psi + wq * q.psi;
  m.pmax = wp * p.pmax + wq * q.pmax;
  m.contact_angle = wp * p.contact_angle + wq * q.contact_angle;
  m.rolling_radius = wp * p.rolling_radius + wq * q.rolling_radius;
  m.y_wheel = wp * p.y_wheel + wq * q.y_wheel;
  m.y_rail = wp * p.y_rail + wq * q.y_rail;
  m.s_wheel = wp * p.s_wheel + wq * q.s_wheel;
  m.share = wp * p.share + wq * q.share;
  return m;
}

// A patch without a partner enters with its weight: its forces scale with it, its sizes (and
// pmax) with the cube root, as a Hertzian patch's do with its load; its place is kept.
TablePatch fade(const TablePatch& p, double weight) {
  return rescaled(p, weight, std::cbrt(weight));
}

// The order-preserving pairing of every patch of `few` with one of `many` that keeps their
// contact points on the rail closest (a bit set over `many`; patches per wheel are few).
unsigned closest_pairing(const std::vector<TablePatch>& few, const std::vector<TablePatch>& many) {
  const unsigned n = static_cast<unsigned>(many.size());
  const int m = static_cast<int>(few.size());
  unsigned best = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (unsigned set = 0; set < (1u << n); ++set) {
    if (std::popcount(set) != m) continue;
    double cost = 0.0;
    std::size_t k = 0;
    for (unsigned j = 0; j < n; ++j)
      if (set & (1u << j)) cost += std::abs(few[k++].y_rail - many[j].y_rail);
    if (cost < best_cost) {
      best_cost = cost;
      best = set;
    }
  }
  return best;
}

// Patches between two nodes, weights wp + wq = 1.
std::vector<TablePatch> blend(const std::vector<TablePatch>& p, double wp,
                              const std::vector<TablePatch>& q, double wq) {
  if (wq == 0.0) return p;
  if (wp == 0.0) return q;
  const bool p_fewer = p.size() <= q.size();
  const std::vector<TablePatch>& few = p_fewer ? p : q;
  const std::vector<TablePatch>& many = p_fewer ? q : p;
  const double w_few = p_fewer ? wp : wq, w_many = p_fewer ? wq : wp;
  const unsigned set = closest_pairing(few, many);
  std::vector<TablePatch> out;
  std::size_t k = 0;
  for (std::size_t j = 0; j < many.size(); ++j) {
    if (set & (1u << j))
      out.push_back(mix(few[k++], w_few, many[j], w_many));
    else
      out.push_back(fade(many[j], w_many));
  }
  return out;
}

// The status the direct solve would report first (solve_on_samples' order of checks).
int precedence(WheelRailStatus s) {
  switch (s) {
    case WheelRailStatus::load_jump:
      return 3;
    case WheelRailStatus::flange_climb:
      return 2;
    case WheelRailStatus::past_flange:
      return 1;
    default:
      return 0;
  }
}

WheelRailStatus worse(WheelRailStatus a, WheelRailStatus b) {
  return precedence(b) > precedence(a) ? b : a;
}

// The wheel's contact at vertical force Fz from its interpolated shares.
WheelRailContact scaled(const std::vector<TablePatch>& patches, WheelRailStatus status, double Fz) {
  WheelRailContact c;
  c.status = status;
  const double root = std::cbrt(Fz);
  for (const TablePatch& share : patches) {
    const TablePatch t = rescaled(share, Fz, root);
    WheelRailPatch& p = c.patches.emplace_back();
    p.normal_force = t.normal;
    p.vertical_force = t.vertical;
    p.lateral_force = t.lateral;
    p.sdec = Sdec{t.a, t.b, t.psi};
    p.pmax = t.pmax;
    p.contact_angle = t.contact_angle;
    p.contact_angle_centre = t.contact_angle;  // not tabulated: O's
    p.plane_angle = t.contact_angle;           // the same
    p.rolling_radius = t.rolling_radius;
    p.y_wheel = t.y_wheel;
    p.y_rail = t.y_rail;
    p.s_wheel = t.s_wheel;
    p.share = t.share;
    c.vertical_force += p.vertical_force;
    c.lateral_force += p.lateral_force;
  }
  return c;
}

// Every load level of one shift. The roll depends on dy alone: it is solved at the first level
// and taken as found at the others.
std::vector<TableNode> solve_shift(const WheelsetOnTrack& track, const WheelRailOptions& options,
                                   double dy, const std::vector<double>& loads, int& solves) {
  std::vector<TableNode> nodes(loads.size());
  WheelsetState state;
  state.dy = dy;
  for (std::size_t j = 0; j < loads.size(); ++j) {
    state.vertical_force_left = state.vertical_force_right = loads[j];
    const WheelsetContact c = solve_wheelset(track, state, options);
    state.known_roll = c.known_roll;
    solves += c.contact_solves + c.touch_evaluations;
    TableNode& n = nodes[j];
    n.roll = c.roll;
    n.centre_height = c.centre_height;
    n.left_dy = c.left_pose.dy;
    n.right_dy = c.right_pose.dy;
    n.left = tabulate(c.left);
    n.right = tabulate(c.right);
    // The pairing of patches between nodes enumerates subsets: a wheel with more patches
    // than kMaxPatches (none of the profiles seen has more than 3) is solved directly.
    n.usable = c.roll_converged && c.known_roll.has_value() && answers(n.left.status) &&
               answers(n.right.status) && n.left.patches.size() <= kMaxPatches &&
               n.right.patches.size() <= kMaxPatches;
  }
  return nodes;
}

double lateral_share(const std::vector<TablePatch>& patches) {
  double sum = 0.0;
  for (const TablePatch& p : patches) sum += p.lateral;
  return sum;
}

double weighted_radius(const std::vector<TablePatch>& patches) {
  double sum = 0.0, weight = 0.0;
  for (const TablePatch& p : patches) {
    sum += p.vertical * p.rolling_radius;
    weight += p.vertical;
  }
  return weight > 0.0 ? sum / weight : 0.0;
}

// Whether one wheel has passed its flange (WheelRailStatus::past_flange) at both ends of an
// interval and halfway, at every load level: a derailed wheelset, whose balance the curving does
// not accept and whose contact the wear does not wear, so the contact there is not refined
// (the time domain, passing through, gets it 0.1 mm apart). Past the flange the contact runs
// over the flange tip and back, whose curvature would otherwise draw a third of a new S1002
// table's nodes.
bool past_flange_throughout(const std::vector<TableNode>& lo, const std::vector<TableNode>& hi,
                            const std::vector<TableNode>& mid) {
  const auto passed = [](const TableNode& n, bool left) {
    return (left ? n.left : n.right).status == WheelRailStatus::past_flange;
  };
  for (bool left : {true, false}) {
    bool all = true;
    for (std::size_t j = 0; j < mid.size() && all; ++j)
      all = passed(lo[j], left) && passed(mid[j], left) && passed(hi[j], left);
    if (all) return true;
  }
  return false;
}

// Whether the contact interpolated halfway between two shifts misses the one solved there, at
// any load level, for either wheel (a change of usability, or of whether a wheel climbs, always
// misses: the boundary is refined to the finest spacing, as the direct solve places it).
bool misses(const std::vector<TableNode>& lo, const std::vector<TableNode>& hi,
            const std::vector<TableNode>& mid, const WheelsetTableOptions& grid) {
  if (past_flange_throughout(lo, hi, mid)) return false;
  for (std::size_t j = 0; j < mid.size(); ++j) {
    if (lo[j].usable != mid[j].usable || hi[j].usable != mid[j].usable) return true;
    if (!mid[j].usable) continue;
    for (bool left : {true, false}) {
      const TableWheel& a = left ? lo[j].left : lo[j].right;
      const TableWheel& b = left ? hi[j].left : hi[j].right;
      const TableWheel& m = left ? mid[j].left : mid[j].right;
      if (climbs(a.status) != climbs(m.status) || climbs(b.status) != climbs(m.status)) return true;
      const std::vector<TablePatch> guess = blend(a.patches, 0.5, b.patches, 0.5);
      if (std::abs(lateral_share(guess) - lateral_share(m.patches)) > grid.lateral_tolerance)
        return true;
      if (std::abs(weighted_radius(guess) - weighted_radius(m.patches)) > grid.radius_tolerance)
        return true;
    }
  }
  return false;
}

bool same_pair(const WheelRailPair& a, const WheelRailPair& b) {
  return a.gauge == b.gauge && a.gauge_depth == b.gauge_depth && a.back_to_back == b.back_to_back &&
         a.wheel_radius == b.wheel_radius && a.flange_back_y == b.flange_back_y &&
         a.youngs_modulus == b.youngs_modulus && a.poisson == b.poisson &&
         a.wheel.knot_points() == b.wheel.knot_points() &&
         a.rail.knot_points() == b.rail.knot_points();
}

// The node at -dy of a wheelset whose wheels and rails are alike: the one at dy with the wheels
// swapped (each wheel's patches and pose are in its own frame) and the roll turned over.
TableNode mirrored(const TableNode& n) {
  TableNode m = n;
  m.roll = -n.roll;
  std::swap(m.left_dy, m.right_dy);
  std::swap(m.left, m.right);
  return m;
}

}  // namespace

bool mirror_symmetric(const WheelsetOnTrack& track) {
  return same_pair(track.left, track.right);
}

void WheelsetTableOptions::validate() const {
  require(std::isfinite(dy_max) && dy_max > 0.0 && dy_max < 0.1, "dy_max", dy_max,
          "the table's shifts must reach beyond 0 and stay below 0.1 m");
  require(std::isfinite(dy_step) && dy_step > 0.0 && dy_step <= dy_max, "dy_step", dy_step,
          "the node spacing must be positive and at most dy_max (m)");
  require(dy_max / dy_step <= 1e5, "dy_step", dy_step,
          "gives more than 2e5 shifts: take it larger");
  require(std::isfinite(dy_step_min) && dy_step_min > 0.0 && dy_step_min <= dy_step, "dy_step_min",
          dy_step_min, "must be positive and at most dy_step (m)");
  require(dy_step / dy_step_min <= 1e4, "dy_step_min", dy_step_min,
          "refines dy_step more than 1e4 times: take it larger");
  require(std::isfinite(lateral_tolerance) && lateral_tolerance > 0.0, "lateral_tolerance",
          lateral_tolerance, "must be positive");
  require(std::isfinite(radius_tolerance) && radius_tolerance > 0.0, "radius_tolerance",
          radius_tolerance, "must be positive (m)");
  require(std::isfinite(load_min) && load_min > 0.0, "load_min", load_min, "must be positive (N)");
  require(std::isfinite(load_max) && load_max > load_min, "load_max", load_max,
          "must be larger than load_min (N)");
  require(std::isfinite(load_ratio) && load_ratio > 1.0 && load_ratio <= 4.0, "load_ratio",
          load_ratio, "must lie in (1, 4]");
  require(std::log(load_max / load_min) / std::log(load_ratio) <= 64.0, "load_ratio", load_ratio,
          "gives more than 64 load levels between load_min and load_max: take it larger");
}

WheelsetContactTable::WheelsetContactTable(const WheelsetOnTrack& track,
                                           const WheelRailOptions& options,
                                           const WheelsetTableOptions& grid)
    : grid_(grid) {
  grid.validate();
  options.validate();
  // Geometric levels from load_min to load_max, at most load_ratio apart.
  const auto intervals = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil(
             std::log(grid.load_max / grid.load_min) / std::log(grid.load_ratio) - 1e-9)));
  for (std::size_t j = 0; j <= intervals; ++j)
    loads_.push_back(grid.load_min *
                     std::pow(grid.load_max / grid.load_min,
                              static_cast<double>(j) / static_cast<double>(intervals)));

  // Solves a batch of shifts in parallel; the table does not depend on the number of threads.
  std::map<double, std::vector<TableNode>> solved;
  auto solve_all = [&](const std::vector<double>& dys) {
    std::vector<std::vector<TableNode>> nodes(dys.size());
    std::vector<int> solves(dys.size(), 0);
    tbb::parallel_for(std::size_t{0}, dys.size(), [&](std::size_t k) {
      nodes[k] = solve_shift(track, options, dys[k], loads_, solves[k]);
    });
    for (std::size_t k = 0; k < dys.size(); ++k) {
      contact_solves_ += solves[k];
      solved.emplace(dys[k], std::move(nodes[k]));
    }
  };

  // A wheelset whose wheels and rails are alike is tabulated over dy >= 0 and mirrored: half
  // the solves, and the table then mirrors exactly (the direct solves do to rounding).
  const bool mirror = mirror_symmetric(track);
  auto initial = std::max<long long>(1, std::llround(2.0 * grid.dy_max / grid.dy_step));
  if (mirror) initial += initial % 2;  // a node at dy = 0
  std::vector<double> dys;
  for (long long k = mirror ? initial / 2 : 0; k <= initial; ++k)
    dys.push_back(-grid.dy_max +
                  2.0 * grid.dy_max * static_cast<double>(k) / static_cast<double>(initial));
  if (mirror) dys.front() = 0.0;
  solve_all(dys);
  // Every initial interval has its midpoint checked; an interval whose midpoint misses has both
  // halves checked in the next pass.
  std::vector<std::pair<double, double>> pending;
  auto answers_somewhere = [&](double dy) {
    const std::vector<TableNode>& levels = solved.at(dy);
    return std::any_of(levels.begin(), levels.end(), [](const TableNode& n) { return n.usable; });
  };
  for (std::size_t k = 0; k + 1 < dys.size(); ++k)
    if (answers_somewhere(dys[k]) || answers_somewhere(dys[k + 1]))
      pending.emplace_back(dys[k], dys[k + 1]);
  while (!pending.empty()) {
    std::erase_if(pending, [&](const auto& iv) {
      return 0.5 * (iv.second - iv.first) < grid.dy_step_min * (1.0 - 1e-9);
    });
    std::vector<double> mids;
    for (const auto& [lo, hi] : pending) mids.push_back(0.5 * (lo + hi));
    solve_all(mids);
    std::vector<std::pair<double, double>> next;
    for (const auto& [lo, hi] : pending) {
      const double mid = 0.5 * (lo + hi);
      if (!misses(solved.at(lo), solved.at(hi), solved.at(mid), grid)) continue;
      next.emplace_back(lo, mid);
      next.emplace_back(mid, hi);
    }
    pending = std::move(next);
  }
  if (mirror) {
    for (auto it = solved.rbegin(); it != solved.rend(); ++it) {
      if (it->first == 0.0) continue;
      shifts_.push_back(-it->first);
      std::vector<TableNode> levels;
      for (const TableNode& n : it->second) levels.push_back(mirrored(n));
      nodes_.push_back(std::move(levels));
    }
  }
  for (auto& [dy, nodes] : solved) {
    shifts_.push_back(dy);
    nodes_.push_back(std::move(nodes));
  }
}

std::size_t WheelsetContactTable::unusable_nodes() const {
  std::size_t count = 0;
  for (const std::vector<TableNode>& levels : nodes_)
    count += static_cast<std::size_t>(
        std::count_if(levels.begin(), levels.end(), [](const TableNode& n) { return !n.usable; }));
  return count;
}

std::optional<WheelsetContact> WheelsetContactTable::contact(const WheelsetState& state) const {
  if (state.lateral_force_left || state.lateral_force_right) return std::nullopt;
  if (!std::isfinite(state.dy) || !std::isfinite(state.yaw)) return std::nullopt;
  if (!(state.dy >= shifts_.front()) || !(state.dy <= shifts_.back())) return std::nullopt;
  const auto above = std::upper_bound(shifts_.begin(), shifts_.end(), state.dy);
  const std::size_t i =
      std::min(static_cast<std::size_t>(above - shifts_.begin()), shifts_.size() - 1) - 1;
  const double t = std::clamp((state.dy - shifts_[i]) / (shifts_[i + 1] - shifts_[i]), 0.0, 1.0);

  // Where a load falls between levels: linear in log(Fz), the end levels' shares beyond.
  struct Level {
    std::size_t j = 0;
    double s = 0.0;
  };
  auto level = [&](double Fz) {
    const auto heavier = std::upper_bound(loads_.begin(), loads_.end(), Fz);
    Level l;
    l.j = std::clamp<std::size_t>(static_cast<std::size_t>(heavier - loads_.begin()), 1,
                                  loads_.size() - 1) -
          1;
    l.s =
        std::clamp(std::log(Fz / loads_[l.j]) / std::log(loads_[l.j + 1] / loads_[l.j]), 0.0, 1.0);
    return l;
  };
  const double Fz_left = state.vertical_force_left, Fz_right = state.vertical_force_right;
  if (!(Fz_left > 0.0) || !(Fz_right > 0.0) || !std::isfinite(Fz_left) || !std::isfinite(Fz_right))
    return std::nullopt;
  const Level left = level(Fz_left), right = level(Fz_right);

  // The four nodes around each wheel must answer (a node of zero weight need not), and agree
  // on whether the wheel climbs: where they do not, the cell holds the onset of the climb,
  // which the direct solve places (the interpolation would report the whole cell climbing).
  for (const bool is_left : {true, false}) {
    const Level& l = is_left ? left : right;
    int climbing = 0, weighted = 0;
    for (std::size_t di = 0; di < 2; ++di) {
      if ((di == 0 ? 1.0 - t : t) == 0.0) continue;
      for (std::size_t dj = 0; dj < 2; ++dj) {
        if ((dj == 0 ? 1.0 - l.s : l.s) == 0.0) continue;
        const TableNode& n = node(i + di, l.j + dj);
        if (!n.usable) return std::nullopt;
        ++weighted;
        climbing += climbs(is_left ? n.left.status : n.right.status) ? 1 : 0;
      }
    }
    if (climbing != 0 && climbing != weighted) return std::nullopt;
  }

  auto wheel_at = [&](std::size_t shift, const Level& l, bool is_left) {
    const TableWheel& lo = is_left ? node(shift, l.j).left : node(shift, l.j).right;
    const TableWheel& hi = is_left ? node(shift, l.j + 1).left : node(shift, l.j + 1).right;
    return std::make_pair(blend(lo.patches, 1.0 - l.s, hi.patches, l.s),
                          worse(l.s < 1.0 ? lo.status : WheelRailStatus::ok,
                                l.s > 0.0 ? hi.status : WheelRailStatus::ok));
  };
  auto wheel = [&](const Level& l, bool is_left, double Fz) {
    const auto [p0, s0] = wheel_at(i, l, is_left);
    const auto [p1, s1] = wheel_at(i + 1, l, is_left);
    const WheelRailStatus status =
        worse(t < 1.0 ? s0 : WheelRailStatus::ok, t > 0.0 ? s1 : WheelRailStatus::ok);
    return scaled(blend(p0, 1.0 - t, p1, t), status, Fz);
  };

  const TableNode& a = node(i, 0);
  const TableNode& b = node(i + 1, 0);
  auto along = [t](double x0, double x1) { return (1.0 - t) * x0 + t * x1; };
  WheelsetContact out;
  out.roll = along(a.roll, b.roll);
  out.centre_height = along(a.centre_height, b.centre_height);
  out.roll_converged = true;
  out.left_pose = WheelsetPose{along(a.left_dy, b.left_dy), out.roll, state.yaw};
  out.right_pose = WheelsetPose{along(a.right_dy, b.right_dy), -out.roll, -state.yaw};
  out.left = wheel(left, true, Fz_left);
  out.right = wheel(right, false, Fz_right);
  return out;
}

}  // namespace wheelwear::contactgeom
