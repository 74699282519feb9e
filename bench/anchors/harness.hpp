#pragma once
// The anchor comparison harness (make bench-anchors): gestura against ozz-animation and ACL on the
// same subject, timed in interleaved rounds.
//
// A Side is one implementation of one workload: a function that runs the workload `n` times. The
// runner times both sides of a workload alternately (thread CPU time, so time spent descheduled on
// a loaded machine is not counted), several rounds, and reports medians and the median of the
// per-round ratios gestura / anchor.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace anchors {

using namespace gestura;

// Keeps a value alive for the optimiser without costing anything.
template <class T>
inline void keep(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

struct Side {
  std::string name;                           // "gestura", "ozz", "ACL"
  std::function<void(std::size_t n)> run;    // runs the workload n times
};

// One comparison: gestura against an anchor, plus notes printed under the table (sizes, errors).
struct Workload {
  std::string name;
  std::string what;
  Side gestura, anchor;
  bool heavy = false;  // whole-clip jobs (compression): fewer rounds, one run per measurement
};

// The shared subject: the clip and skeleton of gestura's W1–W8 and the MakeHuman mesh of W5.
struct Subject {
  Skeleton skeleton;
  Clip clip;                      // synthetic_clip(skeleton, 15 s, 30 Hz)
  float rate = 30.0f;
  Pose rest;
  std::vector<Pose> frames;       // the clip's local pose at every 1/rate s (what both compressors get)
  Pose blend_a, blend_b, blend_c; // the clip at 1, 5 and 9 s: W3's layers
  Pose additive;                  // blend_c relative to rest (W3's additive layer)
  std::vector<float> upper_body;  // 1 on the upper body, 0 on the legs (W3's mask)

  bool has_mesh = false;          // MakeHuman data found
  Mesh mesh;                      // MakeHuman base mesh with 4 influences per vertex
  std::vector<mat4> skinning;     // joint × inverse bind in a pose with every joint turned a little
};

const Subject& subject();

// W4 inputs (those of bench/ik.cpp): an arm hanging at the left shoulder reaching for four targets
// in turn, bending toward a pole point behind it; a head aiming at four targets.
struct TwoBoneCase {
  vec3 start{0.18f, 1.4f, 0.0f}, mid{0.18f, 1.1f, 0.0f}, end{0.18f, 0.84f, 0.0f};
  vec3 mid_axis{-1.0f, 0.0f, 0.0f};  // in the mid joint's frame (identity rotations here)
  vec3 pole{0.6f, 1.0f, -0.5f};
  float soften = 0.97f;
  vec3 targets[4] = {{0.3f, 1.2f, 0.3f}, {0.1f, 1.3f, 0.35f}, {0.4f, 1.0f, 0.2f}, {0.25f, 1.5f, 0.3f}};
};
struct AimCase {
  vec3 position{0.0f, 1.6f, 0.05f};
  quat rotation = glm::angleAxis(0.2f, vec3(0, 1, 0));
  quat parent_rotation = glm::angleAxis(0.1f, vec3(1, 0, 0));
  vec3 targets[4] = {{1, 2, 1}, {-1, 1.5f, 2}, {0.3f, 1.2f, 1}, {0, 1.8f, 3}};
};

// W2/W8 random access: 4096 times drawn uniformly over the clip, the same on both sides.
const std::vector<float>& random_times();
inline constexpr float kForwardStep = 1.0f / 60.0f;  // W8 forward: a 60 fps player on the 30 Hz clip

// The two error bounds of W7/W8, metres on the virtual points (3 cm out): ACL's regime and ozz's.
inline constexpr float kFineBound = 1e-4f, kCoarseBound = 3e-3f, kVirtualPointDistance = 0.03f;

// The ACL error metric on gestura's side: per frame and joint, the largest displacement of the
// three virtual points at `distance` along the joint's axes, model space. Returns the maximum.
float max_virtual_point_error(const Skeleton& skeleton, const std::vector<Pose>& reference,
                              const std::vector<Pose>& decoded, float distance);

// Notes each side adds while it builds its data (sizes, errors), printed after the timing table.
void note(const std::string& line);
const std::vector<std::string>& all_notes();

// gestura's side of a workload by key ("W3_Blend3Layers", …); throws on an unknown key.
Side gestura_side(const std::string& key);

// Each anchor appends its workloads, pairing its side with gestura_side(key).
void add_ozz_workloads(std::vector<Workload>& out);
void add_acl_workloads(std::vector<Workload>& out);

}  // namespace anchors
