// Fuzz target: compressed clips (.gcl), read and decompressed.
#include <vector>

#include "fuzz_target.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/compress/decompress_clip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gestura::fuzz::expect_result_or_error([&] {
    const gestura::CompressedClip clip =
        gestura::CompressedClip::from_bytes(std::vector<std::uint8_t>(data, data + size), "fuzz.gcl");
    (void)gestura::decompress_clip(clip);
  });
  return 0;
}
