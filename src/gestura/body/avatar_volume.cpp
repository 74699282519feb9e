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
  Primitive& capsule(const std::string& bone, vec3 a, vec3 b, float ra, float rb, MaterialId m, float blend,
                     BlendOp op = BlendOp::Union) {
    Primitive p;
    p.shape = PrimitiveShape::Capsule;
    p.a = a;
    p.b = b;
    p.radius_a = ra;
    p.radius_b = rb;
    return push(p, bone, m, blend, op);
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

// A digit's last phalanx: from its last joint to its tip, with the directions across it and to its
// back (the nail side), and its radius there.
struct DigitFrame {
  vec3 joint, tip, dir, across, back;
  float radius;
};

// Half-breadths of the digits at the base of their proximal phalanges, in hand lengths (the PIP
// breadths of hand anthropometry, docs/avatar.md).
struct DigitShape {
  const char* name;
  float r;
};
constexpr DigitShape kDigitShapes[5] = {{"thumb", 0.058f}, {"index", 0.051f}, {"middle", 0.053f}, {"ring", 0.049f},
                                        {"pinky", 0.043f}};

// The hand's frame and scale from the skeleton: the hand length L (wrist to the middle fingertip)
// and the breadth factor of the params.
struct HandFrame {
  vec3 wrist, down, fwd, dorsal;
  float side, L, breadth, thickness;
};
HandFrame hand_frame(const std::vector<vec3>& joints, const Skeleton& skeleton, const AvatarParams& p, const std::string& s) {
  auto at = [&](const std::string& name) {
    const int j = skeleton.find(name);
    if (j < 0) throw Error("avatar volume: skeleton has no joint '" + name + "'");
    return joints[static_cast<std::size_t>(j)];
  };
  HandFrame h;
  const vec3 sh = at(s + "shoulder"), el = at(s + "elbow");
  h.wrist = at(s + "wrist");
  h.down = glm::normalize(h.wrist - el);
  h.fwd = vec3(0, 0, 1);
  h.side = sh.x > 0 ? 1.0f : -1.0f;
  h.dorsal = glm::cross(h.fwd, h.down) * h.side;
  h.L = glm::length(at(s + "middle_tip") - h.wrist) / 0.97f;
  h.breadth = proportions::by_sex(p.sex, 0.955f, 1.0f, 1.035f) * (0.9f + 0.1f * p.build);
  h.thickness = p.finger_thickness * h.breadth;
  return h;
}

DigitFrame digit_frame(const std::vector<vec3>& joints, const Skeleton& skeleton, const HandFrame& h, const std::string& s,
                       const DigitShape& shape) {
  auto at = [&](const std::string& name) { return joints[static_cast<std::size_t>(skeleton.find(name))]; };
  const std::string n = s + shape.name;
  const bool thumb = std::string(shape.name) == "thumb";
  DigitFrame d;
  d.joint = at(n + "3");
  d.tip = at(n + "_tip");
  d.dir = glm::normalize(d.tip - d.joint);
  const vec3 t1 = at(s + "thumb1"), t2 = at(s + "thumb2");
  const vec3 up = thumb ? glm::normalize(glm::cross(h.down, glm::normalize(t2 - t1))) * h.side : h.dorsal;
  d.across = glm::normalize(glm::cross(d.dir, up));
  d.back = glm::normalize(glm::cross(d.across, d.dir));
  d.radius = (thumb ? 0.90f : 0.84f) * shape.r * h.L * h.thickness;
  return d;
}

// Where a digit's nail is, in its last phalanx's frame: from a little over a quarter of the way
// from the joint to the free edge at the tip, two thirds of the digit's breadth wide, on its back.
float nail_plate_field(const DigitFrame& d, const vec3& p) {
  const vec3 q = p - d.joint;
  const float last = glm::distance(d.joint, d.tip);
  const float along = glm::dot(q, d.dir), across = std::abs(glm::dot(q, d.across)), height = glm::dot(q, d.back);
  const float start = 0.30f * last, end = 0.99f * last, half_width = 0.66f * d.radius;
  // The cuticle's end is rounded: an ellipse over the first fifth of the plate.
  const float round_len = 0.22f * (end - start);
  float cuticle = start - along;
  if (along < start + round_len) {
    const float u = across / half_width, v = (start + round_len - along) / round_len;
    cuticle = (std::sqrt(u * u + v * v) - 1.0f) * std::min(half_width, round_len);
  }
  return std::max({across - half_width, cuticle, along - end, 0.25f * d.radius - height});
}

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
      b.ellipsoid("vt6", vec3(s * 0.072f, 1.236f, 0.068f) * k, vec3(0.062f * g, 0.056f, 0.050f * g) * k, cloth, 0.05f * k);
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
    // The deltoid: longer down the arm than across, and only 8 mm proud of the upper arm's
    // capsule (it was 12 mm, a ball that read as a puffed sleeve, most of all on a raised arm).
    b.ellipsoid(s + "shoulder", sh + vec3(dir * 0.006f, -0.036f, 0.0f) * k, vec3(0.048f, 0.072f, 0.050f) * k * g, cloth,
                0.035f * k);
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
  // Blended over 6 mm into the scalp: where the shell rises out of the skin the two surfaces
  // meet at an edge, which 4 mm cells sampled as a sawtooth (the ragged hairline of side views).
  b.push(hair, "skullbase", MaterialId::Hair, 0.006f * k);
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
  b.capsule(s + "shoulder", sh, el, 0.046f * k * g, 0.037f * k * g, MaterialId::Cloth, 0.012f * k);
  // The sleeve covers `sleeve` of the forearm; below it the bare forearm is a little slimmer.
  const vec3 cuff = el + (wr - down * (0.012f * k) - el) * p.sleeve;
  const float wrist_r = proportions::kWristSleeveRadius * k * g;
  const float cuff_r = glm::mix(0.039f * k * g, wrist_r, p.sleeve);
  b.capsule(s + "elbow", el, cuff, 0.039f * k * g, cuff_r, MaterialId::Cloth, proportions::kForearmBlend * k);
  if (p.sleeve < 1.0f)
    b.capsule(s + "elbow", cuff - down * (0.004f * k), wr - down * (0.012f * k), cuff_r - 0.003f * k * g, wrist_r - 0.003f * k * g,
              MaterialId::Skin, proportions::kForearmBlend * k);

  // The hand, in shares of its length L (the skeleton's), in its frame: down the hand, forward
  // (thumb side), dorsal (back of the hand). Widths from the hand's breadth; women's hands are
  // narrower for their length (ANSUR), men's broader.
  const HandFrame hand = hand_frame(b.joints, b.skeleton, p, s);
  const vec3 fwd = hand.fwd, palm_dorsal = hand.dorsal;
  const float side = hand.side, L = hand.L, breadth = hand.breadth, th = hand.thickness;
  auto hp = [&](float d, float f, float o) { return wr + (down * d + fwd * f * breadth + palm_dorsal * o) * L; };
  const MaterialId skin = MaterialId::Skin;
  const mat3 palm_axes(palm_dorsal, down, fwd);  // local x dorsal, y along the hand, z towards the thumb
  // Wrist, narrower than the palm.
  b.capsule(s + "wrist", wr - down * (0.030f * k), wr + down * (0.05f * L), 0.025f * k * (0.8f + 0.2f * g), 0.135f * L * breadth,
            skin, 0.06f * L);
  // Palm: a flattened egg from the wrist to the knuckles, broadest over the metacarpal heads, its
  // back gently domed.
  b.ellipsoid(s + "wrist", hp(0.285f, -0.008f, -0.006f), vec3(0.072f, 0.215f, 0.205f * breadth) * L, skin, 0.050f * L,
              BlendOp::Union, palm_axes);
  b.ellipsoid(s + "wrist", hp(0.150f, -0.005f, -0.010f), vec3(0.070f, 0.120f, 0.155f * breadth) * L, skin, 0.050f * L,
              BlendOp::Union, palm_axes);
  // Heads of the metacarpals: the knuckle ridge across the back of the hand, on an arch.
  const char* digits[4] = {"index", "middle", "ring", "pinky"};
  for (int i = 0; i + 1 < 4; ++i)
    b.capsule(s + "wrist", b.at(s + digits[i] + "1") + palm_dorsal * (0.012f * L),
              b.at(s + digits[i + 1] + "1") + palm_dorsal * (0.012f * L), (0.058f - 0.004f * static_cast<float>(i)) * L * th,
              (0.054f - 0.004f * static_cast<float>(i)) * L * th, skin, 0.030f * L);
  // The fleshy pads along the palm under the fingers, the hypothenar eminence along the little
  // finger's edge and the thenar eminence over the thumb's metacarpal.
  b.capsule(s + "wrist", hp(0.405f, 0.150f, -0.035f), hp(0.385f, -0.150f, -0.035f), 0.052f * L, 0.048f * L, skin, 0.035f * L);
  b.ellipsoid(s + "wrist", hp(0.250f, -0.145f, -0.035f), vec3(0.050f, 0.150f, 0.060f) * L, skin, 0.040f * L, BlendOp::Union,
              palm_axes);
  const vec3 t1 = b.at(s + "thumb1"), t2 = b.at(s + "thumb2"), t3 = b.at(s + "thumb3"), index1 = b.at(s + "index1");
  {
    const vec3 along = glm::normalize(t2 - t1);
    const vec3 outward = glm::normalize(glm::cross(along, down) * side);
    const mat3 thenar_axes(glm::normalize(glm::cross(along, outward)), along, outward);
    b.ellipsoid(s + "thumb1", glm::mix(t1, t2, 0.40f) - palm_dorsal * (0.022f * L), vec3(0.055f, 0.115f, 0.060f) * L, skin,
                0.045f * L, BlendOp::Union, thenar_axes);
    // The web between thumb and index: a thin sheet from the thumb's knuckle to the index's,
    // across the gap, blended in so its edge curves.
    const vec3 a = glm::mix(t2, t3, 0.15f), c = index1 - down * (0.03f * L) - palm_dorsal * (0.012f * L);
    const vec3 web_centre = glm::mix(glm::mix(a, c, 0.5f), t1, 0.25f);
    const vec3 u = glm::normalize(c - a), n = glm::normalize(glm::cross(c - a, t1 - a));
    const mat3 web_axes(n, glm::normalize(glm::cross(n, u)), u);
    b.ellipsoid(s + "thumb1", web_centre, vec3(0.022f, 0.085f, 0.5f * glm::length(c - a) / L + 0.02f) * L, skin, 0.040f * L,
                BlendOp::Union, web_axes);
  }

  // Digits: tapered phalanges, the joints a little thicker with knuckles on their backs, pads on
  // the palm side (the fingertip's fullest), creases across the palm side at the joints.
  for (const DigitShape& f : kDigitShapes) {
    const std::string n = s + f.name;
    const bool thumb = std::string(f.name) == "thumb";
    const vec3 j1 = b.at(n + "1"), j2 = b.at(n + "2"), j3 = b.at(n + "3"), tip = b.at(n + "_tip");
    const float r0 = f.r * L * th;
    const float rt = 0.80f * r0;
    const DigitFrame frame = digit_frame(b.joints, b.skeleton, hand, s, f);
    const vec3 dir = frame.dir, across = frame.across, back = frame.back;
    if (thumb) {
      b.capsule(n + "2", j2, j3, 0.98f * r0, 0.90f * r0, skin, 0.02f * L);
    } else {
      b.capsule(n + "1", j1 + down * (0.02f * L), j2, r0, 0.92f * r0, skin, 0.02f * L);
      b.capsule(n + "2", j2, j3, 0.90f * r0, 0.84f * r0, skin, 0.015f * L);
      // Knuckle of the middle joint and the pad of the proximal phalanx.
      b.ellipsoid(n + "2", j2 + back * (0.40f * r0), vec3(0.46f * r0, 0.42f * r0, 0.30f * r0), skin, 0.4f * r0, BlendOp::Union,
                  mat3(across, dir, back));
      b.ellipsoid(n + "1", glm::mix(j1, j2, 0.55f) - back * (0.28f * r0), vec3(0.70f * r0, 0.40f * glm::distance(j1, j2), 0.45f * r0),
                  skin, 0.5f * r0, BlendOp::Union, mat3(across, glm::normalize(j2 - j1), back));
    }
    b.capsule(n + "3", j3, tip - dir * rt, (thumb ? 0.90f : 0.84f) * r0, rt, skin, 0.015f * L);
    // The last joint's knuckle, and the fingertip's pad, fullest a little short of the tip.
    b.ellipsoid(n + "3", j3 + back * (0.36f * r0), vec3(0.40f * r0, 0.38f * r0, 0.28f * r0), skin, 0.4f * r0, BlendOp::Union,
                mat3(across, dir, back));
    const float last = glm::distance(j3, tip);
    b.ellipsoid(n + "3", j3 + dir * (0.55f * last) - back * (0.22f * r0), vec3(0.72f * r0, 0.40f * last, 0.50f * r0), skin,
                0.45f * r0, BlendOp::Union, mat3(across, dir, back));
    // The nail plate, standing a fraction of a millimetre proud of the skin at its edges.
    b.ellipsoid(n + "3", j3 + dir * (0.64f * last) + back * (0.52f * frame.radius),
                vec3(0.64f * frame.radius, 0.36f * last, 0.50f * frame.radius), MaterialId::Nail, 0.25f * frame.radius,
                BlendOp::Union, mat3(across, dir, back));
    // Flexion creases across the palm side of the last two joints (thumb: its one).
    for (const vec3& joint : thumb ? std::vector<vec3>{j3} : std::vector<vec3>{j2, j3}) {
      const float r = glm::distance(joint, j3) < 1e-6f ? 0.86f * r0 : 0.92f * r0;
      b.capsule(n + (thumb ? "3" : "2"), joint - back * (1.02f * r) - across * (0.75f * r), joint - back * (1.02f * r) + across * (0.75f * r),
                0.10f * r, 0.10f * r, skin, 0.10f * r, BlendOp::Subtract);
    }
  }
  // The palm's creases: the distal and proximal transverse creases and the thenar crease.
  const float groove = 0.006f * L;
  auto crease = [&](vec3 from, vec3 to) {
    b.capsule(s + "wrist", from, to, groove, groove, skin, groove, BlendOp::Subtract);
  };
  crease(hp(0.370f, -0.205f, -0.086f), hp(0.355f, 0.070f, -0.088f));
  crease(hp(0.305f, -0.120f, -0.084f), hp(0.330f, 0.190f, -0.088f));
  crease(hp(0.150f, 0.080f, -0.080f), hp(0.300f, 0.170f, -0.090f));
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

NailPlates::NailPlates(const Skeleton& skeleton, const AvatarParams& params) {
  const std::vector<vec3> joints = rest_joint_positions(skeleton);
  for (const char* side : {"l_", "r_"}) {
    const HandFrame hand = hand_frame(joints, skeleton, params, side);
    for (const DigitShape& shape : kDigitShapes) {
      const DigitFrame d = digit_frame(joints, skeleton, hand, side, shape);
      plates_.push_back({d.joint, d.tip, d.dir, d.across, d.back, d.radius});
    }
  }
}

float NailPlates::field(const vec3& p) const {
  float f = 1.0f;
  for (const Plate& plate : plates_) {
    if (glm::distance(p, plate.tip) > 0.05f) continue;
    f = std::min(f, nail_plate_field({plate.joint, plate.tip, plate.dir, plate.across, plate.back, plate.radius}, p));
  }
  return f;
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
