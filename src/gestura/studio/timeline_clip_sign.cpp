#include "gestura/studio/timeline_clip_sign.hpp"

#include "gestura/core/error.hpp"
#include "gestura/lexicon/clip_sign.hpp"
#include "gestura/lexicon/lexicon.hpp"

namespace gestura::studio {

SignEntry clip_sign_entry(const std::string& gloss, const std::string& language, const Clip& clip, const Skeleton& skeleton) {
  if (gloss.empty()) throw Error("a clip sign needs a gloss");
  SignEntry e;
  e.gloss = gloss;
  e.language = language.empty() ? "ase" : language;
  e.notation_kind = NotationKind::clip;
  e.clip = encode_clip_sign(clip, skeleton);
  e.source = "gestura studio timeline";
  return e;
}

void store_clip_sign(const std::string& db_path, const SignEntry& entry) {
  Lexicon lexicon = Lexicon::open(db_path);
  lexicon.atomically([&] { lexicon.add(entry, OnConflict::replace); });
}

Clip clip_of(const SignEntry& entry) {
  return decode_clip_sign(entry);
}

}  // namespace gestura::studio
