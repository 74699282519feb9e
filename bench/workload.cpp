#include "workload.hpp"

#include <cstdint>
#include <string>

namespace gestura::bench {

namespace {

struct Lcg {
  std::uint32_t state;
  float next() {  // [0, 1)
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  }
};

}  // namespace

Skeleton workload_skeleton() {
  Skeleton s;
  const int root = s.add_joint("humanoid_root", -1, vec3(0, 1.0f, 0));
  int spine = root;
  const char* column[] = {"sacroiliac", "vl5", "vt12", "vt6", "vc4", "skullbase"};
  for (const char* name : column) spine = s.add_joint(name, spine, vec3(0, 0.1f, 0));
  for (const char* name : {"temporomandibular", "l_eyeball_joint", "r_eyeball_joint", "head_top"})
    s.add_joint(name, spine, vec3(0, 0.05f, 0.02f));
  for (int side = 0; side < 2; ++side) {
    const std::string p = side == 0 ? "l_" : "r_";
    const float x = side == 0 ? 1.0f : -1.0f;
    int leg = s.add_joint(p + "hip", 1, vec3(0.1f * x, -0.05f, 0));
    leg = s.add_joint(p + "knee", leg, vec3(0, -0.45f, 0));
    leg = s.add_joint(p + "ankle", leg, vec3(0, -0.42f, 0));
    s.add_joint(p + "toes", leg, vec3(0, -0.05f, 0.12f));
    int arm = s.add_joint(p + "sternoclavicular", 4, vec3(0.03f * x, 0.2f, 0));
    arm = s.add_joint(p + "shoulder", arm, vec3(0.15f * x, 0, 0));
    arm = s.add_joint(p + "elbow", arm, vec3(0, -0.3f, 0));
    arm = s.add_joint(p + "wrist", arm, vec3(0, -0.25f, 0));
    for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"}) {
      int f = arm;
      for (int k = 1; k <= 3; ++k) f = s.add_joint(p + finger + std::to_string(k), f, vec3(0, -0.03f, 0.01f));
      s.add_joint(p + finger + "_tip", f, vec3(0, -0.02f, 0));
    }
  }
  return s;  // 1 + 6 + 4 + 2·(4 + 4 + 5·4) = 67 joints
}

Clip workload_clip(const Skeleton& skeleton, float duration, float key_rate) {
  Clip clip;
  clip.name = "workload";
  clip.duration = duration;
  clip.resize_joints(skeleton.size());
  const int keys = static_cast<int>(duration * key_rate + 0.5f) + 1;
  Lcg rng{12345u};
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    float freq[3][3], amp[3][3], phase[3][3];
    for (int a = 0; a < 3; ++a)
      for (int h = 0; h < 3; ++h) {
        freq[a][h] = 0.2f + 2.0f * rng.next();
        amp[a][h] = 0.05f + 0.3f * rng.next() / static_cast<float>(h + 1);
        phase[a][h] = 6.2831853f * rng.next();
      }
    QuatTrack& track = clip.rotations[j];
    track.interpolation = Interpolation::Linear;
    track.times.reserve(static_cast<std::size_t>(keys));
    track.values.reserve(static_cast<std::size_t>(keys));
    for (int k = 0; k < keys; ++k) {
      const float t = static_cast<float>(k) / key_rate;
      vec3 angles(0.0f);
      for (int a = 0; a < 3; ++a)
        for (int h = 0; h < 3; ++h) angles[a] += amp[a][h] * std::sin(6.2831853f * freq[a][h] * t + phase[a][h]);
      track.add(t, skeleton.rest_rotations[j] * euler_to_quat(angles, RotationOrder::ZXY));
    }
    make_continuous(track);
  }
  Vec3Track& root = clip.translations[0];
  for (int k = 0; k < keys; ++k) {
    const float t = static_cast<float>(k) / key_rate;
    root.add(t, skeleton.rest_translations[0] + vec3(0.05f * std::sin(t), 0.02f * std::sin(3 * t), 0.1f * t / duration));
  }
  return clip;
}

}  // namespace gestura::bench
