#pragma once
// A keyframed sign kept in the lexicon as a clip sign (notation_kind 'clip'): the timeline's baked
// motion, joints as a .gcl and its face channels beside them (lexicon/clip_sign.hpp), in the row's
// clip blob. The sentence layer plays it like any other sign (sentence/clip_sign_motion.hpp).
#include <string>

#include "gestura/anim/clip.hpp"
#include "gestura/lexicon/sign_entry.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::studio {

// The entry for `clip` (on `skeleton`). Throws gestura::Error for an empty gloss or a clip that
// does not fit the skeleton.
SignEntry clip_sign_entry(const std::string& gloss, const std::string& language, const Clip& clip, const Skeleton& skeleton);
// Writes it into the lexicon at `db_path` in one transaction, replacing the same gloss, language
// and variant. Throws gestura::Error (a locked or read-only database, a full disk) with nothing written.
void store_clip_sign(const std::string& db_path, const SignEntry& entry);
// The motion of a clip sign, face channels included. Throws gestura::Error naming the gloss when
// the blob does not decode.
Clip clip_of(const SignEntry& entry);

}  // namespace gestura::studio
