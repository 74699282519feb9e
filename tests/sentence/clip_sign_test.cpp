// A clip sign (keyframed in the studio's timeline) stored in the lexicon and played in a sentence
// like any other sign (sentence/clip_sign_motion.hpp, lexicon/clip_sign.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "gestura/anim/sampler.hpp"
#include "gestura/anim/track.hpp"
#include "gestura/core/error.hpp"
#include "gestura/lexicon/clip_sign.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/sentence/sign_prosody.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace gestura {
namespace {

constexpr float kClipSeconds = 0.8f;
constexpr float kPeakSeconds = 0.4f;
constexpr float kPeakBendDegrees = 60.0f;

float degrees_between(const quat& a, const quat& b) {
  return glm::degrees(2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(glm::normalize(a), glm::normalize(b))))));
}

// Built once: the avatar, the built-in lexicon with a user layer holding the clip sign ZAP.
struct World {
  Avatar avatar = build_avatar();
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  Lexicon user = Lexicon::in_memory();
  LayeredLexicon layers;
  std::optional<Signer> signer;
  Clip zap;
  int elbow = -1;
  quat peak{1, 0, 0, 0};

  World() {
    layers.push_layer(builtin);
    layers.push_layer(user);
    signer.emplace(avatar, layers);
    const Skeleton& s = avatar.skeleton;
    const SigningRig& rig = signer->rig();
    // The right arm keyed from the relaxed signing posture, the elbow bent 60° more at 0.4 s and
    // back; every other joint untouched (its track empty: at rest). The inner left brow rises with it.
    zap.name = "zap";
    zap.duration = kClipSeconds;
    zap.resize_joints(s.size());
    const HandRig& arm = rig.hand(Hand::Right);
    elbow = arm.elbow;
    for (const int j : {arm.clavicle, arm.shoulder, arm.elbow, arm.wrist}) {
      const quat q = rig.neutral.rotations[joint_slot(j)];
      QuatTrack& track = zap.rotations[joint_slot(j)];
      track.interpolation = Interpolation::Linear;
      if (j == elbow) {
        peak = glm::normalize(q * glm::angleAxis(glm::radians(kPeakBendDegrees), vec3(1, 0, 0)));
        track.add(0.0f, q), track.add(kPeakSeconds, peak), track.add(kClipSeconds, q);
      } else {
        track.add(0.0f, q), track.add(kClipSeconds, q);
      }
    }
    FloatTrack& brow = zap.channel("browInnerUp_L");
    brow.add(0.0f, 0.0f), brow.add(kPeakSeconds, 1.0f), brow.add(kClipSeconds, 0.0f);
    SignEntry e;
    e.gloss = "ZAP";
    e.language = "ase";
    e.notation_kind = NotationKind::clip;
    e.clip = encode_clip_sign(zap, s);
    e.keywords = {Keyword{"zap", "eng", ""}};
    user.add(e);
  }
};

World& world() {
  static World w;
  return w;
}

const PerformedGloss& gloss_named(const SentencePerformance& p, const std::string& gloss) {
  for (const PerformedGloss& g : p.glosses)
    if (g.gloss == gloss) return g;
  throw Error("no gloss " + gloss);
}

TEST(ClipSign, StoredBlobKeepsTheMotionAndTheFaceChannels) {
  World& w = world();
  const std::optional<SignEntry> row = w.user.find("ZAP", "ase");
  ASSERT_TRUE(row);
  const Clip back = decode_clip_sign(*row);
  ASSERT_EQ(back.joint_count(), w.avatar.skeleton.size());
  EXPECT_LT(degrees_between(sample_track(back.rotations[joint_slot(w.elbow)], kPeakSeconds), w.peak), 1.0f);
  const int brow = back.find_channel("browInnerUp_L");
  ASSERT_GE(brow, 0);
  EXPECT_NEAR(sample_track(back.channels[static_cast<std::size_t>(brow)], kPeakSeconds), 1.0f, 1e-6f);
  EXPECT_NEAR(sample_track(back.channels[static_cast<std::size_t>(brow)], 0.2f), 0.5f, 1e-6f);
}

TEST(ClipSign, ACutBlobIsAnErrorNamingTheSign) {
  std::optional<SignEntry> row = world().user.find("ZAP", "ase");
  ASSERT_TRUE(row);
  row->clip.resize(row->clip.size() - 3);
  try {
    (void)decode_clip_sign(*row);
    FAIL() << "a cut blob decoded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ZAP"), std::string::npos) << e.what();
  }
}

TEST(ClipSign, GlossListsIt) {
  LexiconInventory inventory(world().layers, "ase");
  const Translation t = translate_to_gloss("Hello, zap!", inventory);
  bool found = false;
  for (const GlossToken& g : t.glosses) found = found || (g.gloss == "ZAP" && g.kind == GlossKind::sign);
  EXPECT_TRUE(found);
}

TEST(ClipSign, ASentencePerformsTheClipsPeakAtItsTime) {
  World& w = world();
  SayOptions options;
  options.mouthing = false;
  options.nonmanuals = false;
  const SentencePerformance p = w.signer->say("hello zap", options);
  for (const std::string& note : p.notes) EXPECT_EQ(note.find("ZAP"), std::string::npos) << note;
  const PerformedGloss& hello = gloss_named(p, "HELLO");
  const PerformedGloss& zap = gloss_named(p, "ZAP");
  // ZAP ends the phrase: played at its recorded pace slowed by kPhraseFinalSlowing, from its first
  // posture on, then held.
  const float tempo = 1.0f / kPhraseFinalSlowing;
  EXPECT_NEAR(zap.end - zap.start, std::max(kClipSeconds / tempo + kPhraseFinalHold, kMinPhraseFinalSeconds), 0.01f);
  const QuatTrack& elbow = p.clip.rotations[joint_slot(w.elbow)];
  const float peak_time = zap.start + kPeakSeconds / tempo;
  EXPECT_LT(degrees_between(sample_track(elbow, peak_time), w.peak), 2.0f);
  // Before the peak the elbow is still opening toward it: the peak is not reached early.
  EXPECT_GT(degrees_between(sample_track(elbow, zap.start + 0.5f * kPeakSeconds / tempo), w.peak), 20.0f);
  // Transitions in: the sign starts at the clip's first posture, reached from HELLO's last.
  const quat first = sample_track(w.zap.rotations[joint_slot(w.elbow)], 0.0f);
  EXPECT_LT(degrees_between(sample_track(elbow, zap.start), first), 2.0f);
  EXPECT_LT(hello.end, zap.start);
  EXPECT_GT(degrees_between(sample_track(elbow, hello.end), first), 2.0f);
  // … and out: the hands return to rest after it.
  EXPECT_GT(p.duration, zap.end + 0.1f);
  // Its face channel rises with it.
  const int brow = p.clip.find_channel("browInnerUp_L");
  ASSERT_GE(brow, 0);
  const FloatTrack& b = p.clip.channels[static_cast<std::size_t>(brow)];
  EXPECT_GT(sample_track(b, peak_time), 0.95f);
  EXPECT_LT(sample_track(b, hello.start), 0.01f);
}

TEST(ClipSign, AClipForAnotherSkeletonIsANoteAndTheWordIsSpelled) {
  Lexicon user = Lexicon::in_memory();
  World& w = world();
  LayeredLexicon layers;
  layers.push_layer(w.builtin);
  layers.push_layer(user);
  Skeleton small;
  small.add_joint("root", -1, vec3(0.0f));
  Clip clip;
  clip.duration = 0.5f;
  clip.resize_joints(1);
  clip.rotations[0].add(0.0f, quat(1, 0, 0, 0)), clip.rotations[0].add(0.5f, quat(1, 0, 0, 0));
  SignEntry e;
  e.gloss = "ZOP";
  e.language = "ase";
  e.notation_kind = NotationKind::clip;
  e.clip = encode_clip_sign(clip, small);
  e.keywords = {Keyword{"zop", "eng", ""}};
  user.add(e);
  Signer signer(w.avatar, layers);
  const SentencePerformance p = signer.say("zop");
  bool noted = false;
  for (const std::string& note : p.notes) noted = noted || note.find("ZOP: its clip cannot be played") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_GT(p.duration, 0.5f);  // fingerspelled instead
}

// A clip sign keyed on the right arm from the relaxed posture: the elbow turned `bend_at_start`
// degrees more at 0, `bend_at_peak` at `peak` seconds, and back to the relaxed posture at `duration`.
Clip arm_clip(const SigningRig& rig, float duration, float bend_at_start, float bend_at_peak, float peak) {
  Clip clip;
  clip.duration = duration;
  clip.resize_joints(rig.skeleton().size());
  const HandRig& arm = rig.hand(Hand::Right);
  for (const int j : {arm.clavicle, arm.shoulder, arm.elbow, arm.wrist}) {
    const quat q = rig.neutral.rotations[joint_slot(j)];
    QuatTrack& track = clip.rotations[joint_slot(j)];
    track.interpolation = Interpolation::Linear;
    const auto bent = [&](float degrees) {
      return j == arm.elbow ? glm::normalize(q * glm::angleAxis(glm::radians(degrees), vec3(1, 0, 0))) : q;
    };
    track.add(0.0f, bent(bend_at_start)), track.add(peak, bent(bend_at_peak)), track.add(duration, bent(0.0f));
  }
  return clip;
}

SignEntry clip_entry(const std::string& gloss, const std::string& word, const Clip& clip, const Skeleton& s) {
  SignEntry e;
  e.gloss = gloss;
  e.language = "ase";
  e.notation_kind = NotationKind::clip;
  e.clip = encode_clip_sign(clip, s);
  e.keywords = {Keyword{word, "eng", ""}};
  return e;
}

TEST(ClipSign, ItsHeadKeysTurnTheHeadInASentence) {
  World& w = world();
  const Skeleton& s = w.avatar.skeleton;
  const int skull = s.find("skullbase");
  ASSERT_GE(skull, 0);
  // ZONK: the elbow bends and the head turns 25° to the avatar's left at 0.4 s, and back.
  Clip zonk = arm_clip(w.signer->rig(), kClipSeconds, 0.0f, kPeakBendDegrees, kPeakSeconds);
  const quat rest = s.rest_rotations[joint_slot(skull)];
  const quat turned = glm::normalize(rest * glm::angleAxis(glm::radians(25.0f), vec3(0, 1, 0)));
  QuatTrack& head = zonk.rotations[joint_slot(skull)];
  head.interpolation = Interpolation::Linear;
  head.add(0.0f, rest), head.add(kPeakSeconds, turned), head.add(kClipSeconds, rest);
  Lexicon user = Lexicon::in_memory();
  user.add(clip_entry("ZONK", "zonk", zonk, s));
  LayeredLexicon layers;
  layers.push_layer(w.builtin);
  layers.push_layer(user);
  Signer signer(w.avatar, layers);
  SayOptions options;
  options.mouthing = false;
  options.nonmanuals = false;
  const SentencePerformance p = signer.say("hello zonk", options);
  const PerformedGloss& hello = gloss_named(p, "HELLO");
  const PerformedGloss& sign = gloss_named(p, "ZONK");
  const float tempo = 1.0f / kPhraseFinalSlowing;
  const QuatTrack& performed = p.clip.rotations[joint_slot(skull)];
  ASSERT_FALSE(performed.empty());
  // At the clip's peak the head is turned as keyed; during HELLO it is not.
  EXPECT_LT(degrees_between(sample_track(performed, sign.start + kPeakSeconds / tempo), turned), 2.0f);
  EXPECT_LT(degrees_between(sample_track(performed, 0.5f * (hello.start + hello.end)), rest), 1.0f);
}

TEST(ClipSign, AnAgreementVerbRecordedAsAClipRunsBetweenItsPlaces) {
  World& w = world();
  const Skeleton& s = w.avatar.skeleton;
  const SigningRig& rig = w.signer->rig();
  // GIVE recorded as a clip: the hand goes out as the bent elbow opens (a path with a direction).
  Lexicon user = Lexicon::in_memory();
  // Agreement is the entry's field: the user's recording says it agrees as the built-in GIVE does.
  SignEntry give = clip_entry("GIVE", "give", arm_clip(rig, 0.6f, 70.0f, 35.0f, 0.3f), s);
  give.agreement = Agreement::forward;
  user.add(give);
  LayeredLexicon layers;
  layers.push_layer(w.builtin);
  layers.push_layer(user);
  Signer signer(w.avatar, layers);
  const auto palm = [&](const Clip& clip, float t) {
    Pose pose;
    sample_clip(clip, t, WrapMode::Clamp, rig.rest, pose);
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    return 0.5f * (vec3(model[joint_slot(s.find("r_wrist"))][3]) + vec3(model[joint_slot(s.find("r_middle1"))][3]));
  };
  const SentencePerformance mine = signer.say("I give you the book.");
  const SentencePerformance yours = signer.say("You give me the book.");
  for (const std::string& note : mine.notes) EXPECT_EQ(note.find("GIVE"), std::string::npos) << note;
  const PerformedGloss& out = gloss_named(mine, "GIVE:1→2");
  const PerformedGloss& in = gloss_named(yours, "GIVE:2→1");
  const vec3 away = palm(mine.clip, out.end) - palm(mine.clip, out.start);
  const vec3 toward = palm(yours.clip, in.end) - palm(yours.clip, in.start);
  // The same recording runs out toward the addressee in one and in toward the signer in the other.
  EXPECT_GT(away.z, 0.05f) << away.x << " " << away.y << " " << away.z;
  EXPECT_LT(toward.z, -0.05f) << toward.x << " " << toward.y << " " << toward.z;
  // The fingers keep the recording (they were never keyed: the relaxed hand's).
  const int index = s.find("r_index2");
  EXPECT_LT(degrees_between(sample_track(mine.clip.rotations[joint_slot(index)], 0.5f * (out.start + out.end)),
                            sample_track(yours.clip.rotations[joint_slot(index)], 0.5f * (in.start + in.end))),
            3.0f);
}

}  // namespace
}  // namespace gestura
