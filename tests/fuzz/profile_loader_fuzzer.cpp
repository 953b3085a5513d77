// Fuzz target: the whole way from a file's text to a fitted profile, as load_profile() goes
// (profiles/profile_loader.hpp) without the file: check_text, detect_format (by content: the
// name has no extension), parse_profile_text, then orientation, cleaning, validation and fit.

#include "fuzz_support.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/core/text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace wheelwear;
  const std::string_view text = fuzz::as_text(data, size);
  fuzz::expect_only_input_errors([&] {
    core::check_text(text, "fuzz-input");
    const auto format = profiles::detect_format("fuzz-input", text);
    profiles::RawProfile raw = profiles::parse_profile_text(text, "fuzz-input", format);
    profiles::LoadOptions options;
    // A file that does not say what it is: try it as the body its size's parity picks, so both
    // the wheel and the rail paths are reached.
    if (!raw.body) options.read.body = size % 2 ? profiles::Body::wheel : profiles::Body::rail;
    profiles::prepare_profile(std::move(raw), options);
  });
  return 0;
}
