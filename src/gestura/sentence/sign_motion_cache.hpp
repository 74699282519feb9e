#pragma once
// Joint-space motion computed once per avatar and reused by every utterance: the citation form of
// each lexicon sign performed by inverse kinematics (sign_performer.hpp), and single hand postures
// (fingerspelled letters, rest) solved once each. A sentence then only stitches and time-scales
// stored joint angles instead of solving IK every frame (docs/say.md, "Speed").
//
//   SignMotionCache cache(rig);                                   // one per Signer (= per avatar)
//   const CitationMotion& m = cache.sign(notation);               // planned + performed on first use
//   m.sample(Hand::Right, 0.2f, out);                             // arm and finger rotations at 0.2 s
//
// Keys: a sign by its notation text (the rig fixes the avatar); a posture by the exact hand state.
// Thread-safe: lookups and inserts are serialised; entries are never moved or evicted, so the
// references returned stay valid for the cache's lifetime.
#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/sign_planner.hpp"

namespace gestura {

// Which joints carry a hand's motion, in the order postures store them: the arm chain (clavicle →
// wrist), then thumb1..3, index1..3, … pinky1..3.
std::vector<int> hand_motion_joints(const SigningRig& rig, Hand hand);

// One hand's joint rotations, in hand_motion_joints order.
using HandJointPosture = std::vector<quat>;

// A lexicon sign in citation form: planned at speed 1 without holds (plan_citation), time 0 at its
// first posture, and performed once.
struct CitationMotion {
  SignPlan plan;          // as the planner made it: sign_start = 0; sign_end = seconds of movement
  float rate = 40.0f;     // samples per second of citation time
  float first_posture = 0.0f;  // sample time of the first posture (an approach may come before)
  int frames = 0;             // at least 2
  ByHand<std::vector<quat>> samples;  // per hand: frames × joints, frame-major
  ByHand<std::size_t> joints{};       // joints per hand

  float movement() const { return plan.sign_end; }
  // The hand's joint rotations at citation time `t` (clamped to the sign), linearly interpolated
  // between samples. Contract: out.size() == joints[hand].
  void sample(Hand hand, float t, std::span<quat> out) const;
};

// Where citation forms solved by earlier processes are kept: asked before a sign is solved and
// given what was solved (sentence/citation_store.hpp keeps them in SQLite). Implementations are
// thread-safe and never throw: a form they cannot read is nullptr, one they cannot keep is dropped.
class CitationKeeper {
 public:
  virtual ~CitationKeeper() = default;
  virtual std::unique_ptr<CitationMotion> load(std::string_view key) = 0;
  virtual void save(std::string_view key, const CitationMotion& motion) = 0;
};

class SignMotionCache {
 public:
  // Contract: `rig` outlives the cache.
  explicit SignMotionCache(const SigningRig& rig);

  // The sign written in HamNoSys (Unicode) `notation`. Throws gestura::Error when it cannot be
  // parsed or performed (then nothing is stored).
  const CitationMotion& sign(std::string_view notation);

  // The same sign changed in space before it is performed (sentence/signing_space.hpp: a pointing
  // sign aimed at a locus, an agreement verb moved from one place to another): `change` maps the
  // citation plan to the plan performed; stored under the notation and `place` ("3a→3b").
  using PlanChange = std::function<SignPlan(const SignPlan&)>;
  const CitationMotion& sign(std::string_view notation, std::string_view place, const PlanChange& change);

  // The joint posture that puts `hand` in `state` (rest pose when the state is inactive), solved
  // once per distinct state and stored.
  const HandJointPosture& posture(Hand hand, const HandState& state);
  // The same, solved now and not stored (for states that occur once, like points on a path).
  HandJointPosture solve(Hand hand, const HandState& state) const;
  // The same, solved from `seed` (joint rotations in joints(hand) order) by damped least squares
  // alone, with the hand pushed out of the body as perform_plan does every frame: for points near
  // a known posture, where starting from the relaxed posture could end in another arm configuration.
  HandJointPosture solve_from(Hand hand, const HandState& state, std::span<const quat> seed) const;
  // solve_from, stored by state: for states that recur with the same seed (the via postures of a
  // transition between two given signs), so the first solution is reused.
  const HandJointPosture& posture_from(Hand hand, const HandState& state, std::span<const quat> seed);

  // Citation forms are looked up in `store` before they are solved and given to it after (forms
  // solved by an earlier process). Contract: `store` outlives the cache; call before the first
  // sign(). nullptr: solve everything.
  void persist_to(CitationKeeper* store) { store_ = store; }

  const SigningRig& rig() const { return *rig_; }
  const std::vector<int>& joints(Hand hand) const { return joints_[hand]; }
  std::size_t signs_stored() const;
  // How many times a sign has been performed (once per stored sign, unless two threads raced to
  // store the same one).
  std::size_t performances() const { return performances_.load(std::memory_order_relaxed); }

 private:
  SignPlan approached_from_relaxed(const SignPlan& citation) const;
  std::unique_ptr<CitationMotion> perform_citation(const SignPlan& citation) const;
  // Performs `citation` (see sign()) and stores it under `key`; the first stored wins.
  const CitationMotion& perform_and_store(std::string key, const SignPlan& citation);

  const SigningRig* rig_;
  CitationKeeper* store_ = nullptr;
  ByHand<std::vector<int>> joints_;
  mutable std::mutex mutex_;
  mutable std::atomic<std::size_t> performances_{0};
  std::unordered_map<std::string, std::unique_ptr<CitationMotion>> signs_;
  std::unordered_map<std::string, std::unique_ptr<HandJointPosture>> postures_;
};

}  // namespace gestura
