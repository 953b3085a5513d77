// Fuzz target: plain two-column text and CSV profiles (profiles/columns_format.hpp). Whatever
// the reader accepts with finite coordinates must come back unchanged from the CSV the writer
// makes of it (in metres, numbers written exactly).

#include "fuzz_support.hpp"
#include "wheelwear/profiles/columns_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wheelwear;
  const std::string_view text = fuzz::as_text(data, size);
  fuzz::expect_only_input_errors([&] {
    const profiles::RawProfile raw = profiles::parse_columns(text, "fuzz-input");
    if (raw.points.empty() || !fuzz::all_finite(raw.points)) return;
    profiles::CsvWriteOptions options;
    options.unit = profiles::LengthUnit::metre;
    const std::string written = profiles::format_csv(raw.points, options);
    const profiles::RawProfile again =
        fuzz::reread([&] { return profiles::parse_columns(written, "fuzz-rewritten"); });
    if (again.points.size() != raw.points.size() ||
        fuzz::max_difference(again.points, raw.points) != 0.0)
      fuzz::fail("columns: the written CSV does not read back to the same points");
  });
  return 0;
}
