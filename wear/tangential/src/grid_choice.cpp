#include "wheelwear/tangential/grid_choice.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

namespace {

struct ModelEntry {
  FastsimMethod method;
  FastsimScheme scheme;
  TractionBound bound;
  GridErrorModel model;
};

// Provenance: studies/runtime_error_study.cpp, part 2 (bench/results/grid_error_constants.csv).
// For every n = 5 ... 200 and n = 250, 300, 400, 500, 600, 800, 1000 it measures
// e(n) = max over the 17 pure-spin cases of CONTACT's set b (tests/data/contact/
// b_pure_spin_mx80.csv, phi > 0) and over Fx, Fy of |F(n) - F(conv)|/(mu N), with F(conv) the
// Richardson extrapolation of n = 1600 and 3200 (itself within 4e-6 mu N for Kalker's scheme
// and 3e-7 for the second-order one). C is the largest e(n) n^order for n >= min_cells, so the
// model bounds every measurement from there to n = 1000.
// * Kalker's scheme converges at first order: e(n) n changes by at most 3 % between n = 200
//   and 1000 (0.299 ... 0.301 for FASTSIM-SDEC), and the envelope is at most 11 % above it.
// * The second-order scheme (after Vollebregt & Wilders' FASTSIM2, 2011) with the parabolic
//   bound of Liu, Fu & Bruni (2022, Eq. 18) is second order with a slow drift: e(n) n^2 grows
//   from 0.65 at n = 20 to 0.98 at n = 1000 (FASTSIM-SDEC), whence C is taken at n = 1000
//   and choose_grid goes no further. Below n = 10 it is not yet second order (e(n) n^2 = 1.45
//   at n = 6), so it starts at 10.
// * With the semi-elliptic bound, whose slope is unbounded at the strip ends, the same scheme
//   reaches order 1.5 (e(n) n^2 grows about 2 times from n = 200 to 1000; e(n) n^1.5 levels
//   off at 0.06); from n = 20 on, e(n) n^1.5 <= C, which the coarsest grids set, so the model
//   is up to 2 times conservative on fine grids.
constexpr double kFirst = 1.0, kSecond = 2.0, kSemiSecond = 1.5;
constexpr auto P = TractionBound::parabolic;
constexpr auto S = TractionBound::semi_elliptic;
constexpr auto K = FastsimScheme::kalker;
constexpr auto T = FastsimScheme::second_order;
constexpr std::array<ModelEntry, 20> kModels = {{
    {FastsimMethod::elliptic, K, P, {kFirst, 0.2989, 5}},
    {FastsimMethod::elliptic, T, P, {kSecond, 0.9681, 10}},
    {FastsimMethod::eqe, K, P, {kFirst, 0.2989, 5}},
    {FastsimMethod::eqe, T, P, {kSecond, 0.9681, 10}},
    {FastsimMethod::eqe_shifted, K, P, {kFirst, 0.3610, 5}},
    {FastsimMethod::eqe_shifted, T, P, {kSecond, 1.164, 10}},
    {FastsimMethod::eql, K, P, {kFirst, 0.3275, 5}},
    {FastsimMethod::eql, T, P, {kSecond, 1.021, 10}},
    {FastsimMethod::sdec, K, P, {kFirst, 0.3169, 5}},
    {FastsimMethod::sdec, T, P, {kSecond, 0.9789, 10}},
    {FastsimMethod::elliptic, K, S, {kFirst, 0.3453, 5}},
    {FastsimMethod::elliptic, T, S, {kSemiSecond, 0.08425, 20}},
    {FastsimMethod::eqe, K, S, {kFirst, 0.3453, 5}},
    {FastsimMethod::eqe, T, S, {kSemiSecond, 0.08425, 20}},
    {FastsimMethod::eqe_shifted, K, S, {kFirst, 0.4010, 5}},
    {FastsimMethod::eqe_shifted, T, S, {kSemiSecond, 0.08018, 20}},
    {FastsimMethod::eql, K, S, {kFirst, 0.3672, 5}},
    {FastsimMethod::eql, T, S, {kSemiSecond, 0.1340, 20}},
    {FastsimMethod::sdec, K, S, {kFirst, 0.3570, 5}},
    {FastsimMethod::sdec, T, S, {kSemiSecond, 0.1200, 20}},
}};

std::string describe(FastsimMethod method, FastsimScheme scheme, TractionBound bound) {
  std::string text(method_name(method));
  text += scheme == FastsimScheme::kalker ? " (Kalker's scheme, " : " (second-order scheme, ";
  text += bound == TractionBound::parabolic ? "parabolic bound)" : "semi-elliptic bound)";
  return text;
}

}  // namespace

GridErrorModel grid_error_model(FastsimMethod method, FastsimScheme scheme, TractionBound bound) {
  for (const ModelEntry& e : kModels)
    if (e.method == method && e.scheme == scheme && e.bound == bound) return e.model;
  throw InputError("grid_error_model: no error model for " + describe(method, scheme, bound));
}

GridChoice choose_grid(FastsimMethod method, FastsimScheme scheme, TractionBound bound,
                       double target_error) {
  require(std::isfinite(target_error) && target_error > 0.0 && target_error < 1.0, "target_error",
          target_error, "the target error (a fraction of mu N) must lie in (0, 1)");
  const GridErrorModel model = grid_error_model(method, scheme, bound);
  const auto error_at = [&](int n) {
    return model.constant / std::pow(static_cast<double>(n), model.order);
  };
  // n = ceil((C/target)^(1/order)), then corrected by one either way for rounding in pow.
  const double exact = std::pow(model.constant / target_error, 1.0 / model.order);
  if (!(exact <= kGridChoiceMaxCells + 1.0) || error_at(kGridChoiceMaxCells) > target_error) {
    std::ostringstream message;
    message << "target_error = " << target_error << ": finer than "
            << describe(method, scheme, bound)
            << " reaches on the largest grid the error model covers (" << kGridChoiceMaxCells
            << " x " << kGridChoiceMaxCells << ", " << error_at(kGridChoiceMaxCells)
            << " of mu N); raise the target";
    if (scheme == FastsimScheme::kalker) message << " or use the second-order scheme";
    throw InputError(message.str());
  }
  int n = std::max(model.min_cells, static_cast<int>(std::ceil(exact)));
  while (n > model.min_cells && error_at(n - 1) <= target_error) --n;
  while (error_at(n) > target_error) ++n;
  return {n, n, error_at(n)};
}

}  // namespace wheelwear::tangential
