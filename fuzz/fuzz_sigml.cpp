// Fuzz target: SiGML documents (hns_sign and hamgestural_sign), every sign read with its own error.
#include "fuzz_target.hpp"
#include "gestura/sign/sigml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] { (void)gestura::sign::read_sigml_entries(text, "fuzz.sigml"); });
  return 0;
}
