#pragma once
// A sign as its notation has it, before it meets a body: the citation schedule. The notation
// walker (notation_walker.hpp) reads a parsed sign into it; the planner (sign_planner.hpp) finds
// its places on an avatar (place_resolver.hpp), lets the body have its say (body_repair.hpp) and
// lays the result out in time (two_hand_timeline.hpp).
//
// The schedule is a list of steps in the notation's order. A manual segment starts with its
// posture (each hand's shape, turn and place), held briefly; then its actions, each a step for one
// or both hands made of changes: a new shape, a new turn, a place to go to, a path to follow, an
// oscillation. Everything a step needs is here except geometry: places are named (a site, the
// other hand's palm, neutral space), turns are directions in the signer's frame (already mirrored
// for the non-dominant hand of a mirror-symmetric sign), times are seconds at the schedule's tempo
// or "as long as the way there takes", which only the places tell.
#include <optional>
#include <variant>
#include <vector>

#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hand_timeline.hpp"
#include "gestura/sign/movement_timing.hpp"

namespace gestura {

// A turn the notation asks of a hand: where its extended fingers point and where its palm faces,
// either left as the hand has it. Directions are the signer's (phonology_direction.hpp).
struct TurnTarget {
  std::optional<vec3> finger;        // unit vector (a hambetween direction already averaged in)
  std::optional<Direction> palm;     // a palm symbol: frontal ones are read relative to the fingers
  std::optional<vec3> palm_between;  // hambetween: the palm halfway toward this direction
};

// Distances from a site to the hand's nearest surface for a proximity symbol (metres). Without a
// contact symbol HamNoSys places the hand near the site, in the space just in front of it (a little
// farther in front of the trunk).
float contact_gap(std::optional<sign::Proximity> proximity, sign::SiteRegion region);

// The hand's turn (HandState::orientation) once a hand turned `current` takes `target`; the palm
// is kept perpendicular to the fingers.
quat turn_hand(const quat& current, const TurnTarget& target, Hand hand);

// ---- one hand's step: its changes, applied in order ---------------------------------------------

// How the length of a move to a place is judged once the place is found.
enum class Travel : std::uint8_t {
  None,        // the step's own seconds only (a replacement)
  Transition,  // as long as a transition over the distance (a location written as an action)
  Straight,    // as long as a straight movement over the distance (a movement to a place)
};

struct Reshape {
  HandPosture shape;
};
struct Turn {
  TurnTarget turn;
};
// To a place the notation names. A place on the other hand or forearm while that hand rests at
// the hip is no place to go: the hand stays (and the parser reads a hand part written after a
// replacement as the moving hand's, which leaves the hand where it is too). Without a place, only
// the time of the travel is judged (a movement to a place left unwritten).
struct MoveTo {
  std::optional<sign::Location> place;
  Travel travel = Travel::None;
  MovementSpeed speed = MovementSpeed::Normal;  // Travel::Straight
};
// A path displacement on top of the step (fused paths add up); it takes the step's time.
struct FollowPath {
  Movement movement;
  bool constant_speed = false;  // the path sets the pace (circles): the step blends linearly
};
struct Oscillate {
  Oscillation kind = Oscillation::None;
  float cycles = 0.0f;
  FingerSet fingers = 0;  // finger play
};
// The wrist bends, the hand turning about its own thumb-to-little-finger axis.
struct BendWrist {
  float radians = 0.0f;
};
// Back to the site last named for this hand, at `gap` metres (a contact written after a movement).
struct TouchLastSite {
  float gap = 0.0f;
};
using HandChange = std::variant<Reshape, Turn, MoveTo, FollowPath, Oscillate, BendWrist, TouchLastSite>;

struct HandStep {
  std::vector<HandChange> changes;
  float seconds = 0.0f;  // at least this long (at the schedule's tempo); travel may need longer
  // Take the nearest place in space where the arm makes the turn (body_repair.hpp); false when
  // both hands move and settle together afterwards.
  bool settle = true;
};

// ---- the posture ---------------------------------------------------------------------------------

// Where a posture puts a hand that signs in it.
enum class PosturePlace : std::uint8_t {
  NeutralSpace,   // nothing written: in front, on its own side
  Site,           // its own notated location
  DominantSite,   // a symmetric sign's other hand at the dominant hand's location; mirrored across
                  // the midline when the symmetry is (the place found for the dominant hand)
  BaseHand,       // the non-dominant hand as a base: in front, in toward the midline
};

struct PostureHand {
  bool posed = false;  // the posture gives this hand a shape, a turn and a place
  HandPosture shape;
  TurnTarget turn;
  PosturePlace place = PosturePlace::NeutralSpace;  // also for a hand still signing from before
  std::optional<sign::Location> location;           // Site, DominantSite
  bool mirror_dominant = false;                     // DominantSite: take the dominant place mirrored
};

// A hand constellation: the non-dominant hand waits as a base and the dominant hand brings a part
// of itself to a part of it.
struct Constellation {
  sign::Site other_site;  // the part of the non-dominant hand (or its wrist)
  sign::SitePoint part;   // the dominant hand's part that meets it
  float gap = 0.0f;
};

struct PostureStep {
  ByHand<PostureHand> hands;
  bool both_hands = false;  // a symmetric sign: neutral space lies farther out to each side
  std::optional<Constellation> constellation;
  // Two hands at one central site stand side by side, each at least this far (metres) on its own
  // side of the midline.
  std::optional<float> side_by_side;
  // The hands touch: the dominant hand's palm comes to the other hand at this gap.
  std::optional<float> hands_touch;
};

// ---- the steps -----------------------------------------------------------------------------------

// Both hands hold for `seconds` once the one behind has caught up.
struct HoldStep {
  float seconds = 0.0f;
};
// The hand that is behind holds until the other catches up.
struct SyncStep {};
// One step for the hands `hands` drives, started together (each hand waits for the later clock).
// With both hands, their ends then settle in space together.
struct MoveStep {
  Hands hands = Hands::Dominant;
  ByHand<HandStep> steps;
};
// Each hand does its own branch at the same time (hamparbegin … hamplus … hamparend).
struct HandPairStep {
  struct Branch {
    bool waits = false;  // the branch has an action: its hand first waits for the pair's start
    std::vector<HandStep> steps;
  };
  ByHand<Branch> branches;
};
// The hands `hands` drives (those with a site named) go back to their last site at `gap`.
struct ContactStep {
  Hands hands = Hands::Dominant;
  float gap = 0.0f;
  float seconds = 0.0f;
};
// Where an action starts, for a repetition "from the start" that may follow it: the hands' states
// are put aside when the action starts, and kept as the action's start when it ends (a contact or
// a repetition is not an action to return to).
struct ActionBegins {};
struct ActionEnds {
  bool keep = true;
};
// The hands back to where the repeated action started.
struct ReturnToStart {
  float seconds = 0.0f;
};
// A repetition in reverse: the hands go back to where the action started, which becomes where
// they were.
struct Reverse {
  float seconds = 0.0f;
};

using ScheduleStep = std::variant<PostureStep, HoldStep, SyncStep, MoveStep, HandPairStep, ContactStep, ActionBegins,
                                  ActionEnds, ReturnToStart, Reverse>;

struct CitationSchedule {
  float speed = 1.0f;  // the tempo the seconds are at (2 = twice as fast)
  std::vector<ScheduleStep> steps;
};

}  // namespace gestura
