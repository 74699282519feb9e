#pragma once
// A CompressedClip decoded back into an ordinary Clip, so the rest of the toolkit (BVH export,
// re-compression, blending) can use it: one key per sample frame on every joint's rotation and
// translation, linear between keys — the decoder's own interpolation, so sampling the result at any
// time gives what CompressedClip::sample gives. Scale tracks are kept only for joints whose decoded
// scale is not exactly 1 (a .gcl stores identity scales as such).
#include "gestura/anim/clip.hpp"
#include "gestura/compress/compressed_clip.hpp"

namespace gestura {

Clip decompress_clip(const CompressedClip& compressed, const std::string& name = "decompressed");

}  // namespace gestura
