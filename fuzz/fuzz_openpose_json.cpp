// Fuzz target: one OpenPose keypoint frame (JSON).
#include "fuzz_target.hpp"
#include "gestura/io/openpose_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] { (void)gestura::read_openpose_frame(text, "fuzz.json"); });
  return 0;
}
