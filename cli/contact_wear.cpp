#include "contact_wear.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"

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
      model,
      tangential::solve_patch(mp.method, mp.region, in.creepages_at(pair, p),
                              {contactgeom::description_load(p), in.mu}, in.material(), options),
      {},
      {}};
  // A grid on the wheel wide enough for every model's region around O, 0.1 mm bins.
  const double reach = 2.0 * std::max(p.sdec.b, hertz ? hertz->b : 0.0) + 2e-3;
  const double ds = 0.1e-3;
  const auto bins = static_cast<std::size_t>(2.0 * reach / ds) + 1;
  out.distribution = wear::WearDistribution::zeros(p.s_wheel - reach, ds, bins);
  wear::accumulate_wear(*out.solution.fields, in.motion.speed, law, {p.s_wheel, p.rolling_radius},
                        p.share, out.distribution);
  out.summary = wear::summarise(out.distribution);
  if (p.share != 1.0) {
    out.solution.forces = tangential::weighted(out.solution.forces, p.share);
    out.solution.frictional_work *= p.share;
    for (double& w : out.solution.fields->work) w *= p.share;
  }
  return out;
}

}  // namespace wheelwear::cli
