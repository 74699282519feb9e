// The body's rules, one pass at a time, on the default avatar's collision body.
#include <gtest/gtest.h>

#include "gestura/sign/body_repair.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

HandState flat_hand(vec3 at, vec3 finger, vec3 palm, Hand h = Hand::Right) {
  HandState s;
  s.active = true;
  s.position = at;
  s.orientation = hand_frame_from_vectors(finger, palm, h).rotation;
  s.shape = make_handshape(BasicHandshape::Flat);
  return s;
}

vec3 chest() { return site_position(*find_site(fx().rig.sites, "chest"), fx().rig.bind_model); }

float clearance(const HandState& s) {
  Pose scratch = fx().rig.rest;
  BodyRepair body(fx().rig);
  const HandPoints points = planned_hand_points(fx().rig, Hand::Right, s, scratch);
  return body.clearance(points, s.position);
}

}  // namespace

TEST(BodyRepair, KeepOutMovesAHandInTheBodyOutAndMarksItAtTheBody) {
  BodyRepair body(fx().rig);
  HandState s = flat_hand(chest() - vec3(0, 0, 0.03f), vec3(1, 0, 0), vec3(0, 0, -1));  // 3 cm into the chest
  ASSERT_LT(clearance(s), -0.02f);
  body.keep_out(Hand::Right, s);
  EXPECT_GT(clearance(s), -1e-3f);
  EXPECT_TRUE(s.at_body);
  // Far out in front it stays where it is, and is not at the body.
  HandState away = flat_hand(chest() + vec3(0, 0, 0.3f), vec3(0, 1, 0), vec3(1, 0, 0));
  const vec3 before = away.position;
  body.keep_out(Hand::Right, away);
  EXPECT_EQ(away.position, before);
  EXPECT_FALSE(away.at_body);
  // A resting hand is left alone.
  HandState rest = rest_hand_state(fx().rig, Hand::Right);
  rest.at_body = true;
  body.keep_out(Hand::Right, rest);
  EXPECT_FALSE(rest.at_body);
}

TEST(BodyRepair, AMovementThroughTheBodyStopsAtItsSurface) {
  BodyRepair body(fx().rig);
  const HandState from = flat_hand(chest() + vec3(0, 0, 0.12f), vec3(1, 0, 0), vec3(0, 0, -1));
  HandState to = from;
  to.position = chest() - vec3(0, 0, 0.12f);  // behind the chest
  body.stop_at_surface(Hand::Right, from, to);
  EXPECT_GT(to.position.z, chest().z - 0.01f);  // stopped on the side it came from
  EXPECT_GT(clearance(to), -0.01f);
}

TEST(BodyRepair, APathThroughTheBodyBowsOutRoundIt) {
  BodyRepair body(fx().rig);
  // From the right of the chest across to the left, passing through it on the straight line.
  HandSegment seg;
  seg.from = flat_hand(chest() + vec3(-0.17f, 0, 0.02f), vec3(0, 1, 0), vec3(1, 0, 0));
  seg.to = flat_hand(chest() + vec3(0.17f, 0, 0.02f), vec3(0, 1, 0), vec3(1, 0, 0));
  seg.end = 0.5f;
  HandTimeline straight;
  straight.segments = {seg};
  float through = 1e9f;
  for (float u = 0.1f; u < 0.95f; u += 0.1f) through = std::min(through, clearance(sample_hand(straight, u * seg.end)));
  ASSERT_LT(through, -0.01f);  // the straight way goes into the chest
  body.detour_around_body(Hand::Right, seg);
  EXPECT_GT(seg.detour.z, 0.0f);  // out in front
  HandTimeline bowed;
  bowed.segments = {seg};
  // Along the bowed way the hand keeps (nearly) as far off the body as at its ends.
  const float ends = std::min({clearance(seg.from), clearance(seg.to), 0.005f});
  for (float u = 0.1f; u < 0.95f; u += 0.1f) EXPECT_GE(clearance(sample_hand(bowed, u * seg.end)), ends - 0.004f) << u;
  // A hold goes nowhere.
  HandSegment hold;
  hold.from = hold.to = seg.from;
  hold.end = 0.5f;
  body.detour_around_body(Hand::Right, hold);
  EXPECT_EQ(hold.detour, vec3(0.0f));
}

TEST(BodyRepair, AHandRisingFromRestComesUpInFront) {
  HandSegment seg;
  seg.from = rest_hand_state(fx().rig, Hand::Right);
  seg.to = flat_hand(chest() + vec3(-0.05f, 0.2f, 0.15f), vec3(0, 1, 0), vec3(1, 0, 0));
  BodyRepair::come_up_in_front(seg);
  EXPECT_GT(seg.detour.z, 0.05f);
  HandSegment in_space;
  in_space.from = in_space.to = seg.to;
  BodyRepair::come_up_in_front(in_space);  // signing to signing: no change
  EXPECT_EQ(in_space.detour, vec3(0.0f));
}

TEST(BodyRepair, AHandAtTheBodyKeepsItsPlaceWhenSettling) {
  BodyRepair body(fx().rig);
  HandState touching = flat_hand(chest() + vec3(0, 0, 0.02f), vec3(1, 0, 0), vec3(0, 0, -1));
  body.keep_out(Hand::Right, touching);
  ASSERT_TRUE(touching.at_body);
  const vec3 before = touching.position;
  body.settle_in_space(Hand::Right, touching, rest_hand_state(fx().rig, Hand::Left));
  EXPECT_EQ(touching.position, before);
}

TEST(BodyRepair, AHandInSpaceSettlesWhereTheArmMakesTheTurn) {
  BodyRepair body(fx().rig);
  // Fingers straight up, palm toward the signer, low in front of the lower chest: the forearm
  // cannot twist that far back there, and the hand goes where it can.
  HandState s = flat_hand(chest() + vec3(-0.08f, -0.15f, 0.3f), vec3(0, 1, 0), vec3(0, 0, -1));
  const vec3 before = s.position;
  body.settle_in_space(Hand::Right, s, rest_hand_state(fx().rig, Hand::Left));
  EXPECT_GT(glm::distance(s.position, before), 0.01f);
  EXPECT_LE(glm::distance(s.position, before), 0.25f);
  EXPECT_LE(std::abs(s.position.x - before.x), 0.1f + 1e-4f);  // keeps to its side
}

TEST(BodyRepair, ASmallTurnGoesTheShortWay) {
  BodyRepair body(fx().rig);
  HandSegment seg;
  seg.from = flat_hand(chest() + vec3(-0.1f, 0, 0.3f), vec3(0, 1, 0), vec3(1, 0, 0));
  seg.to = flat_hand(chest() + vec3(-0.1f, 0, 0.3f), glm::normalize(vec3(0.3f, 1, 0)), vec3(1, -0.3f, 0));
  body.choose_turn_way(Hand::Right, seg);
  EXPECT_FALSE(seg.long_turn);
}
