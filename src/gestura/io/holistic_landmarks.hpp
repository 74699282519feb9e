#pragma once
// The landmarks MediaPipe Holistic reports — 33 body points, 468 face-mesh points, 21 per hand —
// computed from a performing avatar, so that tools built on Holistic output (sign.mt, the
// pose-evaluation metrics) read gestura's motion as if a camera had filmed it, and so that a
// detector's output can be scored against where the avatar's joints really were.
//
// Body and hand points come from H-Anim joints (any rig the name tables know). Face points come
// from the mesh: the face-mesh contours (lips outer and inner, eyelids, brows, face oval) and the
// nose tip are bound once, at bind pose, to the avatar's own vertices by reading a front view of
// the head (material regions: lips, eye whites, brows; the lower lip is the part the jaw carries).
// Bound vertices are then morphed and skinned per frame, so the mouth opens with the mouthing and
// the lids close with a blink. The other face-mesh points (cheek and forehead interior) have no
// counterpart on a mesh without the face-mesh topology: confidence 0.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/io/keypoints.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

inline constexpr int kHolisticBodyCount = 33, kHolisticFaceCount = 468, kHolisticHandCount = 21;
// MediaPipe's PoseLandmark names in index order ("NOSE", "LEFT_EYE_INNER", … "RIGHT_FOOT_INDEX");
// LEFT is the signer's left. The hand points use kHandNames (keypoints.hpp), MediaPipe's order too.
extern const std::array<const char*, kHolisticBodyCount> kHolisticBodyNames;

// Connections for drawing: MediaPipe's POSE_CONNECTIONS, HAND_CONNECTIONS, and the face-mesh
// contours (lips, eyes, brows, oval) as index pairs into the 468 face points.
std::span<const std::array<std::uint16_t, 2>> holistic_body_limbs();
std::span<const std::array<std::uint16_t, 2>> holistic_hand_limbs();
std::span<const std::array<std::uint16_t, 2>> holistic_face_limbs();

// Face-mesh landmark → mesh vertex, found at bind pose; -1 where the face has no such point.
struct FaceLandmarkBinding {
  std::array<std::int32_t, kHolisticFaceCount> vertex;
  int bound() const;  // how many points were placed
};
// Contract: `mesh` at bind pose in the skeleton's model space, facing +Z. A mesh without a head
// (no skullbase, or no vertices carried by it) or without lips / eye whites binds nothing for
// those parts; never throws for a partial face.
FaceLandmarkBinding bind_face_landmarks(const Skeleton& skeleton, const Mesh& mesh);

// Landmarks in model space (metres) for every frame of a clip sampled at fps, frames × count each,
// with a confidence per point (1 placed, 0 not placed: a missing joint or an unbound face point).
struct HolisticTrack {
  int frames = 0;
  std::vector<vec3> body, face, left_hand, right_hand;
  std::vector<float> body_confidence, face_confidence, left_confidence, right_confidence;
};

// `mesh` may be null (a bare skeleton: no face points). Clip channels named like a mesh morph
// drive it, as in rendering. Throws gestura::Error for fps outside (0, 1000].
HolisticTrack holistic_track(const Skeleton& skeleton, const Mesh* mesh, const Clip& clip, float fps);

}  // namespace gestura
