// Fuzz target: VRM 1.0 avatars (glTF binary with the VRMC_vrm extension).
#include "fuzz_target.hpp"
#include "gestura/io/vrm.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(gestura::fuzz::text_of(data, size));
  gestura::fuzz::expect_result_or_error([&] { (void)gestura::read_vrm(bytes, "fuzz.vrm"); });
  return 0;
}
