#pragma once
/// Track irregularities for the time-domain simulation: the ERRI B176 spectra of lateral
/// alignment and cross-level, a generator of random tracks with those spectra that gives the
/// same samples for the same seed on every platform, and a reader of measured irregularities.
/// Manual page: docs/track_irregularities.md.
///
/// Conventions (docs/architecture.md, "Frames and sign conventions"): s [m] is the distance
/// along the track in the running direction (the track frame's x).
/// - Alignment [m]: lateral position of the track centre line (the mean of the two rails'
///   lateral positions) against the design line, + to the left (the track frame's +y).
/// - Cross-level [m]: height of the left rail above the right one, measured over the distance
///   2b = 1.5 m between the rail centres (the base of the cant, EN 13803), + when the left rail
///   is higher. In a right-hand curve (R > 0, left rail outer) it adds to the cant.
///
/// Spectra are one-sided power spectral densities in the spatial angular frequency
/// Omega = 2 pi / wavelength [rad/m]: the variance of an irregularity is the integral of its
/// spectrum over 0 < Omega < infinity. (A density per cycle/m is 2 pi times as large.)

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::vehicle {

/// The ORE/ERRI B176 track spectra, low or high level, as one-sided densities in Omega [rad/m]
/// (the ERRI B176 committee's spectra for vehicle simulation; the high level agrees to the five
/// printed digits with the "ORE B176 high level" table in the manual of the GENSYS program
/// TRC_IPSD, which lists the lateral and vertical densities per cycle/m, 2 pi times these):
///   S_a(Omega)   = A_a Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2)) [m^2/(rad/m)]
///   S_phi(Omega) = (A_v / b^2) Omega_c^2 Omega^2
///                  / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2)(Omega^2 + Omega_s^2))
///                  [rad^2/(rad/m)]
/// S_phi is the density of the cross-level angle phi = (z_left - z_right) / 2b [rad]; the
/// cross-level height over 2b is 2b phi, S_c = (2b)^2 S_phi [m^2/(rad/m)], which at short
/// wavelengths tends to 4 S_v, the difference of two independent rails whose mean has the
/// vertical spectrum S_v = A_v Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2)).
struct ErriSpectrum {
  double A_a = 2.119e-7;            ///< alignment roughness [m rad] (low level; high 6.125e-7)
  double A_v = 4.032e-7;            ///< vertical roughness [m rad] (low level; high 1.080e-6)
  double omega_c = 0.8246;          ///< Omega_c [rad/m]
  double omega_r = 0.0206;          ///< Omega_r [rad/m]
  double omega_s = 0.438;           ///< Omega_s [rad/m]
  double half_rail_spacing = 0.75;  ///< b: half the distance between the rail centres [m]

  static ErriSpectrum low();   ///< A_a = 2.119e-7, A_v = 4.032e-7 m rad
  static ErriSpectrum high();  ///< A_a = 6.125e-7, A_v = 1.080e-6 m rad

  /// S_a at `omega` [rad/m], >= 0: one-sided density of the alignment [m^2/(rad/m)].
  double alignment(double omega) const;
  /// S_phi at `omega` [rad/m], >= 0: one-sided density of the cross-level angle [rad^2/(rad/m)].
  double cross_level_angle(double omega) const;
  /// S_c = (2b)^2 S_phi at `omega` [rad/m]: one-sided density of the cross-level height
  /// [m^2/(rad/m)].
  double cross_level(double omega) const;

  /// Variance of the alignment between the angular frequencies omega_lo < omega_hi [rad/m]
  /// [m^2]: the integral of S_a, in closed form (partial fractions, arctangents).
  double alignment_variance(double omega_lo, double omega_hi) const;
  /// Variance of the cross-level height between omega_lo < omega_hi [rad/m] [m^2]: the
  /// integral of S_c, in closed form.
  double cross_level_variance(double omega_lo, double omega_hi) const;

  void validate() const;  ///< throws InputError naming the bad field
};

/// What to generate: the spectra, the band of wavelengths they are cut to, the number of
/// cosines and the fade-in.
struct IrregularitySpec {
  ErriSpectrum spectrum = ErriSpectrum::low();
  /// Band of wavelengths [m]: EN 13848-1's wavebands D1 to D3 (3-25, 25-70, 70-150 m)
  /// together. Outside the band the generated track has no irregularity.
  double shortest_wavelength = 3.0;
  double longest_wavelength = 150.0;
  /// N: cosines per irregularity, one in each of N equal intervals of Omega across the band.
  int components = 1000;
  /// Run-in distance [m] over which the irregularities fade in from zero, so that a
  /// simulation starting from its quasi-static state on ideal track is not kicked: the
  /// samples are multiplied by w(s/run_in), w(t) = t^3 (10 - 15 t + 6 t^2) (w, w' and w'' are
  /// 0 at s = 0; w = 1, w' = w'' = 0 at s = run_in). 0: no fade-in.
  double run_in = 0.0;

  void validate() const;  ///< throws InputError naming the bad field
};

/// Irregularities sampled along the track, generated or measured. Between the samples they
/// are linear in s.
struct TrackIrregularities {
  std::vector<double> distance;     ///< s [m], strictly increasing
  std::vector<double> alignment;    ///< [m], + left (one per distance)
  std::vector<double> cross_level;  ///< [m], + left rail above the right (one per distance)
  std::string source;               ///< the file, or the spectrum and seed it was generated from

  /// Alignment at `s` [m], linear between the samples. Throws InputError if `s` lies outside
  /// distance.front() ... distance.back().
  double alignment_at(double s) const;
  /// Cross-level at `s` [m], linear between the samples; throws as alignment_at.
  double cross_level_at(double s) const;
};

/// `record` seen by a vehicle running backwards along a route of `route_length` [m]: the
/// distance s becomes route_length - s (samples in increasing order again), and alignment and
/// cross-level change sign (the physical left rail is on the right in travel).
TrackIrregularities reversed(const TrackIrregularities& record, double route_length);

/// SplitMix64 (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number generators";
/// Vigna's reference splitmix64.c): a 64-bit state advanced by 0x9e3779b97f4a7c15 and mixed by
/// two xorshift-multiplies. Integer arithmetic only, so the stream is the same everywhere.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();  ///< the next 64-bit output
  /// The next output's top 53 bits times 2^-53: uniform on [0, 1), exact in a double.
  double next_uniform();

 private:
  std::uint64_t state_;
};

/// The seed of section `section_index` of a track whose irregularities are drawn from
/// `base_seed`: mix(mix(base_seed) + (section_index + 1) 0x9e3779b97f4a7c15), mix being
/// SplitMix64's output function. For one base seed distinct sections get distinct seeds (the
/// map is a bijection of the index), and their records are independent.
std::uint64_t seed_for_section(std::uint64_t base_seed, std::uint64_t section_index);

/// Generates alignment and cross-level with the spectra of `spec` over 0 <= s <= `length_m`
/// [m], sampled every `sample_distance_m` [m] (samples at s = i sample_distance_m for
/// i = 0 ... ceil(length_m / sample_distance_m)), each as a sum of N cosines
///   x(s) = w(s) sum_k sqrt(2 S(Omega_k) dOmega) cos(Omega_k s + phi_k),
/// dOmega = (Omega_max - Omega_min) / N, Omega_k uniform in the k-th interval and phi_k uniform
/// in [0, 2 pi), both drawn from SplitMix64(seed): the spectral representation of Shinozuka &
/// Jan 1972, with each frequency drawn within its interval so that the record does not repeat
/// every 2 pi / dOmega. The draws, in this order: for the alignment, k = 0 ... N-1, the frequency's
/// place in its interval and the phase; then the same for the cross-level. The samples are
/// the same, bit for bit, on every platform, build and thread count: the phases are 64-bit
/// fixed-point fractions of a turn, the cosine is the project's own polynomial, and every sum
/// uses only correctly rounded operations in a fixed order, with fused multiply-adds switched
/// off (docs/track_irregularities.md, "Seeds and reproducibility"). Throws InputError for a bad
/// spec, a length or sample distance that is not positive and finite, fewer than 4 samples per
/// shortest wavelength or more than 1e8 samples.
TrackIrregularities generate_irregularities(const IrregularitySpec& spec, double length_m,
                                            double sample_distance_m, std::uint64_t seed);

/// Reads measured irregularities from a text file (docs/track_irregularities.md): a header
/// naming the columns distance_m, alignment_m and cross_level_m (any order, other columns
/// ignored), then one row of numbers per line, fields separated by commas, tabs or blanks;
/// '#' starts a comment. Values in metres with this header's signs; distance strictly
/// increasing; at least two rows. Throws InputError naming the file, the line and the fix.
TrackIrregularities read_irregularities(const std::filesystem::path& path);

/// As read_irregularities, from `text`; `source` names it in messages.
TrackIrregularities parse_irregularities(std::string_view text, std::string_view source);

/// Writes `record` in the format read_irregularities reads, every number in the shortest form
/// that reads back to the same double. Throws InputError if the file cannot be written.
void write_irregularities(const TrackIrregularities& record, const std::filesystem::path& path);

}  // namespace wheelwear::vehicle
