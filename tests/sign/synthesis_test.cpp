#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/sign/arm_reach.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/sign_synthesis.hpp"
#include "support/build_paths.hpp"
#include "support/shared_data.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

using gestura::test::shared_data;

// The avatar's joint model matrices in the middle of the sign's held posture.
std::vector<mat4> held_pose(const SignSynthesis& r, float at = -1.0f) {
  const Skeleton& s = fx().avatar.skeleton;
  Pose pose;
  const float t = at >= 0 ? at : r.plan.sign_start + 0.05f;
  sample_clip(r.clip, t, WrapMode::Clamp, fx().rig.rest, pose);
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  return model;
}

vec3 joint(const std::vector<mat4>& model, const char* name) {
  return vec3(model[static_cast<std::size_t>(fx().avatar.skeleton.find(name))][3]);
}

float angle_between(vec3 a, vec3 b) { return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)); }

SignSynthesis synth(const std::string& names) { return synthesize_sign(sign::parse_hamnosys_names(names), fx().rig); }

// A sign of the built-in ASL lexicon (data/lexicon/ase.jsonl) as written there.
SignSynthesis lexicon_sign(const std::string& gloss) {
  std::ifstream file(test::source_dir() + "/data/lexicon/ase.jsonl");
  for (std::string line; std::getline(file, line);) {
    const auto j = nlohmann::json::parse(line);
    if (j.value("gloss", "") == gloss) return synth(j.at("names").get<std::string>());
  }
  throw Error("no " + gloss + " in the built-in lexicon");
}

// The palm normal of a hand as performed (the hand frame carried by the wrist).
vec3 palm_normal(const std::vector<mat4>& model, Hand hand) {
  const HandRig& h = fx().rig.hand(hand);
  const quat wrist = glm::normalize(glm::quat_cast(mat3(model[joint_slot(h.wrist)])));
  return (wrist * glm::inverse(h.rest_wrist_rotation) * h.rest_frame.rotation) * vec3(0, 0, 1);
}

vec3 palm_centre(const std::vector<mat4>& model, Hand hand) {
  const HandRig& h = fx().rig.hand(hand);
  return vec3(model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
}

}  // namespace

// Extended-finger direction and palm orientation of single-posture signs, measured on the
// performed skeleton (wrist → middle knuckle; the palm normal from the knuckle line).
TEST(Synthesis, HandOrientationFollowsTheNotation) {
  struct Case { const char* finger; const char* palm; vec3 finger_dir; vec3 palm_dir; };
  // Expected vectors from the notation's definition (signer's frame: u = +Y, o = +Z, l = +X).
  const Case cases[] = {
      {"u", "l", {0, 1, 0}, {1, 0, 0}},      // fingers up, palm to the signer's left
      {"o", "d", {0, 0, 1}, {0, -1, 0}},     // fingers forward, palm down
      {"l", "d", {1, 0, 0}, {0, -1, 0}},     // fingers to the left (across the body), palm down
      {"uo", "d", glm::normalize(vec3(0, 1, 1)), glm::normalize(vec3(0, 1, -1) * -1.0f)},
      {"o", "l", {0, 0, 1}, {1, 0, 0}},
  };
  for (const Case& c : cases) {
    const std::string names = std::string("hamflathand,hamextfinger") + c.finger + ",hampalm" + c.palm + ",hamchest";
    const SignSynthesis r = synth(names);
    const auto m = held_pose(r);
    const HandFrame f = hand_frame_from_joints(joint(m, "r_wrist"), joint(m, "r_index1"), joint(m, "r_middle1"),
                                               joint(m, "r_pinky1"), Hand::Right);
    EXPECT_LT(to_degrees(angle_between(f.finger, c.finger_dir)), 15.0f) << names;
    // The palm normal expected for this finger direction (projection rule of the phonology).
    const vec3 palm_expected = palm_normal(c.finger_dir, *parse_palm_orientation(c.palm));
    EXPECT_LT(to_degrees(angle_between(f.palm, palm_expected)), 20.0f) << names;
    (void)c.palm_dir;
  }
}

TEST(Synthesis, TouchingSignsReachTheirSiteWithin3cm) {
  struct Case { const char* names; const char* site; };
  const Case cases[] = {
      {"hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch", "chin"},
      {"hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamforehead,hamtouch", "forehead"},
      {"hamflathand,hamextfingerl,hampalml,hamchest,hamtouch", "chest"},  // fingers across, palm toward the signer
      {"hamfinger2,hamextfingeru,hampalml,hamnose,hamclose", "nose"},
      {"hamflathand,hamextfingeru,hampalml,hamlrat,hamcheek,hamtouch", "r_cheek"},
  };
  for (const Case& c : cases) {
    const SignSynthesis r = synth(c.names);
    const auto m = held_pose(r);
    HandPoints pts;
    hand_surface_points(fx().rig, Hand::Right, m, pts);
    const BodySite* site = find_site(fx().rig.sites, c.site);
    ASSERT_NE(site, nullptr) << c.site;
    const vec3 target = site_position(*site, fx().rig.bind_model);
    float nearest = 1e9f;
    for (const vec3& p : pts) nearest = std::min(nearest, glm::distance(p, target));
    EXPECT_LT(nearest, 0.03f) << c.names;
  }
}

TEST(Synthesis, HandshapesCurlTheFingersAsNotated) {
  auto tip_to_palm = [](const std::string& shape) {
    const SignSynthesis r = synth(shape + ",hamextfingeru,hampalml,hamshoulders");
    const auto m = held_pose(r);
    const HandRig& h = fx().rig.hand(Hand::Right);
    const vec3 palm = vec3(m[static_cast<std::size_t>(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
    return std::array<float, 2>{glm::distance(joint(m, "r_index_tip"), palm), glm::distance(joint(m, "r_pinky_tip"), palm)};
  };
  const auto flat = tip_to_palm("hamflathand");
  const auto fist = tip_to_palm("hamfist");
  const auto point = tip_to_palm("hamfinger2");
  EXPECT_GT(flat[0], 0.10f);  // straight fingers: the tips are a finger's length from the palm
  EXPECT_LT(fist[0], 0.07f);  // curled into the palm
  EXPECT_LT(fist[1], 0.06f);
  EXPECT_GT(point[0], 0.10f);  // index extended
  EXPECT_LT(point[1], 0.07f);  // the others curled
}

TEST(Synthesis, ASingleMovementSignLastsHalfASecondToAbout1point2) {
  for (const char* names : {"hamflathand,hamextfingeru,hampalml,hamchest,hammoveo",
                            "hamfist,hamextfingero,hampalmd,hamshoulders,hammovel",
                            "hamfinger2,hamextfingeru,hampalmd,hamchest,hamcircleo"}) {
    const SignSynthesis r = synth(names);
    const float sign = r.plan.sign_end - r.plan.sign_start;
    EXPECT_GE(sign, 0.5f) << names;
    EXPECT_LE(sign, 1.2f) << names;
  }
  // Faster and slower tempo scale the sign.
  const auto parsed = sign::parse_hamnosys_names("hamflathand,hamextfingeru,hampalml,hamchest,hammoveo");
  PlanOptions fast;
  fast.speed = 2.0f;
  const SignSynthesis quick = synthesize_sign(parsed, fx().rig, fast);
  const SignSynthesis normal = synthesize_sign(parsed, fx().rig);
  EXPECT_LT(quick.plan.sign_end - quick.plan.sign_start, 0.6f * (normal.plan.sign_end - normal.plan.sign_start));
}

TEST(Synthesis, AMovementMovesTheHandTheNotatedWay) {
  const SignSynthesis r = synth("hamflathand,hamextfingeru,hampalml,hamchest,hammoveo");
  const auto start = held_pose(r, r.plan.sign_start + 0.05f);
  const auto end = held_pose(r, r.plan.sign_end - 0.05f);
  const vec3 d = joint(end, "r_wrist") - joint(start, "r_wrist");
  EXPECT_GT(d.z, 0.10f);  // out, away from the body
  EXPECT_LT(std::abs(d.x), 0.05f);
  EXPECT_LT(std::abs(d.y), 0.05f);
}

// Issue 15's movements, measured on the performed skeleton of the built-in lexicon's signs.
// BOOK: the flat hands close palm to palm, then open like a book to palms up.
TEST(Synthesis, BookClosesPalmToPalmThenOpens) {
  const SignSynthesis r = lexicon_sign("BOOK");
  const auto closed = held_pose(r, r.plan.sign_start + 0.02f);
  const auto open = held_pose(r, r.plan.sign_end - 0.02f);
  EXPECT_LT(glm::distance(palm_centre(closed, Hand::Right), palm_centre(closed, Hand::Left)), 0.06f);
  EXPECT_LT(glm::dot(palm_normal(closed, Hand::Right), palm_normal(closed, Hand::Left)), -0.8f);  // facing
  for (Hand h : kBothHands) {
    EXPECT_GT(angle_between(palm_normal(closed, h), palm_normal(open, h)), deg(60.0f));
    EXPECT_GT(palm_normal(open, h).y, 0.7f);  // palms up
  }
}

// HELP: the thumb-up fist rests on the other palm, and both rise together: the base hand rises.
TEST(Synthesis, HelpRaisesTheBaseHand) {
  const SignSynthesis r = lexicon_sign("HELP");
  const auto start = held_pose(r, r.plan.sign_start + 0.02f);
  const auto end = held_pose(r, r.plan.sign_end - 0.02f);
  EXPECT_GT(palm_centre(end, Hand::Left).y - palm_centre(start, Hand::Left).y, 0.08f);
  EXPECT_GT(palm_centre(end, Hand::Right).y - palm_centre(start, Hand::Right).y, 0.08f);
  EXPECT_LT(glm::distance(palm_centre(end, Hand::Right), palm_centre(end, Hand::Left)), 0.08f);  // still together
}

// WHERE: the upright index finger wags side to side, each swing at full size (the fingertip
// travels over 5 cm across; 4 cm when the wag's envelope spanned the whole movement).
TEST(Synthesis, WhereWagsTheIndexFingerVisibly) {
  const SignSynthesis r = lexicon_sign("WHERE");
  float left = -1e9f, right = 1e9f;
  for (float t = r.plan.sign_start; t <= r.plan.sign_end; t += 1.0f / 60.0f) {
    const float x = joint(held_pose(r, t), "r_index_tip").x;
    left = std::max(left, x);
    right = std::min(right, x);
  }
  EXPECT_GT(left - right, 0.05f);
}

// HOUSE: the roof before the head (hands meeting at the top, sloping down and apart), then the
// walls: the hands, upright and facing each other, go straight down.
TEST(Synthesis, HouseHasARoofBeforeTheHeadAndWalls) {
  const SignSynthesis r = lexicon_sign("HOUSE");
  float top = -1e9f, bottom = 1e9f;
  for (float t = r.plan.sign_start; t <= r.plan.sign_end; t += 1.0f / 30.0f) {
    const float y = palm_centre(held_pose(r, t), Hand::Right).y;
    top = std::max(top, y);
    bottom = std::min(bottom, y);
  }
  const float chin = site_position(*find_site(fx().rig.sites, "chin"), fx().rig.bind_model).y;
  EXPECT_GT(top, chin);            // the roof's peak is up before the face, not at the chest
  EXPECT_GT(top - bottom, 0.18f);  // roof and walls together come down a long way
  const auto end = held_pose(r, r.plan.sign_end - 0.02f);
  EXPECT_GT(palm_centre(end, Hand::Left).x - palm_centre(end, Hand::Right).x, 0.2f);      // walls apart
  EXPECT_LT(glm::dot(palm_normal(end, Hand::Right), palm_normal(end, Hand::Left)), -0.8f);  // facing
}

TEST(Synthesis, SymmetricSignsMirrorTheOtherHand) {
  const SignSynthesis r = synth("hamsymmlr,hamflathand,hamextfingeru,hampalml,hamshoulders,hammover");
  const auto m = held_pose(r);
  const vec3 right = joint(m, "r_wrist"), left = joint(m, "l_wrist");
  EXPECT_NEAR(right.x, -left.x, 0.03f);
  EXPECT_NEAR(right.y, left.y, 0.03f);
  EXPECT_LT(right.x, 0.0f);  // the dominant (right) hand on the signer's right
}

TEST(Synthesis, AMovementIntoTheFaceStopsAtItsSurface) {
  // From close in front of the chin, "move in": the hand meets the chin and stays in front of the
  // face (it used to pass through the head and be pushed out at the back of it).
  const SignSynthesis r = synth("hamflathand,hamfingerstraightmod,hamextfingeru,hampalml,hamchin,hamclose,hammovei,hamtouch");
  EXPECT_LT(r.stats.max_penetration, 0.01f);
  for (float t = r.plan.sign_start; t < r.plan.sign_end; t += 0.05f) {
    const auto m = held_pose(r, t);
    EXPECT_GT(joint(m, "r_wrist").z, joint(m, "skullbase").z) << "at " << t << " s";
  }
}

TEST(Synthesis, AMovementAcrossTheFaceStopsAtItsSurface) {
  // From close beside the forehead, "move in and left": the hand meets the forehead on its own
  // (right) side (it used to pass across the face to the other side).
  const SignSynthesis r = synth("hamflathand,hamextfingerul,hampalmdr,hamforehead,hamlrbeside,hamclose,hammoveil,hamtouch");
  EXPECT_LT(r.stats.max_penetration, 0.01f);
  for (float t = r.plan.sign_start; t < r.plan.sign_end; t += 0.05f) {
    const auto m = held_pose(r, t);
    EXPECT_LT(joint(m, "r_wrist").x, joint(m, "skullbase").x) << "at " << t << " s";
  }
}

TEST(Synthesis, AHandGivingWayInSpaceKeepsItsSideAndItsMovement) {
  // Near the right of the chest, thumb side up and out, moving left: the arm cannot quite make the
  // turn there, and the hand gives way, but neither out past the shoulder nor back against the
  // movement (it once started 9 cm outside the shoulder).
  const SignSynthesis r = synth("hamfist,hamthumboutmod,hamextfingeruo,hampalmd,hamshoulders,hamlrat,hammovel");
  const auto start = held_pose(r);
  const auto end = held_pose(r, r.plan.sign_end - 0.05f);
  EXPECT_GT(joint(start, "r_wrist").x - joint(start, "r_shoulder").x, -0.05f);
  EXPECT_GT(joint(end, "r_wrist").x - joint(start, "r_wrist").x, 0.06f);  // to the left
}

TEST(Synthesis, EveryIslSigmlSignIsPerformedWithinLimitsAndWithoutNaN) {
  const std::string dir = shared_data() + "/sigml-isl";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no shared data at " << dir;
  int signs = 0, deep = 0, off = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string path = entry.path().string();
    for (const sign::SigmlSign& s : sign::read_sigml(sign::read_text_file(path), path)) {
      const SignSynthesis r = synthesize_sign(s.manual, fx().rig);
      ++signs;
      const auto problem = synthesis_problem(r, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f});  // NaN and limits only
      EXPECT_FALSE(problem.has_value()) << path << ": " << *problem;
      if (r.stats.max_penetration > 0.01f) ++deep;
      if (synthesis_problem(r, fx().rig, {1e9f}).has_value()) ++off;
    }
  }
  EXPECT_EQ(signs, 100);
  std::printf("ISL SiGML: %d signs performed; %d with a hand more than 1 cm inside the collision body; %d off "
              "their planned key postures (IK residual over 2 cm or 25 degrees)\n", signs, deep, off);
  EXPECT_EQ(deep, 0);   // issue #5: no hand more than 1 cm inside the body (5 before the analytic swivel seed, 1 before detours)
  EXPECT_LE(off, 6);    // ratchet: measured 6 with the wrist's ulnar range and the elbow at 150° and a frame that loses its hand searching afresh; 18 once body sites took the surface's smooth normals (the nose normal no longer leans 16°); 17 on the anatomical hands of issue 14 (the same 17 signs as the planner before the sign layer became passes); 15 on the previous avatar (22 before the planner kept the performer's hand points off the body; 19 with the chin found by a fixed-height ray; 30 before hands in space took reachable places; 57 before the analytic swivel seed)
}

TEST(Synthesis, ElbowRiseIsMeasuredAgainstTheShoulder) {
  // PerformanceStats::max_elbow_rise: a flat hand before the chest keeps its elbow well below the
  // shoulder; a hand on top of the head lifts it toward the shoulder. Both read off the same
  // performed frames as the clip.
  const SignSynthesis chest = synth("hamflathand,hamextfingeru,hampalml,hamchest");
  const SignSynthesis high = synth("hamflathand,hamextfingeru,hampalml,hamheadtop");
  EXPECT_LT(chest.stats.max_elbow_rise, -0.10f);
  EXPECT_GT(high.stats.max_elbow_rise, chest.stats.max_elbow_rise + 0.10f);
  const auto m = held_pose(chest);
  EXPECT_LE(joint(m, "r_elbow").y - joint(m, "r_shoulder").y, chest.stats.max_elbow_rise + 1e-3f);
}

TEST(Synthesis, HandConstellationsBringTheHandsTogether) {
  // The dominant fist's little-finger side on the other hand's palm, in front of the body.
  const SignSynthesis r = synth("hamfist,hamthumboutmod,hamextfingero,hampalml,hamparbegin,hampinkyside,hamplus,hampalm,hamparend,hamtouch");
  const auto m = held_pose(r);
  HandPoints right, left;
  hand_surface_points(fx().rig, Hand::Right, m, right);
  hand_surface_points(fx().rig, Hand::Left, m, left);
  float nearest = 1e9f;
  for (const vec3& a : right)
    for (const vec3& b : left) nearest = std::min(nearest, glm::distance(a, b));
  EXPECT_LT(nearest, 0.03f);
  EXPECT_GT(joint(m, "l_wrist").z, 0.15f);  // the other hand is up in front, not resting
  EXPECT_GT(joint(m, "r_wrist").z, 0.15f);
}

// Ratchets over the German and Polish lexicons (4,070 signs); lower them as synthesis improves.
// Before hands out in space took places their arm can turn them at (arm_reach.hpp): 934 off
// place, 446 turned, 86 in the body.
// A hand at the body is measured at the point where it meets the body (planned_contact) since
// the lower face joined the collision body and its sites (chin, lips) count as at the body.
// Since the planner plans with the performer's hand points (hand_geometry.hpp; 11 of its 16
// before): 393 off place, 199 turned; measured 341 and 182 on the previous avatar.
// The anatomical hands of issue 14 (re-laid finger and thumb bones, sculpted nose) measured 426
// off place and 226 turned with the planner of the time, 409 and 227 with the sign layer as
// passes (a flat hand's contact found among the hand's ends, hands settling in space staying
// there); 408 and 230 once a finger named after a one-finger form is the finger it extends (the Y
// hands of hamfinger2 hampinky extend the little finger, not the index, and turn otherwise).
constexpr int kMaxOffPlace = 195;   // measured 195 with one arm rule scored by what reads (hand_solver.cpp; 208 with it scored in metres, place plus weighted turn); 196 with the wrist's ulnar range at 47°, the elbow to 150° and frames that lose
                                    // their hand searching afresh (pose_hand); 412 with body-site normals from the smooth surface (408 before)
constexpr int kMaxOffTurn = 103;    // measured 103 with one arm rule scored by what reads (hand_solver.cpp): arms that keep the turn are kept; 139 with both of the next two changes; 140 once a continued arm that misses its plan is re-solved without history (hand_solver.cpp), 142 with mirrored pairs shifting in the midline plane and the fist's thumb along the index; 143 with those arm ranges; 231 with body-site normals from the smooth surface (230 before)

// Every sign of the German and Polish lexicons: no NaN, no joint outside its limits, no hand more
// than 1 cm inside the collision body (issue #5; 140 signs did before the analytic swivel seed,
// 44 before transitions took detours round the body and the solver its straight way out).
TEST(Synthesis, EveryLexiconSignIsPerformedWithinLimitsAndWithoutNaN) {
  const std::string path = shared_data() + "/hamnosys/signs.jsonl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no shared data at " << path;
  std::ifstream file(path);
  std::string line;
  int signs = 0, deep = 0, bad = 0, off_place = 0, off_2cm = 0, off_turn = 0;
  while (std::getline(file, line)) {
    const auto key = line.find("\"hamnosys\": \"");
    if (key == std::string::npos) continue;
    const auto start = key + 13, end = line.find('"', start);
    const std::string notation = line.substr(start, end - start);
    sign::HamSign parsed;
    try {
      parsed = sign::parse_hamnosys_unicode(notation);
    } catch (const Error&) {
      continue;  // parsing is covered by the coverage test
    }
    const SignSynthesis r = synthesize_sign(parsed, fx().rig);
    ++signs;
    if (const auto problem = synthesis_problem(r, fx().rig, {1e9f, 1e9f, 1e9f, 1e9f})) {
      ADD_FAILURE() << line.substr(0, 80) << ": " << *problem;
      if (++bad > 10) break;
    }
    if (r.stats.max_penetration > 0.01f) ++deep;
    const SynthesisTolerance tol;
    if (r.stats.key_position_error > tol.position || r.stats.key_space_position_error > tol.space_position) ++off_place;
    if (std::max(r.stats.key_position_error, r.stats.key_space_position_error) > tol.position) ++off_2cm;
    if (r.stats.key_orientation_error > tol.orientation) ++off_turn;
  }
  EXPECT_GE(signs, 4000);
  std::printf("lexicon: %d signs performed; %d with a hand more than 1 cm inside the collision body; IK residual "
              "at a key posture: off its place (2 cm at the body, 5 cm in space) in %d (over 2 cm anywhere in %d), "
              "turned over 25 degrees in %d\n", signs, deep, off_place, off_2cm, off_turn);
  EXPECT_EQ(deep, 0);
  // Ratchets on the IK residual (SynthesisTolerance). Before the analytic swivel seed (with one
  // 2 cm threshold everywhere): 1,630 signs off their place, 599 turned more than 25°.
  EXPECT_LE(off_place, kMaxOffPlace);
  EXPECT_LE(off_turn, kMaxOffTurn);
}

TEST(Synthesis, BadRequestsGiveClearErrors) {
  const auto parsed = sign::parse_hamnosys_names("hamflathand,hamextfingeru,hampalml,hamchest");
  PlanOptions silly;
  silly.speed = 0.0f;
  EXPECT_THROW(synthesize_sign(parsed, fx().rig, silly), Error);
  silly.speed = std::nanf("");
  EXPECT_THROW(synthesize_sign(parsed, fx().rig, silly), Error);
  PerformOptions bad_fps;
  bad_fps.fps = 0.0f;
  EXPECT_THROW(synthesize_sign(parsed, fx().rig, {}, bad_fps), Error);
  sign::ParseOptions strict;
  strict.strict = true;
  EXPECT_THROW(sign::parse_hamnosys_names("hamflathand,hamparbegin,hamextfingeru", strict), Error);
  EXPECT_THROW(sign::parse_hamnosys_names("hamchest,hamextfingeru,hamflathand,hamparend"), Error);
}

TEST(Synthesis, AReturnToRestFromTheNeckBowsOutRoundTheChest) {
  // DGS: a C hand touching the neck, then down along it. The straight line from there to the
  // resting hand at the hip runs through the chest (the chest stands 6 cm further forward than
  // the throat), so the way back bows forward.
  const SignSynthesis r = synthesize_sign(
      sign::parse_hamnosys_names("hamcee12,hamextfingeril,hampalmdr,hamneck,hamtouch,hammoved"), fx().rig);
  const HandSegment& back = r.plan.right.segments.back();
  ASSERT_FALSE(back.to.active);     // the return to rest
  EXPECT_GT(back.detour.z, 0.05f);  // forward, round the chest
  EXPECT_LE(r.stats.max_penetration, 0.01f);
  // The planned palm centre keeps further off the body all the way down than on the straight
  // line, which passes within a finger's length of the chest (and the fingers through it).
  float straight = 1e9f, bowed = 1e9f;
  for (int k = 1; k < 10; ++k) {
    const float u = static_cast<float>(k) / 10.0f, t = back.start + (back.end - back.start) * u;
    bowed = std::min(bowed, body_signed_distance(fx().rig, fx().rig.bind_model, sample_hand(r.plan.right, t).position));
    straight = std::min(straight, body_signed_distance(fx().rig, fx().rig.bind_model, glm::mix(back.from.position, back.to.position, u)));
  }
  EXPECT_LT(straight, 0.07f);
  EXPECT_GT(bowed, straight + 0.04f);
}

TEST(Synthesis, HandPosturesAreClampedIntoTheFingerJointLimits) {
  // A thumb asked for more than its joints allow is posed at their limits, so that what the
  // planner and the solver keep out of the body is the hand that will be performed.
  HandPosture shape = make_handshape(BasicHandshape::Flat);
  shape.thumb.cmc_abduction = deg(150.0f);
  shape.thumb.cmc_flexion = deg(-120.0f);
  shape.thumb.mcp = deg(170.0f);
  Pose pose = fx().rig.rest;
  apply_hand_posture(fx().rig, Hand::Right, shape, pose);
  const Skeleton& s = fx().avatar.skeleton;
  for (const auto& finger : fx().rig.hand(Hand::Right).fingers)
    for (int j : finger) EXPECT_TRUE(within_limits(s, j, pose.rotations[static_cast<std::size_t>(j)])) << s.names[static_cast<std::size_t>(j)];
}

TEST(Synthesis, ARaisedHandTurnsTheWayTheForearmCanFollow) {
  // DGS WOMAN2D starts with the fingers up and left and the palm forward at the chin. From the
  // resting hand (palm in, fingers down) the short way round twists the forearm far past its
  // range mid-way (the arm swung its elbow up above the shoulder to follow); the long way does not.
  const SignPlan plan = plan_sign(
      sign::parse_hamnosys_names("hamfinger23spread,hamfingerstraightmod,hamthumboutmod,hambetween,hamfinger23spread,"
                                 "hamthumboutmod,hamextfingerul,hampalmdr,hamchin,hamlrat,hamseqbegin,hamtouch,hamthumb,"
                                 "hamfingertip,hamseqend"),
      fx().rig);
  const HandSegment& up = plan.right.segments.front();
  ASSERT_FALSE(up.from.active);
  EXPECT_TRUE(up.long_turn);
  const vec3 mid = sample_hand(plan.right, 0.5f * (up.start + up.end)).position;
  const float short_way = arm_reach_excess(fx().rig, Hand::Right, mid, blend_turn(up.from.orientation, up.to.orientation, 0.5f, false));
  const float long_way = arm_reach_excess(fx().rig, Hand::Right, mid, blend_turn(up.from.orientation, up.to.orientation, 0.5f, true));
  EXPECT_GT(short_way, long_way + 0.5f) << short_way << " vs " << long_way;
  // Either way ends exactly at the turns it joins.
  EXPECT_GT(std::abs(glm::dot(blend_turn(up.from.orientation, up.to.orientation, 1.0f, true), up.to.orientation)), 0.9999f);
  EXPECT_GT(std::abs(glm::dot(blend_turn(up.from.orientation, up.to.orientation, 0.0f, true), up.from.orientation)), 0.9999f);
  // And the elbow stays about shoulder-high or lower on the way up (it went 16 cm above the
  // shoulder, 24 cm above the hand).
  const SignSynthesis r = synthesize_sign(
      sign::parse_hamnosys_names("hamfinger23spread,hamfingerstraightmod,hamthumboutmod,hambetween,hamfinger23spread,"
                                 "hamthumboutmod,hamextfingerul,hampalmdr,hamchin,hamlrat,hamseqbegin,hamtouch,hamthumb,"
                                 "hamfingertip,hamseqend"),
      fx().rig);
  for (float t = 0.0f; t < r.plan.sign_start; t += 1.0f / 30.0f) {
    const auto m = held_pose(r, t);
    EXPECT_LT(joint(m, "r_elbow").y, joint(m, "r_shoulder").y + 0.05f) << t;
  }
}

TEST(Synthesis, AHandPlacedOnTheOtherHandBringsItUpAsItsBase) {
  // Nothing is written for the non-dominant hand, but the dominant hand goes to its palm: the
  // other hand comes up in front as the base (flat, palm up) instead of being met at the hip.
  const SignSynthesis r = synthesize_sign(sign::parse_hamnosys_names("hamflathand,hamextfingerol,hampalmd,hampalm,hamtouch"), fx().rig);
  const auto m = held_pose(r);
  const vec3 base = joint(m, "l_wrist");
  EXPECT_GT(base.z, 0.15f);  // in front of the body
  EXPECT_GT(base.y, 0.95f);  // up from the hip (it hangs at 0.84 m)
  // Palm on palm.
  const vec3 right_palm = vec3(m[static_cast<std::size_t>(fx().rig.hand(Hand::Right).wrist)] *
                               vec4(fx().rig.hand(Hand::Right).palm_centre_local, 1.0f));
  const vec3 left_palm = vec3(m[static_cast<std::size_t>(fx().rig.hand(Hand::Left).wrist)] *
                              vec4(fx().rig.hand(Hand::Left).palm_centre_local, 1.0f));
  EXPECT_LT(glm::distance(right_palm, left_palm), 0.07f);  // palm centres; the contact is at the palm site
  EXPECT_LT(right_palm.y - left_palm.y, 0.05f);
  EXPECT_GT(right_palm.y, left_palm.y);  // the dominant hand lies on top
}

TEST(Synthesis, AHandAtTheOtherWristBringsThatForearmUpAcrossTheBody) {
  // A bent index tapping the back of the other wrist (nothing written for the other hand): the
  // other forearm comes up in front, palm down, fingers across the body; the fingertip meets it.
  const SignSynthesis r = synthesize_sign(
      sign::parse_hamnosys_names("hamfinger2,hamfingerbendmod,hamextfingerol,hampalmd,hamwristback,hamtouch"), fx().rig);
  const auto m = held_pose(r);
  const vec3 wrist = joint(m, "l_wrist"), elbow = joint(m, "l_elbow");
  EXPECT_GT(wrist.z, 0.15f);
  EXPECT_GT(wrist.y, 0.95f);
  EXPECT_LT(std::abs(wrist.y - elbow.y), 0.12f);  // the forearm roughly level
  EXPECT_LT(glm::distance(joint(m, "r_index_tip"), wrist), 0.08f);
}

TEST(Synthesis, NotationNamingAPartOfTheRestingHandDoesNotSendTheHandToTheHip) {
  // DGS PROFESSION1A: thumb tip at the chin, a small arc, and the thumb tip at the chin again,
  // written "…chin, (touch, thumb tip)". The part after the arc reads as a place on the other
  // hand, which rests at the hip: the hand went 75 cm down to it. It stays at the face now.
  const SignSynthesis r = synthesize_sign(
      sign::parse_hamnosys_names("hamfist,hamthumboutmod,hamextfingerul,hampalmdl,hamchin,hamlrat,hamseqbegin,hamtouch,"
                                 "hamthumb,hamfingertip,hamseqend,hammovel,hamarcr,hamlrat,hamchin,hamseqbegin,hamtouch,"
                                 "hamthumb,hamfingertip,hamseqend"),
      fx().rig);
  for (float t = r.plan.sign_start; t <= r.plan.sign_end; t += 0.1f)
    EXPECT_GT(sample_hand(r.plan.right, t).position.y, 1.3f) << t;
}

TEST(Synthesis, AFingerNamedAfterAReplacementIsNotAPlaceOnTheRestingHand) {
  // DGS NOVEMBER5: the handshape changes to a fist with "middle finger, between, ring finger"
  // after it, which reads as a place on the other hand. That hand rests at the hip, so the hand
  // stays up in front rather than diving 70 cm down to it.
  const SignSynthesis r = synthesize_sign(
      sign::parse_hamnosys_names("hamfinger23spread,hamextfingeruo,hampalmd,hamreplace,hamfist,hammiddlefinger,"
                                 "hambetween,hamringfinger"),
      fx().rig);
  for (float t = r.plan.sign_start; t <= r.plan.sign_end; t += 0.1f)
    EXPECT_GT(sample_hand(r.plan.right, t).position.y, 1.0f) << t;
}

TEST(Synthesis, AWristOnTheOtherHandIsAHandConstellationInFrontOfTheBody) {
  // DGS TO-PALM1: the dominant wrist's back at the other index finger's pad, both flat palms down.
  // Both hands come up together in front (they met at 0.6 m, by the thighs).
  const SignSynthesis r = synthesize_sign(
      sign::parse_hamnosys_names("hamflathand,hamparbegin,hamextfingerol,hampalmd,hamplus,hamextfingeror,hampalmd,"
                                 "hamparend,hamparbegin,hamwristback,hamplus,hamindexfinger,hamfingerpad,hamparend,hamclose"),
      fx().rig);
  const auto m = held_pose(r);
  for (const char* j : {"r_wrist", "l_wrist"}) {
    EXPECT_GT(joint(m, j).y, 1.0f) << j;
    EXPECT_GT(joint(m, j).z, 0.15f) << j;
  }
  EXPECT_LT(glm::distance(joint(m, "r_wrist"), joint(m, "l_index2")), 0.10f);
}
