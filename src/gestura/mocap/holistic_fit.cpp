#include "gestura/mocap/holistic_fit.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/ik/limb.hpp"

namespace gestura {
namespace {

// MediaPipe's PoseLandmark indices (LEFT = the person's left) and hand / face-mesh points used here.
constexpr int kLeftEar = 7, kRightEar = 8, kLeftShoulder = 11, kRightShoulder = 12, kLeftElbow = 13, kRightElbow = 14,
              kLeftWrist = 15, kRightWrist = 16, kLeftHip = 23, kRightHip = 24;
constexpr int kHandWrist = 0, kHandIndex = 5, kHandMiddle = 9, kHandPinky = 17;
constexpr int kFaceRightEyeOuter = 33, kFaceLeftEyeOuter = 263, kFaceTop = 10, kFaceChin = 152;
constexpr float kSeen = 0.5f;        // MediaPipe's own threshold for a visible point
constexpr float kNeckShare = 0.4f;   // of the head's turn, the neck takes this much, the skull the rest
constexpr float kTiny = 1e-6f;

int need(const Skeleton& s, const std::string& name) {
  const int j = s.find(name);
  if (j < 0) throw Error("motion capture: the skeleton has no joint '" + name + "' (H-Anim names are needed)");
  return j;
}

// MediaPipe's picture coordinates → a right-handed frame in units of the picture's width: +X the
// picture's right (the person's left), +Y up, +Z toward the camera (the person's front).
vec3 camera_space(const vec3& p, float aspect) { return vec3(p.x, -p.y / aspect, -p.z); }

void check_part(std::span<const vec3> points, std::size_t size, const char* part, bool optional_478 = false) {
  if (points.empty()) return;
  if (points.size() != size && !(optional_478 && points.size() == 478))
    throw Error(std::string("landmarks: ") + part + " has " + std::to_string(points.size()) + " points; MediaPipe Holistic reports " +
                std::to_string(size) + (optional_478 ? " (or 478)" : ""));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i])) throw Error(std::string("landmarks: ") + part + "[" + std::to_string(i) + "] is not a finite point");
}

// The rotation of a frame whose columns are orthonormal.
quat frame_rotation(const mat3& m) { return glm::normalize(glm::quat_cast(m)); }

// A frame from a primary axis `a` (kept) and a second one `b` (made perpendicular): columns a, b, a×b.
// Null when they are (nearly) parallel.
std::optional<mat3> frame_from(const vec3& a, const vec3& b) {
  if (glm::length(a) < kTiny) return std::nullopt;
  const vec3 x = glm::normalize(a);
  vec3 y = b - x * glm::dot(x, b);
  if (glm::length(y) < kTiny) return std::nullopt;
  y = glm::normalize(y);
  return mat3(x, y, glm::cross(x, y));
}

quat model_rotation(const mat4& m) { return glm::normalize(glm::quat_cast(mat3(m))); }

// Sets joint `j`'s model rotation to `target` (its parent as posed), clamped to its limits.
void set_model_rotation(const Skeleton& s, Pose& pose, int j, const quat& target) {
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  const int parent = s.parents[joint_slot(j)];
  const quat parent_rotation = parent < 0 ? quat(1, 0, 0, 0) : model_rotation(model[joint_slot(parent)]);
  pose.rotations[joint_slot(j)] = clamp_joint_rotation(s, j, glm::normalize(glm::inverse(parent_rotation) * target));
}

}  // namespace

mat3 palm_frame(const vec3& wrist, const vec3& index, const vec3& middle, const vec3& pinky) {
  return frame_from(middle - wrist, index - pinky).value_or(mat3(1.0f));
}

HolisticFit::HolisticFit(const Skeleton& skeleton) : skeleton_(skeleton) {
  skeleton_.validate();
  rest_model_.resize(skeleton_.size());
  local_to_model(skeleton_, rest_pose(skeleton_), rest_model_);
  const auto position = [&](int j) { return vec3(rest_model_[joint_slot(j)][3]); };
  for (const char side : {'l', 'r'}) {
    Arm& arm = side == 'l' ? left_ : right_;
    const std::string p(1, side);
    arm.shoulder = need(skeleton_, p + "_shoulder");
    arm.elbow = need(skeleton_, p + "_elbow");
    arm.wrist = need(skeleton_, p + "_wrist");
    arm.index = need(skeleton_, p + "_index1");
    arm.middle = need(skeleton_, p + "_middle1");
    arm.pinky = need(skeleton_, p + "_pinky1");
    arm.upper = glm::length(position(arm.elbow) - position(arm.shoulder));
    arm.fore = glm::length(position(arm.wrist) - position(arm.elbow));
    if (arm.upper < kTiny || arm.fore < kTiny) throw Error("motion capture: the " + p + " arm has a bone of zero length");
    // The elbow's hinge is its free axis across the forearm, turned so that a positive turn folds
    // the arm (flexion is the wider side of its range); its twist is the free axis along the forearm.
    const JointDofs& d = skeleton_.dofs[joint_slot(arm.elbow)];
    const vec3 forearm = glm::normalize(skeleton_.rest_translations[joint_slot(arm.wrist)]);
    const quat rest = skeleton_.rest_rotations[joint_slot(arm.elbow)];
    const auto along = [&](int a) {
      vec3 axis(0.0f);
      axis[a] = 1.0f;
      return std::abs(glm::dot(rest * axis, forearm));
    };
    int hinge = -1, twist = -1;
    for (int a = 0; a < 3; ++a) {
      if (!d.free(a)) continue;
      if (hinge < 0 || along(a) < along(hinge)) hinge = a;
      if (twist < 0 || along(a) > along(twist)) twist = a;
    }
    if (twist == hinge) twist = -1;
    if (hinge >= 0) {
      vec3 axis(0.0f);
      axis[hinge] = std::abs(d.min_angle[hinge]) > std::abs(d.max_angle[hinge]) ? -1.0f : 1.0f;
      arm.hinge = rest * axis;
    }
    arm.twist = forearm;
    if (twist >= 0) {
      vec3 axis(0.0f);
      axis[twist] = 1.0f;
      arm.twist = rest * axis;
    }
    arm.palm_rest = palm_frame(position(arm.wrist), position(arm.index), position(arm.middle), position(arm.pinky));
    arm.clavicle = skeleton_.parents[joint_slot(arm.shoulder)];
  }
  neck_ = need(skeleton_, "vc4");
  head_ = need(skeleton_, "skullbase");
  for (const int j : {left_.shoulder, left_.elbow, left_.wrist, right_.shoulder, right_.elbow, right_.wrist, neck_, head_}) driven_.push_back(j);
  std::sort(driven_.begin(), driven_.end());
}

void HolisticFit::fit_arm(const Arm& arm, const mat3& to_body, const vec3& shoulder, const vec3& elbow, const vec3& wrist,
                          Pose& pose) const {
  const vec3 upper = to_body * (elbow - shoulder), fore = to_body * (wrist - elbow);
  if (glm::length(upper) < kTiny || glm::length(fore) < kTiny) return;
  // The person's arm directions on the avatar's arm lengths: reachable by construction.
  std::vector<mat4> model(skeleton_.size());
  local_to_model(skeleton_, pose, model);
  const vec3 start = vec3(model[joint_slot(arm.shoulder)][3]);
  const vec3 elbow_point = start + glm::normalize(upper) * arm.upper;
  const vec3 wrist_point = elbow_point + glm::normalize(fore) * arm.fore;
  // The pole is the elbow point nudged the way elbows point when the arm is loose (back, down, a
  // little out): a bent arm's elbow decides; a nearly straight arm, whose elbow lies on the
  // shoulder–wrist line in any direction, does not spin about that line with the landmarks' noise.
  const float outward = arm.shoulder == left_.shoulder ? 1.0f : -1.0f;
  const vec3 loose = glm::normalize(vec3(0.3f * outward, -0.5f, -1.0f));
  const float bend = std::acos(std::clamp(glm::dot(glm::normalize(upper), glm::normalize(fore)), -1.0f, 1.0f));
  const float nudge = 0.05f + 0.6f * std::max(0.0f, 1.0f - bend / deg(45.0f));
  solve_limb(skeleton_, pose, arm.shoulder, arm.elbow, arm.wrist, arm.hinge, wrist_point, elbow_point + loose * (nudge * arm.upper));
}

void HolisticFit::fit_hand(const Arm& arm, const mat3& palm, Pose& pose) const {
  // The hand turned as the palm is: its model rotation is the turn from the rest palm to this one
  // applied to its rest rotation.
  const quat wrist_rest = model_rotation(rest_model_[joint_slot(arm.wrist)]);
  const quat target = glm::normalize(frame_rotation(palm) * glm::inverse(frame_rotation(arm.palm_rest)) * wrist_rest);
  std::vector<mat4> model(skeleton_.size());
  local_to_model(skeleton_, pose, model);
  const int parent = skeleton_.parents[joint_slot(arm.wrist)];
  const quat wrist_local = glm::normalize(glm::inverse(model_rotation(model[joint_slot(parent)])) * target);
  if (parent != arm.elbow) {
    pose.rotations[joint_slot(arm.wrist)] = clamp_joint_rotation(skeleton_, arm.wrist, wrist_local);
    return;
  }
  // Swing and twist: the turn about the forearm is the forearm's (pronation and supination, the
  // elbow's twist axis), what remains bends the wrist. Both clamped to their ranges; the wrist is
  // then solved again below the clamped forearm so that it gets as close as its own range allows.
  const vec3 axis = glm::normalize(arm.twist);
  const vec3 v(wrist_local.x, wrist_local.y, wrist_local.z);
  quat twist = glm::normalize(quat(wrist_local.w, axis * glm::dot(v, axis)));
  if (!is_finite(twist)) twist = quat(1, 0, 0, 0);
  const quat elbow_local = pose.rotations[joint_slot(arm.elbow)];
  pose.rotations[joint_slot(arm.elbow)] = clamp_joint_rotation(skeleton_, arm.elbow, glm::normalize(elbow_local * twist));
  set_model_rotation(skeleton_, pose, arm.wrist, target);
}

void HolisticFit::turn_head(const quat& turn, Pose& pose) const {
  const quat neck_turn = glm::slerp(quat(1, 0, 0, 0), turn, kNeckShare);
  set_model_rotation(skeleton_, pose, neck_, glm::normalize(neck_turn * model_rotation(rest_model_[joint_slot(neck_)])));
  set_model_rotation(skeleton_, pose, head_, glm::normalize(turn * model_rotation(rest_model_[joint_slot(head_)])));
}

Pose HolisticFit::fit(const HolisticFrame& frame, HolisticFitParts* parts) const {
  if (frame.pose.size() != kHolisticPosePoints)
    throw Error("landmarks: pose has " + std::to_string(frame.pose.size()) + " points; MediaPipe Holistic's body has " +
                std::to_string(kHolisticPosePoints));
  check_part(frame.pose, kHolisticPosePoints, "pose");
  check_part(frame.left_hand, kHolisticHandPoints, "left_hand");
  check_part(frame.right_hand, kHolisticHandPoints, "right_hand");
  check_part(frame.face, kHolisticFacePoints, "face", true);
  if (!frame.pose_visibility.empty() && frame.pose_visibility.size() != kHolisticPosePoints)
    throw Error("landmarks: pose visibility has " + std::to_string(frame.pose_visibility.size()) + " values; expected 33");
  if (!(std::isfinite(frame.aspect) && frame.aspect > 0.05f && frame.aspect < 20.0f))
    throw Error("landmarks: aspect " + std::to_string(frame.aspect) + " is not a picture's width / height");
  const auto seen = [&](int i) { return frame.pose_visibility.empty() || frame.pose_visibility[static_cast<std::size_t>(i)] >= kSeen; };
  std::vector<vec3> p(frame.pose.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = camera_space(frame.pose[i], frame.aspect);

  // The body's frame: left from the shoulders, up from the hips (or the picture's up).
  const vec3 across = p[kLeftShoulder] - p[kRightShoulder];
  const vec3 mid_shoulder = (p[kLeftShoulder] + p[kRightShoulder]) * 0.5f;
  vec3 up(0.0f, 1.0f, 0.0f);
  if (seen(kLeftHip) && seen(kRightHip)) {
    const vec3 spine = mid_shoulder - (p[kLeftHip] + p[kRightHip]) * 0.5f;
    if (glm::length(spine) > 0.5f * glm::length(across)) up = spine;
  }
  const std::optional<mat3> body = frame_from(across, up);
  if (!body) throw Error("landmarks: pose[11] and pose[12] (the shoulders) lie on one spot or along the body's up");
  const mat3 to_body = glm::transpose(*body);

  HolisticFitParts done;
  Pose pose = rest_pose(skeleton_);
  const struct {
    const Arm& arm;
    int shoulder, elbow, wrist;
    const std::vector<vec3>& hand;
    bool* arm_done;
    bool* hand_done;
  } sides[2] = {{left_, kLeftShoulder, kLeftElbow, kLeftWrist, frame.left_hand, &done.left_arm, &done.left_hand},
                {right_, kRightShoulder, kRightElbow, kRightWrist, frame.right_hand, &done.right_arm, &done.right_hand}};
  for (const auto& side : sides) {
    if (!(seen(side.elbow) && seen(side.wrist)) && side.hand.empty()) continue;  // the arm is out of the picture
    fit_arm(side.arm, to_body, p[static_cast<std::size_t>(side.shoulder)], p[static_cast<std::size_t>(side.elbow)],
            // The hand model's wrist is the better one when the hand was found.
            side.hand.empty() ? p[static_cast<std::size_t>(side.wrist)] : camera_space(side.hand[kHandWrist], frame.aspect), pose);
    *side.arm_done = true;
    if (side.hand.empty()) continue;
    std::array<vec3, 4> h;
    for (int k = 0; const int i : {kHandWrist, kHandIndex, kHandMiddle, kHandPinky})
      h[static_cast<std::size_t>(k++)] = to_body * camera_space(side.hand[static_cast<std::size_t>(i)], frame.aspect);
    const std::optional<mat3> palm = frame_from(h[2] - h[0], h[1] - h[3]);
    if (!palm) continue;
    fit_hand(side.arm, *palm, pose);
    *side.hand_done = true;
  }

  // The head: the face's frame when the face was found, else the ears' line (turn and tilt only).
  std::optional<quat> head;
  if (!frame.face.empty()) {
    const auto f = [&](int i) { return to_body * camera_space(frame.face[static_cast<std::size_t>(i)], frame.aspect); };
    if (const auto face = frame_from(f(kFaceLeftEyeOuter) - f(kFaceRightEyeOuter), f(kFaceTop) - f(kFaceChin))) head = frame_rotation(*face);
  } else if (seen(kLeftEar) && seen(kRightEar)) {
    const vec3 ears = to_body * (p[kLeftEar] - p[kRightEar]);
    if (glm::length(ears) > kTiny) head = glm::rotation(vec3(1, 0, 0), glm::normalize(ears));
  }
  if (head && is_finite(*head)) {
    turn_head(*head, pose);
    done.head = true;
  }
  if (parts) *parts = done;
  return pose;
}

}  // namespace gestura
