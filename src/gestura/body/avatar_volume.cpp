#include "gestura/body/avatar_volume.hpp"

#include <algorithm>
#include <string>

#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/head_sculpt.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/body/trunk_sculpt.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

std::uint8_t mat(MaterialId m) { return static_cast<std::uint8_t>(m); }

struct VolumeBuilder {
  const Skeleton& skeleton;
  std::vector<vec3> joints;
  ImplicitBody body;

  int joint(const std::string& name) const {
    const int j = skeleton.find(name);
    if (j < 0) throw Error("avatar volume: skeleton has no joint '" + name + "'");
    return j;
  }
  vec3 at(const std::string& name) const { return joints[static_cast<std::size_t>(joint(name))]; }

  Primitive& push(Primitive p, const std::string& bone, MaterialId m, float blend, BlendOp op = BlendOp::Union) {
    p.joint = static_cast<std::int16_t>(joint(bone));
    p.material = mat(m);
    p.blend = blend;
    p.op = op;
    p.skinned = op == BlendOp::Union;
    body.primitives.push_back(p);
    return body.primitives.back();
  }
  Primitive& capsule(const std::string& bone, vec3 a, vec3 b, float ra, float rb, MaterialId m, float blend) {
    Primitive p;
    p.shape = PrimitiveShape::Capsule;
    p.a = a;
    p.b = b;
    p.radius_a = ra;
    p.radius_b = rb;
    return push(p, bone, m, blend);
  }
  Primitive& ellipsoid(const std::string& bone, vec3 c, vec3 radii, MaterialId m, float blend,
                       BlendOp op = BlendOp::Union, mat3 axes = mat3(1.0f)) {
    Primitive p;
    p.shape = PrimitiveShape::Ellipsoid;
    p.a = c;
    p.radii = radii;
    p.axes = axes;
    return push(p, bone, m, blend, op);
  }
  Primitive& round_box(const std::string& bone, vec3 c, vec3 half, float round, mat3 axes, MaterialId m, float blend) {
    Primitive p;
    p.shape = PrimitiveShape::RoundBox;
    p.a = c;
    p.radii = half;
    p.radius_a = round;
    p.axes = axes;
    return push(p, bone, m, blend);
  }
};

using proportions::by_sex;

void add_trunk(VolumeBuilder& b, const AvatarParams& p, float k) {
  const float g = p.build;
  const MaterialId cloth = MaterialId::Cloth;
  // The trunk's loft, one piece per spine joint (trunk_sculpt.hpp).
  const auto loft = std::make_shared<const TrunkLoft>(trunk_sections(p));
  const struct {
    const char* joint;
    float top;  // metres at 1.70 m; each piece starts where the one below ends
  } pieces[] = {{"sacroiliac", 0.975f}, {"vl5", 1.025f}, {"vl3", 1.095f}, {"vt12", 1.185f}, {"vt6", 1.320f}, {"vt1", 9.0f}};
  float bottom = loft->bottom() - 0.05f * k;
  for (const auto& piece : pieces) {
    Primitive trunk;
    trunk.shape = PrimitiveShape::Sculpt;
    const float top = std::min(piece.top * k, loft->top() + 0.05f * k);
    trunk.sculpt = std::make_shared<TrunkPiece>(loft, bottom, top);
    b.push(trunk, piece.joint, cloth, 0.0f);
    bottom = top;
  }
  const float chest_breadth = loft->at(1.23f * k).half_breadth;
  if (p.sex == Sex::Female)
    for (float s : {1.0f, -1.0f})
      b.ellipsoid("vt6", vec3(s * 0.080f, 1.240f, 0.078f) * k, vec3(0.060f * g, 0.054f, 0.050f * g) * k, cloth, 0.03f * k);
  // The shoulder girdle over the top of the loft, sloping from the base of the neck down to the
  // shoulders (its top keeps its height for any build, so the neck stays free).
  for (const char* side : {"l_", "r_"}) {
    const vec3 sh = b.at(std::string(side) + "shoulder");
    const float dir = sh.x > 0 ? 1.0f : -1.0f;
    b.capsule("vt1", vec3(0.0f, (1.430f - 0.050f * g) * k, -0.035f * k),
              vec3(sh.x - dir * 0.080f * k, (1.404f - 0.050f * g) * k, -0.030f * k), 0.050f * k * g, 0.048f * k * g, cloth,
              0.04f * k);
  }
  for (const char* side : {"l_", "r_"}) {
    const std::string s = side;
    const vec3 sh = b.at(s + "shoulder");
    const float dir = sh.x > 0 ? 1.0f : -1.0f;
    b.capsule(s + "sternoclavicular", b.at(s + "sternoclavicular") + vec3(0, -0.008f, -0.020f) * k,
              sh + vec3(-dir * 0.02f, 0.008f, -0.006f) * k, 0.024f * k, 0.030f * k, cloth, 0.04f * k);
    b.capsule("vt1", vec3(dir * 0.050f, 1.448f - 0.033f * g, -0.050f) * k, sh + vec3(-dir * 0.035f, -0.004f, -0.015f) * k,
              0.033f * k * g, 0.030f * k * g, cloth, 0.035f * k);
    b.ellipsoid(s + "shoulder", sh + vec3(dir * 0.010f, -0.033f, 0.0f) * k, vec3(0.048f, 0.068f, 0.052f) * k * g, cloth,
                0.03f * k);
    // The hollow of the armpit: the chest wall under the shoulder falls back a centimetre, so the
    // hanging arm (added later, not carved) stays clear of it below the armpit.
    b.ellipsoid("vt6", vec3(dir * (chest_breadth + 0.012f * k), 1.230f * k, -0.010f * k), vec3(0.022f, 0.075f, 0.050f) * k, cloth,
                0.02f * k, BlendOp::Subtract);
  }
  // Neck: skin above the collar.
  const float neck = by_sex(p.sex, 0.050f, 0.054f, 0.058f) * (0.85f + 0.15f * g) * k;
  b.capsule("vc4", vec3(0, 1.400f, -0.028f) * k, b.at("skullbase") + vec3(0, 0.0f, 0.0f), neck, 0.93f * neck,
            MaterialId::Skin, 0.03f * k);
}

// The head: one sculpted surface with the mouth carved in and the jaw open by the bind angle
// (head_sculpt.hpp), the hair as a shell over it, ears, and a ball of lid skin over each eyeball
// with the almond of the eye opening carved into it down past the eyeball's surface: what is left of
// the ball above and below the opening are the upper and lower lids, whose margins rest on the
// eyeball, so a lid that turns about the eye's centre slides over it (the blink morph). The eyeballs,
// teeth and tongue are separate rigid parts (face_parts.hpp).
void add_head(VolumeBuilder& b, const AvatarParams& p, float k, float jaw_open_degrees) {
  auto head = std::make_shared<HeadSculpt>(p, b.at("temporomandibular"),
                                           std::array<vec3, 2>{b.at("l_eyeball_joint"), b.at("r_eyeball_joint")},
                                           jaw_open_degrees);
  Primitive face;
  face.shape = PrimitiveShape::Sculpt;
  face.sculpt = head;
  b.push(face, "skullbase", MaterialId::Skin, 0.007f * k);
  Primitive hair;
  hair.shape = PrimitiveShape::Sculpt;
  hair.sculpt = std::make_shared<HairSculpt>(head, p.hair);
  b.push(hair, "skullbase", MaterialId::Hair, 0.002f * k);
  auto v = [k](float x, float y, float z) { return vec3(x, y, z) * k; };
  if (p.hair == HairStyle::Bun)
    b.ellipsoid("skullbase", v(0.0f, 1.652f, -0.094f), v(0.031f, 0.029f, 0.026f), MaterialId::Hair, 0.012f * k);
  if (p.hair != HairStyle::Bob && p.hair != HairStyle::Curly)
    for (float s : {1.0f, -1.0f}) {
      // Ears, tilted slightly back, with the hollow of the concha.
      const mat3 tilt = glm::mat3_cast(glm::angleAxis(deg(-15.0f), vec3(1, 0, 0)));
      b.ellipsoid("skullbase", v(s * 0.0770f, 1.584f, -0.010f), v(0.0095f, 0.0310f, 0.0185f), MaterialId::Skin, 0.006f * k,
                  BlendOp::Union, tilt);
      b.ellipsoid("skullbase", v(s * 0.0855f, 1.579f, -0.006f), v(0.0055f, 0.0120f, 0.0085f), MaterialId::Skin, 0.003f * k,
                  BlendOp::Subtract, tilt);
    }
  for (const char* side : {"l_", "r_"}) {
    const vec3 eye = b.at(std::string(side) + "eyeball_joint");
    b.ellipsoid("skullbase", eye, vec3(proportions::kEyeballRadius + proportions::kLidThickness) * k, MaterialId::Skin,
                0.004f * k);
    b.ellipsoid("skullbase", eye + vec3(proportions::kEyeOpeningCentre[0], proportions::kEyeOpeningCentre[1],
                                        proportions::kEyeOpeningCentre[2]) * k,
                vec3(proportions::kEyeOpeningRadii[0], proportions::kEyeOpeningRadii[1], proportions::kEyeOpeningRadii[2]) * k,
                MaterialId::Skin, 0.0015f * k, BlendOp::Subtract);
  }
}

void add_arm(VolumeBuilder& b, const AvatarParams& p, const std::string& s, float k) {
  const float g = p.build;
  const vec3 sh = b.at(s + "shoulder"), el = b.at(s + "elbow"), wr = b.at(s + "wrist");
  const vec3 down = glm::normalize(wr - el);
  // A narrow blend: the upper arm joins the trunk at the armpit only, not along the chest wall it
  // hangs beside (a wide one would web them together and stretch the web when the arm rises).
  b.capsule(s + "shoulder", sh, el, 0.046f * k * g, 0.036f * k * g, MaterialId::Cloth, 0.012f * k);
  b.capsule(s + "elbow", el, wr - down * (0.012f * k), 0.037f * k * g, proportions::kWristSleeveRadius * k * g, MaterialId::Cloth,
            proportions::kForearmBlend * k);

  // Hand frame as in the skeleton: down the hand, forward (thumb side), dorsal (back of the hand).
  const vec3 fwd(0, 0, 1);
  const float side = sh.x > 0 ? 1.0f : -1.0f;
  const vec3 palm_dorsal = glm::cross(fwd, down) * side;
  const float hand = glm::length(b.at(s + "middle1") - wr) / 0.098f;  // hand scale from the skeleton
  const float th = p.finger_thickness;
  auto hp = [&](float d, float f, float o) { return wr + (down * d + fwd * f + palm_dorsal * o) * hand; };
  b.capsule(s + "wrist", wr - down * (0.030f * k), wr + down * (0.012f * hand), 0.025f * k * (0.8f + 0.2f * g),
            0.026f * hand, MaterialId::Skin, 0.012f * hand);
  const mat3 palm_axes(palm_dorsal, down, fwd);
  // Palm: a rounded slab under the knuckles, tapering through an ellipsoid into the wrist; the
  // knuckle ridge follows the metacarpal heads (the little finger's sits lower).
  b.round_box(s + "wrist", hp(0.068f, -0.002f, -0.001f), vec3(0.0055f, 0.024f, 0.026f) * hand, 0.0105f * hand, palm_axes,
              MaterialId::Skin, 0.008f * hand);
  b.ellipsoid(s + "wrist", hp(0.036f, -0.002f, -0.002f), vec3(0.016f, 0.028f, 0.031f) * hand, MaterialId::Skin,
              0.010f * hand, BlendOp::Union, palm_axes);
  b.capsule(s + "wrist", hp(0.091f, 0.022f, 0.001f), hp(0.083f, -0.026f, 0.001f), 0.0105f * hand, 0.0095f * hand,
            MaterialId::Skin, 0.008f * hand);
  b.ellipsoid(s + "wrist", hp(0.052f, -0.024f, -0.006f), vec3(0.010f, 0.030f, 0.012f) * hand, MaterialId::Skin,
              0.008f * hand, BlendOp::Union, palm_axes);

  struct FingerShape {
    const char* name;
    float r;
  };
  static constexpr FingerShape fingers[5] = {{"thumb", 0.0105f}, {"index", 0.0090f}, {"middle", 0.0093f},
                                             {"ring", 0.0086f}, {"pinky", 0.0076f}};
  for (const FingerShape& f : fingers) {
    const std::string n = s + f.name;
    const vec3 j1 = b.at(n + "1"), j2 = b.at(n + "2"), j3 = b.at(n + "3"), tip = b.at(n + "_tip");
    const float r0 = f.r * hand * th;
    const float rt = 0.78f * r0;
    if (std::string(f.name) == "thumb") {
      // Thenar eminence along the first metacarpal.
      b.capsule(n + "1", j1 - down * (0.012f * hand), j2, 1.35f * r0, 1.02f * r0, MaterialId::Skin, 0.010f * hand);
      b.ellipsoid(n + "1", glm::mix(j1, j2, 0.35f) - palm_dorsal * (0.007f * hand), vec3(0.012f, 0.022f, 0.014f) * hand,
                  MaterialId::Skin, 0.010f * hand, BlendOp::Union, palm_axes);
      b.capsule(n + "2", j2, j3, 0.98f * r0, 0.88f * r0, MaterialId::Skin, 0.003f * hand);
    } else {
      b.capsule(n + "1", j1, j2, r0, 0.90f * r0, MaterialId::Skin, 0.004f * hand);
      b.capsule(n + "2", j2, j3, 0.90f * r0, 0.84f * r0, MaterialId::Skin, 0.003f * hand);
    }
    const vec3 dir = glm::normalize(tip - j3);
    b.capsule(n + "3", j3, tip - dir * rt, 0.84f * r0, rt, MaterialId::Skin, 0.003f * hand);
  }
}

void add_leg(VolumeBuilder& b, const AvatarParams& p, const std::string& s, float k) {
  const float g = p.build * proportions::thigh_factor(p.sex);
  const vec3 hip = b.at(s + "hip"), knee = b.at(s + "knee"), ankle = b.at(s + "ankle");
  const float x = hip.x;
  const MaterialId cloth = MaterialId::Cloth;
  b.capsule(s + "hip", hip + vec3(0, 0.02f, 0) * k, knee, proportions::kThighRadius * k * g, 0.050f * k * g, cloth, 0.05f * k);
  b.capsule(s + "knee", knee, ankle, 0.049f * k * g, 0.031f * k * g, cloth, 0.03f * k);
  b.ellipsoid(s + "knee", knee + vec3(0, -0.13f, -0.022f) * k, vec3(0.043f, 0.10f, 0.042f) * k * g, cloth, 0.04f * k);
  b.ellipsoid(s + "ankle", ankle, vec3(0.033f, 0.035f, 0.035f) * k, cloth, 0.02f * k);
  b.ellipsoid(s + "subtalar", vec3(x, 0.036f * k, -0.048f * k), vec3(0.032f, 0.040f, 0.040f) * k, cloth, 0.02f * k);
  b.ellipsoid(s + "midtarsal", vec3(x * 1.06f, 0.032f * k, 0.055f * k), vec3(0.042f, 0.036f, 0.095f) * k, cloth,
              0.03f * k);
  b.ellipsoid(s + "metatarsal", vec3(x * 1.12f, 0.022f * k, 0.160f * k), vec3(0.044f, 0.024f, 0.042f) * k, cloth,
              0.02f * k);
}

}  // namespace

ImplicitBody build_avatar_volume(const Skeleton& skeleton, const AvatarParams& params, float jaw_open_degrees) {
  params.validate();
  VolumeBuilder b{skeleton, rest_joint_positions(skeleton), {}};
  const float k = params.height / 1.70f;
  add_trunk(b, params, k);
  add_head(b, params, k, jaw_open_degrees);
  for (const char* side : {"l_", "r_"}) add_arm(b, params, side, k);
  for (const char* side : {"l_", "r_"}) add_leg(b, params, side, k);
  // The floor flattens the soles.
  Primitive floor;
  floor.shape = PrimitiveShape::HalfSpace;
  floor.a = vec3(0.0f);
  floor.axes[1] = vec3(0, -1, 0);
  b.push(floor, "humanoid_root", MaterialId::Cloth, 0.0f, BlendOp::Intersect);
  b.body.finish();
  return std::move(b.body);
}

std::vector<DetailBox> avatar_detail_boxes(const Skeleton& skeleton, const AvatarParams& params) {
  const auto joints = rest_joint_positions(skeleton);
  const float k = params.height / 1.70f;
  std::vector<DetailBox> boxes;
  for (const char* side : {"l_", "r_"}) {
    // The hand and the last few centimetres of the sleeve; the forearm enters through the top.
    const int wrist = skeleton.find(std::string(side) + "wrist");
    DetailBox box;
    box.lo = box.hi = joints[static_cast<std::size_t>(wrist)];
    for (std::size_t j = 0; j < skeleton.size(); ++j) {
      int a = static_cast<int>(j);
      while (a > wrist) a = skeleton.parents[static_cast<std::size_t>(a)];
      if (a != wrist) continue;
      box.lo = glm::min(box.lo, joints[j]);
      box.hi = glm::max(box.hi, joints[j]);
    }
    const float flesh = proportions::hand_flesh_margin(params) * k;
    box.lo -= vec3(flesh, 0.02f * k, flesh);
    box.hi += vec3(flesh, 0.0f, flesh);
    box.hi.y = joints[static_cast<std::size_t>(wrist)].y + 0.035f * k;
    // The sleeve crosses the top face (and the coarse lattice's cut a cell above it).
    const vec3 elbow = joints[static_cast<std::size_t>(skeleton.parents[static_cast<std::size_t>(wrist)])];
    const vec3 wrist_pos = joints[static_cast<std::size_t>(wrist)];
    const vec3 up = glm::normalize(elbow - wrist_pos);
    // A horizontal cut through a tilted sleeve is an ellipse, longer by 1 / cos(tilt).
    const float sleeve = proportions::sleeve_margin(params) * k / std::max(0.5f, up.y);
    for (float y_above : {0.035f * k, 0.07f * k}) {
      const vec3 axis = wrist_pos + up * (y_above / up.y);
      box.lo = glm::min(box.lo, vec3(axis.x - sleeve, box.lo.y, axis.z - sleeve));
      box.hi = glm::max(box.hi, vec3(axis.x + sleeve, box.hi.y, axis.z + sleeve));
    }
    box.refine = 5;
    box.open_axis = 1;
    box.open_side = 1;
    boxes.push_back(box);
  }
  // The head above the neck; the neck enters through the bottom.
  DetailBox head;
  head.lo = vec3(-0.112f, 1.470f, -0.145f) * k;
  head.hi = vec3(0.112f, 1.745f, 0.15f) * k;
  head.refine = 4;
  head.open_axis = 1;
  head.open_side = -1;
  boxes.push_back(head);
  return boxes;
}

}  // namespace gestura
