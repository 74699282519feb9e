// Fuzz target: HamNoSys as comma-separated symbol names (hamflathand,hamextfingeru,...), parsed
// leniently and strictly.
#include "fuzz_target.hpp"
#include "gestura/sign/hamnosys_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gestura::sign;
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] { (void)parse_hamnosys_names(text); });
  gestura::fuzz::expect_result_or_error([&] { (void)parse_hamnosys_names(text, ParseOptions{.strict = true}); });
  return 0;
}
