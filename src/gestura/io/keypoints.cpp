#include "gestura/io/keypoints.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/skeleton/joint_names.hpp"

namespace gestura {

const std::array<const char*, kBody25Count> kBody25Names = {
    "Nose",  "Neck",   "RShoulder", "RElbow",   "RWrist",    "LShoulder", "LElbow",    "LWrist",  "MidHip",
    "RHip",  "RKnee",  "RAnkle",    "LHip",     "LKnee",     "LAnkle",    "REye",      "LEye",    "REar",
    "LEar",  "LBigToe", "LSmallToe", "LHeel",   "RBigToe",   "RSmallToe", "RHeel"};

const std::array<const char*, kHandKeypointCount> kHandNames = {
    "WRIST",      "THUMB_CMC",  "THUMB_MCP",  "THUMB_IP",   "THUMB_TIP",  "INDEX_FINGER_MCP", "INDEX_FINGER_PIP",
    "INDEX_FINGER_DIP", "INDEX_FINGER_TIP", "MIDDLE_FINGER_MCP", "MIDDLE_FINGER_PIP", "MIDDLE_FINGER_DIP",
    "MIDDLE_FINGER_TIP", "RING_FINGER_MCP", "RING_FINGER_PIP", "RING_FINGER_DIP", "RING_FINGER_TIP",
    "PINKY_MCP",  "PINKY_PIP",  "PINKY_DIP",  "PINKY_TIP"};

namespace {

// Where a keypoint sits: joint `a` (or the midpoint of a and b) plus `offset`, a model-space vector
// at rest that turns with joint a. Offsets are body-proportioned guesses for an adult (metres).
struct KeypointDef {
  const char* a;
  const char* b = nullptr;
  vec3 offset{0.0f};
};

const std::vector<KeypointDef>& body25() {
  static const std::vector<KeypointDef> defs = {
      {"skullbase", nullptr, {0.0f, 0.02f, 0.105f}},  // nose tip, in front of the skull base
      {"l_shoulder", "r_shoulder"},
      {"r_shoulder"}, {"r_elbow"}, {"r_wrist"},
      {"l_shoulder"}, {"l_elbow"}, {"l_wrist"},
      {"l_hip", "r_hip"},
      {"r_hip"}, {"r_knee"}, {"r_ankle"},
      {"l_hip"}, {"l_knee"}, {"l_ankle"},
      {"r_eyeball_joint"}, {"l_eyeball_joint"},
      {"skullbase", nullptr, {-0.075f, 0.04f, 0.0f}}, {"skullbase", nullptr, {0.075f, 0.04f, 0.0f}},
      {"l_toe_tip", nullptr, {-0.02f, 0.0f, 0.0f}}, {"l_toe_tip", nullptr, {0.035f, 0.0f, -0.03f}},
      {"l_ankle", nullptr, {0.0f, -0.065f, -0.05f}},
      {"r_toe_tip", nullptr, {0.02f, 0.0f, 0.0f}}, {"r_toe_tip", nullptr, {-0.035f, 0.0f, -0.03f}},
      {"r_ankle", nullptr, {0.0f, -0.065f, -0.05f}},
  };
  return defs;
}

std::vector<std::string> hand_joints(const char* side) {
  std::vector<std::string> names{std::string(side) + "wrist"};
  for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"}) {
    const std::string f = std::string(side) + finger;
    names.insert(names.end(), {f + "1", f + "2", f + "3", f + "_tip"});
  }
  return names;
}

constexpr std::array<std::uint16_t, 2> kBodyLimbs[] = {
    {1, 8},   {1, 2},   {1, 5},   {2, 3},   {3, 4},   {5, 6},   {6, 7},   {8, 9},
    {9, 10},  {10, 11}, {8, 12},  {12, 13}, {13, 14}, {1, 0},   {0, 15},  {15, 17},
    {0, 16},  {16, 18}, {14, 19}, {19, 20}, {14, 21}, {11, 22}, {22, 23}, {11, 24}};

constexpr std::array<std::uint16_t, 2> kHandLimbs[] = {
    {0, 1},  {1, 2},   {2, 3},   {3, 4},   {0, 5},   {5, 6},   {6, 7},   {7, 8},   {0, 9},   {9, 10},
    {10, 11}, {11, 12}, {0, 13}, {13, 14}, {14, 15}, {15, 16}, {0, 17}, {17, 18}, {18, 19}, {19, 20}};

}  // namespace

std::vector<vec3> sample_joint_positions(const Skeleton& skeleton, const Clip& clip, float fps, int* frame_count) {
  if (!(fps > 0.0f) || fps > 1000.0f) throw Error("keypoints: fps must be in (0, 1000], got " + std::to_string(fps));
  const float duration = std::max(clip.duration, 0.0f);
  check_output_length(duration, fps, "keypoints");
  const double n = std::floor(double(duration) * fps + 0.5) + 1.0;
  if (n > 1e7) throw Error("keypoints: more than 10,000,000 frames");
  const int frames = static_cast<int>(n);
  const Pose rest = rest_pose(skeleton);
  Sampler sampler(clip);
  Pose pose;
  std::vector<mat4> model(skeleton.size());
  std::vector<vec3> out(static_cast<std::size_t>(frames) * skeleton.size());
  for (int f = 0; f < frames; ++f) {
    sampler.sample(std::min(float(f) / fps, duration), WrapMode::Clamp, rest, pose);
    local_to_model(skeleton, pose, model);
    model_positions(model, std::span(out).subspan(static_cast<std::size_t>(f) * skeleton.size(), skeleton.size()));
  }
  if (frame_count) *frame_count = frames;
  return out;
}

Keypoints compute_keypoints(const Skeleton& skeleton, const Clip& clip, float fps, KeypointSet set) {
  std::vector<KeypointDef> defs;
  std::vector<std::string> storage;
  if (set == KeypointSet::Body25) {
    defs = body25();
  } else {
    storage = hand_joints(set == KeypointSet::LeftHand ? "l_" : "r_");
    for (const std::string& n : storage) defs.push_back({n.c_str()});
  }
  // Joint lookup through the H-Anim guesses, so other rigs' names work too.
  const std::vector<std::string> hanim = guess_hanim_names(skeleton);
  std::map<std::string, int, std::less<>> by_name;
  for (std::size_t j = 0; j < hanim.size(); ++j)
    if (!hanim[j].empty()) by_name.emplace(hanim[j], static_cast<int>(j));
  auto find = [&](const char* name) {
    if (!name) return -1;
    const auto it = by_name.find(std::string_view(name));
    return it == by_name.end() ? -1 : it->second;
  };

  Keypoints out;
  out.count = static_cast<int>(defs.size());
  std::vector<mat4> rest_model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), rest_model);
  const std::vector<vec3> joints = sample_joint_positions(skeleton, clip, fps, &out.frames);
  // Orientation change of joint a since rest, for offsets: needs model matrices, recomputed here.
  const Pose rest = rest_pose(skeleton);
  Pose pose;
  std::vector<mat4> model(skeleton.size());
  const float duration = std::max(clip.duration, 0.0f);
  out.positions.resize(static_cast<std::size_t>(out.frames) * defs.size());
  out.confidence.resize(out.positions.size());
  for (int f = 0; f < out.frames; ++f) {
    const bool any_offset = std::any_of(defs.begin(), defs.end(), [](const KeypointDef& d) { return d.offset != vec3(0.0f); });
    if (any_offset) {
      sample_clip(clip, std::min(float(f) / fps, duration), WrapMode::Clamp, rest, pose);
      local_to_model(skeleton, pose, model);
    }
    const vec3* p = joints.data() + static_cast<std::size_t>(f) * skeleton.size();
    for (std::size_t k = 0; k < defs.size(); ++k) {
      const KeypointDef& d = defs[k];
      const int a = find(d.a), b = find(d.b);
      const std::size_t at = static_cast<std::size_t>(f) * defs.size() + k;
      if (a < 0 || (d.b && b < 0)) continue;  // position 0, confidence 0
      vec3 pos = b >= 0 ? 0.5f * (p[a] + p[b]) : p[a];
      if (d.offset != vec3(0.0f))
        pos += mat3(model[static_cast<std::size_t>(a)]) * glm::inverse(mat3(rest_model[static_cast<std::size_t>(a)])) * d.offset;
      out.positions[at] = pos;
      out.confidence[at] = 1.0f;
    }
  }
  return out;
}

std::span<const std::array<std::uint16_t, 2>> keypoint_limbs(KeypointSet set) {
  if (set == KeypointSet::Body25) return kBodyLimbs;
  return kHandLimbs;
}

vec3 PinholeCamera::project(const vec3& point) const {
  const vec3 forward = glm::normalize(target - position);
  const vec3 right = glm::normalize(glm::cross(forward, vec3(0.0f, 1.0f, 0.0f)));
  const vec3 up = glm::cross(right, forward);
  const vec3 d = point - position;
  const float depth = glm::dot(d, forward);
  const float focal = 0.5f * float(height) / std::tan(0.5f * vertical_fov);
  if (std::abs(depth) < 1e-6f) return vec3(0.0f, 0.0f, depth);
  return vec3(0.5f * float(width) + focal * glm::dot(d, right) / depth,
              0.5f * float(height) - focal * glm::dot(d, up) / depth, depth);
}

}  // namespace gestura
