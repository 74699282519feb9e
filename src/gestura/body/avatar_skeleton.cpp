#include "gestura/body/avatar_skeleton.hpp"

#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/trunk_sculpt.hpp"

#include <algorithm>
#include <string>

namespace gestura {
namespace {

constexpr std::uint8_t kX = 1, kY = 2, kZ = 4;

JointDofs dofs(RotationOrder order, std::uint8_t axes, vec3 min_deg, vec3 max_deg) {
  JointDofs d;
  d.order = order;
  d.axes = axes;
  for (int a = 0; a < 3; ++a) {
    d.min_angle[a] = (axes >> a) & 1 ? deg(min_deg[a]) : 0.0f;
    d.max_angle[a] = (axes >> a) & 1 ? deg(max_deg[a]) : 0.0f;
  }
  return d;
}

// Mirror image in X of a left joint's limits: y and z angles change sign (see the header).
JointDofs mirrored(JointDofs d) {
  for (int a = 1; a < 3; ++a) {
    const float lo = d.min_angle[a], hi = d.max_angle[a];
    d.min_angle[a] = -hi;
    d.max_angle[a] = -lo;
  }
  return d;
}

// Builds joints from model-space positions (all rest rotations are the identity, so a joint's
// offset is simply the difference to its parent's position).
struct Builder {
  Skeleton skeleton;
  std::vector<vec3> model;

  int add(const std::string& name, int parent, vec3 position, JointDofs d = {}) {
    const vec3 offset = parent < 0 ? position : position - model[static_cast<std::size_t>(parent)];
    const int j = skeleton.add_joint(name, parent, offset);
    skeleton.dofs[static_cast<std::size_t>(j)] = d;
    model.push_back(position);
    return j;
  }
};

struct SideDims {
  float side;  // +1 left, −1 right
  float scale, shoulder_x, hip_x, upper_arm, forearm, hand, phalanx;
  float a_pose = 0.0f;  // radians from vertical
};

vec3 mirror(vec3 p, float side) { return vec3(p.x * side, p.y, p.z); }

void add_arm(Builder& b, int vt1, const SideDims& s) {
  const std::string p = s.side > 0 ? "l_" : "r_";
  auto limits = [&](JointDofs d) { return s.side > 0 ? d : mirrored(d); };
  auto at = [&](vec3 left) { return mirror(left, s.side); };
  const float k = s.scale;

  const int clav = b.add(p + "sternoclavicular", vt1, at(vec3(0.020f, 1.400f, 0.040f) * k),
                         limits(dofs(RotationOrder::ZXY, kY | kZ, {0, -30, -10}, {0, 25, 40})));
  const vec3 shoulder_pos = at(vec3(s.shoulder_x, 1.385f * k, -0.020f * k));
  const int shoulder = b.add(p + "shoulder", clav, shoulder_pos,
                             limits(dofs(RotationOrder::ZXY, kX | kY | kZ, {-188, -70, -48}, {61, 90, 134})));
  // A-pose: the arm hangs 10° away from the body in the frontal plane, more for a heavier build so
  // that the hands stay clear of the hips.
  const float a = s.a_pose;
  const vec3 down = at(vec3(std::sin(a), -std::cos(a), 0.0f));
  const vec3 elbow_pos = shoulder_pos + down * s.upper_arm;
  // Table 1 of sign-language-interpreter.txt, with two corrections from the goniometry norms (AAOS;
  // Boone & Azen 1979; Macedo & Magee 2008): the elbow flexes to 150° (means 143–158°), not 142°,
  // and the wrist bends 47° toward the little finger (+x, ulnar: the table's figure for the
  // larger side; the norms give 26–41°, always more than radial), not 27°. The radial side keeps
  // the table's 47° (norms 18–25°): the avatar's palm is rigid, where a real hand's carpal and
  // metacarpal joints add to what a goniometer reads, and a flat hand held upright in front of the
  // chest needs it. With 27° ulnar a palm-down hand could not point its fingers ahead of its
  // forearm, and with 142° a hand could not bring its fingertips to the ear or the chin at a
  // notated turn (docs/sign-phonology.md).
  const int elbow = b.add(p + "elbow", shoulder, elbow_pos,
                          limits(dofs(RotationOrder::XYZ, kX | kY, {-150, -77, 0}, {0, 113, 0})));
  const vec3 wrist_pos = elbow_pos + down * s.forearm;
  const int wrist = b.add(p + "wrist", elbow, wrist_pos,
                          limits(dofs(RotationOrder::ZXY, kX | kZ, {-47, 0, -90}, {47, 0, 99})));

  // Hand frame: `down` along the hand, `fwd` towards the thumb (+Z), `dorsal` the back of the hand.
  const vec3 fwd(0.0f, 0.0f, 1.0f);
  const vec3 dorsal = at(vec3(std::cos(a), std::sin(a), 0.0f));
  auto hand_point = [&](float d, float f, float o) {
    return wrist_pos + (down * d + fwd * f + dorsal * o) * s.hand;
  };

  // The hand in shares of its length L (wrist to the middle fingertip, s.hand): knuckles (the
  // metacarpophalangeal joints) on an arch, the index's and little finger's further back; their
  // spacing from the hand's breadth at the metacarpals (ANSUR: 0.45 L); phalanx lengths after
  // Buryanov & Kotiuk (2010), the last with the fingertip's pad (docs/avatar.md).
  // Thumb: carpometacarpal joint on the palm side near the wrist, its metacarpal pointing down,
  // forward and towards the palm, the phalanges curving back towards "down" beside the index.
  // The sign layer's thumb poses and this joint's limits are angles from this rest thumb: its CMC
  // 1.1 cm (0.060 L) on the palm side, the metacarpal 22° out of the palm plane, the phalanges 18°
  // and 15°, which puts the flat hand's thumb (pressed back to the limit) with its tip ~2 cm from
  // the palm plane, beside the palm rather than under it. Set deeper (1.6 cm, 26°), it hung 3 cm
  // below the palm, and a palm laid on the other hand met it with the thumb tip, 10 cm off.
  {
    const vec3 cmc = hand_point(0.135f, 0.165f, -0.060f);
    const vec3 d1 = glm::normalize(down * 0.80f + fwd * 0.34f - dorsal * 0.349f);
    const vec3 d2 = glm::normalize(down * 0.88f + fwd * 0.20f - dorsal * 0.300f);
    const vec3 d3 = glm::normalize(down * 0.93f + fwd * 0.12f - dorsal * 0.248f);
    const int t1 = b.add(p + "thumb1", wrist, cmc,
                         limits(dofs(RotationOrder::ZXY, kX | kY | kZ, {-20, -45, -60}, {50, 15, 15})));
    const vec3 mcp = cmc + d1 * (0.250f * s.hand * s.phalanx);
    const int t2 = b.add(p + "thumb2", t1, mcp, limits(dofs(RotationOrder::XZY, kX | kZ, {-10, 0, -10}, {60, 0, 10})));
    const vec3 ip = mcp + d2 * (0.168f * s.hand * s.phalanx);
    const int t3 = b.add(p + "thumb3", t2, ip, limits(dofs(RotationOrder::XYZ, kX, {-15, 0, 0}, {80, 0, 0})));
    b.add(p + "thumb_tip", t3, ip + d3 * (0.140f * s.hand * s.phalanx));
  }

  struct Finger {
    const char* name;
    float mcp_down, mcp_fwd, spread_deg;
    float len[3];
    float cmc_down, cmc_fwd, cup_deg;  // cup_deg = 0: no metacarpal joint
  };
  static constexpr Finger fingers[4] = {
      {"index", 0.452f, 0.168f, 5.0f, {0.217f, 0.122f, 0.108f}, 0, 0, 0},
      {"middle", 0.468f, 0.056f, 1.0f, {0.242f, 0.143f, 0.116f}, 0, 0, 0},
      {"ring", 0.455f, -0.057f, -4.0f, {0.225f, 0.140f, 0.115f}, 0.140f, -0.040f, 15.0f},
      {"pinky", 0.415f, -0.165f, -9.0f, {0.178f, 0.099f, 0.106f}, 0.130f, -0.090f, 25.0f},
  };
  for (const Finger& f : fingers) {
    const std::string n = p + f.name;
    int parent = wrist;
    if (f.cup_deg > 0.0f)
      parent = b.add(n + "0", wrist, hand_point(f.cmc_down, f.cmc_fwd, 0.0f),
                     limits(dofs(RotationOrder::XYZ, kZ, {0, 0, -f.cup_deg}, {0, 0, 0})));
    const float sp = deg(f.spread_deg);
    const vec3 dir = down * std::cos(sp) + fwd * std::sin(sp);
    vec3 pos = hand_point(f.mcp_down, f.mcp_fwd, 0.0f);
    const int j1 = b.add(n + "1", parent, pos, limits(dofs(RotationOrder::XZY, kX | kZ, {-20, 0, -90}, {20, 0, 30})));
    pos += dir * (f.len[0] * s.hand * s.phalanx);
    const int j2 = b.add(n + "2", j1, pos, limits(dofs(RotationOrder::XYZ, kZ, {0, 0, -110}, {0, 0, 0})));
    pos += dir * (f.len[1] * s.hand * s.phalanx);
    const int j3 = b.add(n + "3", j2, pos, limits(dofs(RotationOrder::XYZ, kZ, {0, 0, -80}, {0, 0, 10})));
    pos += dir * (f.len[2] * s.hand * s.phalanx);
    b.add(n + "_tip", j3, pos);
  }
}

void add_leg(Builder& b, int pelvis, const SideDims& s) {
  const std::string p = s.side > 0 ? "l_" : "r_";
  auto limits = [&](JointDofs d) { return s.side > 0 ? d : mirrored(d); };
  auto at = [&](float x, float y, float z) { return vec3(s.side * x, y * s.scale, z * s.scale); };
  const float hx = s.hip_x;
  // Hip, knee and ankle at 0.530, 0.285 and 0.039 of the stature (Drillis & Contini).
  const int hip = b.add(p + "hip", pelvis, at(hx, 0.901f, 0.0f),
                        limits(dofs(RotationOrder::ZXY, kX | kY | kZ, {-125, -40, -30}, {30, 45, 45})));
  const int knee = b.add(p + "knee", hip, at(hx * 1.02f, 0.4845f, 0.008f),
                         limits(dofs(RotationOrder::XYZ, kX | kY, {0, -10, 0}, {140, 10, 0})));
  const int ankle = b.add(p + "ankle", knee, at(hx, 0.070f, -0.020f),
                          limits(dofs(RotationOrder::XYZ, kX, {-20, 0, 0}, {50, 0, 0})));
  const int subtalar = b.add(p + "subtalar", ankle, at(hx, 0.055f, -0.030f),
                             limits(dofs(RotationOrder::XYZ, kZ, {0, 0, -35}, {0, 0, 15})));
  const int midtarsal = b.add(p + "midtarsal", subtalar, at(hx * 1.05f, 0.050f, 0.045f),
                              limits(dofs(RotationOrder::XYZ, kY, {0, -10, 0}, {0, 10, 0})));
  const int toes = b.add(p + "metatarsal", midtarsal, at(hx * 1.12f, 0.022f, 0.140f),
                         limits(dofs(RotationOrder::XYZ, kX, {-60, 0, 0}, {40, 0, 0})));
  b.add(p + "toe_tip", toes, at(hx * 1.14f, 0.016f, 0.195f));
}

// The A-pose angle: 10° from vertical, or wider when needed for the hand (with its detail box,
// see avatar_volume.cpp) to clear the widest of pelvis and thighs by a few centimetres.
float a_pose_angle(const AvatarParams& p, float shoulder_x) {
  using namespace proportions;
  const float hip_x = 0.086f * (0.8f + 0.2f * p.build);
  // The trunk's widest below the waist (its sections at 1.70 m) or the thighs.
  AvatarParams at_170 = p;
  at_170.height = 1.70f;
  float trunk = 0.0f;
  for (const TrunkSection& s : trunk_sections(at_170))
    if (s.y < 0.95f) trunk = std::max(trunk, s.half_breadth);
  const float hips = std::max(trunk, (hip_x + kThighRadius * thigh_factor(p.sex)) * p.build);
  // Blend bulge of the thighs, lattice snapping (one coarse cell) and a centimetre of air.
  const float clearance = 0.0125f * p.build + 0.016f + 0.010f;
  const float wrist_x = hips + clearance + kThumbPalmReach * p.hand_size + hand_flesh_margin(p);
  const float arm = (0.186f + 0.146f) * 1.70f * p.arm_length;
  const float s = std::clamp((wrist_x - shoulder_x) / arm, std::sin(deg(10.0f)), std::sin(deg(30.0f)));
  return std::asin(s);
}

}  // namespace

Skeleton build_avatar_skeleton(const AvatarParams& params) {
  params.validate();
  const float k = params.height / 1.70f;
  // Segment lengths as shares of the stature after Drillis & Contini (1966): upper arm 0.186 H,
  // forearm 0.146 H, hand 0.108 H; shoulder joints from the biacromial breadth (ANSUR: 0.232 H in
  // men, 0.225 H in women) less the two or so centimetres from the acromion in to the joint's centre
  // (docs/avatar.md). Relative to the stature the hand is as long in women as in men.
  const float shoulder = params.sex == Sex::Male ? 0.188f : params.sex == Sex::Female ? 0.167f : 0.178f;
  const float hip = params.sex == Sex::Male ? 0.082f : params.sex == Sex::Female ? 0.092f : 0.086f;

  Builder b;
  const auto spine = [](RotationOrder o, vec3 lo, vec3 hi) { return dofs(o, kX | kY | kZ, lo, hi); };
  const int root = b.add("humanoid_root", -1, vec3(0.0f, 0.950f, 0.0f) * k,
                         spine(RotationOrder::ZXY, {-180, -180, -180}, {180, 180, 180}));
  const int pelvis = b.add("sacroiliac", root, vec3(0.0f, 0.935f, -0.015f) * k,
                           spine(RotationOrder::ZXY, {-20, -30, -15}, {20, 30, 15}));
  int j = b.add("vl5", root, vec3(0.0f, 0.990f, -0.030f) * k, spine(RotationOrder::ZXY, {-10, -5, -10}, {25, 5, 10}));
  j = b.add("vl3", j, vec3(0.0f, 1.050f, -0.038f) * k, spine(RotationOrder::ZXY, {-10, -5, -10}, {25, 5, 10}));
  j = b.add("vt12", j, vec3(0.0f, 1.110f, -0.045f) * k, spine(RotationOrder::ZXY, {-8, -12, -8}, {15, 12, 8}));
  j = b.add("vt6", j, vec3(0.0f, 1.240f, -0.055f) * k, spine(RotationOrder::ZXY, {-8, -12, -8}, {15, 12, 8}));
  const int vt1 = b.add("vt1", j, vec3(0.0f, 1.390f, -0.045f) * k, spine(RotationOrder::ZXY, {-8, -12, -8}, {15, 12, 8}));
  j = b.add("vc7", vt1, vec3(0.0f, 1.425f, -0.035f) * k, spine(RotationOrder::ZXY, {-30, -35, -20}, {25, 35, 20}));
  j = b.add("vc4", j, vec3(0.0f, 1.475f, -0.022f) * k, spine(RotationOrder::ZXY, {-30, -35, -20}, {25, 35, 20}));
  const int skull = b.add("skullbase", j, vec3(0.0f, 1.540f, -0.012f) * k,
                          spine(RotationOrder::ZXY, {-25, -30, -15}, {20, 30, 15}));
  b.add("temporomandibular", skull, vec3(0.0f, 1.545f, 0.030f) * k,
        dofs(RotationOrder::XYZ, kX | kY, {-2, -8, 0}, {28, 8, 0}));
  const JointDofs eye = dofs(RotationOrder::YXZ, kX | kY, {-25, -35, 0}, {30, 35, 0});
  b.add("l_eyeball_joint", skull, vec3(0.031f, 1.591f, 0.070f) * k, eye);
  b.add("r_eyeball_joint", skull, vec3(-0.031f, 1.591f, 0.070f) * k, mirrored(eye));
  b.add("skull_tip", skull, vec3(0.0f, 1.700f, 0.000f) * k);

  for (float side : {1.0f, -1.0f}) {
    const SideDims dims{side,
                        k,
                        shoulder * params.shoulder_width * k * (0.85f + 0.15f * params.build),
                        hip * k * (0.8f + 0.2f * params.build),
                        0.186f * 1.70f * k * params.arm_length,
                        0.146f * 1.70f * k * params.arm_length,
                        0.108f * 1.70f * k * params.hand_size,  // hand length (Drillis & Contini: 0.108 H)
                        params.finger_length,
                        a_pose_angle(params, shoulder * params.shoulder_width * (0.85f + 0.15f * params.build))};
    add_arm(b, vt1, dims);
  }
  for (float side : {1.0f, -1.0f}) {
    const SideDims dims{side, k, 0.0f, hip * k * (0.8f + 0.2f * params.build), 0, 0, 0, 0};
    add_leg(b, pelvis, dims);
  }
  b.skeleton.validate();
  return std::move(b.skeleton);
}

std::vector<vec3> rest_joint_positions(const Skeleton& skeleton) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  std::vector<vec3> out(skeleton.size());
  model_positions(model, out);
  return out;
}

}  // namespace gestura
