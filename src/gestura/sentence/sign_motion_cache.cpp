#include "gestura/sentence/sign_motion_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gestura/core/error.hpp"
#include "gestura/sign/hand_solver.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_performer.hpp"

namespace gestura {

namespace {

// Samples per second of citation time. Running signing plays citation movements ~3× faster, so at
// speed 1 this is ~13 samples per second of the sentence, and a circle (≥ 0.4 s in citation form)
// gets at least 16; joint angles are interpolated in between. 60 gave the same accuracy at the key
// instants (SayMotion test) for 1.6× the first-use cost.
constexpr float kCitationRate = 40.0f;

// A cached performance whose palms stay this close to the plan is not tried from another start.
constexpr float kPlanTolerance = 0.01f;
// Seconds of the approach from the relaxed posture a sign is performed with before its first posture.
constexpr float kApproachSeconds = 0.4f;

int side_of(Hand hand) { return hand == Hand::Right ? 0 : 1; }

// The plan of a timeline from `start` on, shifted so that `start` becomes time 0.
void shift_to_start(HandTimeline& timeline, float start) {
  std::vector<HandSegment> kept;
  for (HandSegment& seg : timeline.segments) {
    if (seg.end <= start) continue;  // the approach from rest
    seg.start = std::max(seg.start, start) - start;
    seg.end -= start;
    kept.push_back(std::move(seg));
  }
  timeline.segments = std::move(kept);
}

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

}  // namespace

std::vector<int> hand_motion_joints(const SigningRig& rig, Hand hand) {
  const HandRig& h = rig.hand(hand);
  std::vector<int> joints(h.arm.joints.begin(), h.arm.joints.end());
  for (const auto& finger : h.fingers) joints.insert(joints.end(), finger.begin(), finger.end());
  return joints;
}

HandState relaxed_hand_state(const SigningRig& rig, Hand hand) {
  std::vector<mat4> model(rig.skeleton().size());
  local_to_model(rig.skeleton(), rig.neutral, model);
  const HandRig& h = rig.hand(hand);
  const mat4& wrist = model[static_cast<std::size_t>(h.wrist)];
  HandState s = rest_hand_state(rig, hand);
  s.position = vec3(wrist * vec4(h.palm_centre_local, 1.0f));
  // The hand frame turns with the wrist from its bind-pose relation.
  s.orientation = glm::normalize(glm::quat_cast(mat3(wrist)) * glm::inverse(h.rest_wrist_rotation) * h.rest_frame.rotation);
  s.active = true;
  return s;
}

void CitationMotion::sample(Hand hand, float t, std::span<quat> out) const {
  const int side = side_of(hand);
  const std::size_t n = joints[static_cast<std::size_t>(side)];
  const std::vector<quat>& s = samples[static_cast<std::size_t>(side)];
  // perform_plan keys at least two frames.
  const float f = std::clamp((first_posture + t) * rate, first_posture * rate, static_cast<float>(frames - 1));
  const auto i = static_cast<std::size_t>(std::min(static_cast<int>(f), frames - 2));
  const float w = f - static_cast<float>(i);
  const quat* a = &s[i * n];
  const quat* b = &s[(i + 1) * n];
  for (std::size_t j = 0; j < n; ++j) out[j] = nlerp(a[j], b[j], w);
}

SignMotionCache::SignMotionCache(const SigningRig& rig) : rig_(&rig) {
  joints_[0] = hand_motion_joints(rig, Hand::Right);
  joints_[1] = hand_motion_joints(rig, Hand::Left);
}

SignPlan SignMotionCache::approached_from_relaxed(const SignPlan& plan) const {
  // Each hand the sign uses first moves from its relaxed posture to the sign's first posture
  // (replacing the planner's instant entry from rest).
  SignPlan out = plan;
  for (int side = 0; side < 2; ++side) {
    HandTimeline& timeline = side == 0 ? out.right : out.left;
    shift_to_start(timeline, plan.sign_start);
    if (timeline.segments.empty()) continue;
    for (HandSegment& seg : timeline.segments) seg.start += kApproachSeconds, seg.end += kApproachSeconds;
    HandSegment approach;
    approach.end = kApproachSeconds;
    approach.to = timeline.segments.front().from;
    approach.from = approach.to.active ? relaxed_hand_state(*rig_, side == 0 ? Hand::Right : Hand::Left) : approach.to;
    timeline.segments.insert(timeline.segments.begin(), approach);
  }
  out.sign_start = kApproachSeconds;
  out.sign_end = plan.sign_end - plan.sign_start + kApproachSeconds;
  return out;
}

std::unique_ptr<CitationMotion> SignMotionCache::perform_citation(SignPlan plan) const {
  auto motion = std::make_unique<CitationMotion>();
  const Clip clip = perform_plan(plan, *rig_, PerformOptions{kCitationRate});
  motion->first_posture = plan.sign_start;
  shift_to_start(plan.right, plan.sign_start);
  shift_to_start(plan.left, plan.sign_start);
  plan.sign_end -= plan.sign_start;
  plan.sign_start = 0.0f;
  motion->plan = std::move(plan);
  motion->rate = kCitationRate;
  for (int side = 0; side < 2; ++side) {
    const std::vector<int>& joints = joints_[static_cast<std::size_t>(side)];
    const std::size_t frames = clip.rotations[static_cast<std::size_t>(joints.front())].size();
    motion->frames = static_cast<int>(frames);
    motion->joints[static_cast<std::size_t>(side)] = joints.size();
    std::vector<quat>& out = motion->samples[static_cast<std::size_t>(side)];
    out.resize(frames * joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const QuatTrack& track = clip.rotations[static_cast<std::size_t>(joints[j])];
      for (std::size_t f = 0; f < frames; ++f) out[f * joints.size() + j] = track.values[f];
    }
  }
  return motion;
}

float SignMotionCache::plan_error(const CitationMotion& motion) const {
  // Largest distance of a signing palm from its planned place, over the sign's samples.
  const Skeleton& skeleton = rig_->skeleton();
  Pose pose = rig_->neutral;
  std::vector<mat4> model(skeleton.size());
  std::vector<quat> posture;
  float worst = 0.0f;
  for (float t = 0.0f; t <= motion.movement() + 0.5f / motion.rate; t += 1.0f / motion.rate) {
    for (int side = 0; side < 2; ++side) {
      const Hand hand = side == 0 ? Hand::Right : Hand::Left;
      const HandTimeline& timeline = side == 0 ? motion.plan.right : motion.plan.left;
      if (timeline.segments.empty()) continue;
      const HandState planned = sample_hand(timeline, t);
      if (!planned.active) continue;
      const std::vector<int>& joints = this->joints(hand);
      posture.resize(joints.size());
      motion.sample(hand, t, posture);
      for (std::size_t j = 0; j < joints.size(); ++j) pose.rotations[static_cast<std::size_t>(joints[j])] = posture[j];
      local_to_model(skeleton, pose, model);
      const HandRig& h = rig_->hand(hand);
      const vec3 palm = vec3(model[static_cast<std::size_t>(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
      worst = std::max(worst, glm::distance(palm, planned.position));
    }
  }
  return worst;
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
  // Computed outside the lock: two threads may both compute a new sign; the first stored wins.
  // The solver's result depends on where it starts from. The sign is performed approached from the
  // relaxed signing posture in front (as in running signing, where the hands arrive from the
  // signing space — starting at the first posture itself, the solver may end in another arm
  // configuration, e.g. the hand behind the head for SLEEP); if a palm strays more than 1 cm from
  // the plan, it is performed again started cold at its first posture, which is kept only if it is
  // closer to the plan by more than 1 cm.
  const sign::HamSign parsed = sign::parse_hamnosys_unicode(notation);
  PlanOptions options;
  options.from_rest = false;
  options.to_rest = false;
  options.initial_hold = 0.0f;
  options.final_hold = 0.0f;
  const SignPlan plan = plan_sign(parsed, *rig_, options);
  std::unique_ptr<CitationMotion> motion = perform_citation(approached_from_relaxed(plan));
  const float error = plan_error(*motion);
  if (error > kPlanTolerance) {
    SignPlan at_first_posture = plan;  // without the planner's instant entry from rest
    shift_to_start(at_first_posture.right, plan.sign_start);
    shift_to_start(at_first_posture.left, plan.sign_start);
    at_first_posture.sign_end -= plan.sign_start;
    at_first_posture.sign_start = 0.0f;
    auto cold = perform_citation(std::move(at_first_posture));
    if (plan_error(*cold) < error - kPlanTolerance) motion = std::move(cold);
  }
  std::lock_guard lock(mutex_);
  return *signs_.emplace(key, std::move(motion)).first->second;
}

const CitationMotion& SignMotionCache::sign(std::string_view notation, std::string_view place, const PlanChange& change) {
  const std::string key = std::string(notation) + '\x1f' + std::string(place);
  {
    std::lock_guard lock(mutex_);
    if (auto it = signs_.find(key); it != signs_.end()) return *it->second;
  }
  // As sign(notation), on the changed plan.
  PlanOptions options;
  options.from_rest = false;
  options.to_rest = false;
  options.initial_hold = 0.0f;
  options.final_hold = 0.0f;
  const SignPlan plan = change(plan_sign(sign::parse_hamnosys_unicode(notation), *rig_, options));
  std::unique_ptr<CitationMotion> motion = perform_citation(approached_from_relaxed(plan));
  const float error = plan_error(*motion);
  if (error > kPlanTolerance) {
    SignPlan at_first_posture = plan;
    shift_to_start(at_first_posture.right, plan.sign_start);
    shift_to_start(at_first_posture.left, plan.sign_start);
    at_first_posture.sign_end -= plan.sign_start;
    at_first_posture.sign_start = 0.0f;
    auto cold = perform_citation(std::move(at_first_posture));
    if (plan_error(*cold) < error - kPlanTolerance) motion = std::move(cold);
  }
  std::lock_guard lock(mutex_);
  return *signs_.emplace(key, std::move(motion)).first->second;
}

HandJointPosture SignMotionCache::solve(Hand hand, const HandState& state) const {
  // A plan that holds the state for an instant, performed like any sign (IK, joint limits, the
  // hand kept out of the body); the other hand rests.
  SignPlan plan;
  HandSegment hold;
  hold.from = hold.to = state;
  (hand == Hand::Right ? plan.right : plan.left).segments.push_back(hold);
  const Clip clip = perform_plan(plan, *rig_, PerformOptions{});
  const std::vector<int>& joints = this->joints(hand);
  HandJointPosture out(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) out[j] = clip.rotations[static_cast<std::size_t>(joints[j])].values.front();
  return out;
}

HandJointPosture SignMotionCache::solve_from(Hand hand, const HandState& state, std::span<const quat> seed) const {
  const std::vector<int>& joints = this->joints(hand);
  if (!state.active) return solve(hand, state);
  const Skeleton& s = rig_->skeleton();
  const HandRig& h = rig_->hand(hand);
  Pose pose = rig_->neutral;
  for (std::size_t j = 0; j < joints.size(); ++j) pose.rotations[static_cast<std::size_t>(joints[j])] = seed[j];
  apply_hand_posture(*rig_, hand, state.shape, pose);
  // The solver of perform_plan (sign/hand_solver.hpp), so both solve the same problem; the seed's
  // elbow is where the analytic arm solver looks first.
  std::vector<mat4> model(s.size());
  std::vector<vec3> points;
  local_to_model(s, pose, model);
  const auto at = [&](int j) { return vec3(model[static_cast<std::size_t>(j)][3]); };
  HandSolverState solver(h.arm);
  solver.swivel = measure_swivel(h.swivel, at(h.shoulder), at(h.elbow), at(h.wrist));
  solve_hand(*rig_, hand, state, PerformOptions{}.body_margin, true, solver, pose, model, points);
  clamp_to_limits(s, pose);
  HandJointPosture out(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) out[j] = pose.rotations[static_cast<std::size_t>(joints[j])];
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
