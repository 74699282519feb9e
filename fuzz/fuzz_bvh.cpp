// Fuzz target: BVH motion files, read as they are and as Z-up decimetres (the MakeHuman reading).
#include "fuzz_target.hpp"
#include "gestura/io/bvh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] { (void)gestura::read_bvh(text, "fuzz.bvh"); });
  gestura::fuzz::expect_result_or_error(
      [&] { (void)gestura::read_bvh(text, "fuzz.bvh", gestura::BvhReadOptions{.scale = 0.1f, .z_up = true}); });
  return 0;
}
