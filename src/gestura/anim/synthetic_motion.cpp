#include "gestura/anim/synthetic_motion.hpp"

#include <cmath>
#include <cstdint>
#include <string>

namespace gestura {

Skeleton synthetic_humanoid() {
  Skeleton s;
  const int root = s.add_joint("humanoid_root", -1, vec3(0.0f, 0.95f, 0.0f));
  const int sacro = s.add_joint("sacroiliac", root, vec3(0.0f, 0.05f, 0.0f));
  for (const char side : {'l', 'r'}) {
    const float x = side == 'l' ? 1.0f : -1.0f;
    const std::string p(1, side);
    const int hip = s.add_joint(p + "_hip", root, vec3(0.09f * x, -0.05f, 0.0f));
    const int knee = s.add_joint(p + "_knee", hip, vec3(0.0f, -0.43f, 0.0f));
    const int ankle = s.add_joint(p + "_ankle", knee, vec3(0.0f, -0.42f, 0.0f));
    s.add_joint(p + "_midtarsal", ankle, vec3(0.0f, -0.05f, 0.12f));
  }
  int spine = sacro;
  for (const char* name : {"vl5", "vt12", "vt6", "vt1"}) spine = s.add_joint(name, spine, vec3(0.0f, 0.12f, 0.0f));
  const int neck = s.add_joint("vc4", spine, vec3(0.0f, 0.08f, 0.0f));
  const int skull = s.add_joint("skullbase", neck, vec3(0.0f, 0.08f, 0.0f));
  s.add_joint("temporomandibular", skull, vec3(0.0f, -0.02f, 0.06f));
  s.add_joint("l_eyeball", skull, vec3(0.03f, 0.07f, 0.08f));
  s.add_joint("r_eyeball", skull, vec3(-0.03f, 0.07f, 0.08f));
  for (const char side : {'l', 'r'}) {
    const float x = side == 'l' ? 1.0f : -1.0f;
    const std::string p(1, side);
    const int clavicle = s.add_joint(p + "_sternoclavicular", spine, vec3(0.02f * x, 0.0f, 0.03f));
    const int shoulder = s.add_joint(p + "_shoulder", clavicle, vec3(0.16f * x, 0.02f, -0.03f));
    const int elbow = s.add_joint(p + "_elbow", shoulder, vec3(0.30f * x, 0.0f, 0.0f));
    const int wrist = s.add_joint(p + "_wrist", elbow, vec3(0.26f * x, 0.0f, 0.0f));
    const char* fingers[] = {"thumb", "index", "middle", "ring", "pinky"};
    for (int f = 0; f < 5; ++f) {
      const float z = 0.035f - 0.0175f * static_cast<float>(f);
      int joint = s.add_joint(p + "_" + fingers[f] + "1", wrist, vec3((f == 0 ? 0.03f : 0.09f) * x, 0.0f, z));
      const float bone = f == 0 ? 0.035f : 0.04f - 0.004f * static_cast<float>(f);
      for (int k = 2; k <= 3; ++k) joint = s.add_joint(p + "_" + fingers[f] + std::to_string(k), joint, vec3(bone * x, 0.0f, 0.0f));
      s.add_joint(p + "_" + fingers[f] + "_tip", joint, vec3(0.8f * bone * x, 0.0f, 0.0f));
    }
  }
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.names[j].find("_tip") == std::string::npos)
      s.dofs[j] = JointDofs{RotationOrder::XYZ, 0b111, vec3(-kPi), vec3(kPi)};
  s.validate();
  return s;
}

Clip synthetic_clip(const Skeleton& skeleton, float seconds, float rate) {
  Clip clip;
  clip.name = "synthetic";
  clip.resize_joints(skeleton.size());
  const int frames = static_cast<int>(std::lround(seconds * rate)) + 1;
  clip.duration = static_cast<float>(frames - 1) / rate;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1ull << 24);
  };
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    if (skeleton.names[j].find("_tip") != std::string::npos) continue;
    const bool finger = skeleton.names[j].find_first_of("123") != std::string::npos;
    const float amplitude = finger ? 0.6f : 0.35f;
    float freq[3][3], phase[3][3];
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < 3; ++k) freq[axis][k] = 0.15f + 1.2f * next(), phase[axis][k] = 2.0f * kPi * next();
    QuatTrack& track = clip.rotations[j];
    track.interpolation = Interpolation::Linear;
    for (int f = 0; f < frames; ++f) {
      const float t = static_cast<float>(f) / rate;
      vec3 angles(0.0f);
      for (int axis = 0; axis < 3; ++axis)
        for (int k = 0; k < 3; ++k)
          angles[axis] += amplitude / static_cast<float>(k + 1) * std::sin(2.0f * kPi * freq[axis][k] * t + phase[axis][k]);
      track.add(t, skeleton.rest_rotations[j] * euler_to_quat(angles, RotationOrder::XYZ));
    }
    make_continuous(track);
  }
  Vec3Track& root = clip.translations[0];
  for (int f = 0; f < frames; ++f) {
    const float t = static_cast<float>(f) / rate;
    root.add(t, skeleton.rest_translations[0] + vec3(0.04f * std::sin(2.0f * kPi * 0.3f * t), 0.02f * std::sin(2.0f * kPi * 0.7f * t + 1.0f),
                                                     0.03f * std::sin(2.0f * kPi * 0.2f * t + 2.0f)));
  }
  return clip;
}

}  // namespace gestura
