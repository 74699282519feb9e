#pragma once
// Retargeting: playing a clip made for one skeleton on another.
//
// Method (world-space delta retargeting):
// 1. Pair joints by name (match_joints: both skeletons' names guessed to H-Anim).
// 2. Rest alignment. The two rest poses may differ (a T-pose source, our A-pose avatar), so each
//    paired target joint gets a model-space rotation A that turns its rest bone direction (towards
//    its next paired descendants) onto the source's rest bone direction. Roots keep A = identity;
//    joints with no paired descendant inherit the A of their paired ancestor.
// 3. Every frame, each paired joint's model-space rotation change from rest on the source,
//    D = W_src(t) · W_src_rest⁻¹, is applied to the aligned target rest: W_tgt(t) = S · D · A · W_tgt_rest,
//    where the swing S (shortest arc) turns the bone onto the source bone's current direction —
//    needed because unpaired source joints inside a bone (MakeHuman's twist bones) also bend it.
//    Rest rotations of either side may be anything (identity or not): only model-space rotations
//    are compared. Unpaired target joints keep their rest local transform.
// 4. The root's displacement from rest is scaled by the ratio of leg lengths (hip → knee → ankle;
//    the root's height above the lowest joint when legs are not paired).
// 5. Optionally, end effectors: wrists and ankles are put where the source has them relative to its
//    root, scaled by the same ratio, by an analytic two-bone fix-up of shoulder/elbow (hip/knee)
//    that keeps the wrist's (ankle's) model-space orientation. This is self-contained here (the
//    general IK solver lives elsewhere); targets out of reach are approached as far as the limb
//    stretches.
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct RetargetOptions {
  float frame_time = 1.0f / 30.0f;   // output key spacing (seconds); > 0
  bool preserve_end_effectors = false;
  // Empty: match_joints(source, target). Otherwise target_to_source, one entry per target joint.
  std::vector<int> mapping;
};

// Contract: `clip` is valid for `source`. Throws gestura::Error when the mapping has the wrong size
// or indexes outside the source, or nothing is paired. The result is valid for `target`: a rotation
// track on every paired joint, a translation track on the paired root, keys every frame_time over
// [0, clip.duration]. Scalar channels are copied.
Clip retarget(const Skeleton& source, const Clip& clip, const Skeleton& target, const RetargetOptions& options = {});

// Leg-length ratio target / source used for root motion (exposed for tests and tools).
float retarget_scale(const Skeleton& source, const Skeleton& target, const std::vector<int>& target_to_source);

}  // namespace gestura
