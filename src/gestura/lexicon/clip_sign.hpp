#pragma once
// The motion of a clip sign (notation_kind 'clip'): a keyframed sign kept in the lexicon's clip
// blob. The joints are a .gcl (compress/compressed_clip.hpp); the face channels (visemes,
// expressions, brows: the scalar channels of the clip), which a .gcl does not carry, follow it:
//
//   plain    the .gcl bytes alone (no face channel ever leaves 0)
//   framed   "GCS\0" | u32 version (1) | u32 gcl_size | gcl bytes
//            | u32 channel_count | per channel: u16 name_size, name | u32 keys | keys × (f32 time, f32 value)
//
// little-endian. A channel that stays 0 throughout is not stored.
#include <cstdint>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/lexicon/sign_entry.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Throws gestura::Error when the clip does not fit the skeleton.
std::vector<std::uint8_t> encode_clip_sign(const Clip& clip, const Skeleton& skeleton);
// The clip, its joints one key per sample frame (compress/decompress_clip.hpp) and its face
// channels as stored. Throws gestura::Error naming the gloss for an entry that is not a clip sign
// or a blob that does not decode.
Clip decode_clip_sign(const SignEntry& entry);

}  // namespace gestura
