// Fuzz target: MiniProf .whl and .ban exports (profiles/miniprof_format.hpp), read as either.
// Points read from a wheel file (finite, within 1 km) must read back from the wheel file the
// writer makes of them (wheel axes are the file's own), to the rounding of the mm conversion.

#include "fuzz_support.hpp"
#include "wheelwear/profiles/miniprof_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wheelwear;
  const std::string_view text = fuzz::as_text(data, size);
  fuzz::expect_only_input_errors([&] { profiles::parse_miniprof(text, "fuzz-input", ".ban"); });
  fuzz::expect_only_input_errors([&] {
    const profiles::RawProfile raw = profiles::parse_miniprof(text, "fuzz-input", ".whl");
    if (raw.points.empty() || !fuzz::all_finite(raw.points)) return;
    double largest = 0.0;
    for (const auto& p : raw.points) largest = std::max({largest, std::abs(p[0]), std::abs(p[1])});
    if (largest > 1e3) return;
    const std::string written = profiles::format_miniprof(raw.points, profiles::Body::wheel);
    const profiles::RawProfile again =
        fuzz::reread([&] { return profiles::parse_miniprof(written, "fuzz-rewritten", ".whl"); });
    if (again.points.size() != raw.points.size() ||
        fuzz::max_difference(again.points, raw.points) > 1e-14 * largest + 1e-300)
      fuzz::fail("miniprof: the written wheel file does not read back to the same points");
  });
  return 0;
}
