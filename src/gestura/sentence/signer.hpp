#pragma once
// The interpreter of sign-language-interpreter.txt: written text in, a signing performance out.
//
//   Signer signer(avatar, lexicon);                // once
//   SentencePerformance p = signer.say("Hello! How are you?", {});
//   p.clip                                         // body, hands, face channels on avatar.skeleton
//
// Pipeline: English → ASL glosses (text/translator) → lexicon entries (lexicon/, built-in ASL from
// data/lexicon/ase.jsonl plus user lexicons) → each sign planned on the avatar (sign/sign_planner)
// without returning to rest, joined by coarticulated transitions, with prosody (sentence/sign_prosody:
// phrase-final lengthening, pauses, holds) → performed from joint angles cached per sign and avatar
// (sentence/sign_motion_cache, sentence/utterance_performer) → non-manual markers and mouthing added
// as face channels and head rotations (face/).
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <unordered_map>
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/sentence/sign_motion_cache.hpp"
#include "gestura/sentence/utterance_performer.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

class CitationStore;
class LexiconMemo;
struct ClipSignMotion;
struct GlossToken;

struct SayOptions {
  float speed = 1.0f;        // global tempo 0.25–2
  std::string lang = "ase";  // sign language (ISO 639-3); only ASL has a built-in lexicon
  bool mouthing = true;
  bool nonmanuals = true;
  float fps = 30.0f;
};

// One gloss of the utterance as performed.
struct PerformedGloss {
  std::string gloss;         // e.g. "MOTHER", "FS-JOHN", "47"
  std::string source;        // the English words it came from
  float start = 0.0f;        // seconds: when the hands reach the sign's first posture
  float end = 0.0f;          // when its last hold ends
};

struct SentencePerformance {
  Clip clip;                            // on the Signer's avatar skeleton, with face channels
  std::vector<PerformedGloss> glosses;
  float duration = 0.0f;                // seconds, including the return to rest
  std::vector<std::string> notes;       // e.g. "'zyx' fingerspelled: not in the lexicon"
  SignPlan plan;                        // what each hand does, in space (the plan the clip performs)
  UtteranceStats motion;                // how the joint motion was made (transitions bent around the body)
};

// Limits on one utterance (docs/say.md): longer text is refused with an error, never truncated
// silently, so a caller sees exactly what will be signed.
inline constexpr std::size_t kMaxSayBytes = 16 * 1024;
inline constexpr std::size_t kMaxSayGlosses = 300;
// The longest one utterance may last: 30 minutes, six seconds for each of kMaxSayGlosses glosses
// at the slowest tempo. Planning stops at the gloss that passes it, before any motion is made.
inline constexpr float kMaxSaySeconds = 30.0f * 60.0f;

class Signer {
 public:
  // Contract: `avatar` and `lexicon` outlive the signer (the rig is built once, here).
  Signer(const Avatar& avatar, LayeredLexicon& lexicon);
  Signer(const Signer&) = delete;  // the motion cache refers to this signer's rig
  Signer& operator=(const Signer&) = delete;
  ~Signer();

  // Throws gestura::Error for empty text, text over kMaxSayBytes or kMaxSayGlosses glosses, an
  // utterance that would last over kMaxSaySeconds, invalid UTF-8, a sign language without a lexicon, and a speed outside 0.25–2.
  // The first utterance that uses a sign performs its citation form by IK and stores it (per
  // signer, so per avatar); later ones reuse it. A clip sign (keyframed in the studio) plays its
  // recorded motion and face channels between the same transitions (sentence/clip_sign_motion.hpp).
  // Safe to call from several threads.
  SentencePerformance say(std::string_view text, const SayOptions& options = {}) const;

  // Keeps solved citation forms in the SQLite database at `path` (the user lexicon) and reads the
  // ones an earlier process solved (sentence/citation_store.hpp). Never throws: a database that
  // cannot be used leaves the signer as it was (store()->problem() says why). Call before say().
  void keep_citations_in(const std::string& path);
  const CitationStore* store() const { return store_.get(); }

  // Signs given by their notation (HamNoSys 4 Unicode), performed one after another on one two-hand
  // timeline as running signing: a SiGML document of several signs. `gloss` names each in the result.
  // Throws gestura::Error for none, more than kMaxSayGlosses, a notation that does not parse, a speed
  // outside 0.25–2, or an utterance over kMaxSaySeconds.
  struct NotatedSign {
    std::string gloss, notation;
  };
  SentencePerformance sign_sequence(std::span<const NotatedSign> signs, const SayOptions& options = {}) const;

  // Signs whose joint motion is stored so far.
  std::size_t cached_signs() const { return cache_->signs_stored(); }

  const SigningRig& rig() const { return rig_; }

 private:
  const Avatar* avatar_;
  LayeredLexicon* lexicon_;
  SigningRig rig_;
  std::unique_ptr<SignMotionCache> cache_;
  std::unique_ptr<CitationStore> store_;
  std::unique_ptr<LexiconMemo> memo_;  // the lexicon's answers, kept while it is unchanged
  // What the timing model (sign/citation_timing.hpp) says of a notation, in planned seconds: the
  // whole movement, one of its movements (0 when it has none), and how many repeats it makes. Kept
  // by notation, so a notation is parsed once, not at every utterance.
  struct ModelledTiming {
    float moving = 0.0f;
    float once = 0.0f;
    int repeats = 0;
  };
  ModelledTiming modelled_timing(const std::string& notation) const;
  mutable std::mutex modelled_mutex_;
  mutable std::unordered_map<std::string, ModelledTiming> modelled_;
  // Clip signs made ready for this rig, by their stored bytes.
  // `placed`: the gloss as translated when it is made at places of the signing space.
  const ClipSignMotion& clip_sign(const SignEntry& entry, const GlossToken* placed = nullptr) const;
  mutable std::mutex clip_mutex_;
  mutable std::unordered_map<std::string, std::unique_ptr<ClipSignMotion>> clip_signs_;
};

}  // namespace gestura
