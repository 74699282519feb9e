// The sentence motion cache: a lexicon sign's citation form as the planner made it, performed once
// per avatar; single postures solved once.
#include <gtest/gtest.h>

#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sentence/sign_motion_cache.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"
#include "support/hamnosys_text.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

std::string unicode(const std::string& names) { return test::hamnosys_text(names); }

const std::string kMother = "hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart";

vec3 palm_centre(const SignMotionCache& cache, const CitationMotion& m, Hand hand, float t) {
  const SigningRig& rig = cache.rig();
  Pose pose = rig.neutral;
  std::vector<quat> posture(cache.joints(hand).size());
  m.sample(hand, t, posture);
  for (std::size_t j = 0; j < posture.size(); ++j) pose.rotations[joint_slot(cache.joints(hand)[j])] = posture[j];
  std::vector<mat4> model(rig.skeleton().size());
  local_to_model(rig.skeleton(), pose, model);
  const HandRig& h = rig.hand(hand);
  return vec3(model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
}

}  // namespace

TEST(SignMotionCache, StoresThePlannersCitationFormAsItIs) {
  SignMotionCache cache(fx().rig);
  const CitationMotion& m = cache.sign(unicode(kMother));
  const SignPlan planned =
      plan_citation(sign::parse_hamnosys_names(kMother), fx().rig, ScheduleOptions{1.0f, 0.0f, 0.0f});
  EXPECT_FLOAT_EQ(m.plan.sign_start, 0.0f);
  EXPECT_FLOAT_EQ(m.movement(), planned.sign_end);
  for (Hand h : kBothHands) {
    const auto& a = m.plan.hand(h).segments;
    const auto& b = planned.hand(h).segments;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_FLOAT_EQ(a[i].start, b[i].start);
      EXPECT_FLOAT_EQ(a[i].end, b[i].end);
      EXPECT_EQ(a[i].to.position, b[i].to.position);
      EXPECT_EQ(a[i].to.orientation, b[i].to.orientation);
    }
  }
  EXPECT_EQ(m.plan.right.segments.front().start, 0.0f);  // no entry from rest to strip
}

TEST(SignMotionCache, ASignIsPerformedOnceAndFollowsItsPlan) {
  SignMotionCache cache(fx().rig);
  const std::string notation = unicode(kMother);
  const CitationMotion& first = cache.sign(notation);
  EXPECT_EQ(&cache.sign(notation), &first);  // stored, not performed again
  EXPECT_EQ(cache.signs_stored(), 1u);
  EXPECT_GE(first.frames, 2);
  EXPECT_EQ(first.joints[Hand::Right], cache.joints(Hand::Right).size());
  // The performed palm stays near its planned place through the sign (MOTHER: at the chin).
  for (float t = 0.0f; t <= first.movement(); t += 0.1f) {
    const HandState planned = sample_hand(first.plan.right, t);
    EXPECT_LT(glm::distance(palm_centre(cache, first, Hand::Right, t), planned.position), 0.03f) << "at " << t << " s";
  }
}

TEST(SignMotionCache, NotationThatCannotBePerformedIsNotStored) {
  SignMotionCache cache(fx().rig);
  EXPECT_THROW(cache.sign("not hamnosys"), Error);
  EXPECT_THROW(cache.sign(""), Error);
  EXPECT_EQ(cache.signs_stored(), 0u);
}

TEST(SignMotionCache, PosturesAreSolvedOnceAndMatchASolve) {
  SignMotionCache cache(fx().rig);
  HandState s = relaxed_hand_state(fx().rig, Hand::Left);
  s.position += vec3(0.0f, 0.1f, 0.05f);
  const HandJointPosture& stored = cache.posture(Hand::Left, s);
  EXPECT_EQ(&cache.posture(Hand::Left, s), &stored);
  const HandJointPosture fresh = cache.solve(Hand::Left, s);
  ASSERT_EQ(stored.size(), fresh.size());
  for (std::size_t j = 0; j < stored.size(); ++j) EXPECT_EQ(stored[j], fresh[j]);
  // At rest the arm hangs in the rest pose.
  const HandJointPosture rest = cache.solve(Hand::Left, rest_hand_state(fx().rig, Hand::Left));
  const HandRig& h = fx().rig.hand(Hand::Left);
  for (std::size_t j = 0; j < h.arm.joints.size(); ++j) EXPECT_EQ(rest[j], fx().rig.rest.rotations[joint_slot(h.arm.joints[j])]);
}

TEST(SignMotionCache, ASeededSolveStaysNearItsSeed) {
  SignMotionCache cache(fx().rig);
  HandState s = relaxed_hand_state(fx().rig, Hand::Right);
  s.position += vec3(0.0f, 0.12f, 0.06f);
  const HandJointPosture seed = cache.solve(Hand::Right, s);
  HandState near = s;
  near.position += vec3(0.01f, 0.0f, 0.0f);
  const HandJointPosture moved = cache.solve_from(Hand::Right, near, seed);
  float largest = 0.0f;
  for (std::size_t j = 0; j < seed.size(); ++j) largest = std::max(largest, glm::angle(glm::inverse(seed[j]) * moved[j]));
  EXPECT_LT(largest, deg(15.0f));  // a centimetre away: the same arm configuration
}

TEST(SignMotionCache, HandMotionJointsAreTheArmThenTheFingers) {
  const std::vector<int> joints = hand_motion_joints(fx().rig, Hand::Right);
  const HandRig& h = fx().rig.hand(Hand::Right);
  ASSERT_EQ(joints.size(), h.arm.joints.size() + 15);
  EXPECT_EQ(joints.front(), h.arm.joints.front());
  EXPECT_EQ(joints[h.arm.joints.size()], h.fingers[0][0]);  // thumb1
  EXPECT_EQ(joints.back(), h.fingers[4][2]);                // pinky3
}

TEST(SignMotionCache, EachSignIsPerformedExactlyOnce) {
  // Signs whose palm a low elbow carried in from the relaxed posture held centimetres off were
  // performed a second time from their first posture; now every sign is performed once, and
  // asking again performs nothing.
  SignMotionCache cache(fx().rig);
  const std::string outside =
      "hamparbegin,hampinchall,hamextfingerdo,hampalmd,hamplus,hamceeall,hamextfingeror,hampalml,hamparend,hamchest,"
      "hammoveu,hamsmallmod,hamreplace,hampinchall,hamrepeatfromstart";
  const std::string speed =
      "hamparbegin,hamfinger2,hamthumboutmod,hamextfingero,hampalml,hamplus,hamfinger2,hamthumboutmod,hamextfingero,"
      "hampalml,hamparend,hamchest,hammoveo,hamfast";
  std::size_t signs = 0;
  for (const std::string& names : {kMother, outside, speed}) {
    const CitationMotion& m = cache.sign(unicode(names));
    EXPECT_EQ(cache.performances(), ++signs) << names;
    EXPECT_EQ(&cache.sign(unicode(names)), &m);
    EXPECT_EQ(cache.performances(), signs);
    // …and the one performance keeps the palms on the plan.
    for (float t = 0.0f; t <= m.movement(); t += 0.05f)
      for (Hand hand : kBothHands) {
        if (m.plan.hand(hand).segments.empty()) continue;
        const HandState planned = sample_hand(m.plan.hand(hand), t);
        if (!planned.active) continue;
        EXPECT_LT(glm::distance(palm_centre(cache, m, hand, t), planned.position), 0.012f) << names << " at " << t << " s";
      }
  }
  EXPECT_EQ(cache.signs_stored(), signs);
}
