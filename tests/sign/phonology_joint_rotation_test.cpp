#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gestura/core/error.hpp"
#include "gestura/sign/phonology_joint_rotation.hpp"

using namespace gestura;

namespace {

// Direction of the fingertip segment in the hand-local frame after MCP, PIP, DIP.
vec3 tip_direction(const FingerJointRotations& r) { return r.mcp * r.pip * r.dip * vec3{0, 1, 0}; }

}  // namespace

TEST(PhonologyJointRotation, FlatHandIsTheIdentityAndFlexionCurlsTowardThePalm) {
  const HandPosture flat = basic_handshape(BasicHandshape::Flat);
  for (Hand hand : {Hand::Right, Hand::Left}) {
    const FingerJointRotations r = finger_joint_rotations(flat, Finger::Middle, hand);
    EXPECT_NEAR(glm::angle(r.mcp), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::angle(r.pip), 0.0f, 1e-6f);
    // Fist: the flexions add up in the finger's plane (no spread): MCP + PIP + DIP = 241°, so the
    // tip segment points back toward the wrist (−Y) and into the palm (−Z).
    const HandPosture fist = basic_handshape(BasicHandshape::Fist);
    const FingerFlexion& m = fist.finger(Finger::Middle);
    const float total = m.mcp + m.pip + m.dip;
    const vec3 tip = tip_direction(finger_joint_rotations(fist, Finger::Middle, hand));
    EXPECT_NEAR(tip.y, std::cos(total), 1e-5f);
    EXPECT_NEAR(tip.z, std::sin(total), 1e-5f);
    EXPECT_NEAR(tip.x, 0.0f, 1e-6f);
    EXPECT_LT(tip.y, 0.0f);
    EXPECT_LT(tip.z, 0.0f);
    // Bent (MCP 80° only): the finger points almost straight out of the palm.
    const HandPosture bent = make_handshape(BasicHandshape::Flat, ThumbModifier::Default, FingerBending::Bent);
    const vec3 b = tip_direction(finger_joint_rotations(bent, Finger::Ring, hand));
    EXPECT_NEAR(b.z, std::sin(deg(85)), 1e-5f);  // 80° MCP + 5° PIP
  }
}

TEST(PhonologyJointRotation, SpreadFansTheIndexTowardTheThumbSide) {
  const HandPosture v = basic_handshape(BasicHandshape::Finger23Spread);
  const HandFrame right = hand_frame(Direction::U, PalmOrientation::D, Hand::Right);  // fingers up, palm away
  const HandFrame left = hand_frame(Direction::U, PalmOrientation::D, Hand::Left);
  for (const auto& [hand, frame] : {std::pair{Hand::Right, right}, std::pair{Hand::Left, left}}) {
    const vec3 index = frame.rotation * tip_direction(finger_joint_rotations(v, Finger::Index, hand));
    const vec3 middle = frame.rotation * tip_direction(finger_joint_rotations(v, Finger::Middle, hand));
    // In the signer frame the index leans to the thumb side, the middle finger away from it.
    EXPECT_GT(glm::dot(index, frame.thumb_side), 0.15f);
    EXPECT_LT(glm::dot(middle, frame.thumb_side), -0.15f);
    EXPECT_NEAR(glm::dot(index, middle), std::cos(deg(24)), 1e-5f);  // 12° + 12° apart
  }
  EXPECT_THROW(finger_joint_rotations(v, Finger::Thumb, Hand::Right), std::out_of_range);
}

TEST(PhonologyJointRotation, WristRotationBringsASkeletonHandOntoTheNotatedFrame) {
  // A right hand hanging at rest: fingers down, palm facing the thigh (the body's midline, +X),
  // thumb forward (+Z). Knuckles 9 cm below the wrist, index in front of the pinky.
  const vec3 wrist{-0.2f, 0.8f, 0.0f};
  const vec3 index = wrist + vec3{0, -0.09f, 0.03f}, middle = wrist + vec3{0, -0.09f, 0.01f},
             pinky = wrist + vec3{0, -0.085f, -0.03f};
  const HandFrame rest = hand_frame_from_joints(wrist, index, middle, pinky, Hand::Right);
  EXPECT_LT(rest.finger.y, -0.99f);
  EXPECT_GT(rest.palm.x, 0.99f);
  EXPECT_GT(rest.thumb_side.z, 0.9f);
  const quat wrist_rest = glm::angleAxis(0.3f, glm::normalize(vec3{1, 2, 3}));  // any skeleton-specific rest rotation
  const HandFrame target = hand_frame(Direction::OL, PalmOrientation::D, Hand::Right);
  const quat wrist_target = wrist_rotation_for(target, rest.rotation, wrist_rest);
  // Move the rest knuckles rigidly with the wrist and rebuild the frame: it is the target.
  const quat delta = wrist_target * glm::inverse(wrist_rest);
  auto moved = [&](vec3 p) { return wrist + delta * (p - wrist); };
  const HandFrame result = hand_frame_from_joints(wrist, moved(index), moved(middle), moved(pinky), Hand::Right);
  EXPECT_LT(glm::length(result.finger - target.finger), 1e-5f);
  EXPECT_LT(glm::length(result.palm - target.palm), 1e-5f);
  EXPECT_THROW(hand_frame_from_joints(wrist, wrist, wrist, wrist, Hand::Left), Error);
  EXPECT_THROW(hand_frame_from_joints(wrist, wrist + vec3{0, -0.2f, 0}, wrist + vec3{0, -0.1f, 0}, wrist, Hand::Left), Error);
}

TEST(PhonologyJointRotation, FistFingertipsLandOnThePalmAndFlatOnesReachOut) {
  // Typical adult phalanx lengths (proximal, middle, distal), metres, index..pinky.
  const float lengths[4][3] = {{0.043f, 0.025f, 0.019f}, {0.047f, 0.029f, 0.020f}, {0.044f, 0.028f, 0.020f},
                               {0.035f, 0.020f, 0.018f}};
  auto tip = [&](const HandPosture& h, std::size_t f) {
    const FingerJointRotations r = finger_joint_rotations(h, static_cast<Finger>(f + 1), Hand::Right);
    const vec3 y{0, 1, 0};
    return r.mcp * (lengths[f][0] * y + r.pip * (lengths[f][1] * y + r.dip * (lengths[f][2] * y)));
  };
  const HandPosture fist = basic_handshape(BasicHandshape::Fist), flat = basic_handshape(BasicHandshape::Flat);
  for (std::size_t f = 0; f < 4; ++f) {
    const vec3 p = tip(fist, f);
    // Relative to the knuckle: pulled back toward the wrist (the palm is ~9 cm long) and within
    // the 1–3.5 cm in front of the knuckle axis where the palm's skin is.
    EXPECT_LT(p.y, 0.0f) << f;
    EXPECT_GT(p.y, -0.06f) << f;
    EXPECT_GT(p.z, 0.01f) << f;
    EXPECT_LT(p.z, 0.035f) << f;
    EXPECT_NEAR(tip(flat, f).y, lengths[f][0] + lengths[f][1] + lengths[f][2], 1e-6f);
  }
}
