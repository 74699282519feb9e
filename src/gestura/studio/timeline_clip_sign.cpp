#include "gestura/studio/timeline_clip_sign.hpp"

#include "gestura/compress/compress.hpp"
#include "gestura/compress/decompress_clip.hpp"
#include "gestura/core/error.hpp"
#include "gestura/lexicon/lexicon.hpp"

namespace gestura::studio {

SignEntry clip_sign_entry(const std::string& gloss, const std::string& language, const Clip& clip, const Skeleton& skeleton) {
  if (gloss.empty()) throw Error("a clip sign needs a gloss");
  SignEntry e;
  e.gloss = gloss;
  e.language = language.empty() ? "ase" : language;
  e.notation_kind = NotationKind::clip;
  e.clip = compress(clip, skeleton).bytes();
  e.source = "gestura studio timeline";
  return e;
}

void store_clip_sign(const std::string& db_path, const SignEntry& entry) {
  Lexicon lexicon = Lexicon::open(db_path);
  lexicon.atomically([&] { lexicon.add(entry, OnConflict::replace); });
}

Clip clip_of(const SignEntry& entry) {
  if (entry.notation_kind != NotationKind::clip) throw Error("sign '" + entry.gloss + "' is not a clip sign");
  return decompress_clip(CompressedClip::from_bytes(entry.clip, "clip sign '" + entry.gloss + "'"), entry.gloss);
}

}  // namespace gestura::studio
