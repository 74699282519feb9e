#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/sign/sign_synthesis.hpp"
#include "support/shared_data.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

// A one-handed sign held in front of the chest (flat hand, fingers up, palm to the left, a short
// movement forward), with the given non-manual elements written on the lines after line 3.
std::string sigml(const std::string& nonmanual) {
  return "<sigml>\n"
         "<hns_sign gloss=\"test\">\n"
         "<hamnosys_nonmanual>\n" +
         nonmanual +
         "</hamnosys_nonmanual>\n"
         "<hamnosys_manual><hamflathand/><hamextfingeru/><hampalml/><hamchest/><hammoveo/></hamnosys_manual>\n"
         "</hns_sign>\n"
         "</sigml>\n";
}

// The first sign of a SiGML text, performed with its non-manual tiers.
SignSynthesis perform_sigml(const std::string& xml) {
  const std::vector<sign::SigmlSign> signs = sign::read_sigml(xml, "test.sigml");
  return synthesize_sign(signs.at(0).manual, signs.at(0).nonmanual, fx().rig);
}

SignSynthesis perform(const std::string& nonmanual) { return perform_sigml(sigml(nonmanual)); }

int joint_index(const char* name) { return fx().avatar.skeleton.find(name); }

// The joint's Euler angles (its own order, relative to rest) in the clip at time t.
vec3 angles_at(const Clip& clip, const char* name, float t) {
  const int j = joint_index(name);
  const QuatTrack& track = clip.rotations[static_cast<std::size_t>(j)];
  const quat q = track.empty() ? fx().avatar.skeleton.rest_rotations[static_cast<std::size_t>(j)] : sample_track(track, t);
  return joint_angles(fx().avatar.skeleton, j, q);
}

std::vector<mat4> model_at(const Clip& clip, float t) {
  Pose pose;
  sample_clip(clip, t, WrapMode::Clamp, fx().rig.rest, pose);
  std::vector<mat4> model(fx().avatar.skeleton.size());
  local_to_model(fx().avatar.skeleton, pose, model);
  return model;
}

vec3 position(const std::vector<mat4>& model, const char* name) { return vec3(model[static_cast<std::size_t>(joint_index(name))][3]); }

// Radians between the right eye's line of sight and its direction to the right palm centre at t.
float off_target(const Clip& clip, float t) {
  const auto m = model_at(clip, t);
  const std::size_t eye = static_cast<std::size_t>(joint_index("r_eyeball_joint"));
  const vec3 sight = glm::normalize(vec3(m[eye] * vec4(0, 0, 1, 0)));
  const HandRig& h = fx().rig.hand(Hand::Right);
  const vec3 palm(m[static_cast<std::size_t>(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
  return std::acos(std::clamp(glm::dot(sight, glm::normalize(palm - vec3(m[eye][3]))), -1.0f, 1.0f));
}

float channel_at(const Clip& clip, std::string_view name, float t) {
  const int c = clip.find_channel(std::string(name));
  return c < 0 ? 0.0f : sample_track(clip.channels[static_cast<std::size_t>(c)], t);
}

// When the channel is at its highest (the first such key).
float peak_time(const Clip& clip, std::string_view name) {
  const int c = clip.find_channel(std::string(name));
  if (c < 0) return -1.0f;
  const FloatTrack& tr = clip.channels[static_cast<std::size_t>(c)];
  const auto it = std::max_element(tr.values.begin(), tr.values.end());
  return tr.times[static_cast<std::size_t>(it - tr.values.begin())];
}

}  // namespace

TEST(SignNonManual, HeadShakeTurnsNeckAndSkullbaseToAndFro) {
  const SignSynthesis r = perform("<hnm_head tag=\"SH\"/>\n");
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_FALSE(synthesis_problem(r, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f}).has_value());
  const float s = r.plan.sign_start, e = r.plan.sign_end;
  ASSERT_GT(e - s, 0.4f);
  for (const char* joint : {"skullbase", "vc4"}) {
    int sign_changes = 0;
    float largest = 0.0f, previous = 0.0f;
    for (float t = s; t <= e; t += 0.01f) {
      const float yaw = angles_at(r.clip, joint, t).y;
      largest = std::max(largest, std::abs(yaw));
      if (std::abs(yaw) > deg(0.5f)) {
        if (previous != 0.0f && (yaw > 0) != (previous > 0)) ++sign_changes;
        previous = yaw;
      }
    }
    EXPECT_GE(sign_changes, 2) << joint;            // left, right, left: a shake, not a turn
    EXPECT_GT(largest, deg(3.0f)) << joint;
    EXPECT_LT(largest, deg(10.0f)) << joint;        // the 10° shake is shared by the two joints
    EXPECT_NEAR(angles_at(r.clip, joint, 0.0f).y, 0.0f, 1e-4f) << joint;  // still before the sign
    EXPECT_NEAR(angles_at(r.clip, joint, r.clip.duration).y, 0.0f, 1e-4f) << joint;
  }
}

TEST(SignNonManual, ARepeatedValueIsOneMovement) {
  // Generators write <hnm_head tag="SH"/> several times to insist on it; the shake stays 10°.
  const SignSynthesis once = perform("<hnm_head tag=\"SH\"/>\n");
  const SignSynthesis thrice = perform("<hnm_head tag=\"SH\"/>\n<hnm_head tag=\"SH\"/>\n<hnm_head tag=\"SH\"/>\n");
  EXPECT_TRUE(thrice.warnings.empty());
  for (float t = once.plan.sign_start; t <= once.plan.sign_end; t += 0.05f)
    EXPECT_NEAR(angles_at(thrice.clip, "skullbase", t).y, angles_at(once.clip, "skullbase", t).y, 1e-4f) << t;
}

TEST(SignNonManual, RaisedBrowsHoldOverTheSignAndAreGoneAtBothEnds) {
  const SignSynthesis r = perform("<hnm_eyebrows tag=\"RB\"/>\n");
  EXPECT_TRUE(r.warnings.empty());
  const float mid = 0.5f * (r.plan.sign_start + r.plan.sign_end);
  for (std::string_view brow : {face::kBrowInnerUpL, face::kBrowInnerUpR, face::kBrowOuterUpL, face::kBrowOuterUpR}) {
    EXPECT_GT(channel_at(r.clip, brow, mid), 0.5f) << brow;
    EXPECT_EQ(channel_at(r.clip, brow, 0.0f), 0.0f) << brow;
    EXPECT_EQ(channel_at(r.clip, brow, r.clip.duration), 0.0f) << brow;
  }
  EXPECT_LT(channel_at(r.clip, face::kBrowDownL, mid), 1e-6f);  // raised, not furrowed
}

TEST(SignNonManual, OneSidedBrowAndClosedEyeUseOnlyThatSide) {
  const SignSynthesis r = perform("<hnm_eyebrows tag=\"RL\"/>\n<hnm_eyelids tag=\"CR\"/>\n");
  const float mid = 0.5f * (r.plan.sign_start + r.plan.sign_end);
  EXPECT_GT(channel_at(r.clip, face::kBrowOuterUpL, mid), 0.5f);
  EXPECT_EQ(channel_at(r.clip, face::kBrowOuterUpR, mid), 0.0f);
  EXPECT_GT(channel_at(r.clip, face::kEyeBlinkR, mid), 0.9f);
  EXPECT_EQ(channel_at(r.clip, face::kEyeBlinkL, mid), 0.0f);
}

TEST(SignNonManual, MouthPictureShowsItsVisemesInTheOrderOfItsPhonemes) {
  // SAMPA "mu:s": lips closed (PP), rounded (ou), then s (SS).
  const SignSynthesis r = perform("<hnm_mouthpicture picture=\"mu:s\"/>\n");
  EXPECT_TRUE(r.warnings.empty());
  const float pp = peak_time(r.clip, face::kPP), ou = peak_time(r.clip, face::kOU), ss = peak_time(r.clip, face::kSS);
  ASSERT_GE(pp, 0.0f);
  ASSERT_GE(ou, 0.0f);
  ASSERT_GE(ss, 0.0f);
  EXPECT_LT(pp, ou);
  EXPECT_LT(ou, ss);
  EXPECT_GE(pp, r.plan.sign_start);
  EXPECT_LE(ss, r.plan.sign_end);
  // The jaw opens for the vowel: the temporomandibular joint follows jaw_open.
  EXPECT_GT(angles_at(r.clip, "temporomandibular", ou).x, deg(1.0f));
  EXPECT_NEAR(angles_at(r.clip, "temporomandibular", 0.0f).x, 0.0f, 1e-4f);
}

TEST(SignNonManual, MouthGestureCodesBecomeMouthShapes) {
  const SignSynthesis puffed = perform("<hnm_mouthgesture tag=\"C01\"/>\n");
  const float mid = 0.5f * (puffed.plan.sign_start + puffed.plan.sign_end);
  EXPECT_GT(channel_at(puffed.clip, face::kCheekPuff, mid), 0.9f);
  const SignSynthesis pursed = perform("<hnm_mouthgesture tag=\"L04\"/>\n");
  EXPECT_GT(channel_at(pursed.clip, face::kMouthPucker, mid), 0.5f);
  const SignSynthesis bam = perform("<hnm_mouthgesture tag=\"L09\"/>\n");  // "bam": lips closed, open, closed
  EXPECT_LT(peak_time(bam.clip, face::kPP), peak_time(bam.clip, face::kAA));
}

TEST(SignNonManual, UnknownValuesAreWarnedWithTheirLineAndSkipped) {
  // Line 4 is the first non-manual element.
  const SignSynthesis r = perform("<hnm_head tag=\"XX\"/>\n<hnm_eyebrows tag=\"RB\"/>\n<hnm_mouthpicture picture=\"m#u\"/>\n"
                                  "<hnm_extra tag=\"wink\"/>\n");
  ASSERT_EQ(r.warnings.size(), 3u);
  EXPECT_EQ(r.warnings[0].line, 4);
  EXPECT_NE(r.warnings[0].message.find("'XX'"), std::string::npos) << r.warnings[0].message;
  EXPECT_NE(r.warnings[0].message.find("NO SH"), std::string::npos) << r.warnings[0].message;
  EXPECT_EQ(r.warnings[1].line, 6);
  EXPECT_NE(r.warnings[1].message.find("'#'"), std::string::npos) << r.warnings[1].message;
  EXPECT_EQ(r.warnings[2].line, 7);
  // The known values are still performed.
  const float mid = 0.5f * (r.plan.sign_start + r.plan.sign_end);
  EXPECT_GT(channel_at(r.clip, face::kBrowInnerUpL, mid), 0.5f);
  EXPECT_GE(peak_time(r.clip, face::kPP), 0.0f);
}

TEST(SignNonManual, KnownValuesTheAvatarCannotShowSaySo) {
  const SignSynthesis r = perform("<hnm_mouthgesture tag=\"C09\"/>\n<hnm_nose tag=\"WI\"/>\n");
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_NE(r.warnings[0].message.find("tongue shape"), std::string::npos) << r.warnings[0].message;
  EXPECT_NE(r.warnings[1].message.find("nostril shape"), std::string::npos) << r.warnings[1].message;
  EXPECT_EQ(r.warnings[1].line, 5);
}

TEST(SignNonManual, EmptyTagsAskForNothing) {
  const SignSynthesis r = perform("<hnm_head tag=\"\"/>\n<hnm_mouthpicture picture=\"\"/>\n");
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_TRUE(r.clip.channels.empty());
}

TEST(SignNonManual, RaisedShouldersLiftTheClaviclesWithinTheirLimits) {
  const SignSynthesis plain = perform("");
  const SignSynthesis raised = perform("<hnm_shoulder tag=\"UB\"/>\n");
  EXPECT_FALSE(synthesis_problem(raised, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f}).has_value());
  const float mid = 0.5f * (raised.plan.sign_start + raised.plan.sign_end);
  const auto a = model_at(plain.clip, mid), b = model_at(raised.clip, mid);
  EXPECT_GT(position(b, "l_shoulder").y - position(a, "l_shoulder").y, 0.015f);
  EXPECT_GT(position(b, "r_shoulder").y - position(a, "r_shoulder").y, 0.015f);
  // The arms rise with the shoulders rather than swinging outwards about the clavicles.
  const vec3 wrist_moved = position(b, "r_wrist") - position(a, "r_wrist");
  EXPECT_LT(std::abs(wrist_moved.x), 0.01f);
  EXPECT_LT(std::abs(wrist_moved.z), 0.01f);
  // Back down once the sign is over.
  const auto c = model_at(plain.clip, plain.clip.duration), d = model_at(raised.clip, raised.clip.duration);
  EXPECT_NEAR(position(d, "l_shoulder").y, position(c, "l_shoulder").y, 1e-3f);
}

TEST(SignNonManual, BodyTiltedForwardLeansTheTrunk) {
  const SignSynthesis plain = perform("");
  const SignSynthesis lean = perform("<hnm_body tag=\"TF\"/>\n");
  EXPECT_FALSE(synthesis_problem(lean, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f}).has_value());
  const float mid = 0.5f * (lean.plan.sign_start + lean.plan.sign_end);
  const auto a = model_at(plain.clip, mid), b = model_at(lean.clip, mid);
  EXPECT_GT(position(b, "skullbase").z - position(a, "skullbase").z, 0.04f);
}

TEST(SignNonManual, EyesLookUpOrFollowTheDominantHand) {
  const SignSynthesis up = perform("<hnm_eyegaze tag=\"UP\"/>\n");
  const float mid = 0.5f * (up.plan.sign_start + up.plan.sign_end);
  EXPECT_LT(angles_at(up.clip, "l_eyeball_joint", mid).x, deg(-10.0f));  // − x looks up
  EXPECT_LT(angles_at(up.clip, "r_eyeball_joint", mid).x, deg(-10.0f));

  // At the hand: the eye's line of sight turns towards the palm (as far as the eye can turn).
  const SignSynthesis plain = perform("");
  const SignSynthesis at_hand = perform("<hnm_eyegaze tag=\"HI\"/>\n");
  EXPECT_TRUE(at_hand.warnings.empty());
  EXPECT_FALSE(synthesis_problem(at_hand, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f}).has_value());
  EXPECT_LT(off_target(at_hand.clip, mid), off_target(plain.clip, mid) - deg(20.0f));
}

TEST(SignNonManual, HeadTurnedWithTheGazeJoinsTheEyesOnTheHand) {
  // LI with HI: the head bends towards the hand at the chest (~50° below the eyes) for what is
  // beyond the eyes' range, so the eyes reach the palm that alone they cannot.
  const SignSynthesis eyes = perform("<hnm_eyegaze tag=\"HI\"/>\n");
  const SignSynthesis with_head = perform("<hnm_head tag=\"LI\"/>\n<hnm_eyegaze tag=\"HI\"/>\n");
  EXPECT_TRUE(with_head.warnings.empty());
  const float mid = 0.5f * (eyes.plan.sign_start + eyes.plan.sign_end);
  auto pitch = [&](const Clip& clip) { return angles_at(clip, "vc4", mid).x + angles_at(clip, "skullbase", mid).x; };
  EXPECT_NEAR(pitch(eyes.clip), 0.0f, deg(0.5f));
  EXPECT_GT(pitch(with_head.clip), deg(15.0f));  // forwards, down to the hand
  EXPECT_GT(off_target(eyes.clip, mid), deg(15.0f));
  EXPECT_LT(off_target(with_head.clip, mid), deg(5.0f));
  // Without any gaze LI has nothing to follow.
  EXPECT_EQ(perform("<hnm_head tag=\"LI\"/>\n").warnings.size(), 1u);
}

TEST(SignNonManual, IslSignsWithTiersArePerformedWithoutWarnings) {
  const std::string dir = gestura::test::shared_data() + "/sigml-isl";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no shared data at " << dir;
  int files = 0, with_tiers = 0, values = 0, mapped = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string path = entry.path().string();
    ++files;
    for (const sign::SigmlSign& s : sign::read_sigml(sign::read_text_file(path), path)) {
      if (s.nonmanual.empty()) continue;
      ++with_tiers;
      const SignNonManualActions plan = plan_sign_nonmanuals(s.nonmanual, 0.0f, 1.0f);
      values += plan.values;
      mapped += plan.mapped;
      const SignSynthesis r = synthesize_sign(s.manual, s.nonmanual, fx().rig);
      EXPECT_TRUE(r.warnings.empty()) << path << ": " << r.warnings.front().message;
      EXPECT_FALSE(synthesis_problem(r, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f}).has_value()) << path;
      EXPECT_GE(r.clip.find_channel(std::string(face::kJawOpen)), 0) << path;  // every one is a mouth picture
    }
  }
  std::printf("ISL SiGML: %d files, %d signs with non-manual tiers, %d/%d tier values performed\n", files, with_tiers,
              mapped, values);
  EXPECT_EQ(files, 100);
  EXPECT_EQ(with_tiers, 3);
  EXPECT_EQ(mapped, values);
}

TEST(SignNonManual, ALongSignSaysItsMouthPictureAtSpeakingPaceFromItsStart) {
  // ISL AUSTRALIA's mouth picture "O:stre_IljV" on a long sign (a circle in front of the chest,
  // repeated several times), so that the mouthing would be stretched if it followed the sign.
  const SignSynthesis r = perform_sigml(
      "<sigml><hns_sign gloss=\"long\"><hamnosys_nonmanual><hnm_mouthpicture picture=\"O:stre_IljV\"/>"
      "</hamnosys_nonmanual><hamnosys_manual><hamflathand/><hamextfingeru/><hampalml/><hamchest/><hamcirclel/>"
      "<hamrepeatfromstartseveral/></hamnosys_manual></hns_sign></sigml>");
  ASSERT_GT(r.plan.sign_end - r.plan.sign_start, 3.0f);
  const int jaw = r.clip.find_channel(std::string(face::kJawOpen));
  ASSERT_GE(jaw, 0);
  const FloatTrack& open = r.clip.channels[static_cast<std::size_t>(jaw)];
  EXPECT_NEAR(open.times.front(), r.plan.sign_start, 1e-3f);
  // Nine phonemes at 6–7 a second: about 1.2 s, not stretched over the whole sign.
  const float said = open.times.back() - r.plan.sign_start;
  EXPECT_LT(said, 2.0f);
  EXPECT_GT(said, 0.8f);
  EXPECT_LT(said, 0.7f * (r.plan.sign_end - r.plan.sign_start));
}

TEST(SignNonManual, GesturalTierSequencesShareTheSign) {
  // A nod in the first half, a shake in the second (gestural SiGML's tiers are sequences).
  const std::string xml = R"(<sigml><hamgestural_sign gloss="g">
<sign_nonmanual><head_tier><head_movement movement="NF"/><head_movement movement="SL"/></head_tier></sign_nonmanual>
<sign_manual><handconfig handshape="flat"/><handconfig extfidir="u" palmor="l"/><location_bodyarm location="chest"/>
<directedmotion direction="o"/></sign_manual></hamgestural_sign></sigml>)";
  const SignSynthesis r = perform_sigml(xml);
  EXPECT_TRUE(r.warnings.empty());
  const float a = r.plan.sign_start, b = r.plan.sign_end;
  const vec3 first = angles_at(r.clip, "skullbase", a + 0.25f * (b - a));
  const vec3 second = angles_at(r.clip, "skullbase", a + 0.75f * (b - a));
  EXPECT_GT(first.x, deg(3.0f));            // tilted forwards
  EXPECT_NEAR(first.y, 0.0f, deg(0.5f));    // not yet turned
  EXPECT_NEAR(second.x, 0.0f, deg(0.5f));   // no longer tilted
  EXPECT_GT(second.y, deg(5.0f));           // turned to the signer's left
}

TEST(SignNonManual, PenetrationIsMeasuredAfterTheBodyMoved) {
  // A fist touching the chin; pushing the head forwards pushes the chin into the hand.
  auto chin = [](const std::string& nonmanual) {
    const std::string xml = "<sigml><hns_sign gloss=\"c\"><hamnosys_nonmanual>" + nonmanual +
                            "</hamnosys_nonmanual><hamnosys_manual><hamfist/><hamextfingeru/><hampalml/><hamchin/>"
                            "<hamtouch/></hamnosys_manual></hns_sign></sigml>";
    return perform_sigml(xml);
  };
  const SignSynthesis plain = chin(""), pushed = chin("<hnm_head tag=\"PF\"/>");
  EXPECT_GT(pushed.stats.max_penetration, plain.stats.max_penetration + 0.002f)
      << plain.stats.max_penetration << " vs " << pushed.stats.max_penetration;
}

TEST(SignNonManual, GazeAtTheHandsLooksBetweenThemWhenBothAreUp) {
  auto two_handed = [](const std::string& gaze) {
    const std::string xml = "<sigml><hns_sign gloss=\"t\"><hamnosys_nonmanual><hnm_eyegaze tag=\"" + gaze +
                            "\"/></hamnosys_nonmanual><hamnosys_manual><hamsymmlr/><hamflathand/><hamextfingeru/>"
                            "<hampalml/><hamchest/><hammoveo/></hamnosys_manual></hns_sign></sigml>";
    return perform_sigml(xml);
  };
  const SignSynthesis hands = two_handed("HD"), dominant = two_handed("HI"), other = two_handed("HC");
  const float mid = 0.5f * (hands.plan.sign_start + hands.plan.sign_end);
  // Yaw of the two eyes together (+ to the avatar's left; each eye also converges on the near
  // target). The dominant (right) hand is on the avatar's right.
  auto yaw = [&](const Clip& clip) {
    return 0.5f * (angles_at(clip, "l_eyeball_joint", mid).y + angles_at(clip, "r_eyeball_joint", mid).y);
  };
  const float between = yaw(hands.clip);
  EXPECT_LT(yaw(dominant.clip), between - deg(3.0f));
  EXPECT_GT(yaw(other.clip), between + deg(3.0f));
  EXPECT_NEAR(between, 0.0f, deg(3.0f));
}

TEST(SignNonManual, GazeAtTheOtherHandAtRestTurnsBothEyesToItsSide) {
  // One-handed sign, HC: the left hand hangs at the avatar's left side, below and a little behind
  // the eyes. Both eyes turn down and to the left (+ yaw) as far as they go; neither to the right.
  const SignSynthesis r = perform("<hnm_eyegaze tag=\"HC\"/>\n");
  const float mid = 0.5f * (r.plan.sign_start + r.plan.sign_end);
  for (const char* eye : {"l_eyeball_joint", "r_eyeball_joint"}) {
    const vec3 a = angles_at(r.clip, eye, mid);
    EXPECT_GT(a.y, deg(20.0f)) << eye;
    EXPECT_GT(a.x, deg(20.0f)) << eye;
  }
}
