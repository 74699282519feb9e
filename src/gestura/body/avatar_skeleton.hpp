#pragma once
// The default avatar's skeleton: H-Anim 1.1 joint names, anatomical limits on every degree of
// freedom, built from AvatarParams (no asset files).
//
// Rest pose: standing, feet on y = 0, facing +Z, the avatar's left is +X, arms hanging in a slight
// A-pose (10° from vertical; up to 30° for heavy builds, narrow shoulders or bulky hands, so the hands
// clear the hips) with the palms facing the thighs, thumbs forward, fingers straight and
// slightly spread. Metres.
//
// AXIS CONVENTION (what sign synthesis needs to drive the joints)
// Every joint's rest rotation is the identity: at rest all joint frames are parallel to the model
// frame (H-Anim's rule for the default pose). A joint's Euler angles (x, y, z) are therefore
// rotations about the model axes X (left), Y (up), Z (forward) as they sit at rest, composed in
// the joint's RotationOrder, and limits are relative to the rest pose. The left side is defined
// below; a RIGHT joint is the mirror image in X: the x angle keeps its sign, the y and z angles
// change sign (r_elbow flexion is also −x; r_shoulder abduction is −z).
//
//   joint(s)                    order  x                         y                          z
//   humanoid_root               ZXY    ±180 pitch               ±180 yaw                   ±180 roll
//   sacroiliac (pelvis)         ZXY    −20..20 tilt (+ = fwd)   −30..30 (+ = turn left)    −15..15
//   vl5 vl3 (lumbar)            ZXY    −10..25 (+ = bend fwd)   ±5 (+ = twist left)        ±10 (+ = bend right)
//   vt12 vt6 vt1 (thoracic)     ZXY    −8..15                   ±12                        ±8
//   vc7 vc4 (neck)              ZXY    −30..25 (+ = nod fwd)    ±35 (+ = turn left)        ±20
//   skullbase                   ZXY    −25..20                  ±30                        ±15
//   temporomandibular (jaw)     XYZ    −2..28 (+ = open)        ±8 (lateral)               —
//   l_eyeball_joint             YXZ    −25..30 (+ = look down)  ±35 (+ = look to its left) —
//   l_sternoclavicular          ZXY    —                        −30 protraction..25 retraction  −10 depression..40 elevation
//   l_shoulder                  ZXY    −188 flexion..61 extension  −70 internal..90 external  −48 adduction..134 abduction
//   l_elbow                     XYZ    −150 flexion..0          −77 pronation..113 supination —
//   l_wrist                     ZXY    −47 radial abduction..47 ulnar adduction  —       −90 flexion..99 extension
//   l_index1 l_middle1 l_ring1 l_pinky1 (MCP)
//                               XZY    −20..20 spread (+ = towards the little finger)  —  −90 flexion..30 extension
//   l_*2 (PIP)                  XYZ    —                        —                          −110 flexion..0
//   l_*3 (DIP)                  XYZ    —                        —                          −80 flexion..10
//   l_ring0 l_pinky0 (CMC cup)  XYZ    —                        —                          −15 / −25 flexion..0
//   l_thumb1 (CMC)              ZXY    −20 extension..50 flexion across the palm
//                                                               −45 opposition..15         −60 palmar abduction..15
//   l_thumb2 (MCP)              XZY    −10..60 flexion          —                          ±10
//   l_thumb3 (IP)               XYZ    −15..80 flexion          —                          —
//   l_hip                       ZXY    −125 flexion..30 extension  −40 internal..45 external  −30 adduction..45 abduction
//   l_knee                      XYZ    0..140 flexion           ±10 twist                  —
//   l_ankle                     XYZ    −20 dorsiflexion..50 plantarflexion  —             —
//   l_subtalar                  XYZ    —                        —                          −35 inversion..15 eversion
//   l_midtarsal                 XYZ    —                        ±10 forefoot ab/adduction  —
//   l_metatarsal (toes)         XYZ    −60 extension..40 flexion  —                        —
//
// Arm ranges: Table 1 of sign-language-interpreter.txt, corrected (avatar_skeleton.cpp); hands: MCP ~90, PIP ~110, DIP ~80,
// spread ±20. Rest orientation of the forearm is mid-pronation (palm facing the thigh), which is
// the zero of the pronation/supination angle.
//
// Fingertip sites are leaf joints with no degree of freedom: l_thumb_tip, l_index_tip,
// l_middle_tip, l_ring_tip, l_pinky_tip (and r_…), l_toe_tip / r_toe_tip, skull_tip.
#include "gestura/body/avatar_params.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// The five fingers in H-Anim order, for loops over "l_" + name + "1".."3" / "_tip".
inline constexpr const char* kFingerNames[5] = {"thumb", "index", "middle", "ring", "pinky"};

// Throws gestura::Error when params are invalid. Deterministic; a few microseconds.
Skeleton build_avatar_skeleton(const AvatarParams& params = {});

// Model-space rest positions of every joint (convenience over local_to_model on the rest pose).
std::vector<vec3> rest_joint_positions(const Skeleton& skeleton);

}  // namespace gestura
