// Fuzz target: glTF 2.0 animation files, binary (.glb) and JSON (.gltf with data: URIs).
#include "fuzz_target.hpp"
#include "gestura/io/gltf_animation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(gestura::fuzz::text_of(data, size));
  gestura::fuzz::expect_result_or_error([&] { (void)gestura::read_gltf_animation(bytes, "fuzz.glb"); });
  return 0;
}
