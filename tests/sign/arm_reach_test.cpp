#include <gtest/gtest.h>

#include "gestura/sign/arm_reach.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

// The right hand's palm centre and hand frame in the rig's relaxed signing posture: a place and
// turn the arm has just made, so certainly within its ranges.
struct Held {
  vec3 palm;
  quat orientation;
};
Held neutral_right_hand() {
  const SigningRig& rig = fx().rig;
  const HandRig& h = rig.hand(Hand::Right);
  std::vector<mat4> model(rig.skeleton().size());
  local_to_model(rig.skeleton(), rig.neutral, model);
  const mat4& w = model[static_cast<std::size_t>(h.wrist)];
  const quat wrist = glm::normalize(glm::quat_cast(mat3(w)));
  // HandState orientation = wrist rotation carried from the bind pose's hand frame.
  return {vec3(w * vec4(h.palm_centre_local, 1.0f)), wrist * glm::inverse(h.rest_wrist_rotation) * h.rest_frame.rotation};
}

// Fingers straight up, palm facing the signer, low in front of the lower chest: the forearm
// cannot twist that far back there.
quat fingers_up_palm_in() { return hand_frame_from_vectors(vec3(0, 1, 0), vec3(0, 0, -1), Hand::Right).rotation; }

}  // namespace

TEST(SignArmReach, AHandTheArmHoldsIsWithinReachWhereItIs) {
  const Held held = neutral_right_hand();
  EXPECT_LT(arm_reach_excess(fx().rig, Hand::Right, held.palm, held.orientation), deg(1.0f));
  const HandTurn turn{Hand::Right, held.palm, held.orientation};
  const ReachableShift p = nearest_reachable_shift(fx().rig, std::span(&turn, 1), 0.15f, deg(2.0f));
  EXPECT_EQ(p.offset, vec3(0.0f));
}

TEST(SignArmReach, ATurnTheArmCannotMakeMovesTheHandToWhereItCan) {
  const vec3 low_front = neutral_right_hand().palm + vec3(0.0f, 0.0f, 0.05f);
  const quat turn = fingers_up_palm_in();
  const float here = arm_reach_excess(fx().rig, Hand::Right, low_front, turn);
  ASSERT_GT(here, deg(2.0f));  // the case this test is about
  const HandTurn hand{Hand::Right, low_front, turn};
  const ReachableShift p = nearest_reachable_shift(fx().rig, std::span(&hand, 1), 0.15f, deg(2.0f));
  EXPECT_LT(p.excess, here);
  EXPECT_NEAR(p.excess, arm_reach_excess(fx().rig, Hand::Right, low_front + p.offset, turn), 1e-5f);
  EXPECT_LE(glm::length(p.offset), 0.15f + 1e-4f);
  EXPECT_GT(glm::length(p.offset), 0.0f);
  EXPECT_GT(p.offset.y, 0.0f);  // fingers up: the hand goes up, as a signer's does
}

TEST(SignArmReach, NoShiftAllowedKeepsThePlace) {
  const vec3 low_front = neutral_right_hand().palm + vec3(0.0f, 0.0f, 0.05f);
  const HandTurn hand{Hand::Right, low_front, fingers_up_palm_in()};
  EXPECT_EQ(nearest_reachable_shift(fx().rig, std::span(&hand, 1), 0.0f, deg(2.0f)).offset, vec3(0.0f));
}

TEST(SignArmReach, HandsHeldTogetherMoveTogether) {
  // Both hands fingers up, palms in, low in front: one shift for the pair, better than none.
  const vec3 right = neutral_right_hand().palm + vec3(0.0f, 0.0f, 0.05f);
  const HandTurn hands[2] = {{Hand::Right, right, fingers_up_palm_in()},
                             {Hand::Left, vec3(-right.x, right.y, right.z),
                              hand_frame_from_vectors(vec3(0, 1, 0), vec3(0, 0, -1), Hand::Left).rotation}};
  const float before = arm_reach_excess(fx().rig, Hand::Right, hands[0].palm, hands[0].orientation) +
                       arm_reach_excess(fx().rig, Hand::Left, hands[1].palm, hands[1].orientation);
  const ReachableShift p = nearest_reachable_shift(fx().rig, hands, 0.15f, deg(2.0f));
  EXPECT_LT(p.excess, before);
  EXPECT_GT(glm::length(p.offset), 0.0f);
}

TEST(SignArmReach, AMirroredPairShiftsInTheMidlinePlane) {
  // HOUSE's roof: both flat hands before the forehead, fingers up and in, palms down and in, each
  // the other's mirror image. Shifts to either side are equally good for such a pair; taking one
  // made the roof lopsided (2 cm to the right, the left fingertips across the right ones). Over
  // places around the head, every shift a mirrored pair takes stays in the midline plane.
  const SigningRig& rig = fx().rig;
  const vec3 forehead = site_position(*find_site(rig.sites, "forehead"), rig.bind_model);
  const vec3 up_in = glm::normalize(vec3(1, 1, 0)), down_in = glm::normalize(vec3(1, -1, 0));
  const auto mirrored = [](vec3 v) { return vec3(-v.x, v.y, v.z); };
  int moved = 0;
  for (float x : {-0.05f, -0.07f, -0.10f})
    for (float y : {-0.08f, -0.04f, 0.0f, 0.04f, 0.08f})
      for (float z : {0.06f, 0.10f, 0.15f}) {
        const vec3 right = forehead + vec3(x, y, z);
        const HandTurn hands[2] = {{Hand::Right, right, hand_frame_from_vectors(up_in, down_in, Hand::Right).rotation},
                                   {Hand::Left, mirrored(right),
                                    hand_frame_from_vectors(mirrored(up_in), mirrored(down_in), Hand::Left).rotation}};
        const ReachableShift p = nearest_reachable_shift(rig, hands, 0.15f, deg(2.0f));
        if (glm::length(p.offset) > 0.0f) ++moved;
        EXPECT_EQ(p.offset.x, 0.0f) << "at " << x << ", " << y << ", " << z;
      }
  EXPECT_GT(moved, 0);  // the case this test is about: some of these pairs must move
}
