// The bracketed root finder of the contact solvers.

#include "bracketed_root.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace wheelwear::contactgeom::detail {
namespace {

// Smooth functions with closed-form roots, bracketed on both sides.
struct SmoothCase {
  std::string name;
  std::function<double(double)> f;
  double lo, hi, root;
};

TEST(BracketedRoot, ConvergesSuperlinearlyOnSmoothFunctions) {
  const std::vector<SmoothCase> cases = {
      {"x^1.5 - 2", [](double x) { return std::pow(x, 1.5) - 2.0; }, 0.5, 4.0, std::cbrt(4.0)},
      {"x^3 - 2", [](double x) { return x * x * x - 2.0; }, 0.0, 3.0, std::cbrt(2.0)},
      {"exp(x) - 2", [](double x) { return std::exp(x) - 2.0; }, -1.0, 5.0, std::numbers::ln2},
      {"2 - exp(x) (falling)", [](double x) { return 2.0 - std::exp(x); }, -1.0, 5.0,
       std::numbers::ln2},
      {"1/x - 3", [](double x) { return 1.0 / x - 3.0; }, 0.05, 2.0, 1.0 / 3.0},
  };
  int compared = 0;
  for (const SmoothCase& c : cases) {
    int calls = 0;
    auto f = [&](double x) {
      ++calls;
      return c.f(x);
    };
    const RootResult r = find_root_bracketed(f, c.lo, c.f(c.lo), c.hi, c.f(c.hi), 1e-14, 0.0, 100);
    EXPECT_TRUE(r.converged) << c.name;
    // |f| <= 1e-14 with |f'| >= 0.3 at these roots: x within 4e-14; 1e-13 leaves room.
    EXPECT_NEAR(r.x, c.root, 1e-13) << c.name;
    EXPECT_EQ(r.fx, c.f(r.x)) << c.name;
    EXPECT_EQ(r.evaluations, calls) << c.name;
    // Anderson-Bjorck converges superlinearly (7 to 11 calls here); bisection needs ~50 for
    // 1e-14 on these brackets, and plain regula falsi, which keeps one end, converges linearly.
    EXPECT_LE(r.evaluations, 14) << c.name;
    // The final bracket holds the root, with f's values at its ends.
    EXPECT_EQ(r.f_lo, c.f(r.lo)) << c.name;
    EXPECT_EQ(r.f_hi, c.f(r.hi)) << c.name;
    EXPECT_LE(std::fmin(r.lo, r.hi), c.root) << c.name;
    EXPECT_GE(std::fmax(r.lo, r.hi), c.root) << c.name;
    ++compared;
  }
  EXPECT_EQ(compared, 5);
}

// A jump from -3 to +0.3 at x = 1, sloped on both sides. On its way from [0, 3] the regula
// falsi keeps the end below the jump and scales its stored value down to ~1e-12, which would
// make that side look the nearer one: the result must carry f's true values instead.
TEST(BracketedRoot, StopsAtAJumpWithTheTrueResidualsAtBothEnds) {
  auto step = [](double x) { return x < 1.0 ? -3.0 + 0.2 * (x - 1.0) : 0.3 + 0.5 * (x - 1.0); };
  const double x_tol = 1e-12;
  const RootResult r = find_root_bracketed(step, 0.0, step(0.0), 3.0, step(3.0), 1e-12, x_tol, 200);
  EXPECT_FALSE(r.converged);
  EXPECT_LT(r.evaluations, 200);  // stopped by the bracket's width, not the budget
  // The bracket straddles the jump and has collapsed onto it.
  EXPECT_LT(r.lo, 1.0);
  EXPECT_GE(r.hi, 1.0);
  EXPECT_LE(r.hi - r.lo, x_tol);
  // True values, bit for bit, which are -3 and 0.3 to within the slope times x_tol.
  EXPECT_EQ(r.f_lo, step(r.lo));
  EXPECT_EQ(r.f_hi, step(r.hi));
  EXPECT_NEAR(r.f_lo, -3.0, 1e-11);
  EXPECT_NEAR(r.f_hi, 0.3, 1e-11);
  // The answer is the side nearer zero.
  EXPECT_EQ(r.x, r.hi);
  EXPECT_EQ(r.fx, r.f_hi);
}

TEST(BracketedRoot, HonoursTheEvaluationBudget) {
  int calls = 0;
  auto f = [&calls](double x) {
    ++calls;
    return std::atan(x - 0.3);
  };
  const RootResult r = find_root_bracketed(f, -100.0, f(-100.0), 100.0, f(100.0), 1e-15, 0.0, 5);
  EXPECT_EQ(r.evaluations, 5);
  EXPECT_EQ(calls, 2 + 5);  // the two bracket values are the caller's
  EXPECT_FALSE(r.converged);
  // Still a bracket of the root 0.3 with true values, and x the best point seen.
  EXPECT_EQ(r.f_lo, std::atan(r.lo - 0.3));
  EXPECT_EQ(r.f_hi, std::atan(r.hi - 0.3));
  EXPECT_LT(r.f_lo * r.f_hi, 0.0);
  EXPECT_LE(std::abs(r.fx), std::fmin(std::abs(r.f_lo), std::abs(r.f_hi)));
}

TEST(BracketedRoot, AcceptsAnEndPointThatIsAlreadyARoot) {
  auto f = [](double x) { return x - 1.0; };
  const RootResult r = find_root_bracketed(f, 1.0, 0.0, 2.0, 1.0, 1e-12, 1e-12, 10);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.x, 1.0);
  EXPECT_EQ(r.evaluations, 0);
}

// An acceptance interval that is not symmetric about zero, as the load iterations use: the
// answer is a point inside it even where a point outside has the smaller |f|.
TEST(BracketedRoot, StopsOnTheGivenAcceptanceTest) {
  auto f = [](double x) { return x * x * x - 1.0; };
  auto accept = [](double v) { return v >= -1e-9 && v <= 1e-3; };
  int compared = 0;
  for (double hi : {1.5, 2.0, 3.0}) {
    const RootResult r = find_root_bracketed_until(f, 0.0, f(0.0), hi, f(hi), accept, 0.0, 50);
    EXPECT_TRUE(r.converged) << hi;
    EXPECT_TRUE(accept(r.fx)) << hi;
    EXPECT_EQ(r.fx, f(r.x)) << hi;
    EXPECT_GT(r.evaluations, 0) << hi;
    ++compared;
  }
  EXPECT_EQ(compared, 3);
  // lo misses the test by 1e-9 with the smaller |f|; hi meets it: hi, without an evaluation.
  auto g = [](double x) { return x - 1.0; };
  const double lo = 1.0 - 2e-9, hi = 1.0005;
  const RootResult at_end = find_root_bracketed_until(g, lo, g(lo), hi, g(hi), accept, 0.0, 50);
  EXPECT_TRUE(at_end.converged);
  EXPECT_EQ(at_end.evaluations, 0);
  EXPECT_EQ(at_end.x, hi);
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
