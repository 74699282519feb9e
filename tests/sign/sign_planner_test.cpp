// The planner: a citation schedule laid out on the default avatar; a sign on its own entered from
// rest and left to it.
#include <gtest/gtest.h>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_planner.hpp"
#include "support/signing_avatar.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

const char* kMove = "hamflathand,hamextfingeru,hampalml,hamchest,hammoveo";

void expect_contiguous(const HandTimeline& t) {
  for (std::size_t i = 1; i < t.segments.size(); ++i) {
    EXPECT_NEAR(t.segments[i].start, t.segments[i - 1].end, 1e-5f) << i;
    EXPECT_EQ(t.segments[i].from.position, t.segments[i - 1].to.position) << i;
  }
}

}  // namespace

TEST(SignPlanner, TheCitationFormStartsAtItsFirstPosture) {
  const SignPlan c = plan_citation(sign::parse_hamnosys_names(kMove), fx().rig);
  EXPECT_FLOAT_EQ(c.sign_start, 0.0f);
  EXPECT_NEAR(c.sign_end, c.duration(), 1e-6f);
  const HandState& first = c.right.segments.front().from;
  EXPECT_TRUE(first.active);  // no entry from rest
  EXPECT_FLOAT_EQ(c.right.segments.front().start, 0.0f);
  EXPECT_FALSE(c.left.segments.front().from.active);  // the other hand rests throughout
  for (Hand h : kBothHands) expect_contiguous(c.hand(h));
  EXPECT_NEAR(c.right.end_time(), c.left.end_time(), 1e-5f);  // the hands end together
  // The posture's place: the palm in front of the chest.
  const vec3 chest = site_position(*find_site(fx().rig.sites, "chest"), fx().rig.bind_model);
  EXPECT_LT(glm::distance(first.position, chest), 0.2f);
  EXPECT_GT(first.position.z, chest.z);
}

TEST(SignPlanner, ASignOnItsOwnIsItsCitationFormEnteredFromRestAndLeftToIt) {
  const sign::HamSign parsed = sign::parse_hamnosys_names(kMove);
  const SignPlan c = plan_citation(parsed, fx().rig);
  const SignPlan p = plan_sign(parsed, fx().rig);
  EXPECT_FALSE(p.right.segments.front().from.active);  // from rest …
  EXPECT_FALSE(p.right.final_state().active);           // … to rest
  EXPECT_NEAR(p.sign_end - p.sign_start, c.sign_end, 1e-5f);
  // Between sign_start and sign_end it is the citation form, shifted.
  for (float t = 0.0f; t <= c.sign_end; t += 0.05f) {
    const HandState a = sample_hand(c.right, t), b = sample_hand(p.right, p.sign_start + t);
    EXPECT_LT(glm::distance(a.position, b.position), 1e-4f) << t;
  }
  // The way in comes up in front of the body.
  EXPECT_GT(p.right.segments.front().detour.z, 0.0f);
  for (Hand h : kBothHands) expect_contiguous(p.hand(h));
  // Without the rest at either end it is the citation form itself.
  const SignPlan bare = plan_sign(parsed, fx().rig, PlanOptions{1.0f, false, false});
  EXPECT_EQ(bare.right.segments.size(), c.right.segments.size());
}

TEST(SignPlanner, ASymmetricSignPlacesTheHandsMirrored) {
  const SignPlan c = plan_citation(sign::parse_hamnosys_names("hamsymmlr,hamflathand,hamextfingeru,hampalml,hamshoulders"),
                                   fx().rig);
  const HandState& right = c.right.segments.front().from;
  const HandState& left = c.left.segments.front().from;
  ASSERT_TRUE(right.active && left.active);
  EXPECT_LT(right.position.x, -0.05f);
  EXPECT_NEAR(left.position.x, -right.position.x, 0.01f);
  EXPECT_NEAR(left.position.y, right.position.y, 0.01f);
}

TEST(SignPlanner, BadSchedulesAndOptionsAreRefused) {
  EXPECT_THROW(plan_schedule(CitationSchedule{}, fx().rig), Error);
  CitationSchedule starts_with_a_hold;
  starts_with_a_hold.steps.push_back(HoldStep{0.1f});
  EXPECT_THROW(plan_schedule(starts_with_a_hold, fx().rig), Error);
  EXPECT_THROW(plan_citation(sign::parse_hamnosys_names(kMove), fx().rig, ScheduleOptions{0.0f}), Error);
  EXPECT_THROW(plan_citation(sign::HamSign{}, fx().rig), Error);
}
