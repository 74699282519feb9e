#include "gestura/render/png_writer.hpp"

#include "gestura/core/error.hpp"
#include "gestura/render/staged_file.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace gestura {

void write_png(StagedFile& file, const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot write " + file.target() + ": empty image");
  if (!stbi_write_png(file.temp_path().c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw Error("cannot write " + file.target() + ": PNG encoding or writing failed");
  file.commit();
}

void write_png(const std::string& path, const Image& image) {
  StagedFile file(path);
  write_png(file, image);
}

}  // namespace gestura
