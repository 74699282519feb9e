// Fuzz target: MPEG-4 BAP text files, read and turned into a clip on a small humanoid.
#include "fuzz_target.hpp"
#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/io/bap.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const gestura::Skeleton skeleton = gestura::synthetic_humanoid();
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] {
    const gestura::BapFile file = gestura::read_bap(text, "fuzz.bap");
    (void)gestura::bap_to_clip(file, skeleton);
  });
  return 0;
}
