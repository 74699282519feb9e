// The notation walker: a parsed sign read into its citation schedule, with no body in sight.
#include <gtest/gtest.h>

#include <cmath>

#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/notation_walker.hpp"

using namespace gestura;

namespace {

CitationSchedule read(const std::string& names, const ScheduleOptions& options = {}) {
  return read_citation_schedule(sign::parse_hamnosys_names(names), options);
}

template <class T>
std::vector<const T*> all(const CitationSchedule& s) {
  std::vector<const T*> out;
  for (const ScheduleStep& step : s.steps)
    if (const T* t = std::get_if<T>(&step)) out.push_back(t);
  return out;
}

template <class T>
const T* change(const HandStep& step) {
  for (const HandChange& c : step.changes)
    if (const T* t = std::get_if<T>(&c)) return t;
  return nullptr;
}

vec3 path_end(const Movement& m) { return sample(m, m.duration).position; }

}  // namespace

TEST(NotationWalker, AOneHandedMovementIsAPostureAHoldAndAStep) {
  const CitationSchedule s = read("hamflathand,hamextfingeru,hampalml,hamchest,hammoveo");
  ASSERT_GE(s.steps.size(), 3u);
  const auto* posture = std::get_if<PostureStep>(&s.steps[0]);
  ASSERT_NE(posture, nullptr);  // no rest: the schedule starts at the first posture
  EXPECT_TRUE(posture->hands[Hand::Right].posed);
  EXPECT_FALSE(posture->hands[Hand::Left].posed);
  EXPECT_EQ(posture->hands[Hand::Right].place, PosturePlace::Site);
  ASSERT_TRUE(posture->hands[Hand::Right].location);
  EXPECT_EQ(posture->hands[Hand::Right].location->site, sign::Site::chest);
  // Fingers up, palm to the signer's left, as notated (in the signer's frame, no avatar needed).
  ASSERT_TRUE(posture->hands[Hand::Right].turn.finger);
  EXPECT_NEAR(glm::distance(*posture->hands[Hand::Right].turn.finger, vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(posture->hands[Hand::Right].turn.palm, Direction::L);
  ASSERT_TRUE(std::holds_alternative<HoldStep>(s.steps[1]));
  EXPECT_FLOAT_EQ(std::get<HoldStep>(s.steps[1]).seconds, 0.10f);
  EXPECT_FLOAT_EQ(std::get<HoldStep>(s.steps.back()).seconds, 0.20f);  // the final hold ends it

  const auto moves = all<MoveStep>(s);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0]->hands, Hands::Dominant);
  const FollowPath* path = change<FollowPath>(moves[0]->steps[Hand::Right]);
  ASSERT_NE(path, nullptr);
  const vec3 d = path_end(path->movement);
  EXPECT_GT(d.z, 0.1f);  // out, away from the body
  EXPECT_NEAR(d.x, 0.0f, 1e-4f);
  EXPECT_NEAR(moves[0]->steps[Hand::Right].seconds, path->movement.duration, 1e-6f);
}

TEST(NotationWalker, AMirrorSymmetricSignGivesTheOtherHandAMirroredCopy) {
  const CitationSchedule s = read("hamsymmlr,hamflathand,hamextfingeru,hampalml,hamshoulders,hammover");
  const PostureStep& p = *all<PostureStep>(s).front();
  EXPECT_TRUE(p.both_hands);
  EXPECT_TRUE(p.hands[Hand::Left].posed);
  EXPECT_EQ(p.hands[Hand::Left].place, PosturePlace::DominantSite);
  EXPECT_TRUE(p.hands[Hand::Left].mirror_dominant);
  EXPECT_EQ(p.hands[Hand::Left].turn.palm, Direction::R);  // palm left, mirrored: palm right
  ASSERT_TRUE(p.side_by_side);                              // both hands at one central site
  EXPECT_GT(*p.side_by_side, 0.0f);

  const MoveStep& move = *all<MoveStep>(s).front();
  EXPECT_EQ(move.hands, Hands::Both);
  EXPECT_FALSE(move.steps[Hand::Right].settle);  // the two settle together
  const vec3 right = path_end(change<FollowPath>(move.steps[Hand::Right])->movement);
  const vec3 left = path_end(change<FollowPath>(move.steps[Hand::Left])->movement);
  EXPECT_LT(right.x, -0.05f);  // to the signer's right …
  EXPECT_NEAR(left.x, -right.x, 1e-5f);  // … and the other hand to the left
}

TEST(NotationWalker, TempoDividesEveryTime) {
  const std::string names = "hamflathand,hamextfingeru,hampalml,hamchest,hamreplace,hamfist";
  const CitationSchedule normal = read(names), fast = read(names, {2.0f, 0.10f, 0.20f});
  EXPECT_FLOAT_EQ(fast.speed, 2.0f);
  const HandStep& a = all<MoveStep>(normal).front()->steps[Hand::Right];
  const HandStep& b = all<MoveStep>(fast).front()->steps[Hand::Right];
  EXPECT_GT(a.seconds, 0.0f);
  EXPECT_FLOAT_EQ(b.seconds, 0.5f * a.seconds);
  EXPECT_NE(change<Reshape>(a), nullptr);
  EXPECT_FLOAT_EQ(all<HoldStep>(fast).front()->seconds, 0.05f);
}

TEST(NotationWalker, ARepetitionFromTheStartReturnsThenRepeats) {
  const CitationSchedule s =
      read("hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart");
  EXPECT_EQ(all<MoveStep>(s).size(), 2u);  // the movement, and again
  ASSERT_EQ(all<ReturnToStart>(s).size(), 1u);
  // The return comes between the two movements, after the first has been marked as an action.
  std::size_t first_move = 0, ret = 0, second_move = 0;
  for (std::size_t i = 0; i < s.steps.size(); ++i) {
    if (std::holds_alternative<MoveStep>(s.steps[i])) (first_move ? second_move : first_move) = i;
    if (std::holds_alternative<ReturnToStart>(s.steps[i])) ret = i;
  }
  EXPECT_LT(first_move, ret);
  EXPECT_LT(ret, second_move);
  EXPECT_EQ(all<ActionBegins>(s).size(), all<ActionEnds>(s).size());
}

TEST(NotationWalker, AHandConstellationNamesAPartOfEachHand) {
  const CitationSchedule s =
      read("hamfist,hamthumboutmod,hamextfingero,hampalml,hamparbegin,hampinkyside,hamplus,hampalm,hamparend,hamtouch");
  const PostureStep& p = *all<PostureStep>(s).front();
  ASSERT_TRUE(p.constellation);
  EXPECT_EQ(p.constellation->other_site, sign::Site::palm);
  EXPECT_EQ(p.constellation->part.site, sign::Site::pinky_side);
  EXPECT_FLOAT_EQ(p.constellation->gap, 0.0f);  // touching
  EXPECT_FALSE(p.hands_touch);                  // the constellation places the hands
}

TEST(NotationWalker, AContactAfterAMovementReturnsToTheSite) {
  const CitationSchedule s = read("hamflathand,hamextfingeru,hampalml,hamchin,hamclose,hammoveo,hamtouch");
  // The contact written after the movement is the movement's: it ends back at the chin, touching.
  const auto moves = all<MoveStep>(s);
  ASSERT_EQ(moves.size(), 1u);
  const TouchLastSite* touch = change<TouchLastSite>(moves[0]->steps[Hand::Right]);
  ASSERT_NE(touch, nullptr);
  EXPECT_FLOAT_EQ(touch->gap, 0.0f);
  // Written on its own after a repetition, a contact is a step of its own.
  const CitationSchedule apart = read("hamflathand,hamextfingeru,hampalml,hamchin,hamclose,hammoveo,hamrepeatfromstart,hamtouch");
  ASSERT_FALSE(all<ContactStep>(apart).empty());
  EXPECT_FLOAT_EQ(all<ContactStep>(apart).front()->gap, 0.0f);
}

TEST(NotationWalker, EachBranchOfAHandPairDrivesItsOwnHand) {
  const CitationSchedule s =
      read("hamflathand,hamextfingeru,hampalml,hamchest,hamparbegin,hammoveo,hamplus,hammoveu,hamparend");
  const auto pairs = all<HandPairStep>(s);
  ASSERT_EQ(pairs.size(), 1u);
  for (Hand h : kBothHands) {
    EXPECT_TRUE(pairs[0]->branches[h].waits);
    ASSERT_EQ(pairs[0]->branches[h].steps.size(), 1u);
  }
  EXPECT_GT(path_end(change<FollowPath>(pairs[0]->branches[Hand::Right].steps[0])->movement).z, 0.1f);
  EXPECT_GT(path_end(change<FollowPath>(pairs[0]->branches[Hand::Left].steps[0])->movement).y, 0.1f);
}

TEST(NotationWalker, HandshapesBecomePosturesOfThePhonology) {
  sign::HandshapeForm form;
  form.basic = BasicHandshape::Finger2;
  form.thumb = ThumbModifier::Across;
  const HandPosture p = hand_posture_of(form);
  const HandPosture expected = make_handshape(BasicHandshape::Finger2, ThumbModifier::Across);
  EXPECT_FLOAT_EQ(p.fingers[0].mcp, expected.fingers[0].mcp);
  EXPECT_FLOAT_EQ(p.thumb.cmc_flexion, expected.thumb.cmc_flexion);
  sign::Handshape between{form, sign::HandshapeForm{BasicHandshape::Fist}};
  const HandPosture half = hand_posture_of(between);
  EXPECT_NEAR(half.fingers[0].mcp, 0.5f * (p.fingers[0].mcp + make_handshape(BasicHandshape::Fist).fingers[0].mcp), 1e-5f);
}

TEST(CitationSchedule, TurnHandTakesTheNotatedTurnAndKeepsWhatIsLeftOpen) {
  const quat rest = hand_frame_from_vectors(vec3(0, -1, 0), vec3(1, 0, 0), Hand::Right).rotation;
  TurnTarget up_palm_left;
  up_palm_left.finger = vec3(0, 1, 0);
  up_palm_left.palm = Direction::L;
  const quat q = turn_hand(rest, up_palm_left, Hand::Right);
  EXPECT_NEAR(glm::distance(q * vec3(0, 1, 0), vec3(0, 1, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(q * vec3(0, 0, 1), vec3(1, 0, 0)), 0.0f, 1e-5f);
  // Only the palm: the fingers keep their direction.
  TurnTarget palm_only;
  palm_only.palm = Direction::O;
  const quat r = turn_hand(q, palm_only, Hand::Right);
  EXPECT_NEAR(glm::distance(r * vec3(0, 1, 0), vec3(0, 1, 0)), 0.0f, 1e-5f);
  EXPECT_GT(glm::dot(r * vec3(0, 0, 1), vec3(0, 0, 1)), 0.99f);
}

TEST(CitationSchedule, ContactGapsGrowWithProximity) {
  EXPECT_FLOAT_EQ(contact_gap(sign::Proximity::touch, sign::SiteRegion::face), 0.0f);
  EXPECT_LT(contact_gap(sign::Proximity::close, sign::SiteRegion::face), contact_gap(std::nullopt, sign::SiteRegion::face));
  EXPECT_LT(contact_gap(std::nullopt, sign::SiteRegion::face), contact_gap(std::nullopt, sign::SiteRegion::trunk));
  EXPECT_LT(contact_gap(std::nullopt, sign::SiteRegion::trunk), contact_gap(sign::Proximity::far, sign::SiteRegion::face));
}

TEST(NotationWalker, EverySegmentOfACompoundStartsWithItsPosture) {
  // Two segments joined by a top-level hamplus: each is a posture, its hold, then its actions.
  const sign::HamSign compound = sign::parse_hamnosys_names(
      "hamflathand,hamextfingeru,hampalml,hamchest,hammoveo,hamplus,hamfist,hamextfingero,hampalmd,hamchin");
  ASSERT_EQ(compound.segments.size(), 2u);
  const CitationSchedule s = read_citation_schedule(compound);
  EXPECT_EQ(all<PostureStep>(s).size(), 2u);
  EXPECT_TRUE(std::holds_alternative<PostureStep>(s.steps.front()));
}
