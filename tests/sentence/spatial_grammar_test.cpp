// Spatial grammar as performed (sentence/signing_space.hpp, sentence/role_shift.hpp): measured on
// the skeleton the signed clip poses (forward kinematics), never on the plan — where each pronoun
// points, where an agreement verb's hand goes, how far the shoulders, head and eyes turn in a
// role shift.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sentence/role_shift.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sentence/signing_space.hpp"
#include "support/signing_avatar.hpp"

namespace gestura {
namespace {

struct World {
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  LayeredLexicon layers;
  std::optional<Signer> signer;
  World() {
    layers.push_layer(builtin);
    signer.emplace(test::signing_avatar().avatar, layers);
  }
};

World& world() {
  static World w;
  return w;
}
const SigningRig& rig() { return world().signer->rig(); }
const Skeleton& skeleton() { return rig().skeleton(); }

SentencePerformance say(std::string_view text) { return world().signer->say(text); }

std::vector<mat4> model_at(const Clip& clip, float t) {
  Pose pose;
  sample_clip(clip, t, WrapMode::Clamp, rig().rest, pose);
  std::vector<mat4> model(skeleton().size());
  local_to_model(skeleton(), pose, model);
  return model;
}

vec3 at(const std::vector<mat4>& model, const char* joint) {
  const int j = skeleton().find(joint);
  EXPECT_GE(j, 0) << joint;
  return vec3(model[static_cast<std::size_t>(j < 0 ? 0 : j)][3]);
}

// Yaw in degrees of a joint's forward (+Z) axis, + toward the avatar's left (+X).
float joint_yaw(const std::vector<mat4>& model, const char* joint) {
  const int j = skeleton().find(joint);
  EXPECT_GE(j, 0) << joint;
  const vec3 forward = vec3(model[static_cast<std::size_t>(j < 0 ? 0 : j)][2]);
  return glm::degrees(std::atan2(forward.x, forward.z));
}

vec3 flat(vec3 v) { return vec3(v.x, 0.0f, v.z); }

float degrees_between(vec3 a, vec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

float yaw_of(vec3 v) { return glm::degrees(std::atan2(v.x, v.z)); }

const PerformedGloss& gloss(const SentencePerformance& p, std::string_view name) {
  for (const PerformedGloss& g : p.glosses)
    if (g.gloss == name) return g;
  ADD_FAILURE() << "no gloss " << name;
  static const PerformedGloss none;
  return none;
}

// The right index finger's horizontal pointing direction at time t.
vec3 index_direction(const Clip& clip, float t) {
  const auto m = model_at(clip, t);
  return flat(at(m, "r_index_tip") - at(m, "r_index1"));
}

// The palm centre (wrist and middle knuckle) at time t.
vec3 palm(const Clip& clip, float t) {
  const auto m = model_at(clip, t);
  return 0.5f * (at(m, "r_wrist") + at(m, "r_middle1"));
}

TEST(SpatialGrammar, SheGaveHimTheBookPointsAtTwoPlacesAndGiveRunsBetweenThem) {
  const SentencePerformance p = say("She gave him the book.");
  const PerformedGloss& she = gloss(p, "IX-3a");
  const PerformedGloss& give = gloss(p, "GIVE:3a→3b");
  const PerformedGloss& him = gloss(p, "IX-3b");
  const Locus a{3, 0}, b{3, 1};

  // The two pronouns point in directions at least 30° apart, each at its own place.
  const float she_t = 0.5f * (she.start + she.end), him_t = 0.5f * (him.start + him.end);
  const vec3 she_dir = index_direction(p.clip, she_t), him_dir = index_direction(p.clip, him_t);
  EXPECT_GE(degrees_between(she_dir, him_dir), 30.0f);
  const auto tip = [&](float t) { return at(model_at(p.clip, t), "r_index_tip"); };
  EXPECT_LE(degrees_between(she_dir, flat(locus_point(rig(), a, 0.9f) - tip(she_t))), 20.0f);
  EXPECT_LE(degrees_between(him_dir, flat(locus_point(rig(), b, 0.9f) - tip(him_t))), 20.0f);
  EXPECT_LT(yaw_of(she_dir), -15.0f);  // 3a on the signer's right (−X)
  EXPECT_GT(yaw_of(him_dir), 15.0f);   // 3b on the left

  // GIVE's hand starts nearer her place and ends nearer his, having moved toward his.
  const vec3 pa = locus_point(rig(), a), pb = locus_point(rig(), b);
  const vec3 start = palm(p.clip, give.start), end = palm(p.clip, give.end);
  EXPECT_LT(glm::distance(start, pa), glm::distance(start, pb));
  EXPECT_LT(glm::distance(end, pb), glm::distance(end, pa));
  EXPECT_GT(glm::dot(end - start, glm::normalize(pb - pa)), 0.15f);
}

TEST(SpatialGrammar, TheBoysPlaceIsPointedAtBeforeHelpMovesThere) {
  // "The teacher helped the boy.": BOY's index points at 3b before HELP starts, and HELP's hand
  // then moves from the teacher's place toward it.
  const SentencePerformance p = say("The teacher helped the boy.");
  const PerformedGloss& boy = gloss(p, "IX-3b");
  const PerformedGloss& help = gloss(p, "HELP:3a→3b");
  EXPECT_LE(boy.end, help.start + 1e-4f);
  const float boy_t = 0.5f * (boy.start + boy.end);
  const vec3 boy_dir = index_direction(p.clip, boy_t);
  const vec3 tip = at(model_at(p.clip, boy_t), "r_index_tip");
  EXPECT_LE(degrees_between(boy_dir, flat(locus_point(rig(), Locus{3, 1}, 0.9f) - tip)), 20.0f);
  const vec3 pa = locus_point(rig(), Locus{3, 0}), pb = locus_point(rig(), Locus{3, 1});
  const vec3 start = palm(p.clip, help.start), end = palm(p.clip, help.end);
  EXPECT_GT(glm::dot(end - start, glm::normalize(pb - pa)), 0.10f);
  EXPECT_LT(glm::distance(end, pb), glm::distance(end, pa));
}

TEST(SpatialGrammar, PossessivesFaceTheirPlacesWithThePalm) {
  // POSS is a flat hand, fingers up: its palm, not its fingers, turns to the owner's place.
  const SentencePerformance p = say("He took her dog and his cat.");
  const auto palm_facing = [&](const PerformedGloss& g) {
    const auto m = model_at(p.clip, 0.5f * (g.start + g.end));
    const vec3 fingers = at(m, "r_middle1") - at(m, "r_wrist");
    const vec3 across = at(m, "r_pinky1") - at(m, "r_index1");  // thumb side to little finger
    return flat(glm::cross(fingers, across));                   // the right hand's palm normal
  };
  const vec3 hers = palm_facing(gloss(p, "POSS-3b")), his = palm_facing(gloss(p, "POSS-3a"));
  EXPECT_GE(degrees_between(hers, his), 30.0f);
  EXPECT_GT(yaw_of(hers), 15.0f);  // 3b, on the left
  EXPECT_LT(yaw_of(his), -15.0f);  // 3a, on the right
}

TEST(SpatialGrammar, IGiveYouAndYouGiveMeRunInOppositeDirections) {
  const SentencePerformance mine = say("I give you the book.");
  const SentencePerformance yours = say("You give me the book.");
  const PerformedGloss& out = gloss(mine, "GIVE:1→2");
  const PerformedGloss& in = gloss(yours, "GIVE:2→1");
  const vec3 away = palm(mine.clip, out.end) - palm(mine.clip, out.start);
  const vec3 toward = palm(yours.clip, in.end) - palm(yours.clip, in.start);
  EXPECT_GT(away.z, 0.08f);     // out from the chest toward the addressee
  EXPECT_LT(toward.z, -0.08f);  // in from the addressee to the chest
  EXPECT_LT(glm::dot(glm::normalize(flat(away)), glm::normalize(flat(toward))), -0.7f);
}

TEST(SpatialGrammar, TheySweepsAnArcOverThePlacesOfThoseMeant) {
  const SentencePerformance p = say("John met Mary. They went home.");
  const PerformedGloss& they = gloss(p, "IX-3-PL:3a+3b");
  const float first = yaw_of(index_direction(p.clip, they.start));
  const float last = yaw_of(index_direction(p.clip, they.end));
  EXPECT_LT(first, -15.0f) << "starts at 3a, on the right";
  EXPECT_GT(last, 15.0f) << "ends at 3b, on the left";
}

TEST(SpatialGrammar, QuotedSpeechTurnsShouldersHeadAndEyesTowardTheSpeaker) {
  // She is at 3a, on the signer's right: the shift turns right (negative yaw).
  const SentencePerformance p = say("She said, \"I am hungry.\"");
  const PerformedGloss& before = gloss(p, "SAY");
  const PerformedGloss& quoted = gloss(p, "HUNGRY");
  const auto outside = model_at(p.clip, 0.5f * (before.start + before.end));
  const auto inside = model_at(p.clip, 0.5f * (quoted.start + quoted.end));
  EXPECT_LT(std::abs(joint_yaw(outside, "vt1")), 3.0f);
  const float shoulders = joint_yaw(inside, "vt1");
  const float head = joint_yaw(inside, "skullbase");
  EXPECT_LT(shoulders, -0.8f * kRoleShiftTorsoDegrees);
  EXPECT_LT(head, shoulders - 0.5f * kRoleShiftHeadDegrees);
  // The eyes turn within the head, further toward her place, and are straight ahead before.
  const float eyes_inside = joint_yaw(inside, "r_eyeball_joint") - head;
  const float eyes_outside = joint_yaw(outside, "r_eyeball_joint") - joint_yaw(outside, "skullbase");
  EXPECT_LT(eyes_inside, eyes_outside - 3.0f);
  // Without quotes there is no shift.
  const SentencePerformance plain = say("She said she was hungry.");
  for (const PerformedGloss& g : plain.glosses)
    EXPECT_LT(std::abs(joint_yaw(model_at(plain.clip, 0.5f * (g.start + g.end)), "vt1")), 3.0f) << g.gloss;
}

}  // namespace
}  // namespace gestura
