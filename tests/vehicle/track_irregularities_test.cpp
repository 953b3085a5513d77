// Track irregularities: the ERRI B176 spectra against the published ORE B176 table and their own
// closed-form integrals; generated records against their spectra (variance and band-averaged
// periodogram, with statistical bounds); bit-for-bit determinism, SplitMix64's published
// outputs and independent sections; the fade-in; bad arguments. The records' interpolation and
// their file format: track_irregularity_files_test.cpp.

#include "wheelwear/vehicle/track_irregularities.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "support/input_errors.hpp"
#include "support/same_bits.hpp"

namespace wheelwear::vehicle {
namespace {

using wheelwear::testing::contains;
using wheelwear::testing::error_of;
using wheelwear::testing::same_bits;

constexpr double kPi = std::numbers::pi;

// The generator's default band as angular frequencies [rad/m].
constexpr double kOmegaMin = 2.0 * kPi / 150.0;
constexpr double kOmegaMax = 2.0 * kPi / 3.0;

// Composite Simpson rule of f over [lo, hi] on a logarithmic grid (Omega = e^u), which follows
// the spectra's decades evenly: an independent check of the closed forms.
double integrate_log(const std::function<double(double)>& f, double lo, double hi, int n = 20000) {
  const double a = std::log(lo), b = std::log(hi), h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double omega = std::exp(a + i * h);
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += weight * f(omega) * omega;
  }
  return sum * h / 3.0;
}

// Wilson & Hilferty's approximation of the quantile of chi^2_nu / nu at standard normal z.
double chi2_ratio_quantile(double nu, double z) {
  const double v = 2.0 / (9.0 * nu);
  return std::pow(1.0 - v + z * std::sqrt(v), 3.0);
}

// In-place radix-2 FFT, X_m = sum_i x_i e^{-2 pi i m i / n}; n a power of two.
void fft(std::vector<std::complex<double>>& x) {
  const std::size_t n = x.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i], x[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double angle = -2.0 * kPi / static_cast<double>(len);
    for (std::size_t i = 0; i < n; i += len)
      for (std::size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> w = std::polar(1.0, angle * static_cast<double>(k));
        const std::complex<double> u = x[i + k], v = x[i + k + len / 2] * w;
        x[i + k] = u + v;
        x[i + k + len / 2] = u - v;
      }
  }
}

// --- spectra ---------------------------------------------------------------------------------

// The GENSYS manual's TRC_IPSD example lists "ORE B176 high level" per cycle/m, i.e. 2 pi S(Omega)
// at Omega = 2 pi f, for lateral (alignment) and vertical irregularities. Our S_a at the high
// level must reproduce the lateral rows; the vertical rows, A_v Omega_c^2 / (...), are S_a scaled
// by A_v / A_a and so check the A_v that the cross-level spectrum uses.
TEST(TrackIrregularitySpectra, HighLevelMatchesThePublishedOreB176Table) {
  const ErriSpectrum high = ErriSpectrum::high();
  struct Row {
    double omega;              // [rad/m]
    double lateral, vertical;  // [m^2/(1/m)]
  };
  // The first row is the 314.16 m wave, Omega = 0.02 rad/m (the table's "0.00318" 1/m rounded).
  const Row rows[] = {{0.02, 4.6657e-3, 8.2268e-3},
                      {2.0 * kPi * 0.02, 2.3194e-4, 4.0897e-4},
                      {2.0 * kPi * 0.1, 6.1608e-6, 1.0863e-5},
                      {2.0 * kPi * 0.2, 7.3333e-7, 1.2931e-6},
                      {2.0 * kPi * 100.0, 1.6790e-17, 2.9605e-17}};
  int compared = 0;
  for (const Row& r : rows) {
    const double lateral = 2.0 * kPi * high.alignment(r.omega);
    const double vertical = lateral * high.A_v / high.A_a;
    // 5e-5: the table prints five significant digits, half a unit of the last is at most 5e-5
    // relative.
    EXPECT_NEAR(lateral / r.lateral, 1.0, 5e-5) << "Omega " << r.omega;
    EXPECT_NEAR(vertical / r.vertical, 1.0, 5e-5) << "Omega " << r.omega;
    compared += 2;
  }
  // The cross-level height is the angle over the rail-centre distance 2b = 1.5 m.
  for (double omega : {0.05, 0.3, 1.5}) {
    EXPECT_NEAR(high.cross_level(omega), 2.25 * high.cross_level_angle(omega),
                1e-15 * high.cross_level(omega));  // two roundings apart
    ++compared;
  }
  EXPECT_EQ(compared, 13);
}

// The closed-form band variances against Simpson's rule, for both levels, both irregularities
// and EN 13848-1's wavebands D1, D2, D3 and all three together.
TEST(TrackIrregularitySpectra, ClosedFormVariancesMatchQuadrature) {
  int compared = 0;
  for (const ErriSpectrum& s : {ErriSpectrum::low(), ErriSpectrum::high()}) {
    for (const auto& [longest, shortest] : {std::pair{25.0, 3.0}, std::pair{70.0, 25.0},
                                            std::pair{150.0, 70.0}, std::pair{150.0, 3.0}}) {
      const double lo = 2.0 * kPi / longest, hi = 2.0 * kPi / shortest;
      const double a = integrate_log([&](double w) { return s.alignment(w); }, lo, hi);
      const double c = integrate_log([&](double w) { return s.cross_level(w); }, lo, hi);
      // 1e-9: Simpson's error with 20000 steps of 2e-4 in ln(Omega) is below 1e-12 relative;
      // the rest is room for the arctangent differences' cancellation.
      EXPECT_NEAR(s.alignment_variance(lo, hi) / a, 1.0, 1e-9) << longest << "-" << shortest;
      EXPECT_NEAR(s.cross_level_variance(lo, hi) / c, 1.0, 1e-9) << longest << "-" << shortest;
      compared += 2;
    }
  }
  EXPECT_EQ(compared, 16);
  // For the record: the standard deviations of the low level in D1 (3-25 m).
  const ErriSpectrum low = ErriSpectrum::low();
  std::printf("ERRI low level, 3-25 m: alignment %.3f mm, cross-level %.3f mm\n",
              1e3 * std::sqrt(low.alignment_variance(2 * kPi / 25, 2 * kPi / 3)),
              1e3 * std::sqrt(low.cross_level_variance(2 * kPi / 25, 2 * kPi / 3)));
}

// --- generator: statistics -------------------------------------------------------------------

// Mean square of a record's values [m^2].
double mean_square(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return sum / static_cast<double>(x.size());
}

// The variance of 20 km records, averaged over 8 seeds, is the integral of the spectrum over the
// band. Bound: for a Gaussian process the mean square over a length L scatters with variance
// (2 pi / L) * integral of S^2 (Bendat & Piersol's variance of a mean-square estimate, with the
// autocorrelation's square written as the spectrum's by Parseval). A sum of cosines with fixed
// amplitudes and random phases scatters less (only the cross terms fluctuate), so 4 such standard
// deviations bound it; a spectrum off by 2 (one- against two-sided) or 2 pi (per cycle against
// per radian) lies far outside. (Here the bound is about 6 times the actual scatter: the
// cosines lie dOmega = 2e-3 rad/m apart, 41 times the record's resolution 2 pi / L, so their
// cross terms nearly average out.)
TEST(TrackIrregularityGenerator, VarianceMatchesTheSpectrumIntegral) {
  const IrregularitySpec spec;  // ERRI low, 3-150 m, 1000 cosines
  const double length = 20000.0, ds = 0.25;
  const int seeds = 8;
  const ErriSpectrum& s = spec.spectrum;
  const double expected[2] = {s.alignment_variance(kOmegaMin, kOmegaMax),
                              s.cross_level_variance(kOmegaMin, kOmegaMax)};
  const std::function<double(double)> square[2] = {
      [&](double w) { return s.alignment(w) * s.alignment(w); },
      [&](double w) { return s.cross_level(w) * s.cross_level(w); }};
  double sigma[2];
  for (int c = 0; c < 2; ++c)
    sigma[c] = std::sqrt(2.0 * kPi / length * integrate_log(square[c], kOmegaMin, kOmegaMax));
  double mean[2] = {0.0, 0.0};
  int compared = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const TrackIrregularities r = generate_irregularities(spec, length, ds, seed);
    const double ms[2] = {mean_square(r.alignment), mean_square(r.cross_level)};
    for (int c = 0; c < 2; ++c) {
      // One record: within 4 of its own standard deviations.
      EXPECT_NEAR(ms[c], expected[c], 4.0 * sigma[c]) << "channel " << c << " seed " << seed;
      mean[c] += ms[c] / seeds;
      ++compared;
    }
  }
  for (int c = 0; c < 2; ++c) {
    const double bound = 4.0 * sigma[c] / std::sqrt(seeds);  // the mean of 8 records
    EXPECT_NEAR(mean[c], expected[c], bound) << "channel " << c;
    std::printf("%s: variance %.5e m^2, spectrum %.5e m^2 (%+.2f %%, bound %.2f %%)\n",
                c == 0 ? "alignment" : "cross-level", mean[c], expected[c],
                100.0 * (mean[c] / expected[c] - 1.0), 100.0 * bound / expected[c]);
    ++compared;
  }
  EXPECT_EQ(compared, 18);
}

// The Hann-windowed periodogram of 2^16 samples (16.4 km at 0.25 m), averaged over the Fourier
// frequencies of four bands and over 4 seeds, against the spectrum averaged over the same
// frequencies, for both levels and both irregularities. Bound: for a Gaussian process the average
// is S times chi^2_nu / nu, with nu = 4 * 2 K / 1.944 for K frequencies of nearly equal S (the
// Hann window correlates neighbouring ordinates: 1 + 2 (4/9 + 1/36) = 1.944), reduced by
// Satterthwaite's (sum S)^2 / sum S^2 / K where S varies across the band. The bounds are that
// ratio's 4-sigma quantiles (Wilson & Hilferty); a random-phase sum scatters less.
TEST(TrackIrregularityGenerator, PeriodogramMatchesTheSpectrumInBands) {
  const std::size_t n = std::size_t{1} << 16;
  const double ds = 0.25, length = static_cast<double>(n) * ds;
  const int seeds = 4;
  struct Band {
    double longest, shortest;  // [m]
  };
  const Band bands[] = {{100.0, 60.0}, {40.0, 25.0}, {12.0, 8.0}, {5.0, 3.5}};
  int compared = 0;
  for (const bool high : {false, true}) {
    IrregularitySpec spec;
    spec.spectrum = high ? ErriSpectrum::high() : ErriSpectrum::low();
    // periodogram[c][m], summed over the seeds
    std::vector<double> periodogram[2] = {std::vector<double>(n / 2, 0.0),
                                          std::vector<double>(n / 2, 0.0)};
    double window_power = 0.0;  // sum of w^2
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / n);
      window_power += w * w;
    }
    for (int seed = 1; seed <= seeds; ++seed) {
      // Other seeds for each level: the levels' spectra differ only by a factor.
      const std::uint64_t s = (high ? 200u : 100u) + static_cast<std::uint64_t>(seed);
      const TrackIrregularities r = generate_irregularities(spec, length - ds, ds, s);
      ASSERT_EQ(r.alignment.size(), n);
      for (int c = 0; c < 2; ++c) {
        const std::vector<double>& x = c == 0 ? r.alignment : r.cross_level;
        std::vector<std::complex<double>> X(n);
        for (std::size_t i = 0; i < n; ++i)
          X[i] = x[i] * (0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / n));
        fft(X);
        // One-sided density per rad/m: ds |X_m|^2 / (pi sum w^2), whose sum over the bins
        // times 2 pi / L is the variance.
        for (std::size_t m = 1; m < n / 2; ++m)
          periodogram[c][m] += ds * std::norm(X[m]) / (kPi * window_power) / seeds;
      }
    }
    for (int c = 0; c < 2; ++c) {
      for (const Band& b : bands) {
        double estimate = 0.0, spectrum = 0.0, spectrum2 = 0.0;
        int bins = 0;
        for (std::size_t m = 1; m < n / 2; ++m) {
          const double omega = 2.0 * kPi * static_cast<double>(m) / length;
          if (omega < 2.0 * kPi / b.longest || omega > 2.0 * kPi / b.shortest) continue;
          const double S =
              c == 0 ? spec.spectrum.alignment(omega) : spec.spectrum.cross_level(omega);
          estimate += periodogram[c][m];
          spectrum += S;
          spectrum2 += S * S;
          ++bins;
        }
        const double nu = seeds * 2.0 / 1.944 * spectrum * spectrum / spectrum2;
        const double ratio = estimate / spectrum;
        EXPECT_GT(ratio, chi2_ratio_quantile(nu, -4.0)) << high << c << " " << b.longest;
        EXPECT_LT(ratio, chi2_ratio_quantile(nu, 4.0)) << high << c << " " << b.longest;
        std::printf("%s %s %5.1f-%4.1f m: %4d bins, estimate / spectrum %.4f (bounds %.3f %.3f)\n",
                    high ? "high" : "low ", c == 0 ? "alignment  " : "cross-level", b.longest,
                    b.shortest, bins, ratio, chi2_ratio_quantile(nu, -4.0),
                    chi2_ratio_quantile(nu, 4.0));
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 16);
}

// --- generator: determinism ------------------------------------------------------------------

// SplitMix64's published first outputs: seed 1234567 (Rosetta Code's task "Pseudo-random
// numbers/Splitmix64") and seed 0 (Vigna's splitmix64.c, as the Rust rand_xoshiro tests use).
TEST(TrackIrregularityGenerator, SplitMix64MatchesItsPublishedOutputs) {
  SplitMix64 a(1234567);
  const std::uint64_t expected_a[] = {6457827717110365317ULL, 3203168211198807973ULL,
                                      9817491932198370423ULL, 4593380528125082431ULL,
                                      16408922859458223821ULL};
  for (std::uint64_t v : expected_a) EXPECT_EQ(a.next(), v);
  SplitMix64 b(0);
  for (std::uint64_t v : {0xe220a8397b1dcdafULL, 0x6e789e6aa1b965f4ULL, 0x06c45d188009454fULL})
    EXPECT_EQ(b.next(), v);
  // The uniform double is the output's top 53 bits times 2^-53, exactly.
  SplitMix64 c(1234567);
  EXPECT_EQ(c.next_uniform(), static_cast<double>(6457827717110365317ULL >> 11) * 0x1p-53);
  // 5 + 3 + 1 = 9 comparisons.
}

// Same seed: the same samples, bit for bit, and a longer record begins with the shorter one.
// The hard-coded samples were generated with GCC 12 on x86-64, and the same bits came from
// -march=native (fused multiply-add available), -O0 and Clang 14: a platform or compiler that
// disagrees breaks the reproducibility the manual promises.
TEST(TrackIrregularityGenerator, SameSeedGivesTheSameSamplesBitForBit) {
  const IrregularitySpec spec;
  const TrackIrregularities a = generate_irregularities(spec, 1000.0, 0.25, 42);
  const TrackIrregularities b = generate_irregularities(spec, 1000.0, 0.25, 42);
  EXPECT_TRUE(same_bits(a.distance, b.distance));
  EXPECT_TRUE(same_bits(a.alignment, b.alignment));
  EXPECT_TRUE(same_bits(a.cross_level, b.cross_level));
  EXPECT_EQ(a.source, b.source);
  const TrackIrregularities longer = generate_irregularities(spec, 2000.0, 0.25, 42);
  ASSERT_EQ(a.alignment.size(), 4001u);
  ASSERT_EQ(longer.alignment.size(), 8001u);
  EXPECT_EQ(std::memcmp(a.alignment.data(), longer.alignment.data(), 4001 * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a.cross_level.data(), longer.cross_level.data(), 4001 * sizeof(double)), 0);
  // Golden samples (hexadecimal floating point, exact).
  EXPECT_EQ(a.alignment[0], -0x1.66f676ebd0089p-11);
  EXPECT_EQ(a.alignment[100], -0x1.969cd3301d713p-10);
  EXPECT_EQ(a.alignment[4000], -0x1.347eb65d2d76fp-10);
  EXPECT_EQ(a.cross_level[0], -0x1.e392481474fb5p-10);
  EXPECT_EQ(a.cross_level[1234], 0x1.234a964d5a337p-8);
  EXPECT_EQ(a.cross_level[4000], -0x1.98a4c1eaeec4p-10);
  // And a whole record: the FNV-1a hash of the bytes of 2 x 100001 samples (ERRI high level,
  // 20 km at 0.2 m, 50 m run-in, seed 7).
  IrregularitySpec high;
  high.spectrum = ErriSpectrum::high();
  high.run_in = 50.0;
  const TrackIrregularities r = generate_irregularities(high, 20000.0, 0.2, 7);
  std::uint64_t hash = 14695981039346656037ULL;
  for (const std::vector<double>* v : {&r.alignment, &r.cross_level})
    for (double x : *v) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      for (int byte = 0; byte < 8; ++byte) {
        hash ^= (bits >> (8 * byte)) & 0xff;
        hash *= 1099511628211ULL;
      }
    }
  EXPECT_EQ(hash, 0xb72541814668acf4ULL);
  // 4 + 2 + 6 + 1 = 13 comparisons.
}

// Different seeds, and different sections of one seed, give different, uncorrelated records.
// Bound on the correlation coefficient of two independent records: its standard deviation is
// sqrt((pi / L) * integral of S^2) / sigma^2 (as the variance's above, halved), 4 of them.
TEST(TrackIrregularityGenerator, DifferentSeedsAndSectionsDiffer) {
  // Sections: distinct seeds for 10000 sections of one base, none equal to a base seed or to a
  // section of the next base.
  std::set<std::uint64_t> seeds;
  for (std::uint64_t i = 0; i < 10000; ++i) seeds.insert(seed_for_section(42, i));
  EXPECT_EQ(seeds.size(), 10000u);
  std::size_t collisions = 0;
  for (std::uint64_t i = 0; i < 10000; ++i) collisions += seeds.count(seed_for_section(43, i));
  collisions += seeds.count(42) + seeds.count(43);
  EXPECT_EQ(collisions, 0u);
  EXPECT_NE(seed_for_section(42, 0), seed_for_section(43, 0));

  const IrregularitySpec spec;
  const double length = 20000.0;
  const ErriSpectrum& s = spec.spectrum;
  const double variance = s.alignment_variance(kOmegaMin, kOmegaMax);
  const double sigma_rho =
      std::sqrt(kPi / length *
                integrate_log([&](double w) { return s.alignment(w) * s.alignment(w); }, kOmegaMin,
                              kOmegaMax)) /
      variance;
  const std::uint64_t pairs[][2] = {
      {1, 2}, {seed_for_section(7, 0), seed_for_section(7, 1)}, {7, seed_for_section(7, 0)}};
  int compared = 3;
  for (const auto& p : pairs) {
    const TrackIrregularities a = generate_irregularities(spec, length, 0.25, p[0]);
    const TrackIrregularities b = generate_irregularities(spec, length, 0.25, p[1]);
    std::size_t differ = 0;
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (std::size_t i = 0; i < a.alignment.size(); ++i) {
      differ += a.alignment[i] != b.alignment[i];
      ab += a.alignment[i] * b.alignment[i];
      aa += a.alignment[i] * a.alignment[i];
      bb += b.alignment[i] * b.alignment[i];
    }
    EXPECT_EQ(differ, a.alignment.size()) << p[0] << " " << p[1];
    const double rho = ab / std::sqrt(aa * bb);
    EXPECT_LT(std::abs(rho), 4.0 * sigma_rho) << p[0] << " " << p[1];
    std::printf("seeds %llu, %llu: correlation %+.4f (bound %.4f)\n",
                static_cast<unsigned long long>(p[0]), static_cast<unsigned long long>(p[1]), rho,
                4.0 * sigma_rho);
    compared += 2;
  }
  EXPECT_EQ(compared, 9);
}

// The fade-in: zero at s = 0, the unfaded record times w(s / run_in) = 6 t^5 - 15 t^4 + 10 t^3
// inside the run-in, and the unfaded record itself, bit for bit, beyond it.
TEST(TrackIrregularityGenerator, FadesInOverTheRunIn) {
  IrregularitySpec faded;
  faded.run_in = 100.0;
  const IrregularitySpec plain;
  const TrackIrregularities f = generate_irregularities(faded, 300.0, 0.25, 5);
  const TrackIrregularities p = generate_irregularities(plain, 300.0, 0.25, 5);
  EXPECT_EQ(f.alignment[0], 0.0);
  EXPECT_EQ(f.cross_level[0], 0.0);
  EXPECT_NE(p.alignment[0], 0.0);  // the plain record does not start at zero
  int inside = 0, beyond = 0;
  for (std::size_t i = 1; i < f.distance.size(); ++i) {
    const double t = f.distance[i] / faded.run_in;
    for (int c = 0; c < 2; ++c) {
      const double x = c == 0 ? f.alignment[i] : f.cross_level[i];
      const double y = c == 0 ? p.alignment[i] : p.cross_level[i];
      if (t < 1.0) {
        const double w = 6 * std::pow(t, 5) - 15 * std::pow(t, 4) + 10 * std::pow(t, 3);
        // 1e-14 of the unfaded value: w is evaluated in two different forms (a few roundings).
        EXPECT_NEAR(x, w * y, 1e-14 * std::abs(y)) << "s " << f.distance[i];
        ++inside;
      } else {
        EXPECT_EQ(x, y) << "s " << f.distance[i];
        ++beyond;
      }
    }
  }
  EXPECT_EQ(inside, 2 * 399);  // s = 0.25 ... 99.75 m
  EXPECT_EQ(beyond, 2 * 801);  // s = 100 ... 300 m
}

TEST(TrackIrregularityGenerator, RejectsBadArguments) {
  const IrregularitySpec good;
  struct Case {
    std::function<void()> call;
    std::string expected;
  };
  const auto with = [&](const std::function<void(IrregularitySpec&)>& change) {
    IrregularitySpec s = good;
    change(s);
    return [s] { generate_irregularities(s, 100.0, 0.25, 1); };
  };
  const Case cases[] = {
      {[&] { generate_irregularities(good, 100.0, 0.8, 1); }, "sample distance = 0.8"},
      {[&] { generate_irregularities(good, 100.0, 0.0, 1); }, "sample distance = 0"},
      {[&] { generate_irregularities(good, 0.0, 0.25, 1); }, "length = 0"},
      {[&] { generate_irregularities(good, std::nan(""), 0.25, 1); }, "length = nan"},
      {[&] { generate_irregularities(good, 1e9, 0.25, 1); }, "more than 1e8 samples"},
      {with([](IrregularitySpec& s) { s.components = 0; }), "components = 0"},
      {with([](IrregularitySpec& s) { s.longest_wavelength = 2.0; }), "longest wavelength = 2"},
      {with([](IrregularitySpec& s) { s.shortest_wavelength = -1.0; }), "shortest wavelength = -1"},
      {with([](IrregularitySpec& s) { s.run_in = -5.0; }), "run-in = -5"},
      {with([](IrregularitySpec& s) { s.spectrum.A_a = -1e-7; }), "A_a = -1e-07"},
      {with([](IrregularitySpec& s) { s.spectrum.omega_c = 0.0; }), "omega_c = 0"},
      {with([](IrregularitySpec& s) { s.spectrum.half_rail_spacing = 7.5; }),
       "half rail spacing = 7.5"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.call);
    EXPECT_TRUE(contains(message, c.expected)) << message;
  }
  // 12 comparisons.
}

// A record seen running backwards: at distance s the original's values at L - s with both signs
// changed (the physical left rail is on the right in travel); twice reversed, the original (the
// distances to the rounding of L - (L - s)).
TEST(TrackIrregularityRecord, ReversedRecordIsTheOriginalFromTheOtherEnd) {
  IrregularitySpec spec;
  spec.spectrum = ErriSpectrum::low();
  const TrackIrregularities record = generate_irregularities(spec, 200.0, 0.25, 7);
  const double length = 300.0;
  const TrackIrregularities back = reversed(record, length);
  ASSERT_EQ(back.distance.size(), record.distance.size());
  int compared = 0;
  for (double s = 110.0; s < 290.0; s += 3.7) {
    EXPECT_NEAR(back.alignment_at(s), -record.alignment_at(length - s), 1e-12) << s;
    EXPECT_NEAR(back.cross_level_at(s), -record.cross_level_at(length - s), 1e-12) << s;
    compared += 2;
  }
  const TrackIrregularities twice = reversed(back, length);
  for (std::size_t i = 0; i < record.distance.size(); ++i) {
    EXPECT_NEAR(twice.distance[i], record.distance[i], 1e-12);
    EXPECT_EQ(twice.alignment[i], record.alignment[i]);
    compared += 2;
  }
  std::printf("compared %d values\n", compared);
}

}  // namespace
}  // namespace wheelwear::vehicle
