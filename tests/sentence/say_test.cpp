// gestura say: text → a joined, timed signing performance with face channels (sentence/signer.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "gestura/anim/track.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/sign_performer.hpp"

namespace gestura {
namespace {

// One avatar, lexicon and rig for the whole suite (building them is the slow part).
struct World {
  Avatar avatar = build_avatar();
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  LayeredLexicon layers;
  std::optional<Signer> signer;
  World() {
    layers.push_layer(builtin);
    signer.emplace(avatar, layers);
  }
};

World& world() {
  static World w;
  return w;
}

SentencePerformance say(std::string_view text, const SayOptions& options = {}) { return world().signer->say(text, options); }

std::vector<const PerformedGloss*> signed_glosses(const SentencePerformance& p) {
  std::vector<const PerformedGloss*> out;
  for (const PerformedGloss& g : p.glosses)
    if (g.gloss != "PAUSE") out.push_back(&g);
  return out;
}

float channel_max(const Clip& clip, std::string_view name, float t0, float t1) {
  const int c = clip.find_channel(std::string(name));
  if (c < 0) return 0.0f;
  float m = 0.0f;
  for (float t = t0; t <= t1; t += 0.02f) m = std::max(m, sample_track(clip.channels[static_cast<std::size_t>(c)], t));
  return m;
}

// Largest head yaw (degrees) the skullbase track reaches.
float max_skull_yaw_degrees(const SentencePerformance& p) {
  const int j = world().avatar.skeleton.find("skullbase");
  const QuatTrack& track = p.clip.rotations[static_cast<std::size_t>(j)];
  float m = 0.0f;
  for (const quat& q : track.values) m = std::max(m, glm::degrees(2.0f * std::asin(std::min(1.0f, std::abs(q.y)))));
  return m;
}

TEST(SaySentence, FiveSignSentenceTakesAsLongAsFluentSigning) {
  // Reference: 2.0 signs/s (docs/say.md) → 5 signs in 2.5 s; ±20 % with slack for the phrase-final
  // sign: 1.6–3.0 s from the first sign's posture to the last sign's end.
  const SentencePerformance p = say("Yesterday my mother went to the store.");
  const auto g = signed_glosses(p);
  ASSERT_EQ(g.size(), 5u);
  const float span = g.back()->end - g.front()->start;
  EXPECT_GT(span, 1.6f);
  EXPECT_LT(span, 3.0f);
  for (std::size_t i = 1; i < g.size(); ++i) EXPECT_GE(g[i]->start, g[i - 1]->end) << g[i]->gloss;
  EXPECT_GT(p.duration, g.back()->end);  // the return to rest comes after the last sign
}

TEST(SaySentence, SpeedScalesTheDuration) {
  const float normal = say("My brother bought a new car").duration;
  SayOptions slow;
  slow.speed = 0.5f;
  EXPECT_GT(say("My brother bought a new car", slow).duration, 1.7f * normal);
}

TEST(SaySentence, HandsDoNotReturnToRestBetweenSigns) {
  const SentencePerformance p = say("My brother bought a new car");
  const auto g = signed_glosses(p);
  ASSERT_GE(g.size(), 4u);
  const Avatar& a = world().avatar;
  const RenderSubject subject{a.skeleton, a.mesh, p.clip};
  Animator animator(subject);
  const auto wrist = static_cast<std::size_t>(a.skeleton.find("r_wrist"));
  const auto hip = static_cast<std::size_t>(a.skeleton.find("r_hip"));
  for (float t = g.front()->start; t <= g.back()->end; t += 1.0f / 30.0f) {
    animator.pose_at(t);
    EXPECT_GT(animator.model()[wrist][3].y, animator.model()[hip][3].y + 0.05f) << "at " << t << " s";
  }
  animator.pose_at(p.duration);  // after the utterance the hand hangs at the side again
  EXPECT_LT(animator.model()[wrist][3].y, animator.model()[hip][3].y);
}

TEST(SaySentence, YesNoQuestionRaisesTheBrows) {
  const SentencePerformance q = say("Do you like coffee?");
  const SentencePerformance s = say("I like coffee.");
  const auto gq = signed_glosses(q), gs = signed_glosses(s);
  EXPECT_GT(channel_max(q.clip, face::kBrowInnerUpL, gq.front()->start, gq.back()->end), 0.5f);
  EXPECT_LT(channel_max(s.clip, face::kBrowInnerUpL, gs.front()->start, gs.back()->end), 0.2f);
}

TEST(SaySentence, NegationShakesTheHead) {
  EXPECT_GT(max_skull_yaw_degrees(say("I don't like coffee.")), 3.0f);
  EXPECT_LT(max_skull_yaw_degrees(say("I like coffee.")), 1.0f);
}

TEST(SaySentence, MouthingDuringSignsAndNotWhenDisabled) {
  const SentencePerformance p = say("I like coffee.");
  const auto g = signed_glosses(p);
  const PerformedGloss* coffee = g.back();
  ASSERT_EQ(coffee->gloss, "COFFEE");
  float visemes = 0.0f;
  for (std::string_view v : face::kVisemes)
    if (v != face::kSil) visemes = std::max(visemes, channel_max(p.clip, v, coffee->start, coffee->end));
  EXPECT_GT(visemes, 0.2f);
  EXPECT_GT(channel_max(p.clip, face::kJawOpen, coffee->start, coffee->end), 0.05f);
  SayOptions quiet;
  quiet.mouthing = false;
  EXPECT_EQ(say("I like coffee.", quiet).clip.find_channel(std::string(face::kJawOpen)), -1);
}

TEST(SaySentence, UnknownWordIsFingerspelledLetterByLetter) {
  const SentencePerformance p = say("zyxq");
  const auto g = signed_glosses(p);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0]->gloss, "FS-ZYXQ");
  EXPECT_GT(g[0]->end - g[0]->start, 4 * 0.15f);  // four letters at a careful ~4 letters/s
  EXPECT_GT(channel_max(p.clip, face::kGazeHands, g[0]->start, g[0]->end), 0.5f);
  // The spelling hand is in front of the body, between the hips and the head, 30 cm out.
  const Avatar& a = world().avatar;
  const RenderSubject subject{a.skeleton, a.mesh, p.clip};
  Animator animator(subject);
  const auto wrist = static_cast<std::size_t>(a.skeleton.find("r_wrist"));
  const auto hip = static_cast<std::size_t>(a.skeleton.find("r_hip"));
  const auto skull = static_cast<std::size_t>(a.skeleton.find("skullbase"));
  for (float t = g[0]->start; t <= g[0]->end; t += 0.1f) {
    animator.pose_at(t);
    const vec3 w = animator.model()[wrist][3];
    EXPECT_GT(w.y, animator.model()[hip][3].y + 0.1f) << t;
    EXPECT_LT(w.y, animator.model()[skull][3].y) << t;
    EXPECT_GT(w.z, 0.15f) << t;
  }
}

TEST(SaySentence, NumbersOutsideTheLexiconAreComposed) {
  const SentencePerformance p = say("47");
  const auto g = signed_glosses(p);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0]->gloss, "47");
  // 47 is not a lexicon sign: it is 4 then 7, so it lasts clearly longer than the single sign 4.
  const SentencePerformance four_said = say("4");  // kept: signed_glosses points into it
  const auto four = signed_glosses(four_said);
  ASSERT_EQ(four.size(), 1u);
  EXPECT_GT(g[0]->end - g[0]->start, four[0]->end - four[0]->start + 0.08f);
}

// Articulation rate of an utterance as sign annotators time it: lexical signs per second from the
// first sign's onset to the last sign's offset, without pauses and fingerspelled words. Each later
// sign is counted from the end of whatever came before it (the previous sign, a pause, a spelled
// word) to the end of its own final hold, so it carries its transition in.
float signs_per_second(const SentencePerformance& p) {
  float previous_end = p.glosses.empty() ? 0.0f : p.glosses.front().start, time = 0.0f;
  int signs = 0;
  for (const PerformedGloss& g : p.glosses) {
    if (g.gloss != "PAUSE" && g.gloss.rfind("FS-", 0) != 0) {
      time += g.end - previous_end;
      ++signs;
    }
    previous_end = g.end;
  }
  return time > 0.0f ? static_cast<float>(signs) / time : 0.0f;
}

TEST(ProsodyRate, SentencesAreWithinTwentyPercentOfAFluentSigner) {
  // Reference 2.0 signs/s (docs/say.md: sign_prosody.hpp kReferenceSignsPerSecond); ±20 % → 1.6–2.4.
  const char* sentences[] = {
      "Yesterday my mother went to the store.",
      "My brother bought a new car.",
      "Where do you live?",
      "I don't like coffee, but I like tea.",
      "Tomorrow my friend will visit the doctor.",
      "The teacher is very happy today.",
      "Do you want to eat pizza?",
      "My sister and I went to the big store and bought a new book.",
      "The dog and the cat sleep in the house.",
      "Why are you tired?",
  };
  for (const char* text : sentences) {
    const float rate = signs_per_second(say(text));
    EXPECT_GE(rate, 0.8f * 2.0f) << text;
    EXPECT_LE(rate, 1.2f * 2.0f) << text;
  }
}

TEST(ProsodyRate, EverySignIsHeldLongEnoughToBeSeen) {
  // POSS-1 (MY) and IX-1 (I) have no movement: they still last 0.3 s or more.
  const SentencePerformance p = say("My brother and I bought a new car.");
  for (const PerformedGloss* g : signed_glosses(p)) EXPECT_GE(g->end - g->start, 0.3f - 1e-4f) << g->gloss;
}

TEST(ProsodyRate, CirclesAndRepeatsAreNotSqueezedBelowReadability) {
  // LIBRARY (an L hand circling once) lasted 0.35 s inside a sentence, its circle 0.25 s; MUST
  // (a hooked X bending down twice) 0.13 s a stroke.
  const SentencePerformance p = say("Where is the library? I need to go there today.");
  bool library = false, must = false;
  for (const PerformedGloss* g : signed_glosses(p)) {
    if (g->gloss == "LIBRARY") {
      library = true;
      EXPECT_GE(g->end - g->start, 0.38f);
    }
    if (g->gloss == "MUST") {
      must = true;
      EXPECT_GE(g->end - g->start, 0.40f - 1e-3f);  // two cycles of ≥ 0.15 s and the holds
    }
  }
  EXPECT_TRUE(library && must);
}

TEST(ProsodyRate, PhraseFinalSignIsLongerThanTheSameSignInside) {
  const SentencePerformance inside_performance = say("My car is new, I like it.");
  const SentencePerformance final_performance = say("I like my new car.");
  const auto inside = signed_glosses(inside_performance), final = signed_glosses(final_performance);
  auto span_of = [](const std::vector<const PerformedGloss*>& g, const std::string& gloss) {
    for (const PerformedGloss* x : g)
      if (x->gloss == gloss) return x->end - x->start;
    return 0.0f;
  };
  ASSERT_EQ(final.back()->gloss, "CAR");
  EXPECT_GT(span_of(final, "CAR"), span_of(inside, "CAR") + 0.1f);
}

TEST(ProsodyRate, FullStopPausesHalfASecond) {
  const SentencePerformance p = say("I like coffee. My brother likes tea.");
  bool found = false;
  for (const PerformedGloss& g : p.glosses)
    if (g.gloss == "PAUSE" && g.source == ".") {
      EXPECT_NEAR(g.end - g.start, 0.5f, 0.02f);
      found = true;
    }
  EXPECT_TRUE(found);
}

TEST(ProsodyRate, GlobalSpeedScalesTheWholeUtterance) {
  const char* text = "Yesterday my mother went to the store.";
  const float normal = say(text).duration;
  for (float speed : {0.25f, 0.5f, 2.0f}) {
    SayOptions o;
    o.speed = speed;
    EXPECT_NEAR(say(text, o).duration * speed / normal, 1.0f, 0.1f) << speed;
  }
}

// Palm centre of each hand (model space) in the pose the animator holds.
ByHand<vec3> palm_centres(const Animator& animator, const SigningRig& rig) {
  ByHand<vec3> out;
  for (Hand h : kBothHands) {
    const HandRig& hand = rig.hand(h);
    out[h] = vec3(animator.model()[joint_slot(hand.wrist)] * vec4(hand.palm_centre_local, 1.0f));
  }
  return out;
}

TEST(SayMotion, CachedMotionReachesTheTargetsNearlyAsWellAsIkEveryFrame) {
  // The utterance's joint motion is stitched from cached citation signs and joint-space
  // transitions; the reference performs the same plan with IK every frame (the former pipeline).
  // Compared at every key instant of the signs — each end of each plan segment inside a sign or a
  // fingerspelled word — by how far each signing palm is from its planned place. Neither solver
  // reaches every place (a place on or in the body is pushed out, and the result depends on where
  // the solver starts), so the test asks: (1) the cached motion is on the plan (within 1 cm) at
  // least 95 % as often as the per-frame solver (time-scaled citation forms and joint-space
  // transitions cannot be exact everywhere the per-frame solver is); (2) at 85 % of the instants it is no more than 1 cm
  // farther from the plan than the per-frame solver (docs/say.md lists the exceptions).
  const Avatar& a = world().avatar;
  const SigningRig& rig = world().signer->rig();
  int instants = 0, not_worse = 0, cached_on_plan = 0, reference_on_plan = 0;
  for (const char* text : {"Yesterday my mother went to the store.", "I don't like coffee, but I like tea.",
                           "Do you want to eat pizza?", "Yesterday my sister and I went to the big store and bought a "
                                                        "new book for Anna."}) {
    const SentencePerformance p = say(text);
    const Clip reference = perform_plan(p.plan, rig, PerformOptions{30.0f});
    const RenderSubject fast_subject{a.skeleton, a.mesh, p.clip}, reference_subject{a.skeleton, a.mesh, reference};
    Animator fast(fast_subject), slow(reference_subject);
    for (Hand h : kBothHands) {
      const HandTimeline& timeline = p.plan.hand(h);
      for (const HandSegment& seg : timeline.segments) {
        for (const float t : {seg.start, seg.end}) {
          const bool in_sign = std::any_of(p.glosses.begin(), p.glosses.end(), [&](const PerformedGloss& g) {
            return g.gloss != "PAUSE" && t >= g.start - 1e-4f && t <= g.end + 1e-4f;
          });
          const HandState planned = sample_hand(timeline, t);
          if (!in_sign || !planned.active) continue;
          fast.pose_at(t);
          slow.pose_at(t);
          const float f = glm::distance(palm_centres(fast, rig)[h], planned.position);
          const float r = glm::distance(palm_centres(slow, rig)[h], planned.position);
          ++instants;
          not_worse += f <= r + 0.01f ? 1 : 0;
          cached_on_plan += f <= 0.01f ? 1 : 0;
          reference_on_plan += r <= 0.01f ? 1 : 0;
        }
      }
    }
  }
  ASSERT_GT(instants, 200);
  EXPECT_GE(cached_on_plan, 0.95 * reference_on_plan);
  EXPECT_GE(not_worse, 0.85 * instants);
  RecordProperty("key_instants", instants);
  RecordProperty("cached_within_1cm_of_plan", cached_on_plan);
  RecordProperty("per_frame_ik_within_1cm_of_plan", reference_on_plan);
  RecordProperty("cached_not_worse_than_per_frame_by_1cm", not_worse);
}

// Deepest any hand point goes inside the signing rig's collision body over a clip (metres, ≤ 0 outside).
float deepest_penetration(const Clip& clip, float duration) {
  const Avatar& a = world().avatar;
  const SigningRig& rig = world().signer->rig();
  const RenderSubject subject{a.skeleton, a.mesh, clip};
  Animator animator(subject);
  HandPoints points;
  float deepest = -1.0f;
  for (float t = 0.0f; t <= duration; t += 1.0f / 30.0f) {
    animator.pose_at(t);
    for (const HandRig& h : rig.hands) {
      hand_surface_points(rig, h.hand, animator.model(), points);
      for (const vec3& x : points) deepest = std::max(deepest, -body_signed_distance(rig, animator.model(), x));
    }
  }
  return deepest;
}

TEST(SayMotion, HandsStayOutOfTheBodyAsWellAsWithIkEveryFrame) {
  // Joint-space transitions are checked against the body and bent around it (utterance_performer.hpp);
  // over whole sentences the hands may not go deeper into the body than with IK every frame, which
  // pushes the hand out at every frame, plus 5 mm.
  for (const char* text : {"Where do you live?", "Do you want to eat pizza?", "The dog and the cat sleep in the house.",
                           "My brother bought a new car."}) {
    const SentencePerformance p = say(text);
    const Clip reference = perform_plan(p.plan, world().signer->rig(), PerformOptions{30.0f});
    // Only the arms and hands: the head's non-manual motion is not part of either arm motion.
    Clip arms = p.clip;
    for (std::size_t j = 0; j < arms.rotations.size(); ++j)
      if (!reference.rotations[j].size()) arms.rotations[j] = {};
    const float cached = deepest_penetration(arms, p.duration);
    const float per_frame = deepest_penetration(reference, p.duration);
    EXPECT_LE(cached, std::max(per_frame, 0.0f) + 0.005f) << text << " (per-frame IK " << per_frame << " m)";
  }
}

void expect_error(std::string_view text, const SayOptions& options, const std::string& needle) {
  try {
    say(text, options);
    ADD_FAILURE() << "no error for " << needle;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(SayBadInput, ClearErrors) {
  expect_error("", {}, "empty");
  expect_error("  \n\t ", {}, "empty");
  expect_error(std::string(1 << 20, 'a'), {}, "too long");
  std::string many;
  for (int i = 0; i < 400; ++i) many += "coffee ";
  expect_error(many, {}, "glosses");
  expect_error(std::string("\xff\xfe\x01\x80 junk", 9), {}, "UTF-8");
  SayOptions bsl;
  bsl.lang = "xyz";
  expect_error("hello", bsl, "'xyz'");
  SayOptions fast;
  fast.speed = 9.0f;
  expect_error("hello", fast, "speed");
  expect_error("?!.", {}, "nothing to sign");
}

// An utterance has a cap on its duration (kMaxSaySeconds), checked gloss by gloss while planning so
// that no motion is made for text that would be refused: 300 long unknown words fingerspelled at
// the slowest tempo would last hours.
TEST(SayLimits, AnUtteranceLongerThanTheCapIsRefusedAtTheGlossThatPassesIt) {
  std::string text;
  for (int w = 0; w < 290; ++w) text += std::string(w % 2 ? "zyxwvutsrqponmlkjihgfedcbazyxwvutsrqpon" : "qwertyuiopasdfghjklzxcvbnmqwertyuiopasdfg") + " ";
  SayOptions slow;
  slow.speed = 0.25f;
  try {
    say(text, slow);
    ADD_FAILURE() << "no error for an utterance of hours";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("kMaxSaySeconds"), std::string::npos) << what;
    EXPECT_NE(what.find("1800 s"), std::string::npos) << what;
    EXPECT_NE(what.find("passed at gloss"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace gestura
