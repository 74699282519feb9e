// The place resolver: named places found on the default avatar, and the palm centre that puts the
// right part of the hand at them.
#include <gtest/gtest.h>

#include "gestura/sign/hand_part.hpp"
#include "gestura/sign/notation_walker.hpp"
#include "gestura/sign/place_resolver.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

HandState hand(vec3 finger, vec3 palm, BasicHandshape shape = BasicHandshape::Flat, Hand h = Hand::Right) {
  HandState s;
  s.active = true;
  s.orientation = hand_frame_from_vectors(finger, palm, h).rotation;
  s.shape = make_handshape(shape);
  return s;
}

vec3 site_point(const char* name) { return site_position(*find_site(fx().rig.sites, name), fx().rig.bind_model); }

}  // namespace

TEST(PlaceResolver, BodySitesAreApproachedFromInFront) {
  PlaceResolver places(fx().rig);
  const auto chin = places.body_site("chin");
  ASSERT_TRUE(chin);
  EXPECT_NEAR(glm::distance(chin->point, site_point("chin")), 0.0f, 1e-6f);
  EXPECT_NEAR(chin->normal.y, 0.0f, 1e-6f);  // not along the chin's downward surface normal
  EXPECT_GT(chin->normal.z, 0.9f);
  EXPECT_FALSE(places.body_site("no_such_site"));
}

TEST(PlaceResolver, SitesTheBodyHasTwiceAreOnTheHandsOwnSide) {
  PlaceResolver places(fx().rig);
  const HandState rest = rest_hand_state(fx().rig, Hand::Left);
  const SurfacePoint right = places.site(Hand::Right, sign::Site::cheek, sign::Side::centre, false, rest, false);
  const SurfacePoint left = places.site(Hand::Left, sign::Site::cheek, sign::Side::centre, false, rest, false);
  EXPECT_LT(right.point.x, -0.02f);  // the signer's right is −X
  EXPECT_GT(left.point.x, 0.02f);
  // Beside a central site: out on the hand's side; at its side (hamlrat): less far.
  const SurfacePoint lips = places.site(Hand::Right, sign::Site::lips, sign::Side::centre, false, rest, false);
  const SurfacePoint beside = places.site(Hand::Right, sign::Site::lips, sign::Side::beside, false, rest, false);
  const SurfacePoint at_side = places.site(Hand::Right, sign::Site::lips, sign::Side::dominant_side, false, rest, false);
  EXPECT_LT(beside.point.x, at_side.point.x);
  EXPECT_LT(at_side.point.x, lips.point.x);
}

TEST(PlaceResolver, NeutralSpaceIsInFrontOnTheHandsSideAndWiderForTwoHands) {
  PlaceResolver places(fx().rig);
  const SurfacePoint right = places.neutral_space(Hand::Right, false), left = places.neutral_space(Hand::Left, false);
  EXPECT_LT(right.point.x, 0.0f);
  EXPECT_NEAR(left.point.x, -right.point.x, 1e-5f);
  EXPECT_GT(right.point.z, site_point("chest").z + 0.15f);
  EXPECT_LT(places.neutral_space(Hand::Right, true).point.x, right.point.x);
}

TEST(PlaceResolver, PartsOfTheOtherHandFollowThatHand) {
  PlaceResolver places(fx().rig);
  HandState other = hand(vec3(0, 0, 1), vec3(0, 1, 0), BasicHandshape::Flat, Hand::Left);  // palm up, fingers forward
  other.position = vec3(0.05f, 1.1f, 0.3f);
  const auto palm = places.other_hand_site(Hand::Left, other, sign::Site::palm);
  ASSERT_TRUE(palm);
  EXPECT_NEAR(glm::distance(palm->normal, vec3(0, 1, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(palm->point.y - other.position.y, fx().rig.hand(Hand::Left).palm_half_thickness, 1e-5f);
  const auto fingers = places.other_hand_site(Hand::Left, other, sign::Site::fingers);
  EXPECT_GT(fingers->point.z, other.position.z + 0.05f);  // toward its fingertips
  EXPECT_FALSE(places.other_hand_site(Hand::Left, other, sign::Site::chin));
  // A hand site names the other hand when that hand is there.
  const SurfacePoint site = places.site(Hand::Right, sign::Site::palm, sign::Side::centre, false, other, false);
  EXPECT_NEAR(glm::distance(site.point, palm->point), 0.0f, 1e-6f);
}

TEST(PlaceResolver, PlaceAtPutsTheHandsFacingSurfaceAtTheGap) {
  PlaceResolver places(fx().rig);
  const SurfacePoint chest = *places.body_site("chest");
  // A flat hand, fingers across the body, palm toward the signer: the palm faces the chest.
  HandState s = hand(vec3(1, 0, 0), vec3(0, 0, -1));
  for (float gap : {0.0f, 0.025f, 0.07f}) {
    s.position = places.place_at(Hand::Right, s, chest, gap);
    float nearest = 1e9f;
    for (const vec3& p : places.hand_points(Hand::Right, s))
      nearest = std::min(nearest, glm::dot(s.position + p - chest.point, chest.normal));
    EXPECT_NEAR(nearest, gap, 1e-4f) << gap;
    EXPECT_LT(glm::length(glm::cross(s.position - chest.point, chest.normal)), 0.06f);  // in front of the site
  }
}

TEST(PlaceResolver, PlacePartAtPutsTheNamedPartAtTheSite) {
  PlaceResolver places(fx().rig);
  const SurfacePoint chin = *places.body_site("chin");
  HandState s = hand(vec3(0, 1, 0), vec3(-1, 0, 0), BasicHandshape::Finger2);
  const sign::SitePoint tip{sign::Site::fingers, sign::FingerSet{1u << 1}, sign::FingerPart::tip, sign::Side::centre};
  s.position = places.place_part_at(Hand::Right, s, chin, 0.0f, tip);
  // Where that fingertip is on the hand so placed.
  Pose pose = fx().rig.rest;
  apply_hand_posture(fx().rig, Hand::Right, s.shape, pose);
  const auto part = hand_part_site(fx().rig, Hand::Right, pose, s.shape, tip);
  ASSERT_TRUE(part);
  const vec3 at = s.position + planned_wrist_rotation(fx().rig, Hand::Right, s) *
                                    (part->point - fx().rig.hand(Hand::Right).palm_centre_local);
  EXPECT_LT(glm::distance(at, chin.point), 1e-4f);
}
