// Fingerspelling performed on the avatar (sentence/fingerspelling_performance.hpp) and the eyes on
// the spelling hand (face/eye_gaze.hpp), measured on the performed skeleton.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/eye_gaze.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sentence/fingerspelling_performance.hpp"
#include "gestura/sentence/signer.hpp"
#include "support/signing_avatar.hpp"

namespace gestura {
namespace {

const test::SigningAvatar& world() { return test::signing_avatar(); }
const Skeleton& skeleton() { return world().avatar.skeleton; }

FingerspellingPerformance spell(const std::string& text, ManualAlphabet alphabet = ManualAlphabet::Asl) {
  return perform_fingerspelling(plan_spelling(text, alphabet), world().rig);
}

std::vector<mat4> model_at(const Clip& clip, float t) {
  Pose pose;
  sample_clip(clip, t, WrapMode::Clamp, world().rig.rest, pose);
  std::vector<mat4> model(skeleton().size());
  local_to_model(skeleton(), pose, model);
  return model;
}

vec3 at(const std::vector<mat4>& model, const char* joint) {
  const int j = skeleton().find(joint);
  EXPECT_GE(j, 0) << joint;
  return vec3(model[static_cast<std::size_t>(j)][3]);
}

// Positions of one joint over [t0, t1], n samples.
std::vector<vec3> path_of(const Clip& clip, const char* joint, float t0, float t1, int n) {
  std::vector<vec3> out;
  for (int k = 0; k < n; ++k) out.push_back(at(model_at(clip, t0 + (t1 - t0) * static_cast<float>(k) / (n - 1)), joint));
  return out;
}

const LetterTarget& letter(const FingerspellingPerformance& p, std::size_t index, char expected) {
  EXPECT_EQ(p.letters.at(index).letter, expected);
  return p.letters.at(index);
}

float degrees_between(vec3 a, vec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// Where an eye looks: its model rotation applied to the direction it looks along at bind pose (+Z).
vec3 eye_forward(const std::vector<mat4>& model, const char* eye) {
  const std::vector<mat4> bind = model_at(Clip{}, 0.0f);
  const std::size_t j = static_cast<std::size_t>(skeleton().find(eye));
  const quat bind_rotation = glm::quat_cast(mat3(bind[j]));
  return glm::quat_cast(mat3(model[j])) * (glm::inverse(bind_rotation) * vec3(0, 0, 1));
}

float finger_length(const char* base) {
  const std::vector<mat4> bind = model_at(Clip{}, 0.0f);
  const std::string b(base);
  return glm::distance(at(bind, (b + "1").c_str()), at(bind, (b + "2").c_str())) +
         glm::distance(at(bind, (b + "2").c_str()), at(bind, (b + "3").c_str())) +
         glm::distance(at(bind, (b + "3").c_str()), at(bind, (b + "_tip").c_str()));
}

TEST(FingerspellingPerformance, LettersTakeTheirHandshapesAtTheirInstants) {
  const FingerspellingPerformance p = spell("AB");
  const LetterTarget& a = letter(p, 0, 'A');
  const LetterTarget& b = letter(p, 1, 'B');
  const float index = finger_length("r_index");
  // Middle of each letter's hold: A is a fist (index curled, its tip near its knuckle), B a flat hand.
  const auto ma = model_at(p.clip, 0.5f * (a.reached + a.end));
  const auto mb = model_at(p.clip, 0.5f * (b.reached + b.end));
  EXPECT_LT(glm::distance(at(ma, "r_index_tip"), at(ma, "r_index1")), 0.6f * index);
  EXPECT_GT(glm::distance(at(mb, "r_index_tip"), at(mb, "r_index1")), 0.95f * index);
  EXPECT_GT(glm::distance(at(mb, "r_pinky_tip"), at(mb, "r_pinky1")), 0.95f * finger_length("r_pinky"));
  // Fingers up at B: the index points within 25° of +Y.
  EXPECT_LT(degrees_between(at(mb, "r_index_tip") - at(mb, "r_index1"), vec3(0, 1, 0)), 25.0f);
  // The hand is up in front of the shoulder while spelling, the other arm hangs at rest.
  const auto rest = model_at(Clip{}, 0.0f);
  EXPECT_GT(at(mb, "r_wrist").y, at(rest, "r_elbow").y);
  EXPECT_GT(at(mb, "r_wrist").z, at(rest, "r_wrist").z + 0.15f);
  EXPECT_LT(glm::distance(at(mb, "l_wrist"), at(rest, "l_wrist")), 0.01f);
}

// A point of the right hand in its own frame, in centimetres from the index knuckle: x towards the
// thumb side, y along the hand (wrist to middle knuckle), z out of the palm.
vec3 in_hand(const std::vector<mat4>& m, const char* joint) {
  const vec3 up = glm::normalize(at(m, "r_middle1") - at(m, "r_wrist"));
  vec3 radial = at(m, "r_index1") - at(m, "r_pinky1");
  radial = glm::normalize(radial - glm::dot(radial, up) * up);
  vec3 palmar = glm::cross(up, radial);
  if (glm::dot(at(m, "r_index2") - at(m, "r_index1"), palmar) < 0.0f) palmar = -palmar;  // the fist curls palmward
  const vec3 d = at(m, joint) - at(m, "r_index1");
  return 100.0f * vec3(glm::dot(d, radial), glm::dot(d, up), glm::dot(d, palmar));
}

TEST(FingerspellingPerformance, TheThumbLiesAlongTheFistInAAndAcrossItInS) {
  const FingerspellingPerformance p = spell("AS");
  const LetterTarget& a = letter(p, 0, 'A');
  const LetterTarget& s = letter(p, 1, 'S');
  const auto ma = model_at(p.clip, 0.5f * (a.reached + a.end));
  const auto ms = model_at(p.clip, 0.5f * (s.reached + s.end));
  // A: the thumb against the side of the curled index, its tip about level with the top of the
  // fist (the index's middle joint) — not standing above it like a thumbs-up (4.2 cm above the
  // knuckle and 4.3 cm from the middle joint before).
  const vec3 a_tip = in_hand(ma, "r_thumb_tip"), a_pip = in_hand(ma, "r_index2");
  EXPECT_LT(a_tip.y, a_pip.y + 2.5f);
  EXPECT_LT(glm::distance(a_tip, a_pip), 3.0f);
  EXPECT_GT(a_tip.x, a_pip.x);  // on the thumb side of the index, not over the fingers
  EXPECT_GT(a_tip.z, 2.0f);     // forward with the curled index, not back at the palm
  // S: the thumb across the front of the curled fingers, its tip between the middle and the ring
  // finger's middle joints — not past the little finger (7.0 cm across before, the little
  // finger's middle joint 6.8 cm).
  const vec3 s_tip = in_hand(ms, "r_thumb_tip"), s_ip = in_hand(ms, "r_thumb3");
  EXPECT_LT(s_tip.x, in_hand(ms, "r_middle2").x);
  EXPECT_GT(s_tip.x, in_hand(ms, "r_ring2").x);
  EXPECT_GT(s_ip.z, in_hand(ms, "r_index2").z);  // in front of the fingers
}

TEST(FingerspellingPerformance, FluentLettersFollowOneAnotherAtTheirRate) {
  // Reference: fluent ASL fingerspelling at about 5–7 letters per second (docs/sign-phonology.md).
  const FingerspellingPerformance p = spell("BCDFGH");
  ASSERT_EQ(p.letters.size(), 6u);
  const float per_letter = (p.letters.back().reached - p.letters.front().reached) / 5.0f;
  EXPECT_GT(1.0f / per_letter, 5.0f);
  EXPECT_LT(1.0f / per_letter, 7.0f);
  // Each letter is reached in its transition: the hand does not stand still between letters.
  for (std::size_t k = 1; k < p.letters.size(); ++k) {
    const LetterTarget& l = p.letters[k];
    EXPECT_GT(l.reached - l.start, 0.04f) << l.letter;
    EXPECT_NEAR(l.start, p.letters[k - 1].end, 1e-4f) << l.letter;
  }
}

TEST(FingerspellingPerformance, JIsDrawnDownThenHookedTowardTheMidline) {
  const FingerspellingPerformance p = spell("JAZZ");
  const LetterTarget& j = letter(p, 0, 'J');
  ASSERT_GT(j.movement_end - j.reached, 0.2f);
  const std::vector<vec3> tip = path_of(p.clip, "r_pinky_tip", j.reached, j.movement_end, 41);
  const auto lowest = std::min_element(tip.begin(), tip.end(), [](vec3 a, vec3 b) { return a.y < b.y; });
  const vec3 start = tip.front(), low = *lowest, end = tip.back();
  // Down: the little finger drops at least 4 cm, mostly vertically at first.
  EXPECT_LT(low.y, start.y - 0.04f);
  const vec3 early = tip[16] - start;  // 40% of the time (minimum jerk: the path starts slowly)
  EXPECT_LT(early.y, -0.01f);
  EXPECT_GT(std::abs(early.y), std::abs(early.x));
  // The hook: after the lowest point the tip travels toward the midline (+X for the right hand)
  // and comes up again, and the lowest point is inside the stroke, not at its end.
  EXPECT_LT(lowest - tip.begin(), 38);
  EXPECT_GT(end.x - low.x, 0.015f);
  EXPECT_GT(end.y - low.y, 0.005f);
  // The palm turns toward the signer by the end (the forearm supinates).
  const auto m = model_at(p.clip, j.movement_end);
  const vec3 across = at(m, "r_index1") - at(m, "r_pinky1");  // radial side of the palm
  const vec3 along = at(m, "r_middle1") - at(m, "r_wrist");
  const vec3 palm = glm::normalize(glm::cross(across, along));  // right hand: out of the palm
  EXPECT_LT(palm.z, -0.3f) << palm.x << " " << palm.y << " " << palm.z;
}

// Strokes of a path in the frontal plane: runs in which the sideways (x) motion keeps its sense;
// each stroke is its net displacement. Steps under 0.5 mm sideways do not end a run.
std::vector<vec3> strokes(const std::vector<vec3>& path) {
  std::vector<vec3> out;
  int sense = 0;
  vec3 from = path.front();
  for (std::size_t k = 1; k < path.size(); ++k) {
    const float dx = path[k].x - path[k - 1].x;
    if (std::abs(dx) < 5e-4f) continue;
    const int now = dx > 0 ? 1 : -1;
    if (sense != 0 && now != sense) {
      out.push_back(path[k - 1] - from);
      from = path[k - 1];
    }
    sense = now;
  }
  out.push_back(path.back() - from);
  return out;
}

TEST(FingerspellingPerformance, ZIsDrawnInThreeStrokes) {
  const FingerspellingPerformance p = spell("JAZZ");
  const LetterTarget& z = letter(p, 2, 'Z');
  // Sampled at the clip's own 30 frames per second.
  const int frames = static_cast<int>(std::round((z.movement_end - z.reached) * 30.0f)) + 1;
  const std::vector<vec3> tip = path_of(p.clip, "r_index_tip", z.reached, z.movement_end, frames);
  const std::vector<vec3> s = strokes(tip);
  ASSERT_EQ(s.size(), 3u);
  // As the signer writes it: across to the signer's right (−X), diagonally back down-left, across again.
  EXPECT_LT(s[0].x, -0.035f);
  EXPECT_LT(std::abs(s[0].y), 0.5f * std::abs(s[0].x));
  EXPECT_GT(s[1].x, 0.035f);
  EXPECT_LT(s[1].y, -0.035f);
  EXPECT_LT(s[2].x, -0.035f);
  EXPECT_LT(std::abs(s[2].y), 0.5f * std::abs(s[2].x));
  // The doubled Z bounces: the second one starts where the first did, after a dip.
  const LetterTarget& z2 = letter(p, 3, 'Z');
  EXPECT_EQ(z2.doubled, DoubleMark::Bounce);
  const vec3 first = at(model_at(p.clip, z.reached), "r_index_tip");
  const vec3 second = at(model_at(p.clip, z2.reached), "r_index_tip");
  EXPECT_LT(glm::distance(first, second), 0.01f);
}

TEST(FingerspellingPerformance, DoubledStaticLetterSlidesSideways) {
  const FingerspellingPerformance p = spell("ALL");
  const LetterTarget& l1 = letter(p, 1, 'L');
  const LetterTarget& l2 = letter(p, 2, 'L');
  EXPECT_EQ(l2.doubled, DoubleMark::Slide);
  const vec3 a = at(model_at(p.clip, l1.reached), "r_wrist"), b = at(model_at(p.clip, l2.reached), "r_wrist");
  EXPECT_LT(b.x - a.x, -0.025f);  // toward the dominant (right, −X) side
  EXPECT_LT(std::abs(b.y - a.y), 0.01f);
}

TEST(FingerspellingPerformance, BslUsesBothHandsAndTouchesTheNamedFingertips) {
  const FingerspellingPerformance p = spell("AEIOU", ManualAlphabet::Bsl);
  const auto rest = model_at(Clip{}, 0.0f);
  const char* tips[] = {"l_thumb_tip", "l_index_tip", "l_middle_tip", "l_ring_tip", "l_pinky_tip"};
  for (std::size_t k = 0; k < 5; ++k) {
    const LetterTarget& l = p.letters[k];
    const auto m = model_at(p.clip, 0.5f * (l.reached + l.end));
    // Both hands are up in front of the body.
    EXPECT_GT(glm::distance(at(m, "l_wrist"), at(rest, "l_wrist")), 0.2f) << l.letter;
    EXPECT_GT(glm::distance(at(m, "r_wrist"), at(rest, "r_wrist")), 0.2f) << l.letter;
    // The dominant index tip is on the vowel's fingertip, nearer to it than to any other.
    const vec3 index = at(m, "r_index_tip");
    const float d = glm::distance(index, at(m, tips[k]));
    EXPECT_LT(d, 0.03f) << l.letter;  // tip sites are the fingertip ends; pads touch ~1–2 cm from them
    for (std::size_t o = 0; o < 5; ++o) {
      if (o == k) continue;
      EXPECT_GT(glm::distance(index, at(m, tips[o])), d) << l.letter << " vs " << tips[o];
    }
  }
}

TEST(FingerspellingPerformance, BslDoubledLetterTapsTwice) {
  const FingerspellingPerformance p = spell("BOOK", ManualAlphabet::Bsl);
  const LetterTarget& o1 = letter(p, 1, 'O');
  const LetterTarget& o2 = letter(p, 2, 'O');
  EXPECT_EQ(o2.doubled, DoubleMark::Bounce);
  auto gap = [&](float t) {
    const auto m = model_at(p.clip, t);
    return glm::distance(at(m, "r_index_tip"), at(m, "l_ring_tip"));
  };
  const float touching = gap(0.5f * (o1.reached + o1.end));
  EXPECT_LT(touching, 0.03f);
  EXPECT_LT(gap(0.5f * (o2.reached + o2.end)), 0.03f);
  // Between the two the index lifts off the ring fingertip and comes back.
  float lifted = 0.0f;
  for (float t = o2.start; t <= o2.reached; t += 0.01f) lifted = std::max(lifted, gap(t));
  EXPECT_GT(lifted, touching + 0.012f);
}

TEST(FingerspellingPerformance, BslConsonantsPutTheHandsTogether) {
  const FingerspellingPerformance p = spell("DLGN", ManualAlphabet::Bsl);
  auto middle = [](const std::vector<mat4>& m, const char* a, const char* b) { return 0.5f * (at(m, a) + at(m, b)); };
  auto held = [&](std::size_t k) { return model_at(p.clip, 0.5f * (p.letters[k].reached + p.letters[k].end)); };
  // D: the dominant thumb and index close around the middle of the upright non-dominant index.
  auto m = held(0);
  EXPECT_LT(glm::distance(middle(m, "r_thumb_tip", "r_index_tip"), at(m, "l_index2")), 0.05f);
  EXPECT_GT(at(m, "l_index_tip").y - at(m, "l_index1").y, 0.05f);  // that index points up
  // L: the dominant index lies on the non-dominant palm (palm centre: between wrist and middle knuckle).
  m = held(1);
  EXPECT_LT(glm::distance(at(m, "r_index2"), middle(m, "l_wrist", "l_middle1")), 0.04f);
  // G: the dominant fist sits on the non-dominant fist: its little-finger side above the other's thumb side.
  m = held(2);
  EXPECT_LT(glm::distance(at(m, "r_pinky1"), at(m, "l_index1")), 0.05f);
  EXPECT_GT(at(m, "r_wrist").y, at(m, "l_wrist").y + 0.02f);
  // N: two fingers on the palm.
  m = held(3);
  EXPECT_LT(glm::distance(middle(m, "r_index2", "r_middle2"), middle(m, "l_wrist", "l_middle1")), 0.04f);
}

TEST(FingerspellingGaze, EyesFollowTheSpellingHandThenReturnToTheViewer) {
  const FingerspellingPerformance p = spell("WORD");
  ASSERT_GE(p.clip.find_channel(std::string(face::kGazeHands)), 0);
  for (float u : {0.2f, 0.5f, 0.8f}) {
    const float t = p.spelling_start + u * (p.spelling_end - p.spelling_start);
    const auto m = model_at(p.clip, t);
    const vec3 hand = 0.5f * (at(m, "r_wrist") + at(m, "r_middle1"));
    for (const char* eye : {"l_eyeball_joint", "r_eyeball_joint"})
      EXPECT_LT(degrees_between(eye_forward(m, eye), hand - at(m, eye)), 10.0f) << eye << " at " << t;
  }
  // At the start and the end the eyes look straight ahead, at the viewer.
  for (float t : {0.0f, p.clip.duration}) {
    const auto m = model_at(p.clip, t);
    for (const char* eye : {"l_eyeball_joint", "r_eyeball_joint"})
      EXPECT_LT(degrees_between(eye_forward(m, eye), vec3(0, 0, 1)), 1.0f) << eye << " at " << t;
  }
  // Smooth: no jump between frames. Without ramps the eyes would jump ~40° (20° of it the head's)
  // in one frame; with them the fastest frame is a quick glance, below 15° (450°/s, saccade speed).
  vec3 previous = eye_forward(model_at(p.clip, 0.0f), "r_eyeball_joint");
  float largest = 0.0f;
  for (float t = 1.0f / 30.0f; t <= p.clip.duration; t += 1.0f / 30.0f) {
    const vec3 f = eye_forward(model_at(p.clip, t), "r_eyeball_joint");
    largest = std::max(largest, degrees_between(previous, f));
    previous = f;
  }
  EXPECT_LT(largest, 15.0f);
  FingerspellingOptions no_gaze;
  no_gaze.gaze = false;
  const FingerspellingPerformance q = perform_fingerspelling(plan_spelling("WORD", ManualAlphabet::Asl), world().rig, no_gaze);
  EXPECT_EQ(q.clip.find_channel(std::string(face::kGazeHands)), -1);
}

TEST(FingerspellingGaze, TheSignerLooksAtTheHandWhileSpellingAName) {
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  LayeredLexicon layers;
  layers.push_layer(builtin);
  const Signer signer(world().avatar, layers);
  const SentencePerformance p = signer.say("My name is Zyx.");
  const auto spelled = std::find_if(p.glosses.begin(), p.glosses.end(), [](const PerformedGloss& g) { return g.gloss == "FS-ZYX"; });
  ASSERT_NE(spelled, p.glosses.end());
  const auto m = model_at(p.clip, 0.5f * (spelled->start + spelled->end));
  const vec3 hand = 0.5f * (at(m, "r_wrist") + at(m, "r_middle1"));
  for (const char* eye : {"l_eyeball_joint", "r_eyeball_joint"})
    EXPECT_LT(degrees_between(eye_forward(m, eye), hand - at(m, eye)), 10.0f) << eye;
  // Before the spelled name (on MY, the first sign) the eyes are on the viewer.
  const auto first = model_at(p.clip, 0.5f * (p.glosses.front().start + p.glosses.front().end));
  EXPECT_LT(degrees_between(eye_forward(first, "r_eyeball_joint"), vec3(0, 0, 1)), 1.0f);
  // Z is traced inside the sentence too: the index tip moves sideways over the Z.
  const float z_start = spelled->start, z_end = z_start + 0.5f;  // careful rate: Z takes two 0.25 s slots
  const std::vector<vec3> tip = path_of(p.clip, "r_index_tip", z_start, z_end, 16);
  float span = 0.0f;
  for (const vec3& a : tip) span = std::max(span, std::abs(a.x - tip.front().x));
  EXPECT_GT(span, 0.04f);
}

TEST(FingerspellingGaze, BadInputIsRefused) {
  Clip clip;
  clip.channel(std::string(face::kGazeHands)).add(0.0f, 1.0f);
  Skeleton bare;
  bare.add_joint("humanoid_root", -1, vec3(0.0f));
  EXPECT_THROW(face::write_eye_gaze(bare, clip, 30.0f), Error);
  EXPECT_THROW(face::write_eye_gaze(skeleton(), clip, 0.0f), Error);
  Clip other = clip;
  other.resize_joints(3);
  EXPECT_THROW(face::write_eye_gaze(skeleton(), other, 30.0f), Error);
  const SpellingPlan plan = plan_spelling("AB", ManualAlphabet::Asl);
  FingerspellingOptions fast;
  fast.speed = 9.0f;
  EXPECT_THROW(perform_fingerspelling(plan, world().rig, fast), Error);
  EXPECT_THROW(perform_fingerspelling(SpellingPlan{}, world().rig), Error);
}

}  // namespace
}  // namespace gestura
