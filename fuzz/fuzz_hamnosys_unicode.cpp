// Fuzz target: HamNoSys as Unicode text (private-use code points), parsed leniently and strictly,
// then described in words (as `gestura check` does).
#include "fuzz_target.hpp"
#include "gestura/sign/hamnosys_describe.hpp"
#include "gestura/sign/hamnosys_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gestura::sign;
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] { (void)describe(parse_hamnosys_unicode(text)); });
  gestura::fuzz::expect_result_or_error([&] { (void)parse_hamnosys_unicode(text, ParseOptions{.strict = true}); });
  return 0;
}
