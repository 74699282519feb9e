#include "gestura/render/png_writer.hpp"

#include <string>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace gestura {

namespace {

void append_to_string(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

void write_png(StagedFile& file, const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot write " + file.target() + ": empty image");
  // Encoded in memory and written through the staged file, whose writes are checked: stb's own
  // file writer ignores a short write (a full disk would give a truncated PNG and no error).
  std::string png;
  if (!stbi_write_png_to_func(append_to_string, &png, image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw Error("cannot write " + file.target() + ": PNG encoding failed");
  file.write(png);
  file.commit();
}

void write_png(const std::string& path, const Image& image) {
  StagedFile file(path);
  write_png(file, image);
}

}  // namespace gestura
