#include "support/test_figure.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace gestura {
namespace {

struct Bone {
  const char* name;
  const char* parent;
  vec3 head;  // model-space position at rest
};

// Rest pose: standing, arms hanging slightly forward; model-space joint positions in metres.
const Bone kBones[] = {
    {"HumanoidRoot", nullptr, {0.0f, 0.98f, 0.0f}},   {"vl5", "HumanoidRoot", {0.0f, 1.10f, 0.0f}},
    {"vt10", "vl5", {0.0f, 1.30f, 0.0f}},             {"vc7", "vt10", {0.0f, 1.47f, 0.0f}},
    {"skullbase", "vc7", {0.0f, 1.58f, 0.01f}},       {"skull_top", "skullbase", {0.0f, 1.80f, 0.01f}},
    {"l_hip", "HumanoidRoot", {0.10f, 0.94f, 0.0f}},  {"l_knee", "l_hip", {0.11f, 0.50f, 0.0f}},
    {"l_ankle", "l_knee", {0.11f, 0.08f, -0.01f}},    {"r_hip", "HumanoidRoot", {-0.10f, 0.94f, 0.0f}},
    {"r_knee", "r_hip", {-0.11f, 0.50f, 0.0f}},       {"r_ankle", "r_knee", {-0.11f, 0.08f, -0.01f}},
};

struct Side {
  const char* prefix;
  float sign;
};

vec3 mirror(vec3 p, float sign) { return {p.x * sign, p.y, p.z}; }

class Builder {
 public:
  Builder(RenderSubject& s, int detail) : s_(s), segments_(10 * detail), rings_(5 * detail) {}

  int joint(const std::string& name, const std::string& parent, vec3 model_position) {
    const int p = parent.empty() ? -1 : s_.skeleton.find(parent);
    const vec3 parent_position = p < 0 ? vec3(0.0f) : positions_[static_cast<std::size_t>(p)];
    positions_.push_back(model_position);
    return s_.skeleton.add_joint(name, p, model_position - parent_position);
  }
  vec3 position(const std::string& name) const { return positions_[static_cast<std::size_t>(s_.skeleton.find(name))]; }

  // A tapered capsule from joint `from` towards `to`, skinned to `from`, blended into its parent
  // over the first quarter so bends do not tear. `material(p, n)` picks a MaterialId per vertex.
  void capsule(const std::string& from, vec3 a, vec3 b, float ra, float rb,
               const std::function<MaterialId(vec3, vec3)>& material) {
    Mesh& m = s_.mesh;
    const int j = s_.skeleton.find(from);
    const int parent = s_.skeleton.parents[static_cast<std::size_t>(j)];
    const vec3 axis = glm::normalize(b - a);
    const float length = glm::length(b - a);
    const vec3 helper = std::abs(axis.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0);
    const vec3 u = glm::normalize(glm::cross(axis, helper)), w = glm::cross(axis, u);
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const int cap = std::max(2, rings_ / 3);
    const int rows = 2 * cap + rings_ + 1;
    for (int r = 0; r <= rows; ++r) {
      vec3 centre, normal_axis;
      float radius, normal_radial;
      if (r <= cap) {  // hemisphere at a
        const float theta = -kPi / 2 + kPi / 2 * static_cast<float>(r) / static_cast<float>(cap);
        centre = a + axis * (ra * std::sin(theta)), radius = ra * std::cos(theta);
        normal_axis = axis * std::sin(theta), normal_radial = std::cos(theta);
      } else if (r >= rows - cap) {  // hemisphere at b
        const float theta = kPi / 2 * static_cast<float>(r - (rows - cap)) / static_cast<float>(cap);
        centre = b + axis * (rb * std::sin(theta)), radius = rb * std::cos(theta);
        normal_axis = axis * std::sin(theta), normal_radial = std::cos(theta);
      } else {
        const float t = static_cast<float>(r - cap) / static_cast<float>(rows - 2 * cap);
        centre = a + (b - a) * t, radius = ra + (rb - ra) * t;
        normal_axis = axis * ((ra - rb) / length), normal_radial = 1.0f;
      }
      for (int k = 0; k <= segments_; ++k) {
        const float phi = 2 * kPi * static_cast<float>(k) / static_cast<float>(segments_);
        const vec3 radial = u * std::cos(phi) + w * std::sin(phi);
        const vec3 p = centre + radial * radius;
        const vec3 n = glm::normalize(normal_axis + radial * normal_radial + vec3(1e-6f));
        m.positions.push_back(p);
        m.normals.push_back(n);
        m.materials.push_back(static_cast<std::uint8_t>(material(p, n)));
        const float s = glm::dot(p - a, axis) / length;
        const float to_parent = parent < 0 ? 0.0f : 0.5f * std::clamp(1.0f - s / 0.25f, 0.0f, 1.0f);
        m.joints.emplace_back(static_cast<std::uint16_t>(j), static_cast<std::uint16_t>(std::max(parent, 0)), 0, 0);
        m.weights.emplace_back(1.0f - to_parent, to_parent, 0.0f, 0.0f);
      }
    }
    const auto stride = static_cast<std::uint32_t>(segments_ + 1);
    for (int r = 0; r < rows; ++r)
      for (int k = 0; k < segments_; ++k) {
        const std::uint32_t i0 = base + static_cast<std::uint32_t>(r) * stride + static_cast<std::uint32_t>(k);
        const std::uint32_t i1 = i0 + 1, i2 = i0 + stride, i3 = i2 + 1;
        // Rings run from a to b; (u, w, axis) is right-handed, so this winding faces outwards.
        m.indices.insert(m.indices.end(), {i0, i1, i3, i0, i3, i2});
      }
  }

 private:
  RenderSubject& s_;
  int segments_, rings_;
  std::vector<vec3> positions_;
};

MaterialId constant(MaterialId m, vec3, vec3) { return m; }

}  // namespace

RenderSubject make_test_figure(int detail) {
  RenderSubject s;
  Builder b(s, std::max(1, detail));
  for (const Bone& bone : kBones) b.joint(bone.name, bone.parent ? bone.parent : "", bone.head);
  const Side sides[] = {{"l_", 1.0f}, {"r_", -1.0f}};
  for (const Side& side : sides) {
    const std::string p = side.prefix;
    b.joint(p + "shoulder", "vc7", mirror({0.19f, 1.44f, 0.0f}, side.sign));
    b.joint(p + "elbow", p + "shoulder", mirror({0.25f, 1.17f, 0.03f}, side.sign));
    b.joint(p + "wrist", p + "elbow", mirror({0.28f, 0.93f, 0.08f}, side.sign));
    b.joint(p + "hand_end", p + "wrist", mirror({0.29f, 0.86f, 0.09f}, side.sign));
    const char* fingers[] = {"thumb", "index", "middle", "ring", "pinky"};
    for (int f = 0; f < 5; ++f) {
      const float spread = (static_cast<float>(f) - 2.0f) * 0.014f;
      const vec3 knuckle = f == 0 ? vec3(0.27f, 0.90f, 0.115f) : vec3(0.295f, 0.855f, 0.09f + spread * -1.0f);
      const vec3 step = f == 0 ? vec3(-0.005f, -0.028f, 0.012f) : vec3(0.0f, -0.026f - (f == 2 ? 0.004f : 0.0f), 0.0f);
      const std::string name = p + fingers[f];
      b.joint(name + "1", p + "hand_end", mirror(knuckle, side.sign));
      b.joint(name + "2", name + "1", mirror(knuckle + step, side.sign));
      b.joint(name + "_tip", name + "2", mirror(knuckle + step * 2.0f, side.sign));
    }
  }
  const Skeleton& sk = s.skeleton;
  auto at = [&](const char* name) { return b.position(name); };
  auto skin = [](vec3 p, vec3 n) { return constant(MaterialId::Skin, p, n); };
  auto cloth = [](vec3 p, vec3 n) { return constant(MaterialId::Cloth, p, n); };
  const float head_top = at("skull_top").y;
  auto head = [head_top](vec3 p, vec3 n) {
    return (p.y > head_top - 0.07f && n.z < 0.5f) || (n.z < -0.3f && p.y > head_top - 0.13f) ? MaterialId::Hair
                                                                                            : MaterialId::Skin;
  };
  // Torso and pelvis (shirt, trousers), neck, head.
  b.capsule("HumanoidRoot", at("HumanoidRoot") + vec3(0, -0.04f, 0), at("vl5"), 0.15f, 0.14f, cloth);
  b.capsule("vl5", at("vl5"), at("vt10"), 0.14f, 0.16f, cloth);
  b.capsule("vt10", at("vt10"), at("vc7") + vec3(0, -0.03f, 0), 0.16f, 0.15f, cloth);
  b.capsule("vc7", at("vc7"), at("skullbase"), 0.055f, 0.05f, skin);
  b.capsule("skullbase", at("skullbase") + vec3(0, 0.04f, 0.0f), at("skull_top") + vec3(0, -0.06f, 0), 0.095f, 0.085f, head);
  // Eyes: a white ball each with iris and pupil where the ball faces forward.
  const std::size_t before_eyes = s.mesh.positions.size();
  for (float sign : {1.0f, -1.0f}) {
    const vec3 centre = at("skullbase") + vec3(0.033f * sign, 0.085f, 0.082f);
    b.capsule("skullbase", centre, centre + vec3(0, 0, 0.001f), 0.014f, 0.014f, [centre](vec3 p, vec3) {
      const float facing = glm::normalize(p - centre).z;
      return facing > 0.96f ? MaterialId::Pupil : facing > 0.86f ? MaterialId::Iris : MaterialId::EyeWhite;
    });
  }
  // The morph target: lowers the chin area of the head (a stand-in jaw).
  MorphTarget jaw{"test_jaw_open", {}, {}, {}};
  for (std::uint32_t v = 0; v < before_eyes; ++v) {
    const vec3 p = s.mesh.positions[v];
    if (s.mesh.joints[v].x == sk.find("skullbase") && p.z > 0.03f && p.y < at("skullbase").y + 0.06f) {
      jaw.vertices.push_back(v);
      jaw.position_deltas.push_back({0.0f, -0.03f, 0.01f});
    }
  }
  s.mesh.morphs.push_back(jaw);
  for (const Side& side : sides) {
    const std::string p = side.prefix;
    b.capsule(p + "shoulder", at((p + "shoulder").c_str()), at((p + "elbow").c_str()), 0.055f, 0.045f, cloth);
    b.capsule(p + "elbow", at((p + "elbow").c_str()), at((p + "wrist").c_str()) + mirror({-0.006f, 0.02f, -0.004f}, side.sign),
              0.045f, 0.036f, cloth);
    b.capsule(p + "wrist", at((p + "wrist").c_str()), at((p + "hand_end").c_str()), 0.03f, 0.034f, skin);
    for (const char* f : {"thumb", "index", "middle", "ring", "pinky"}) {
      const std::string name = p + f;
      const float r = std::string(f) == "thumb" ? 0.0105f : std::string(f) == "pinky" ? 0.0075f : 0.0088f;
      b.capsule(name + "1", at((name + "1").c_str()), at((name + "2").c_str()), r, r * 0.95f, skin);
      b.capsule(name + "2", at((name + "2").c_str()), at((name + "_tip").c_str()), r * 0.95f, r * 0.85f, skin);
    }
    b.capsule(p + "hip", at((p + "hip").c_str()), at((p + "knee").c_str()), 0.075f, 0.055f, cloth);
    b.capsule(p + "knee", at((p + "knee").c_str()), at((p + "ankle").c_str()), 0.05f, 0.04f, cloth);
  }

  // The clip: the right arm lifts into the signing space and waves; fingers curl and open; the
  // jaw morph opens halfway through. Rotations replace the (identity) rest rotations.
  Clip clip;
  clip.name = "test_wave";
  clip.duration = 2.0f;
  clip.resize_joints(sk.size());
  const float times[] = {0.0f, 0.5f, 1.0f, 1.5f, 2.0f};
  const float lift[] = {0.0f, 1.0f, 1.0f, 1.0f, 0.0f};
  const float wave[] = {0.0f, -0.5f, 0.5f, -0.5f, 0.0f};
  auto track = [&](const std::string& name) -> QuatTrack& { return clip.rotations[static_cast<std::size_t>(sk.find(name))]; };
  for (int k = 0; k < 5; ++k) {
    const float t = times[k];
    track("r_shoulder").add(t, glm::angleAxis(-1.0f * lift[k], vec3(0, 0, 1)) * glm::angleAxis(-0.6f * lift[k], vec3(1, 0, 0)));
    track("r_elbow").add(t, glm::angleAxis(-1.7f * lift[k], vec3(1, 0, 0)) * glm::angleAxis(wave[k] * lift[k], vec3(0, 0, 1)));
    track("r_wrist").add(t, glm::angleAxis(0.3f * wave[k], vec3(0, 1, 0)));
    track("l_shoulder").add(t, glm::angleAxis(-0.5f * lift[k], vec3(1, 0, 0)));
    track("l_elbow").add(t, glm::angleAxis(-1.2f * lift[k], vec3(1, 0, 0)));
    for (const char* f : {"index", "middle", "ring", "pinky"}) {
      const float curl = 0.9f * (0.5f + 0.5f * wave[k]);
      track(std::string("l_") + f + "1").add(t, glm::angleAxis(curl, vec3(1, 0, 0)));
      track(std::string("l_") + f + "2").add(t, glm::angleAxis(curl, vec3(1, 0, 0)));
    }
  }
  FloatTrack& jaw_channel = clip.channel("test_jaw_open");
  jaw_channel.add(0.0f, 0.0f);
  jaw_channel.add(1.0f, 1.0f);
  jaw_channel.add(2.0f, 0.0f);
  s.clip = std::move(clip);
  return s;
}

}  // namespace gestura
