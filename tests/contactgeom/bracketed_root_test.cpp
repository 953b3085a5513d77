// The bracketed root finder of the contact solvers.

#include "bracketed_root.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelwear::contactgeom::detail {
namespace {

TEST(BracketedRoot, ConvergesSuperlinearlyOnSmoothFunctions) {
  int calls = 0;
  auto f = [&calls](double x) {
    ++calls;
    return std::pow(x, 1.5) - 2.0;  // root 2^(2/3)
  };
  const RootResult r = find_root_bracketed(f, 0.5, f(0.5), 4.0, f(4.0), 1e-14, 1e-15, 100);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.x, std::cbrt(4.0), 1e-13);
  EXPECT_LE(r.evaluations, 12);  // Anderson-Bjorck: superlinear; plain regula falsi needs ~40
}

TEST(BracketedRoot, StopsAtAJumpWithoutClaimingConvergence) {
  auto step = [](double x) { return x < 1.0 ? -1.0 : 1.0; };
  const RootResult r = find_root_bracketed(step, 0.0, -1.0, 3.0, 1.0, 1e-12, 1e-12, 200);
  EXPECT_FALSE(r.converged);
  EXPECT_NEAR(r.x, 1.0, 1e-11);  // bisection safeguard closes in on the jump
}

TEST(BracketedRoot, HonoursTheEvaluationBudget) {
  auto f = [](double x) { return std::atan(x - 0.3); };
  const RootResult r = find_root_bracketed(f, -100.0, f(-100.0), 100.0, f(100.0), 1e-15, 0.0, 5);
  EXPECT_EQ(r.evaluations, 5);
  EXPECT_FALSE(r.converged);
}

TEST(BracketedRoot, AcceptsAnEndPointThatIsAlreadyARoot) {
  auto f = [](double x) { return x - 1.0; };
  const RootResult r = find_root_bracketed(f, 1.0, 0.0, 2.0, 1.0, 1e-12, 1e-12, 10);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.x, 1.0);
  EXPECT_EQ(r.evaluations, 0);
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
