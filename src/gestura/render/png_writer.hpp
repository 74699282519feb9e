#pragma once
// PNG output through stb_image_write, staged (see staged_file.hpp).
#include <string>

#include "gestura/render/image.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {

// Throws gestura::Error("cannot write PATH: ...") and leaves no file behind on failure.
void write_png(const std::string& path, const Image& image);
// Writes into an already staged file (opened early to fail fast) and commits it.
void write_png(StagedFile& file, const Image& image);

}  // namespace gestura
