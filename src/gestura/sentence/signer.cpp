#include "gestura/sentence/signer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

#include "gestura/sentence/citation_store.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/eye_gaze.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/face/jaw_motion.hpp"
#include "gestura/face/mouthing.hpp"
#include "gestura/face/nonmanual.hpp"
#include "gestura/face/nonmanual_from_translation.hpp"
#include "gestura/lexicon/clip_sign.hpp"
#include "gestura/sentence/clip_sign_motion.hpp"
#include "gestura/sentence/fingerspelling_performance.hpp"
#include "gestura/sentence/lexicon_memo.hpp"
#include "gestura/sentence/role_shift.hpp"
#include "gestura/sentence/sign_prosody.hpp"
#include "gestura/sentence/signing_space.hpp"
#include "gestura/sentence/utterance_performer.hpp"
#include "gestura/sign/citation_timing.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"
#include "gestura/sign/movement_timing.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_planner.hpp"
#include "gestura/sign/two_hand_timeline.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace gestura {

namespace {

constexpr float kMouthingAmplitude = 0.6f;        // ASL mouthing is reduced
// The citation-duration model's movement seconds → the planner's citation seconds that running
// signing compresses (sentence/sign_prosody.hpp): a normal straight movement is 0.34 s in the
// model and 0.63 s as planned (movement_timing.hpp), so running signing keeps its rate.
constexpr float kPlannedPerModelSecond = 0.63f / 0.34f;

// Joins per-sign plans into one plan for the utterance: each sign is planned without rest at either
// end, shifted to the utterance clock, and reached from the previous sign's last state by a
// minimum-jerk transition (movement epenthesis), never through the rest position. Both hands end
// every sign, word and pause at the same instant.
class UtteranceBuilder {
 public:
  UtteranceBuilder(const SigningRig& rig, float speed)
      : rig_(rig), speed_(speed), timeline_(ByHand<HandState>{{rest_hand_state(rig, Hand::Right), rest_hand_state(rig, Hand::Left)}}) {
    // Where a hand that has signed waits while the other signs alone: low in front, as in the rig's
    // relaxed signing posture (a signer does not drop it to the hip between signs).
    for (Hand hand : kBothHands) idle_[hand] = relaxed_hand_state(rig, hand);
  }

  float now() const { return timeline_.now(); }
  const std::vector<CachedSignSpan>& spans() const { return spans_; }

  // Appends one sign (its cached citation form) with its running-signing timing
  // (sign_prosody.hpp); returns its articulation interval [first posture, end of last hold].
  // `modelled`: the citation movement's seconds from the notation (sign/citation_timing.hpp), in the
  // planner's seconds; the sign then lasts what the model says and its planned motion is played at
  // the tempo that fits it.
  // `once`: the citation seconds of one of the sign's movements (their mean, no repeats), planner
  // seconds; `repeats`: how often the movement is repeated.
  std::array<float, 2> add_sign(const CitationMotion& motion, bool phrase_final, float extra_hold, float modelled,
                                float once, int repeats) {
    SignTiming timing = running_sign_timing(modelled, phrase_final, extra_hold, speed_, once, repeats);
    if (motion.movement() > 0.0f && timing.movement > 0.0f) timing.tempo = motion.movement() / timing.movement;
    else timing = running_sign_timing(motion.movement(), phrase_final, extra_hold, speed_);
    return place_sign(motion, timing);
  }

  // Appends a recorded sign (a clip sign, clip_sign_motion.hpp) at its own pace (recorded_sign_timing).
  std::array<float, 2> add_recorded_sign(const CitationMotion& motion, bool phrase_final, float extra_hold) {
    return place_sign(motion, recorded_sign_timing(motion.movement(), phrase_final, extra_hold, speed_));
  }

  // Appends a sign with `timing`: reached from where the hands are, held, moved, held.
  std::array<float, 2> place_sign(const CitationMotion& motion, const SignTiming& timing) {
    const SignPlan& plan = motion.plan;
    ByHand<HandState> first;
    for (Hand hand : kBothHands) {
      const HandTimeline& t = plan.hand(hand);
      first[hand] = t.segments.empty() ? rest_hand_state(rig_, hand) : sample_hand(t, 0.0f);
    }
    // The hands the sign uses set the transition time; a hand it does not use drifts to rest — or,
    // once it has signed, to its idle place low in front — over as long as it needs (up to the
    // whole sign) instead of snapping there.
    const float t0 = now();
    float d = 0.0f;
    for (Hand hand : kBothHands)
      if (first[hand].active) d = std::max(d, move_time(timeline_.state(hand), first[hand]));
    if (d == 0.0f) d = move_time(timeline_.state(Hand::Right), timeline_.state(Hand::Right));
    const float start = t0 + d;
    const float moving = start + timing.initial_hold;
    const float end = moving + timing.movement + timing.final_hold;
    for (Hand hand : kBothHands) {
      if (first[hand].active) {
        timeline_.move_to(hand, first[hand], d);
        timeline_.hold_until(hand, moving);
        timeline_.append_shifted(hand, plan.hand(hand), moving, timing.tempo);  // the cached plan starts at its first posture
        spans_.push_back({hand, start, moving, end, timing.tempo, &motion});
        signed_[hand] = true;
      } else {
        const HandState rest = signed_[hand] ? idle_[hand] : rest_hand_state(rig_, hand);
        const float arrival = std::min(std::max(start, t0 + move_time(timeline_.state(hand), rest)), end);
        timeline_.move_to(hand, rest, arrival - t0);
      }
    }
    // Both hands continue from the same clock: the final hold, and the shorter timeline holds.
    for (Hand hand : kBothHands) timeline_.hold_until(hand, end);
    return {start, end};
  }

  // Appends the letters of one word (fingerspelling_performance.hpp), reached from the hands'
  // current state like the first posture of a sign.
  std::array<float, 2> add_spelling(const SpellingPlan& plan) {
    const SpelledHands hands = spell_with_hands(plan, rig_, speed_);
    transition_to({{hands.first(Hand::Right), hands.first(Hand::Left)}});
    const float start = now();
    for (Hand hand : kBothHands) timeline_.append_shifted(hand, hands.hand(hand), start);
    return {start, now()};
  }

  void hold(float seconds) {
    if (seconds > 0.0f) timeline_.hold_both(seconds);
  }

  // The return to rest at the end of the utterance; returns the joined plan.
  SignPlan finish(float sign_start, float sign_end) {
    transition_to({{rest_hand_state(rig_, Hand::Right), rest_hand_state(rig_, Hand::Left)}});
    return timeline_.finish(sign_start, sign_end);
  }

 private:
  float move_time(const HandState& from, const HandState& to) const {
    return transition_duration(glm::length(to.position - from.position)) / (speed_ * kTransitionTempo);
  }

  // Both hands move to their targets together, taking as long as the longer path needs.
  void transition_to(const ByHand<HandState>& target) {
    float d = 0.0f;
    for (Hand hand : kBothHands) d = std::max(d, move_time(timeline_.state(hand), target[hand]));
    timeline_.move_both_to(target, d);
  }

  const SigningRig& rig_;
  float speed_;
  TwoHandTimeline timeline_;
  std::vector<CachedSignSpan> spans_;
  ByHand<HandState> idle_;
  ByHand<bool> signed_{{false, false}};  // the hand has signed in this utterance
};

std::string letters_only(std::string_view text) {
  std::string out;
  for (char c : text)
    if (find_asl_letter(c)) out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return out;
}

bool is_blank(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
}

}  // namespace

Signer::Signer(const Avatar& avatar, LayeredLexicon& lexicon)
    : avatar_(&avatar),
      lexicon_(&lexicon),
      rig_(make_signing_rig(avatar)),
      cache_(std::make_unique<SignMotionCache>(rig_)),
      memo_(std::make_unique<LexiconMemo>(lexicon)) {}

Signer::~Signer() = default;

void Signer::keep_citations_in(const std::string& path) {
  store_ = std::make_unique<CitationStore>(path, rig_);
  cache_->persist_to(store_->readable() ? store_.get() : nullptr);
}

Signer::ModelledTiming Signer::modelled_timing(const std::string& notation) const {
  {
    std::lock_guard lock(modelled_mutex_);
    if (const auto it = modelled_.find(notation); it != modelled_.end()) return it->second;
  }
  // Throws for a notation that does not parse (nothing is kept then).
  const CitationTiming model = citation_timing(sign::parse_hamnosys_unicode(notation));
  const ModelledTiming timing{kPlannedPerModelSecond * model.moving(),
                              model.movements > 0 ? kPlannedPerModelSecond * model.movement / static_cast<float>(model.movements) : 0.0f,
                              static_cast<int>(model.repeats.size())};
  std::lock_guard lock(modelled_mutex_);
  constexpr std::size_t kMaxKept = 8192;  // a long-lived server may meet many notations
  if (modelled_.size() >= kMaxKept) modelled_.clear();
  modelled_.emplace(notation, timing);
  return timing;
}

const ClipSignMotion& Signer::clip_sign(const SignEntry& entry, const GlossToken* placed) const {
  // Keyed by the stored bytes (a clip sign saved again under its gloss is a new motion) and the
  // places it is made at.
  std::string key(entry.clip.begin(), entry.clip.end());
  if (placed) key += "\x1f" + space_key(*placed);
  {
    std::lock_guard lock(clip_mutex_);
    if (auto it = clip_signs_.find(key); it != clip_signs_.end()) return *it->second;
  }
  std::unique_ptr<ClipSignMotion> motion;
  if (placed) {
    const ClipSignMotion& recorded = clip_sign(entry);
    motion = clip_sign_in_space(recorded, in_space(recorded.motion.plan, rig_, *placed), *cache_);
  } else {
    motion = clip_sign_motion(decode_clip_sign(entry), rig_, entry.gloss);
  }
  std::lock_guard lock(clip_mutex_);
  return *clip_signs_.emplace(std::move(key), std::move(motion)).first->second;
}

SentencePerformance Signer::say(std::string_view text, const SayOptions& options) const {
  if (options.lang != "ase")
    throw Error("no lexicon for sign language '" + options.lang + "': only 'ase' (American Sign Language) has one");
  if (!(options.speed >= 0.25f && options.speed <= 2.0f))
    throw Error("speed " + std::to_string(options.speed) + " is outside 0.25–2");
  if (!(options.fps >= 1.0f && options.fps <= 240.0f)) throw Error("fps " + std::to_string(options.fps) + " is outside 1–240");
  if (is_blank(text)) throw Error("nothing to sign: the text is empty");
  if (text.size() > kMaxSayBytes)
    throw Error("text too long: " + std::to_string(text.size()) + " bytes, at most " + std::to_string(kMaxSayBytes) +
                " in one utterance; split it into shorter pieces");

  LexiconMemo::Utterance lexicon = memo_->utterance(options.lang);
  const std::shared_ptr<const Translation> translated = lexicon.translation(text);
  const Translation& translation = *translated;
  const std::size_t n = translation.glosses.size();
  if (n > kMaxSayGlosses)
    throw Error("text too long: " + std::to_string(n) + " glosses, at most " + std::to_string(kMaxSayGlosses) +
                " in one utterance; split it into shorter pieces");
  if (std::none_of(translation.glosses.begin(), translation.glosses.end(),
                   [](const GlossToken& g) { return g.kind != GlossKind::pause; }))
    throw Error("nothing to sign in the text: no word has a sign or can be fingerspelled");

  SentencePerformance out;
  UtteranceBuilder builder(rig_, options.speed);
  std::vector<face::TimedGloss> timed(n);
  std::vector<bool> mouthed(n, false);
  std::vector<bool> sentence_start(n + 1, false);
  std::vector<bool> question_end(n + 1, false);
  for (const Sentence& s : translation.sentences) sentence_start[s.first] = true;
  for (const Marker& m : translation.markers)
    if (m.kind == MarkerKind::yes_no_question && m.last > m.first) question_end[m.last - 1] = true;

  std::vector<ClipSignFace> clip_faces;
  float first_start = -1.0f, last_end = 0.0f;
  auto spell = [&](std::string_view word, const std::string& why) -> std::optional<std::array<float, 2>> {
    const std::string letters = letters_only(word);
    if (letters.empty()) {
      out.notes.push_back("'" + std::string(word) + "' skipped: " + why + " and no letter can be fingerspelled");
      return std::nullopt;
    }
    if (!why.empty()) out.notes.push_back("'" + std::string(word) + "' fingerspelled: " + why);
    return builder.add_spelling(plan_spelling(letters, ManualAlphabet::Asl, SpellingStyle::Careful));
  };
  // A sign from the lexicon, or nullopt (with a note) when it has none the synthesizer can perform.
  // `placed`: the gloss as translated, when the sign is made at places of the signing space
  // (sentence/signing_space.hpp); its lexicon sign is then placed->sign().
  auto sign_gloss = [&](const std::string& gloss, bool phrase_final, float extra_hold,
                        const GlossToken* placed = nullptr) -> std::optional<std::array<float, 2>> {
    const std::shared_ptr<const SignEntry> entry = lexicon.find(placed ? placed->sign() : gloss);
    if (!entry) return std::nullopt;
    if (entry->notation_kind == NotationKind::clip) {
      // A keyframed sign plays its recorded motion, moved to its places in space as a notated one is.
      try {
        const ClipSignMotion& clip = clip_sign(*entry, placed && uses_space(*placed) ? placed : nullptr);
        const std::array<float, 2> span = builder.add_recorded_sign(clip.motion, phrase_final, extra_hold);
        const CachedSignSpan& placed_span = builder.spans().back();
        clip_faces.push_back({&clip.face, &clip.body, placed_span.start, placed_span.moving, placed_span.end, placed_span.tempo});
        return span;
      } catch (const Error& e) {
        out.notes.push_back(gloss + ": its clip cannot be played (" + e.what() + ")");
        return std::nullopt;
      }
    }
    if (entry->notation_kind != NotationKind::hamnosys) {
      out.notes.push_back(gloss + ": only HamNoSys and clip entries are performed, this one is " +
                          std::string(to_string(entry->notation_kind)));
      return std::nullopt;
    }
    try {
      const ModelledTiming model = modelled_timing(entry->notation);
      if (placed && uses_space(*placed))
        return builder.add_sign(cache_->sign(entry->notation, space_key(*placed),
                                             [&](const SignPlan& citation) { return in_space(citation, rig_, *placed); }),
                                phrase_final, extra_hold, model.moving, model.once, model.repeats);
      return builder.add_sign(cache_->sign(entry->notation), phrase_final, extra_hold, model.moving, model.once,
                              model.repeats);
    } catch (const Error& e) {
      out.notes.push_back(gloss + ": its notation cannot be performed (" + e.what() + ")");
      return std::nullopt;
    }
  };

  for (std::size_t i = 0; i < n; ++i) {
    const GlossToken& g = translation.glosses[i];
    const std::string source(text.substr(g.begin, g.end - g.begin));
    const bool phrase_final = i + 1 == n || translation.glosses[i + 1].kind == GlossKind::pause;
    const float extra_hold = question_end[i] ? face::kQuestionHoldSeconds : 0.0f;
    std::optional<std::array<float, 2>> span;
    switch (g.kind) {
      case GlossKind::pause: {
        const float start = builder.now();
        builder.hold((i + 1 < n && sentence_start[i + 1] ? kSentencePause : kClausePause) / options.speed);
        span = std::array<float, 2>{start, builder.now()};
        break;
      }
      case GlossKind::sign:
        span = sign_gloss(g.gloss, phrase_final, extra_hold, &g);
        if (span) mouthed[i] = true;
        else span = spell(g.sign(), "no performable sign for " + g.sign());
        break;
      case GlossKind::fingerspell: {
        std::string word;
        for (const std::string& l : g.letters) word += l;
        span = spell(word, "");
        break;
      }
      case GlossKind::number: {
        // The lexicon's number signs; other numbers digit by digit (docs/asl-lexicon.md composes
        // 21–99 as tens then units; longer numbers go in pairs).
        if ((span = sign_gloss(g.gloss, phrase_final, extra_hold))) break;
        std::vector<std::string> pieces;
        const std::string& d = g.gloss;
        const bool digits = !d.empty() && std::all_of(d.begin(), d.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (!digits) {
          span = spell(d, "");
          break;
        }
        for (std::size_t k = d.size() % 2; k <= d.size(); k += 2)
          if (k > 0) pieces.push_back(d.substr(k < 2 ? 0 : k - 2, k < 2 ? 1 : 2));
        std::optional<std::array<float, 2>> whole;
        for (std::size_t p = 0; p < pieces.size(); ++p) {
          std::vector<std::string> parts{pieces[p]};
          if (!lexicon.find(pieces[p])) parts = {pieces[p].substr(0, 1), pieces[p].substr(1)};
          for (std::size_t q = 0; q < parts.size(); ++q) {
            if (parts[q].empty()) continue;
            const bool last = p + 1 == pieces.size() && q + 1 == parts.size();
            auto part = last ? sign_gloss(parts[q], phrase_final, extra_hold) : sign_gloss(parts[q], false, 0.0f);
            if (!part) part = spell(parts[q], "");
            if (!part) continue;
            if (!whole) whole = part;
            else (*whole)[1] = (*part)[1];
          }
        }
        span = whole;
        break;
      }
    }
    if (!span) span = std::array<float, 2>{builder.now(), builder.now()};
    timed[i] = {(*span)[0], (*span)[1], g.kind};
    if (g.kind != GlossKind::pause) {
      if (first_start < 0.0f) first_start = (*span)[0];
      last_end = (*span)[1];
    }
    out.glosses.push_back({g.gloss, source, (*span)[0], (*span)[1]});
    if (builder.now() > kMaxSaySeconds) {
      char text_limit[160];
      std::snprintf(text_limit, sizeof text_limit,
                    "the utterance would last more than %.0f s (kMaxSaySeconds), passed at gloss %zu of %zu",
                    static_cast<double>(kMaxSaySeconds), i + 1, n);
      throw Error(std::string(text_limit) + " ('" + g.gloss + "'); split the text into shorter pieces or sign it faster");
    }
  }

  out.plan = builder.finish(std::max(first_start, 0.0f), last_end);
  out.clip = perform_utterance(out.plan, builder.spans(), *cache_, options.fps, &out.motion);
  out.clip.name = "say";
  const Skeleton& skeleton = avatar_->skeleton;

  // Quoted speech in role shift (sentence/role_shift.hpp): over the quote's glosses.
  std::vector<TimedRoleShift> shifts;
  if (options.nonmanuals)
    for (const RoleShift& r : translation.role_shifts)
      if (r.first < r.last && r.last <= n) shifts.push_back({timed[r.first].start, timed[r.last - 1].end, r.toward});

  std::vector<face::FaceAction> face_actions;
  if (options.nonmanuals) {
    const face::NonManualPlan nonmanual = face::plan_from_translation(translation, text, timed);
    face::NonManualActions actions = face::plan_nonmanual(nonmanual);
    face_actions = std::move(actions.face);
    for (const face::HeadAction& a : role_shift_head_actions(shifts)) actions.head.push_back(a);
    face::write_head_rotations(actions.head, skeleton, out.clip);
    write_role_shift_torso(shifts, skeleton, out.clip);
  }
  if (options.mouthing) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!mouthed[i]) continue;
      const GlossToken& g = translation.glosses[i];
      // An index the grammar added after a noun (BOY IX-3a) shares the noun's words: mouthed once.
      if (i > 0 && g.lexeme.rfind("IX-3", 0) == 0 && translation.glosses[i - 1].begin == g.begin &&
          translation.glosses[i - 1].end == g.end)
        continue;
      try {
        face::append_mouthing(text.substr(g.begin, g.end - g.begin), timed[i].start, timed[i].end,
                              {kMouthingAmplitude}, face_actions);
      } catch (const Error& e) {
        out.notes.push_back("no mouthing for '" + out.glosses[i].source + "': " + e.what());
      }
    }
  }
  if (!face_actions.empty()) face::write_face_channels(face_actions, out.clip);
  for (const ClipSignFace& face : clip_faces) add_clip_sign_face(face, options.fps, out.clip);
  write_gaze_with_role_shift(shifts, rig_, out.clip, options.fps);
  face::write_jaw_from_channel(skeleton, out.clip);
  // The clip signs' head and torso keys over the nods, role shifts and gaze of the utterance.
  for (const ClipSignFace& body : clip_faces) add_clip_sign_body(body, skeleton, options.fps, out.clip);
  out.clip.duration = std::max(out.clip.duration, out.clip.end_time());
  out.duration = out.clip.duration;
  return out;
}


SentencePerformance Signer::sign_sequence(std::span<const NotatedSign> signs, const SayOptions& options) const {
  if (!(options.speed >= 0.25f && options.speed <= 2.0f))
    throw Error("speed " + std::to_string(options.speed) + " is outside 0.25–2");
  if (!(options.fps >= 1.0f && options.fps <= 240.0f)) throw Error("fps " + std::to_string(options.fps) + " is outside 1–240");
  if (signs.empty()) throw Error("nothing to sign: no sign was given");
  if (signs.size() > kMaxSayGlosses)
    throw Error(std::to_string(signs.size()) + " signs, at most " + std::to_string(kMaxSayGlosses) + " in one utterance");
  SentencePerformance out;
  UtteranceBuilder builder(rig_, options.speed);
  float first_start = -1.0f, last_end = 0.0f;
  for (std::size_t i = 0; i < signs.size(); ++i) {
    const ModelledTiming model = modelled_timing(signs[i].notation);
    const std::array<float, 2> span =
        builder.add_sign(cache_->sign(signs[i].notation), i + 1 == signs.size(), 0.0f, model.moving, model.once, model.repeats);
    if (first_start < 0.0f) first_start = span[0];
    last_end = span[1];
    out.glosses.push_back({signs[i].gloss, signs[i].gloss, span[0], span[1]});
    if (builder.now() > kMaxSaySeconds)
      throw Error("the signs would last more than " + std::to_string(static_cast<int>(kMaxSaySeconds)) + " s, passed at sign " +
                  std::to_string(i + 1) + " of " + std::to_string(signs.size()));
  }
  out.plan = builder.finish(first_start, last_end);
  out.clip = perform_utterance(out.plan, builder.spans(), *cache_, options.fps, &out.motion);
  out.clip.name = "sign";
  write_gaze_with_role_shift({}, rig_, out.clip, options.fps);
  face::write_jaw_from_channel(avatar_->skeleton, out.clip);
  out.clip.duration = std::max(out.clip.duration, out.clip.end_time());
  out.duration = out.clip.duration;
  return out;
}

}  // namespace gestura
