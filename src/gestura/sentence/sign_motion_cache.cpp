#include "gestura/sentence/sign_motion_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gestura/core/error.hpp"
#include "gestura/sign/hand_solver.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_performer.hpp"
#include "gestura/sign/two_hand_timeline.hpp"

namespace gestura {

namespace {

// Samples per second of citation time. Running signing plays citation movements ~3× faster, so at
// speed 1 this is ~13 samples per second of the sentence, and a circle (≥ 0.4 s in citation form)
// gets at least 16; joint angles are interpolated in between. 60 gave the same accuracy at the key
// instants (SayMotion test) for 1.6× the first-use cost.
constexpr float kCitationRate = 40.0f;

// Seconds of the approach from the relaxed posture a sign is performed with before its first posture.
constexpr float kApproachSeconds = 0.4f;

void append(std::string& key, float v) {
  char bytes[sizeof(float)];
  std::memcpy(bytes, &v, sizeof v);
  key.append(bytes, sizeof bytes);
}

std::string posture_key(Hand hand, const HandState& s) {
  std::string key(1, hand == Hand::Right ? 'r' : 'l');
  key.push_back(s.active ? 'a' : 'i');
  for (int i = 0; i < 3; ++i) append(key, s.position[i]);
  for (int i = 0; i < 4; ++i) append(key, s.orientation[i]);
  const HandPosture& p = s.shape;
  for (float v : {p.thumb.cmc_flexion, p.thumb.cmc_abduction, p.thumb.cmc_opposition, p.thumb.mcp, p.thumb.ip}) append(key, v);
  for (const FingerFlexion& f : p.fingers) append(key, f.mcp), append(key, f.pip), append(key, f.dip);
  for (float v : p.spread) append(key, v);
  key.push_back(static_cast<char>(p.thumb_tip_contacts));
  key.push_back(p.middle_crosses_index ? 'x' : '-');
  return key;
}

// A form an earlier process solved (sentence/citation_store.hpp), kept under `key`; nullptr when
// there is no store or it has none.
template <class Map>
const CitationMotion* from_store(CitationKeeper* store, std::mutex& mutex, Map& signs, const std::string& key) {
  if (!store) return nullptr;
  std::unique_ptr<CitationMotion> stored = store->load(key);
  if (!stored) return nullptr;
  std::lock_guard lock(mutex);
  return signs.emplace(key, std::move(stored)).first->second.get();
}

}  // namespace

std::vector<int> hand_motion_joints(const SigningRig& rig, Hand hand) {
  const HandRig& h = rig.hand(hand);
  std::vector<int> joints(h.arm.joints.begin(), h.arm.joints.end());
  for (const auto& finger : h.fingers) joints.insert(joints.end(), finger.begin(), finger.end());
  return joints;
}

void CitationMotion::sample(Hand hand, float t, std::span<quat> out) const {
  const std::size_t n = joints[hand];
  const std::vector<quat>& s = samples[hand];
  // perform_plan keys at least two frames.
  const float f = std::clamp((first_posture + t) * rate, first_posture * rate, static_cast<float>(frames - 1));
  const auto i = static_cast<std::size_t>(std::min(static_cast<int>(f), frames - 2));
  const float w = f - static_cast<float>(i);
  const quat* a = &s[i * n];
  const quat* b = &s[(i + 1) * n];
  for (std::size_t j = 0; j < n; ++j) out[j] = nlerp(a[j], b[j], w);
}

SignMotionCache::SignMotionCache(const SigningRig& rig) : rig_(&rig) {
  for (Hand hand : kBothHands) joints_[hand] = hand_motion_joints(rig, hand);
}

SignPlan SignMotionCache::approached_from_relaxed(const SignPlan& citation) const {
  // Each hand the sign uses first moves from its relaxed posture to the sign's first posture.
  ByHand<HandState> first, start;
  for (Hand hand : kBothHands) {
    first[hand] = citation.hand(hand).segments.front().from;
    start[hand] = first[hand].active ? relaxed_hand_state(*rig_, hand) : first[hand];
  }
  TwoHandTimeline timeline(start);
  for (Hand hand : kBothHands) timeline.move_to(hand, first[hand], kApproachSeconds);
  for (Hand hand : kBothHands) timeline.append_shifted(hand, citation.hand(hand), kApproachSeconds);
  return timeline.finish(kApproachSeconds + citation.sign_start, kApproachSeconds + citation.sign_end);
}

std::unique_ptr<CitationMotion> SignMotionCache::perform_citation(const SignPlan& citation) const {
  performances_.fetch_add(1, std::memory_order_relaxed);
  const SignPlan performed = approached_from_relaxed(citation);
  const Clip clip = perform_plan(performed, *rig_, PerformOptions{kCitationRate});
  auto motion = std::make_unique<CitationMotion>();
  motion->plan = citation;
  motion->first_posture = performed.sign_start;
  motion->rate = kCitationRate;
  for (Hand hand : kBothHands) {
    const std::vector<int>& joints = this->joints(hand);
    const std::size_t frames = clip.rotations[joint_slot(joints.front())].size();
    motion->frames = static_cast<int>(frames);
    motion->joints[hand] = joints.size();
    std::vector<quat>& out = motion->samples[hand];
    out.resize(frames * joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const QuatTrack& track = clip.rotations[joint_slot(joints[j])];
      for (std::size_t f = 0; f < frames; ++f) out[f * joints.size() + j] = track.values[f];
    }
  }
  return motion;
}

std::size_t SignMotionCache::signs_stored() const {
  std::lock_guard lock(mutex_);
  return signs_.size();
}

const CitationMotion& SignMotionCache::sign(std::string_view notation) {
  const std::string key(notation);
  {
    std::lock_guard lock(mutex_);
    if (auto it = signs_.find(key); it != signs_.end()) return *it->second;
  }
  if (const CitationMotion* kept = from_store(store_, mutex_, signs_, key)) return *kept;
  return perform_and_store(key, plan_citation(sign::parse_hamnosys_unicode(notation), *rig_, ScheduleOptions{1.0f, 0.0f, 0.0f}));
}

const CitationMotion& SignMotionCache::sign(std::string_view notation, std::string_view place, const PlanChange& change) {
  std::string key = std::string(notation) + '\x1f' + std::string(place);
  {
    std::lock_guard lock(mutex_);
    if (auto it = signs_.find(key); it != signs_.end()) return *it->second;
  }
  if (const CitationMotion* kept = from_store(store_, mutex_, signs_, key)) return *kept;
  return perform_and_store(std::move(key), change(plan_citation(sign::parse_hamnosys_unicode(notation), *rig_,
                                                                ScheduleOptions{1.0f, 0.0f, 0.0f})));
}

const CitationMotion& SignMotionCache::perform_and_store(std::string key, const SignPlan& citation) {
  // Computed outside the lock: two threads may both compute a new sign; the first stored wins.
  // The citation form is stored as the planner makes it and performed once, arriving from the
  // relaxed posture in front as in running signing, which keeps the elbows low where they can be
  // (started at the first posture, STORE came out with both elbows at shoulder height). Where the
  // hand lands does not depend on that start: the hand solver leaves an elbow that cannot make
  // the place and turn (sign/hand_solver.hpp).
  std::unique_ptr<CitationMotion> motion = perform_citation(citation);
  if (store_) store_->save(key, *motion);
  std::lock_guard lock(mutex_);
  return *signs_.emplace(std::move(key), std::move(motion)).first->second;
}

HandJointPosture SignMotionCache::solve(Hand hand, const HandState& state) const {
  // Solved from the relaxed posture with nothing before it, as the first frame of a performance
  // is (the other hand plays no part).
  Pose pose = rig_->neutral;
  std::vector<mat4> model(rig_->skeleton().size());
  HandPoints points;
  HandSolverState solver(rig_->hand(hand).arm);
  pose_hand(*rig_, hand, state, PerformOptions{}.body_margin, true, solver, pose, model, points);
  clamp_to_limits(rig_->skeleton(), pose);
  const std::vector<int>& joints = this->joints(hand);
  HandJointPosture out(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) out[j] = pose.rotations[joint_slot(joints[j])];
  return out;
}

HandJointPosture SignMotionCache::solve_from(Hand hand, const HandState& state, std::span<const quat> seed) const {
  const std::vector<int>& joints = this->joints(hand);
  if (!state.active) return solve(hand, state);
  const Skeleton& s = rig_->skeleton();
  const HandRig& h = rig_->hand(hand);
  Pose pose = rig_->neutral;
  for (std::size_t j = 0; j < joints.size(); ++j) pose.rotations[joint_slot(joints[j])] = seed[j];
  apply_hand_posture(*rig_, hand, state.shape, pose);
  // The solver of perform_plan (sign/hand_solver.hpp), so both solve the same problem; the seed's
  // elbow is where the analytic arm solver looks first.
  std::vector<mat4> model(s.size());
  HandPoints points;
  local_to_model(s, pose, model);
  const auto at = [&](int j) { return joint_position(model, j); };
  HandSolverState solver(h.arm);
  solver.swivel = measure_swivel(h.swivel, at(h.shoulder), at(h.elbow), at(h.wrist));
  solve_hand(*rig_, hand, state, PerformOptions{}.body_margin, true, solver, pose, model, points);
  clamp_to_limits(s, pose);
  HandJointPosture out(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) out[j] = pose.rotations[joint_slot(joints[j])];
  return out;
}

const HandJointPosture& SignMotionCache::posture_from(Hand hand, const HandState& state, std::span<const quat> seed) {
  const std::string key = "seeded " + posture_key(hand, state);
  {
    std::lock_guard lock(mutex_);
    if (auto it = postures_.find(key); it != postures_.end()) return *it->second;
  }
  auto solved = std::make_unique<HandJointPosture>(solve_from(hand, state, seed));
  std::lock_guard lock(mutex_);
  return *postures_.emplace(key, std::move(solved)).first->second;
}

const HandJointPosture& SignMotionCache::posture(Hand hand, const HandState& state) {
  const std::string key = posture_key(hand, state);
  {
    std::lock_guard lock(mutex_);
    if (auto it = postures_.find(key); it != postures_.end()) return *it->second;
  }
  auto solved = std::make_unique<HandJointPosture>(solve(hand, state));
  std::lock_guard lock(mutex_);
  return *postures_.emplace(key, std::move(solved)).first->second;
}

}  // namespace gestura
