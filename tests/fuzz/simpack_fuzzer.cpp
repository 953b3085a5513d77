// Fuzz target: SIMPACK / CONTACT .prr and .prw profiles (profiles/simpack_format.hpp). What the
// reader accepts (finite, within 1 km) must read back from the file the writer makes of it, to
// the rounding of the mm conversion.

#include "fuzz_support.hpp"
#include "wheelwear/profiles/simpack_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wheelwear;
  const std::string_view text = fuzz::as_text(data, size);
  fuzz::expect_only_input_errors([&] {
    const profiles::RawProfile raw = profiles::parse_simpack(text, "fuzz-input.prr");
    if (raw.points.empty() || !fuzz::all_finite(raw.points)) return;
    double largest = 0.0;
    for (const auto& p : raw.points) largest = std::max({largest, std::abs(p[0]), std::abs(p[1])});
    if (largest > 1e3) return;
    const std::string written =
        profiles::format_simpack(raw.points, raw.body.value_or(profiles::Body::rail));
    const profiles::RawProfile again =
        fuzz::reread([&] { return profiles::parse_simpack(written, "fuzz-rewritten.prr"); });
    // m -> mm -> m: a few ulps of the largest coordinate.
    if (again.points.size() != raw.points.size() ||
        fuzz::max_difference(again.points, raw.points) > 1e-14 * largest + 1e-300)
      fuzz::fail("simpack: the written file does not read back to the same points");
  });
  return 0;
}
