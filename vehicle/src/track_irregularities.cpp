#include "wheelwear/vehicle/track_irregularities.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

// Bit-identical samples on every platform rest on three rules kept in this file: (1) the
// generator uses only +, -, *, /, sqrt and integer arithmetic, which IEEE 754 and C++ define to
// the last bit, and no library cosine or exponential (their last bits differ between C
// libraries); (2) no compiler may fuse a * b + c into one rounding (GCC does by default when
// the target has FMA instructions, Clang within an expression): the pragmas below switch that
// contraction off for this file; (3) phases are 64-bit fixed-point fractions of a turn,
// advanced by exact integer additions. (Nor may the file be built with -ffast-math, which the
// project never sets.)
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#elif defined(_MSC_VER)
#pragma fp_contract(off)
#endif

namespace wheelwear::vehicle {

using core::format_number;
using core::parse_number;
using core::split_lines;
using core::to_lower;
using core::trim;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;    // SplitMix64's increment
constexpr double kTwoTo64 = 18446744073709551616.0;         // 2^64
constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;  // 2^-53
constexpr double kMaxSamples = 1e8;
constexpr int kMaxComponents = 1000000;

// SplitMix64's output function (Stafford's "Mix13" variant, as in Vigna's splitmix64.c).
std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// cos(2 pi p / 2^64): p a fixed-point fraction of a turn. The turn is reduced exactly in integers
// to the nearest quarter n and a remainder x in [-pi/4, pi/4); sin x and cos x are their Taylor
// series up to x^17 and x^18 (the next terms are below 1e-19 there), in Horner form.
double cos_turns(std::uint64_t p) {
  const std::uint64_t quarter = (p + (std::uint64_t{1} << 61)) >> 62;
  const auto rest = static_cast<std::int64_t>(p - (quarter << 62));  // in [-2^61, 2^61)
  const double x = static_cast<double>(rest) * (kTwoPi / kTwoTo64);
  const double x2 = x * x;
  if (quarter == 0 || quarter == 2) {
    static constexpr std::array<double, 9> c = {-1.0 / 2.0,
                                                1.0 / 24.0,
                                                -1.0 / 720.0,
                                                1.0 / 40320.0,
                                                -1.0 / 3628800.0,
                                                1.0 / 479001600.0,
                                                -1.0 / 87178291200.0,
                                                1.0 / 20922789888000.0,
                                                -1.0 / 6402373705728000.0};
    double acc = c[8];
    for (int j = 7; j >= 0; --j) acc = acc * x2 + c[j];
    const double cosine = x2 * acc + 1.0;
    return quarter == 0 ? cosine : -cosine;
  }
  static constexpr std::array<double, 8> s = {
      -1.0 / 6.0,        1.0 / 120.0,        -1.0 / 5040.0,          1.0 / 362880.0,
      -1.0 / 39916800.0, 1.0 / 6227020800.0, -1.0 / 1307674368000.0, 1.0 / 355687428096000.0};
  double acc = s[7];
  for (int j = 6; j >= 0; --j) acc = acc * x2 + s[j];
  const double sine = x * x2 * acc + x;
  // cos(pi/2 + x) = -sin x, cos(3 pi/2 + x) = sin x.
  return quarter == 1 ? -sine : sine;
}

// sin(2 pi p / 2^64) = cos(2 pi p / 2^64 - pi/2).
double sin_turns(std::uint64_t p) {
  return cos_turns(p - (std::uint64_t{1} << 62));
}

// w(t) = t^3 (10 - 15 t + 6 t^2), the quintic that rises from 0 to 1 with zero first and second
// derivatives at both ends.
double fade(double t) {
  return t * t * t * ((6.0 * t - 15.0) * t + 10.0);
}

void require_band(double omega_lo, double omega_hi) {
  require(std::isfinite(omega_lo) && omega_lo >= 0.0, "omega_lo", omega_lo,
          "the lower angular frequency must be finite and >= 0 (rad/m)");
  require(std::isfinite(omega_hi) && omega_hi > omega_lo, "omega_hi", omega_hi,
          "the upper angular frequency must be finite and above omega_lo (rad/m)");
}

// The N cosines of one irregularity: amplitude, phase and advance per sample (turns, fixed
// point), drawn from `rng` in the documented order.
struct Components {
  std::vector<double> amplitude;
  std::vector<std::uint64_t> phase;
  std::vector<std::uint64_t> step;
};

template <typename Density>
Components draw_components(const IrregularitySpec& spec, double sample_distance, SplitMix64& rng,
                           Density density) {
  const double omega_min = kTwoPi / spec.longest_wavelength;
  const double omega_max = kTwoPi / spec.shortest_wavelength;
  const int n = spec.components;
  const double d_omega = (omega_max - omega_min) / n;
  Components c;
  c.amplitude.resize(n);
  c.phase.resize(n);
  c.step.resize(n);
  for (int k = 0; k < n; ++k) {
    const double place = rng.next_uniform();
    const double phase = rng.next_uniform();
    const double omega = omega_min + (k + place) * d_omega;
    c.amplitude[k] = std::sqrt(2.0 * density(omega) * d_omega);
    // phase * 2^64 is an integer below 2^64 (53 significant bits): exact.
    c.phase[k] = static_cast<std::uint64_t>(phase * kTwoTo64);
    // Turns per sample, below 1/4 (at least 4 samples per shortest wave): the realised
    // frequency is this rounded down to a multiple of 2 pi 2^-64 / sample_distance.
    const double turns = omega * sample_distance / kTwoPi;
    c.step[k] = static_cast<std::uint64_t>(turns * kTwoTo64);
  }
  return c;
}

// The sum of the cosines at samples i = 0 ... count-1. Within blocks of kBlock samples starting
// at i0, cos(p0 + j step) = cos p0 cos(j step) - sin p0 sin(j step): the block's anchor phase p0
// and the table of j step (j < kBlock) are exact in fixed point, so the error does not grow along
// the record. Every sample is the same sum, in ascending k, whatever else is computed.
std::vector<double> synthesise(const Components& c, std::size_t count) {
  constexpr std::size_t kBlock = 256;
  std::vector<double> out(count, 0.0);
  std::array<double, kBlock> cos_j{}, sin_j{};
  for (std::size_t k = 0; k < c.amplitude.size(); ++k) {
    const double a = c.amplitude[k];
    const std::uint64_t step = c.step[k];
    for (std::size_t j = 0; j < kBlock; ++j) {
      cos_j[j] = cos_turns(j * step);  // modulo 2^64: whole turns drop out exactly
      sin_j[j] = sin_turns(j * step);
    }
    for (std::size_t i0 = 0; i0 < count; i0 += kBlock) {
      const std::uint64_t p0 = c.phase[k] + i0 * step;
      const double ac = a * cos_turns(p0), as = a * sin_turns(p0);
      const std::size_t n = std::min(kBlock, count - i0);
      double* x = out.data() + i0;
      for (std::size_t j = 0; j < n; ++j) x[j] = x[j] + (ac * cos_j[j] - as * sin_j[j]);
    }
  }
  return out;
}

double interpolate(const TrackIrregularities& r, const std::vector<double>& values, double s) {
  const std::size_t n = r.distance.size();
  if (n < 2 || values.size() != n)
    throw InputError(r.source + ": " + std::to_string(n) + " distances and " +
                     std::to_string(values.size()) +
                     " values: interpolation needs at least two samples, one value per distance");
  require(std::isfinite(s) && s >= r.distance.front() && s <= r.distance.back(), "distance", s,
          "must lie within the record " + r.source + ", " + format_number(r.distance.front()) +
              " ... " + format_number(r.distance.back()) + " m");
  std::size_t i = static_cast<std::size_t>(
      std::upper_bound(r.distance.begin(), r.distance.end(), s) - r.distance.begin());
  i = std::min(std::max<std::size_t>(i, 1), n - 1);  // segment [i-1, i]
  const double t = (s - r.distance[i - 1]) / (r.distance[i] - r.distance[i - 1]);
  // Exact at both ends: t = 0 gives values[i-1], t = 1 gives values[i].
  return (1.0 - t) * values[i - 1] + t * values[i];
}

std::vector<std::string> fields_of(std::string_view line) {
  std::vector<std::string> fields;
  std::string current;
  for (char c : line) {
    if (c == ',' || c == '\t' || c == ' ' || c == '\r') {
      if (!current.empty()) fields.push_back(current);
      current.clear();
    } else {
      current.push_back(c);
    }
  }
  if (!current.empty()) fields.push_back(current);
  return fields;
}

constexpr std::array<std::string_view, 3> kColumns = {"distance_m", "alignment_m", "cross_level_m"};
constexpr std::string_view kColumnsFix =
    "the header must name the columns distance_m, alignment_m and cross_level_m (values in "
    "metres; convert millimetres)";

}  // namespace

// --- spectra ---------------------------------------------------------------------------------

ErriSpectrum ErriSpectrum::low() {
  return ErriSpectrum{};
}

ErriSpectrum ErriSpectrum::high() {
  ErriSpectrum s;
  s.A_a = 6.125e-7;
  s.A_v = 1.080e-6;
  return s;
}

double ErriSpectrum::alignment(double omega) const {
  const double w = omega * omega;
  const double den = (w + omega_r * omega_r) * (w + omega_c * omega_c);
  return A_a * (omega_c * omega_c) / den;
}

double ErriSpectrum::cross_level_angle(double omega) const {
  const double w = omega * omega;
  const double den = (w + omega_r * omega_r) * (w + omega_c * omega_c) * (w + omega_s * omega_s);
  const double b2 = half_rail_spacing * half_rail_spacing;
  return (A_v / b2) * (omega_c * omega_c) * w / den;
}

double ErriSpectrum::cross_level(double omega) const {
  const double base = 2.0 * half_rail_spacing;
  return base * base * cross_level_angle(omega);
}

double ErriSpectrum::alignment_variance(double omega_lo, double omega_hi) const {
  require_band(omega_lo, omega_hi);
  require(omega_r != omega_c, "omega_r", omega_r,
          "the closed form needs distinct corner frequencies Omega_r and Omega_c");
  // 1/((W+r^2)(W+c^2)) = (1/(W+r^2) - 1/(W+c^2)) / (c^2 - r^2), W = Omega^2, and the integral
  // of 1/(Omega^2 + p^2) is atan(Omega/p)/p.
  const auto primitive = [&](double w) {
    return std::atan(w / omega_r) / omega_r - std::atan(w / omega_c) / omega_c;
  };
  const double r2 = omega_r * omega_r, c2 = omega_c * omega_c;
  return A_a * c2 / (c2 - r2) * (primitive(omega_hi) - primitive(omega_lo));
}

double ErriSpectrum::cross_level_variance(double omega_lo, double omega_hi) const {
  require_band(omega_lo, omega_hi);
  require(omega_r != omega_c && omega_r != omega_s && omega_s != omega_c, "omega_s", omega_s,
          "the closed form needs distinct corner frequencies Omega_r, Omega_s and Omega_c");
  // W/((W+R)(W+C)(W+S)) = sum over the poles P of alpha_P/(W+P), alpha_P = -P / prod (Q - P)
  // over the other poles Q, with W = Omega^2 and R = Omega_r^2 etc.
  const std::array<double, 3> p = {omega_r, omega_c, omega_s};
  double sum = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double pj2 = p[j] * p[j];
    double alpha = -pj2;
    for (int m = 0; m < 3; ++m)
      if (m != j) alpha /= p[m] * p[m] - pj2;
    sum += alpha * (std::atan(omega_hi / p[j]) - std::atan(omega_lo / p[j])) / p[j];
  }
  const double b2 = half_rail_spacing * half_rail_spacing;
  const double base = 2.0 * half_rail_spacing;
  return base * base * (A_v / b2) * (omega_c * omega_c) * sum;
}

void ErriSpectrum::validate() const {
  require(std::isfinite(A_a) && A_a >= 0.0, "A_a", A_a,
          "the alignment roughness must be finite and >= 0 (m rad; 0 switches it off)");
  require(std::isfinite(A_v) && A_v >= 0.0, "A_v", A_v,
          "the vertical roughness must be finite and >= 0 (m rad; 0 switches the cross-level "
          "off)");
  require(std::isfinite(omega_c) && omega_c > 0.0, "omega_c", omega_c,
          "must be finite and positive (rad/m)");
  require(std::isfinite(omega_r) && omega_r > 0.0, "omega_r", omega_r,
          "must be finite and positive (rad/m)");
  require(std::isfinite(omega_s) && omega_s > 0.0, "omega_s", omega_s,
          "must be finite and positive (rad/m)");
  require(std::isfinite(half_rail_spacing) && half_rail_spacing > 0.25 && half_rail_spacing < 1.5,
          "half rail spacing", half_rail_spacing,
          "half the distance between the rail centres must lie in 0.25 ... 1.5 m (0.75 for "
          "standard gauge)");
}

void IrregularitySpec::validate() const {
  spectrum.validate();
  require(std::isfinite(shortest_wavelength) && shortest_wavelength > 0.0, "shortest wavelength",
          shortest_wavelength, "must be finite and positive (m)");
  require(std::isfinite(longest_wavelength) && longest_wavelength > shortest_wavelength,
          "longest wavelength", longest_wavelength,
          "must be finite and longer than the shortest wavelength (m)");
  require(components >= 1 && components <= kMaxComponents, "components", components,
          "the number of cosines per irregularity must lie in 1 ... 1000000");
  require(std::isfinite(run_in) && run_in >= 0.0, "run-in", run_in,
          "the fade-in distance must be finite and >= 0 (m; 0: no fade-in)");
}

// --- records ---------------------------------------------------------------------------------

double TrackIrregularities::alignment_at(double s) const {
  return interpolate(*this, alignment, s);
}

double TrackIrregularities::cross_level_at(double s) const {
  return interpolate(*this, cross_level, s);
}

TrackIrregularities reversed(const TrackIrregularities& record, double route_length) {
  TrackIrregularities back;
  back.source = record.source + ", run backwards";
  for (std::size_t i = record.distance.size(); i-- > 0;) {
    back.distance.push_back(route_length - record.distance[i]);
    back.alignment.push_back(-record.alignment[i]);
    back.cross_level.push_back(-record.cross_level[i]);
  }
  return back;
}

// --- generator -------------------------------------------------------------------------------

std::uint64_t SplitMix64::next() {
  state_ += kGolden;
  return mix64(state_);
}

double SplitMix64::next_uniform() {
  return static_cast<double>(next() >> 11) * kTwoToMinus53;
}

std::uint64_t seed_for_section(std::uint64_t base_seed, std::uint64_t section_index) {
  return mix64(mix64(base_seed) + (section_index + 1) * kGolden);
}

TrackIrregularities generate_irregularities(const IrregularitySpec& spec, double length_m,
                                            double sample_distance_m, std::uint64_t seed) {
  spec.validate();
  require(std::isfinite(length_m) && length_m > 0.0, "length", length_m,
          "must be finite and positive (m)");
  require(std::isfinite(sample_distance_m) && sample_distance_m > 0.0 &&
              sample_distance_m <= spec.shortest_wavelength / 4.0,
          "sample distance", sample_distance_m,
          "must be positive and at most a quarter of the shortest wavelength (" +
              format_number(spec.shortest_wavelength) +
              " m): fewer samples per wave alias it and linear interpolation misses its peaks");
  const double intervals = std::ceil(length_m / sample_distance_m);
  require(intervals + 1.0 <= kMaxSamples, "length", length_m,
          "gives more than 1e8 samples at this sample distance: generate it in sections "
          "(seed_for_section)");
  const auto count = static_cast<std::size_t>(intervals) + 1;

  SplitMix64 rng(seed);
  const ErriSpectrum& psd = spec.spectrum;
  const Components alignment = draw_components(spec, sample_distance_m, rng,
                                               [&](double omega) { return psd.alignment(omega); });
  const Components cross_level = draw_components(
      spec, sample_distance_m, rng, [&](double omega) { return psd.cross_level(omega); });

  TrackIrregularities out;
  out.distance.resize(count);
  for (std::size_t i = 0; i < count; ++i)
    out.distance[i] = static_cast<double>(i) * sample_distance_m;
  out.alignment = synthesise(alignment, count);
  out.cross_level = synthesise(cross_level, count);
  if (spec.run_in > 0.0) {
    for (std::size_t i = 0; i < count && out.distance[i] < spec.run_in; ++i) {
      const double w = fade(out.distance[i] / spec.run_in);
      out.alignment[i] *= w;
      out.cross_level[i] *= w;
    }
  }
  out.source =
      "ERRI B176 spectra (A_a " + format_number(psd.A_a) + ", A_v " + format_number(psd.A_v) +
      " m rad), wavelengths " + format_number(spec.shortest_wavelength) + " ... " +
      format_number(spec.longest_wavelength) + " m, " + std::to_string(spec.components) +
      " cosines, run-in " + format_number(spec.run_in) + " m, seed " + std::to_string(seed);
  return out;
}

// --- files -----------------------------------------------------------------------------------

TrackIrregularities parse_irregularities(std::string_view text, std::string_view source_name) {
  const std::string source(source_name);
  const auto at = [&](int line) { return source + ":" + std::to_string(line) + ": "; };
  TrackIrregularities out;
  out.source = source;
  std::vector<std::string> header;
  int header_line = 0;
  std::array<std::size_t, 3> column{};  // index of distance_m, alignment_m, cross_level_m
  int previous_line = 0;
  const std::vector<std::string_view> lines = split_lines(text);
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const int number = static_cast<int>(index) + 1;
    std::string_view line = lines[index];
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    std::vector<std::string> fields = fields_of(line);
    if (header.empty()) {
      if (parse_number(fields.front()))
        throw InputError(
            at(number) + "\"" + std::string(line) +
            "\" is a row of numbers, but no header came before it: " + std::string(kColumnsFix));
      for (std::string& f : fields) f = to_lower(f);
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        const auto found = std::find(fields.begin(), fields.end(), kColumns[c]);
        if (found == fields.end())
          throw InputError(at(number) + "the header names no column " + std::string(kColumns[c]) +
                           ": " + std::string(kColumnsFix));
        if (std::find(found + 1, fields.end(), kColumns[c]) != fields.end())
          throw InputError(at(number) + "the header names the column " + std::string(kColumns[c]) +
                           " twice: name each column once");
        column[c] = static_cast<std::size_t>(found - fields.begin());
      }
      header = std::move(fields);
      header_line = number;
      continue;
    }
    if (fields.size() != header.size())
      throw InputError(at(number) + std::to_string(fields.size()) +
                       " values, but the header (line " + std::to_string(header_line) + ") names " +
                       std::to_string(header.size()) +
                       " columns: a truncated or damaged row; complete or remove it");
    std::array<double, 3> value{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const std::string& token = fields[column[c]];
      const std::optional<double> v = parse_number(token);
      if (!v)
        throw InputError(at(number) + std::string(kColumns[c]) + " = \"" + token +
                         "\" is not a number: write it with a decimal point, in metres");
      if (!std::isfinite(*v))
        throw InputError(at(number) + std::string(kColumns[c]) + " = " + token +
                         ": must be a finite number; repair or remove the row");
      value[c] = *v;
    }
    if (!out.distance.empty() && !(value[0] > out.distance.back()))
      throw InputError(at(number) + "distance_m = " + fields[column[0]] +
                       " does not increase on line " + std::to_string(previous_line) + " (" +
                       format_number(out.distance.back()) +
                       "): distances must be strictly increasing; sort the rows or remove the "
                       "repeated one");
    out.distance.push_back(value[0]);
    out.alignment.push_back(value[1]);
    out.cross_level.push_back(value[2]);
    previous_line = number;
  }
  if (header.empty())
    throw InputError(source + ": no header and no rows (only blanks and comments): " +
                     std::string(kColumnsFix) + ", followed by at least two rows");
  if (out.distance.size() < 2)
    throw InputError(source + ": " + std::to_string(out.distance.size()) +
                     " rows after the header (line " + std::to_string(header_line) +
                     "): at least two are needed to interpolate; add the measured rows");
  return out;
}

TrackIrregularities read_irregularities(const std::filesystem::path& path) {
  return parse_irregularities(core::read_text_file(path), path.string());
}

void write_irregularities(const TrackIrregularities& record, const std::filesystem::path& path) {
  const std::size_t n = record.distance.size();
  if (record.alignment.size() != n || record.cross_level.size() != n)
    throw InputError(path.string() + ": the record has " + std::to_string(n) + " distances, " +
                     std::to_string(record.alignment.size()) + " alignments and " +
                     std::to_string(record.cross_level.size()) +
                     " cross-levels: it needs one of each per distance");
  std::string source = record.source;
  std::replace(source.begin(), source.end(), '\n', ' ');
  std::replace(source.begin(), source.end(), '\r', ' ');
  std::string text;
  text += "# wheelwear track irregularities: " + source + "\n";
  text +=
      "# alignment_m: track centre line, + left; cross_level_m: left rail above the right over "
      "1.5 m\n";
  text += "distance_m,alignment_m,cross_level_m\n";
  for (std::size_t i = 0; i < n; ++i)
    text += format_number(record.distance[i]) + "," + format_number(record.alignment[i]) + "," +
            format_number(record.cross_level[i]) + "\n";
  core::write_file_atomically(path, text);
}

}  // namespace wheelwear::vehicle
