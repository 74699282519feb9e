#include "support/png_file.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace gestura::test {

PngPixels read_png(const std::string& path, int channels) {
  PngPixels out;
  int n = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &out.width, &out.height, &n, channels);
  if (!pixels) return {};
  out.channels = channels;
  out.data.assign(pixels, pixels + static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) *
                                       static_cast<std::size_t>(channels));
  stbi_image_free(pixels);
  return out;
}

}  // namespace gestura::test
