#pragma once
// Real-time motion capture (realtime-virtual-humans.txt: a participant drives their own virtual
// human with their body): a skeleton's pose fitted to one frame of the landmarks MediaPipe
// Holistic finds in a camera picture.
//
// The landmarks are read in the body's own frame — shoulders give its left, the hips (or, when they
// are out of the picture, the picture's up) its up — so that where the person stands, how far from
// the camera and how the camera is turned do not matter; only how the limbs sit on the body.
//   * arms: the directions shoulder→elbow and elbow→wrist, laid onto the avatar's own arm
//     lengths, give an elbow and a wrist point; the core's two-bone IK (ik/limb) reaches the wrist
//     point with the elbow bent toward the elbow point, within the joints' limits;
//   * hands: the palm's frame (wrist → middle knuckle, little → index knuckle) from the hand's 21
//     points turns the hand; the turn about the forearm goes to the forearm (pronation), the rest
//     to the wrist, each clamped to its limits;
//   * head: the face's frame (right → left outer eye corner, chin → top of the forehead) turns the
//     neck and the head; without a face, the ears give the head's turn and tilt.
// A part whose landmarks are missing or unseen (visibility below one half) stays at rest. The torso
// is not turned: the arms and head are fitted relative to it.
//
// Coordinates are MediaPipe's: x and y normalised by the picture's width and height (x to the
// right, y down), z depth in units of the width, smaller nearer the camera. The person faces the
// camera, so the picture's right is the person's left (+X of the avatar).
#include <span>
#include <string>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

inline constexpr int kHolisticPosePoints = 33, kHolisticHandPoints = 21, kHolisticFacePoints = 468;

// One frame of Holistic's output. Each part is empty when Holistic found nothing.
struct HolisticFrame {
  std::vector<vec3> pose;              // 33 body points (MediaPipe's PoseLandmark order)
  std::vector<float> pose_visibility;  // 33, or empty: every point seen
  std::vector<vec3> left_hand, right_hand;  // 21 each: the person's own left and right hand
  std::vector<vec3> face;              // 468 face-mesh points (478 with refined irises)
  float aspect = 4.0f / 3.0f;          // the picture's width / height
};

// What was fitted, for callers that report it.
struct HolisticFitParts {
  bool left_arm = false, right_arm = false, left_hand = false, right_hand = false, head = false;
};

class HolisticFit {
 public:
  // Contract: a skeleton with H-Anim arms (l_/r_ shoulder, elbow, wrist, index1, middle1, pinky1)
  // and neck (vc4, skullbase). Throws gestura::Error naming the first missing joint.
  explicit HolisticFit(const Skeleton& skeleton);

  // The pose for one frame: the rest pose with arms, hands and head fitted. Throws gestura::Error
  // naming the part and the point for a frame without 33 body points, with a part of the wrong
  // size, a non-finite number, or shoulders on one spot.
  Pose fit(const HolisticFrame& frame, HolisticFitParts* parts = nullptr) const;

  // The joints fit() may turn (every other joint stays at rest), in skeleton order.
  std::span<const int> driven_joints() const { return driven_; }
  const Skeleton& skeleton() const { return skeleton_; }

 private:
  struct Arm {
    int clavicle = -1, shoulder = -1, elbow = -1, wrist = -1, index = -1, middle = -1, pinky = -1;
    float upper = 0.0f, fore = 0.0f;  // bone lengths, metres
    vec3 hinge{-1.0f, 0.0f, 0.0f};    // the elbow's flexion axis (its frame), as solve_limb wants it
    vec3 twist{0.0f, -1.0f, 0.0f};    // the forearm's axis in the elbow's frame (toward the wrist)
    mat3 palm_rest{1.0f};             // the palm's frame at rest, model space
  };
  void fit_arm(const Arm& arm, const mat3& to_body, const vec3& shoulder, const vec3& elbow, const vec3& wrist,
               Pose& pose) const;
  void fit_hand(const Arm& arm, const mat3& palm, Pose& pose) const;
  void turn_head(const quat& turn, Pose& pose) const;

  Skeleton skeleton_;
  std::vector<mat4> rest_model_;
  Arm left_, right_;
  int neck_ = -1, head_ = -1;
  std::vector<int> driven_;
};

// The palm's frame (columns: wrist → middle knuckle, the across-the-palm axis toward the index,
// their normal) from a hand's wrist, index, middle and little-finger knuckle points. Shared by the
// fitting and its tests.
mat3 palm_frame(const vec3& wrist, const vec3& index, const vec3& middle, const vec3& pinky);

}  // namespace gestura
