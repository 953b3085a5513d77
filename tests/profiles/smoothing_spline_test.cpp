// Tests of the Reinsch smoothing spline and of the physical meaning of its length scale.

#include "wheelwear/profiles/smoothing_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {
namespace {

TEST(SmoothingSpline, ZeroLambdaReturnsTheData) {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.35, 0.5};
  Eigen::MatrixXd v(5, 1);
  v << 1.0, 3.0, -2.0, 0.5, 4.0;
  EXPECT_EQ(smooth_values(t, v, 0.0), v);
}

TEST(SmoothingSpline, HugeLambdaGivesTheLeastSquaresLine) {
  // As lambda grows the penalty forces f'' = 0: the fit tends to the least-squares straight line.
  std::vector<double> t;
  Eigen::MatrixXd v(50, 1);
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 0.3);
  for (int i = 0; i < 50; ++i) {
    t.push_back(0.02 * i + 0.001 * (i % 3));
    v(i, 0) = 2.0 - 1.5 * t.back() + noise(random);
  }
  double st = 0, sv = 0, stt = 0, stv = 0;
  for (int i = 0; i < 50; ++i) {
    st += t[i];
    sv += v(i, 0);
    stt += t[i] * t[i];
    stv += t[i] * v(i, 0);
  }
  const double slope = (50 * stv - st * sv) / (50 * stt - st * st);
  const double intercept = (sv - slope * st) / 50;
  const Eigen::MatrixXd f = smooth_values(t, v, 1e8);
  // lambda = 1e8 leaves a curvature of order 1/lambda: the fit is the line to about 1e-6.
  for (int i = 0; i < 50; ++i) EXPECT_NEAR(f(i, 0), intercept + slope * t[i], 1e-6);
}

TEST(SmoothingSpline, LengthScaleHalvesTheWavelengthTwoPiL) {
  // smoothing_lambda documents the filter 1 / (1 + (2 pi L / w)^4): a sine of wavelength
  // w = 2 pi L keeps half its amplitude, one of 10 w keeps 1 / (1 + 1e-4).
  const double L = 0.3e-3, h = L / 10.0;
  for (const auto& [w, gain] : {std::pair{2 * std::numbers::pi * L, 0.5},
                                std::pair{20 * std::numbers::pi * L, 1.0 / (1.0 + 1e-4)}}) {
    std::vector<double> t;
    const int n = static_cast<int>(40 * w / h);
    Eigen::MatrixXd v(n, 1);
    for (int i = 0; i < n; ++i) {
      t.push_back(h * i);
      v(i, 0) = std::sin(2 * std::numbers::pi * t.back() / w);
    }
    const Eigen::MatrixXd f = smooth_values(t, v, smoothing_lambda(L, h));
    // Amplitude in the middle, away from the natural end conditions: projection on the sine.
    double num = 0.0, den = 0.0;
    for (int i = n / 4; i < 3 * n / 4; ++i) {
      num += f(i, 0) * v(i, 0);
      den += v(i, 0) * v(i, 0);
    }
    // The discrete sum approximates the continuous functional to O((h/w)^2) ~ 0.3%.
    EXPECT_NEAR(num / den, gain, 0.01) << "wavelength " << w;
  }
}

TEST(SmoothingSpline, RemovesNoiseAndKeepsTheShape) {
  // A 20 mm wave sampled every 0.2 mm with 10 um noise, smoothed with L = 0.3 mm.
  const double h = 0.2e-3, sigma = 10e-6;
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> t;
  Eigen::MatrixXd v(500, 1), truth(500, 1);
  for (int i = 0; i < 500; ++i) {
    t.push_back(h * i);
    truth(i, 0) = 1e-3 * std::sin(2 * std::numbers::pi * t.back() / 0.02);
    v(i, 0) = truth(i, 0) + noise(random);
  }
  const Eigen::MatrixXd f = smooth_values(t, v, smoothing_lambda(0.3e-3, h));
  double sum = 0.0;
  for (int i = 0; i < 500; ++i) sum += (f(i, 0) - truth(i, 0)) * (f(i, 0) - truth(i, 0));
  const double rms = std::sqrt(sum / 500.0);
  // A window of about 2 pi L / h = 9 points averages the noise down by about 3.
  EXPECT_LT(rms, 0.5 * sigma);
}

TEST(SmoothingSpline, RejectsBadArguments) {
  const std::vector<double> t = {0.0, 0.1, 0.1};
  Eigen::MatrixXd v(3, 1);
  v << 1, 2, 3;
  EXPECT_THROW(smooth_values(t, v, 1.0), InputError);
  EXPECT_THROW(smoothing_lambda(-1.0, 1.0), InputError);
  EXPECT_THROW(smoothing_lambda(1.0, 0.0), InputError);
  const std::vector<double> ok = {0.0, 0.1, 0.2};
  EXPECT_THROW(smooth_values(ok, v, std::nan("")), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
