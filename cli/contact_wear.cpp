#include "contact_wear.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "creep_request.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/exact_fields.hpp"

namespace wheelwear::cli {

wear::WearLaw wear_law_named(const std::string& law, const std::string& table) {
  std::optional<wear::WearLaw> out;
  if (!table.empty()) {
    // A user's own table of the law's kind: T gamma regimes, or an Archard wear map.
    if (law == "usfd") out = wear::TgammaLaw::load_csv(table);
    if (law == "archard") out = wear::ArchardLaw::load_csv(table);
  } else {
    out = wear::default_wear_law(law);
  }
  if (!out) throw InputError("--law " + law + ": unknown wear law; use usfd or archard");
  return *out;
}

tangential::ContactModel contact_model_named(const std::string& model) {
  const auto chosen = tangential::parse_contact_model(model);
  if (!chosen)
    throw InputError("--model " + model + ": unknown contact model; use " +
                     core::list_names(tangential::kContactModelNames));
  return *chosen;
}

void check_wear_grid(double speed, int cells) {
  require(speed > 0.0 && std::isfinite(speed), "--V", speed,
          "the rolling speed must be positive (m/s)");
  require(cells >= 2 && cells <= 1000, "--cells", cells,
          "FASTSIM cells per direction must lie in 2 ... 1000");
}

void check_exact_patch_options(const ExactPatchOptions& options) {
  if (options.grid < kMinExactGrid || options.grid > kMaxExactGrid) {
    throw InputError("--exact-grid " + std::to_string(options.grid) + ": needs " +
                     std::to_string(kMinExactGrid) + " ... " + std::to_string(kMaxExactGrid) +
                     " elements per side");
  }
  if (!(options.margin >= 1.0 && options.margin <= 5.0)) {
    throw InputError("--exact-margin " + std::to_string(options.margin) +
                     ": the grid must cover the patch, 1 ... 5 times its extent");
  }
}

namespace {

// The exact solution of the patch's description: at its whole load, not yet weighted by its
// share.
tangential::WheelRailExactSolution exact_description(const ContactInputs& in,
                                                     const contactgeom::WheelRailPair& pair,
                                                     const contactgeom::WheelRailPatch& patch,
                                                     const tangential::Creepages& creepages,
                                                     const ExactPatchOptions& options) {
  tangential::WheelRailExactOptions exact;
  exact.nx = exact.ny = options.grid;
  exact.margin = options.margin;
  exact.radius_variation = options.radius_variation;
  contactgeom::WheelRailPatch whole = patch;
  whole.normal_force = contactgeom::description_load(patch);
  return tangential::wheel_rail_exact(pair, in.pose, whole, creepages, in.mu, exact);
}

// The worn depth of `out.solution`'s cells on 0.1 mm bins of the wheel's arc length reaching
// `reach` [m] either side of O, and its summary; then, for a patch of a blend, the forces and
// work of its description weighted by its share (the wear is weighted as it is placed).
void place_on_wheel(const ContactInputs& in, const contactgeom::WheelRailPatch& p,
                    const wear::WearLaw& law, double reach, ModelWear& out) {
  const double ds = 0.1e-3;
  const auto bins = static_cast<std::size_t>(2.0 * reach / ds) + 1;
  out.distribution = wear::WearDistribution::zeros(p.s_wheel - reach, ds, bins);
  wear::accumulate_wear(*out.solution.fields, in.motion.speed, law, {p.s_wheel, p.rolling_radius},
                        p.share, out.distribution);
  out.summary = wear::summarise(out.distribution);
  if (p.share == 1.0) return;
  out.solution.forces = tangential::weighted(out.solution.forces, p.share);
  out.solution.frictional_work *= p.share;
  for (double& w : out.solution.fields->work) w *= p.share;
}

}  // namespace

tangential::WheelRailExactSolution exact_patch(const ContactInputs& in,
                                               const contactgeom::WheelRailPair& pair,
                                               const contactgeom::WheelRailPatch& patch,
                                               const tangential::Creepages& creepages,
                                               const ExactPatchOptions& options) {
  tangential::WheelRailExactSolution s = exact_description(in, pair, patch, creepages, options);
  s.rolling.normal_force *= patch.share;
  s.rolling.forces = tangential::weighted(s.rolling.forces, patch.share);
  return s;
}

ModelWear exact_wear(const ContactInputs& in, const contactgeom::WheelRailPair& pair,
                     const contactgeom::WheelRailPatch& p, const wear::WearLaw& law,
                     const ExactPatchOptions& options) {
  const tangential::Creepages creepages = in.creepages_at(pair, p);
  const tangential::WheelRailExactSolution e = exact_description(in, pair, p, creepages, options);
  if (e.rolling.status != tangential::ExactStatus::converged) {
    throw std::runtime_error(std::string("--exact: Kalker's exact theory on the patch at y = ") +
                             std::to_string(-p.y_wheel * 1e3) +
                             " mm on the wheel: " + tangential::status_name(e.rolling.status) +
                             ", " + e.rolling.message + " (a finer --exact-grid may converge)");
  }
  ModelWear out{"exact", tangential::exact_tangential_solution(e.rolling, creepages), {}, {}};
  // Its grid, margin times the patch about the patch's middle, and 2 mm beyond.
  const double reach = options.margin * (p.measures.W1 + p.measures.W2) + 2e-3;
  place_on_wheel(in, p, law, reach, out);
  return out;
}

ModelWear model_wear(const ContactInputs& in, const contactgeom::WheelRailPair& pair,
                     const contactgeom::WheelRailPatch& p, tangential::ContactModel model,
                     const wear::WearLaw& law, int cells, bool positions) {
  std::optional<contactgeom::Sdec> hertz;
  if (p.hertz) hertz = contactgeom::Sdec{p.hertz->a, p.hertz->b, 0.0};
  const tangential::ModelPatch mp = tangential::model_patch(model, p.sdec, hertz);
  tangential::SolveOptions options;
  options.fastsim.nx = options.fastsim.ny = cells;
  options.fastsim.cell_fields = true;
  // The T gamma map needs the cells' positions; the wear alone needs work, slip and pressure.
  options.fastsim.field_set =
      positions ? tangential::CellFieldSet::all : tangential::CellFieldSet::wear;
  // A patch of a blend: its description's problem, weighted by its share.
  ModelWear out{
      std::string(tangential::model_name(model)),
      tangential::solve_patch(mp.method, mp.region, in.creepages_at(pair, p),
                              {contactgeom::description_load(p), in.mu}, in.material(), options),
      {},
      {}};
  // A grid on the wheel wide enough for every model's region around O.
  place_on_wheel(in, p, law, 2.0 * std::max(p.sdec.b, hertz ? hertz->b : 0.0) + 2e-3, out);
  return out;
}

}  // namespace wheelwear::cli
