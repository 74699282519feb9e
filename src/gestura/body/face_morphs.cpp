#include "gestura/body/face_morphs.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "gestura/body/avatar_proportions.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// Smooth bump: 1 at the centre, 0 on and outside the ellipsoid with semi-axes `radii`.
float falloff(const vec3& p, const vec3& centre, const vec3& radii) {
  const vec3 q = (p - centre) / radii;
  const float r2 = glm::dot(q, q);
  if (r2 >= 1.0f) return 0.0f;
  return (1.0f - r2) * (1.0f - r2);
}

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// What a vertex of the face is: skin (soft tissue, every field applies), or one of the rigid
// parts, which only turn with the jaw (teeth, tongue) or shift as a whole (tongue), or never move
// (eyeballs: gaze belongs to the eye joints).
enum class Part : std::uint8_t { Soft, Teeth, Tongue, Eyeball };

Part part_of(std::uint8_t material) {
  switch (static_cast<MaterialId>(material)) {
    case MaterialId::Teeth: return Part::Teeth;
    case MaterialId::Tongue: return Part::Tongue;
    case MaterialId::EyeWhite:
    case MaterialId::Iris:
    case MaterialId::Pupil: return Part::Eyeball;
    default: return Part::Soft;
  }
}

struct FacePoint {
  vec3 p;
  float jaw;  // skin weight of the jaw joint
  Part part;
};

// Landmarks of the default face, from the skeleton plus fixed proportions (avatar_proportions.hpp).
struct Face {
  float k;
  vec3 jaw;          // temporomandibular joint
  vec3 eye[2];       // [0] left (+X), [1] right
  FaceLandmarks marks;  // mouth, lips, brows and cheeks of the sculpted head
  // The eye opening as seen from the eye's centre: for a lateral offset dx, the elevation angles
  // (radians about the eye's x axis, up > 0) of the upper and lower lid margins on the eyeball;
  // tabulated over |dx| < opening_half_width, both 0 outside.
  static constexpr int kOpeningSamples = 33;
  float opening_half_width = 0.0f;
  std::array<float, kOpeningSamples> upper{}, lower{};

  vec3 v(float x, float y, float z) const { return vec3(x, y, z) * k; }
  float mouth_y() const { return marks.mouth_y; }
  // A point relative to the mouth: x across, y up from the mouth line, z from the lips' front.
  vec3 mouth(float x, float y, float z) const { return vec3(x * k, marks.mouth_y + y * k, marks.lip_front + z * k); }
  float corner_x() const { return 0.95f * marks.mouth_half_width; }
  vec3 tongue_centre() const {
    return v(proportions::kTongueCentre[0], proportions::kTongueCentre[1], proportions::kTongueCentre[2]);
  }
  float tongue_length() const { return proportions::kTongueRadii[2] * k; }

  // Upper and lower margin elevations at lateral offset dx from the eye centre.
  std::pair<float, float> opening(float dx) const {
    const float t = std::abs(dx) / opening_half_width * (kOpeningSamples - 1);
    if (t >= kOpeningSamples - 1) return {0.0f, 0.0f};
    const int i = static_cast<int>(t);
    const float f = t - static_cast<float>(i);
    return {upper[i] + f * (upper[i + 1] - upper[i]), lower[i] + f * (lower[i + 1] - lower[i])};
  }
};

// Where the carved eye opening (avatar_volume.cpp) lays the eyeball bare: scan the eyeball's
// surface for the highest and lowest point inside the opening ellipsoid at each lateral offset.
void tabulate_eye_opening(Face& f) {
  const float r = proportions::kEyeballRadius * f.k;
  const vec3 centre = vec3(proportions::kEyeOpeningCentre[0], proportions::kEyeOpeningCentre[1],
                           proportions::kEyeOpeningCentre[2]) * f.k;
  const vec3 radii = vec3(proportions::kEyeOpeningRadii[0], proportions::kEyeOpeningRadii[1],
                          proportions::kEyeOpeningRadii[2]) * f.k;
  f.opening_half_width = std::min(radii.x, r);
  constexpr int kSteps = 200;
  for (int i = 0; i < Face::kOpeningSamples; ++i) {
    const float dx = f.opening_half_width * static_cast<float>(i) / (Face::kOpeningSamples - 1);
    float hi = 0.0f, lo = 0.0f;
    bool any = false;
    for (int s = 0; s <= kSteps; ++s) {
      const float dy = r * (2.0f * static_cast<float>(s) / kSteps - 1.0f);
      const float z2 = r * r - dx * dx - dy * dy;
      if (z2 <= 0.0f) continue;
      const vec3 q = (vec3(dx, dy, std::sqrt(z2)) - centre) / radii;
      if (glm::dot(q, q) >= 1.0f) continue;
      const float elevation = std::atan2(dy, std::sqrt(z2));
      hi = any ? std::max(hi, elevation) : elevation;
      lo = any ? std::min(lo, elevation) : elevation;
      any = true;
    }
    f.upper[static_cast<std::size_t>(i)] = any ? hi : 0.0f;
    f.lower[static_cast<std::size_t>(i)] = any ? lo : 0.0f;
  }
}

using Field = std::function<vec3(const FacePoint&)>;

// --- The deformation vocabulary: every morph is a weighted sum of these ---

// Turns the point (after an optional shift of its own) about the jaw joint by its jaw weight: the
// lower face, lower teeth and tongue open with the jaw exactly as skinning turns them.
vec3 jaw_turn(const Face& f, const FacePoint& fp, float degrees, vec3 shift = vec3(0.0f)) {
  const vec3 p = fp.p + shift;
  if (fp.jaw <= 0.0f || degrees == 0.0f) return shift;
  const quat r = glm::angleAxis(deg(degrees), vec3(1, 0, 0));
  return shift + (r * (p - f.jaw) + f.jaw - p) * fp.jaw;
}

// Mouth corners out (+) or in (−) along x, lips stretched thin.
vec3 mouth_wide(const Face& f, const vec3& p, float amount) {
  vec3 d(0.0f);
  for (float s : {1.0f, -1.0f})
    d += vec3(s * 0.006f * f.k * amount, 0, -0.002f * f.k * amount) *
         falloff(p, vec3(s * f.corner_x(), f.mouth_y() + 0.0015f * f.k, f.marks.lip_front - 0.010f * f.k),
                 f.v(0.026f, 0.020f, 0.025f));
  return d;
}

// Lips gathered towards the mouth centre and pushed forward.
vec3 mouth_round(const Face& f, const vec3& p, float amount) {
  const vec3 c = f.mouth(0.0f, 0.0f, -0.003f);
  const float w = falloff(p, c, f.v(0.040f, 0.028f, 0.035f));
  if (w <= 0.0f) return vec3(0.0f);
  return vec3(-(p.x - c.x) * 0.45f, -(p.y - c.y) * 0.2f, 0.008f * f.k) * (w * amount);
}

// Lips pressed together: the upper lip down, the lower up, both slightly in.
vec3 mouth_press(const Face& f, const vec3& p, float amount) {
  const vec3 up = f.mouth(0.0f, 0.0075f, -0.003f), lo = f.mouth(0.0f, -0.0075f, -0.004f);
  const vec3 r = f.v(0.030f, 0.010f, 0.020f);
  return (vec3(0, -0.0025f * f.k, -0.0015f * f.k) * falloff(p, up, r) +
          vec3(0, 0.0030f * f.k, -0.0010f * f.k) * falloff(p, lo, r)) *
         amount;
}

// Lower lip tucked up and back under the upper teeth (F, V).
vec3 lower_lip_tuck(const Face& f, const vec3& p, float amount) {
  return vec3(0, 0.004f * f.k, -0.005f * f.k) * falloff(p, f.mouth(0.0f, -0.0085f, -0.004f), f.v(0.028f, 0.010f, 0.020f)) * amount;
}

// The lips part: the upper lip lifts off the teeth, the lower lip drops a little (the open vowels:
// the jaw's share of the opening is the jaw bone's).
vec3 lips_part(const Face& f, const vec3& p, float amount) {
  const vec3 r = f.v(0.028f, 0.009f, 0.022f);
  return (vec3(0, 0.0022f * f.k, 0.0006f * f.k) * falloff(p, f.mouth(0.0f, 0.0060f, -0.004f), r) +
          vec3(0, -0.0016f * f.k, 0.0004f * f.k) * falloff(p, f.mouth(0.0f, -0.0065f, -0.005f), r)) *
         amount;
}

// The tongue's shift (metres at 1.70 m, in the closed jaw's frame): its front moves by `move`, its
// root stays, the length between stretches.
vec3 tongue_shift(const Face& f, const vec3& p, vec3 move) {
  const float z0 = f.tongue_centre().z - f.tongue_length(), z1 = f.tongue_centre().z + f.tongue_length();
  return move * f.k * smoothstep(z0, z1, p.z);
}

// Corner of the mouth up/out (smile) or down (frown) on one side, with the cheek following.
vec3 mouth_corner(const Face& f, const vec3& p, float side, vec3 move, float cheek) {
  const vec3 corner(side * f.corner_x(), f.mouth_y() + 0.0015f * f.k, f.marks.lip_front - 0.012f * f.k);
  const vec3 apex(side * f.marks.cheek.x, f.marks.cheek.y, f.marks.cheek.z);
  return move * f.k * falloff(p, corner, f.v(0.022f, 0.018f, 0.022f)) +
         vec3(0, 0.003f, 0.0015f) * (f.k * cheek) * falloff(p, apex, f.v(0.026f, 0.022f, 0.025f));
}

vec3 brow(const Face& f, const vec3& p, float side, float x, vec3 move) {
  return move * f.k * falloff(p, vec3(side * x * f.k, f.marks.brow_y, f.marks.brow_z), f.v(0.022f, 0.020f, 0.030f));
}

// The lids turn about the eye's centre, so they slide over the eyeball instead of squashing it.
// `upper` and `lower` are shares of the opening's height (the angle between the margins at that
// lateral offset) by which the upper lid comes down and the lower goes up; negative opens wider.
// The turn is full on the lid skin and fades out towards the brow and the cheek.
vec3 lids(const Face& f, const vec3& p, int eye, float upper, float lower) {
  const vec3 q = p - f.eye[eye];
  if (q.z < -0.002f * f.k) return vec3(0.0f);
  const auto [up, low] = f.opening(q.x);
  const float gap = up - low;
  if (gap <= 0.0f) return vec3(0.0f);
  const float elevation = std::atan2(q.y, q.z);
  const float lid_surface = (proportions::kEyeballRadius + proportions::kLidThickness) * f.k;
  const float near = 1.0f - smoothstep(lid_surface + 0.003f * f.k, lid_surface + 0.010f * f.k, glm::length(q));
  if (near <= 0.0f) return vec3(0.0f);
  const float middle = 0.5f * (up + low);
  const float is_upper = smoothstep(middle - deg(6.0f), middle + deg(6.0f), elevation);
  // Closing lids overlap a little, so a full blink leaves no slit.
  const float overlap = deg(6.0f) * smoothstep(0.0f, deg(10.0f), gap);
  float angle = 0.0f;
  if (is_upper > 0.0f) {
    const float reach = 1.0f - smoothstep(up + deg(25.0f), up + deg(70.0f), elevation);
    angle += is_upper * reach * (upper * gap + (upper > 0.0f ? upper * overlap : 0.0f));
  }
  if (is_upper < 1.0f) {
    const float reach = 1.0f - smoothstep(-low + deg(20.0f), -low + deg(50.0f), -elevation);
    angle -= (1.0f - is_upper) * reach * lower * gap;
  }
  angle *= near;
  if (angle == 0.0f) return vec3(0.0f);
  return glm::angleAxis(angle, vec3(1, 0, 0)) * q - q;  // a positive turn about +x brings the front down
}

vec3 cheek_puff(const Face& f, const vec3& p) {
  vec3 d(0.0f);
  for (float s : {1.0f, -1.0f})
    d += vec3(s * 0.007f, -0.001f, 0.003f) * f.k * falloff(p, f.mouth(s * 0.042f, 0.0195f, -0.021f), f.v(0.030f, 0.030f, 0.035f));
  return d;
}

struct MorphRecipe {
  std::string name;
  Field field;
};

// A field that moves skin only (the rigid parts stay).
Field soft(std::function<vec3(const vec3&)> on_skin) {
  return [on_skin = std::move(on_skin)](const FacePoint& fp) {
    return fp.part == Part::Soft ? on_skin(fp.p) : vec3(0.0f);
  };
}

std::vector<MorphRecipe> recipes(const Face& f) {
  std::vector<MorphRecipe> r;
  // Visemes shape only the lips and the tongue: the jaw opening of each phoneme is the jaw bone's
  // (face/viseme_track.hpp adds it to jaw_open), so mouthing and expressions never open it twice.
  auto viseme = [&](const char* name, float wide, float round, float press, float tuck, float part, vec3 tongue_move) {
    r.push_back({name, [=, &f](const FacePoint& fp) {
                   if (fp.part == Part::Eyeball) return vec3(0.0f);
                   vec3 d = fp.part == Part::Tongue ? tongue_shift(f, fp.p, tongue_move) : vec3(0.0f);
                   if (fp.part == Part::Soft)
                     d += mouth_wide(f, fp.p, wide) + mouth_round(f, fp.p, round) + mouth_press(f, fp.p, press) +
                          lower_lip_tuck(f, fp.p, tuck) + lips_part(f, fp.p, part);
                   return d;
                 }});
  };
  //       name  wide round press tuck  part  tongue front (m at 1.70 m)
  viseme("sil", 0.0f, 0.0f, 0.3f, 0.0f, 0.0f, vec3(0.0f));
  viseme("PP", 0.0f, 0.1f, 1.0f, 0.0f, 0.0f, vec3(0.0f));
  viseme("FF", 0.2f, 0.0f, 0.0f, 1.0f, 0.3f, vec3(0.0f));
  viseme("TH", 0.2f, 0.0f, 0.0f, 0.0f, 0.6f, vec3(0, 0.009f, 0.016f));
  viseme("DD", 0.3f, 0.0f, 0.0f, 0.0f, 0.5f, vec3(0, 0.006f, 0.004f));
  viseme("kk", 0.3f, 0.0f, 0.0f, 0.0f, 0.5f, vec3(0, 0.003f, -0.002f));
  viseme("CH", 0.0f, 0.6f, 0.0f, 0.0f, 0.6f, vec3(0, 0.004f, 0.0f));
  viseme("SS", 0.6f, 0.0f, 0.0f, 0.0f, 0.5f, vec3(0, 0.002f, 0.002f));
  viseme("nn", 0.2f, 0.0f, 0.0f, 0.0f, 0.4f, vec3(0, 0.006f, 0.003f));
  viseme("RR", 0.0f, 0.4f, 0.0f, 0.0f, 0.5f, vec3(0, 0.003f, -0.002f));
  viseme("aa", 0.1f, 0.0f, 0.0f, 0.0f, 1.0f, vec3(0.0f));
  viseme("E", 0.6f, 0.0f, 0.0f, 0.0f, 0.8f, vec3(0, 0.002f, 0.0f));
  viseme("ih", 0.4f, 0.0f, 0.0f, 0.0f, 0.7f, vec3(0, 0.002f, 0.0f));
  viseme("oh", 0.0f, 0.7f, 0.0f, 0.0f, 0.8f, vec3(0.0f));
  viseme("ou", 0.0f, 1.0f, 0.0f, 0.0f, 0.5f, vec3(0.0f));

  const char* suffix[2] = {"_L", "_R"};
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    const std::string sx = suffix[e];
    r.push_back({"browInnerUp" + sx, soft([=, &f](const vec3& p) { return brow(f, p, s, 0.016f, vec3(0, 0.007f, 0.001f)); })});
  }
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("browOuterUp") + suffix[e],
                 soft([=, &f](const vec3& p) { return brow(f, p, s, 0.046f, vec3(0, 0.007f, 0.0f)); })});
  }
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("browDown") + suffix[e],
                 soft([=, &f](const vec3& p) { return brow(f, p, s, 0.026f, vec3(-s * 0.002f, -0.006f, 0.001f)); })});
  }
  for (int e = 0; e < 2; ++e)
    r.push_back({std::string("eyeBlink") + suffix[e], soft([=, &f](const vec3& p) { return lids(f, p, e, 0.85f, 0.15f); })});
  for (int e = 0; e < 2; ++e)
    r.push_back({std::string("eyeWide") + suffix[e], soft([=, &f](const vec3& p) { return lids(f, p, e, -0.3f, -0.1f); })});
  for (int e = 0; e < 2; ++e)
    r.push_back({std::string("eyeSquint") + suffix[e], soft([=, &f](const vec3& p) { return lids(f, p, e, 0.15f, 0.35f); })});
  r.push_back({"cheekPuff", soft([&f](const vec3& p) { return cheek_puff(f, p); })});
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("mouthSmile") + suffix[e],
                 soft([=, &f](const vec3& p) { return mouth_corner(f, p, s, vec3(s * 0.004f, 0.006f, -0.002f), 1.0f); })});
  }
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("mouthFrown") + suffix[e],
                 soft([=, &f](const vec3& p) { return mouth_corner(f, p, s, vec3(s * 0.001f, -0.005f, 0.0f), 0.0f); })});
  }
  r.push_back({"mouthPucker", soft([&f](const vec3& p) { return mouth_round(f, p, 1.0f); })});
  r.push_back({"mouthPress", soft([&f](const vec3& p) { return mouth_press(f, p, 1.0f); })});
  r.push_back({"mouthOpen", [&f](const FacePoint& fp) {
                 return fp.part == Part::Eyeball ? vec3(0.0f) : jaw_turn(f, fp, 14.0f);
               }});
  // The tongue slides out over the lower teeth and lip as the jaw drops.
  r.push_back({"tongueOut", [&f](const FacePoint& fp) {
                 if (fp.part == Part::Eyeball) return vec3(0.0f);
                 const vec3 shift = fp.part == Part::Tongue ? tongue_shift(f, fp.p, vec3(0, 0.016f, 0.036f)) : vec3(0.0f);
                 return jaw_turn(f, fp, 12.0f, shift);
               }});
  return r;
}

// The expression table: MPEG-4's six universal expressions as morph weights.
struct ExpressionEntry {
  Expression expression;
  std::vector<std::pair<std::string_view, float>> weights;
};

const std::vector<ExpressionEntry>& expression_table() {
  static const std::vector<ExpressionEntry> table{
      {Expression::Neutral, {}},
      {Expression::Joy,
       {{"mouthSmile_L", 1.0f}, {"mouthSmile_R", 1.0f}, {"eyeSquint_L", 0.5f}, {"eyeSquint_R", 0.5f},
        {"mouthOpen", 0.15f}, {"browOuterUp_L", 0.2f}, {"browOuterUp_R", 0.2f}}},
      {Expression::Sadness,
       {{"browInnerUp_L", 0.9f}, {"browInnerUp_R", 0.9f}, {"mouthFrown_L", 0.8f}, {"mouthFrown_R", 0.8f},
        {"eyeBlink_L", 0.25f}, {"eyeBlink_R", 0.25f}, {"mouthPress", 0.3f}}},
      {Expression::Anger,
       {{"browDown_L", 1.0f}, {"browDown_R", 1.0f}, {"eyeSquint_L", 0.5f}, {"eyeSquint_R", 0.5f},
        {"mouthPress", 0.7f}, {"mouthFrown_L", 0.3f}, {"mouthFrown_R", 0.3f}}},
      {Expression::Fear,
       {{"browInnerUp_L", 1.0f}, {"browInnerUp_R", 1.0f}, {"browOuterUp_L", 0.4f}, {"browOuterUp_R", 0.4f},
        {"eyeWide_L", 1.0f}, {"eyeWide_R", 1.0f}, {"mouthOpen", 0.3f}, {"mouthFrown_L", 0.4f}, {"mouthFrown_R", 0.4f}}},
      {Expression::Disgust,
       {{"browDown_L", 0.6f}, {"browDown_R", 0.6f}, {"eyeSquint_L", 0.8f}, {"eyeSquint_R", 0.8f},
        {"mouthFrown_L", 0.6f}, {"mouthFrown_R", 0.6f}, {"mouthPucker", 0.3f}}},
      {Expression::Surprise,
       {{"browInnerUp_L", 1.0f}, {"browInnerUp_R", 1.0f}, {"browOuterUp_L", 1.0f}, {"browOuterUp_R", 1.0f},
        {"eyeWide_L", 1.0f}, {"eyeWide_R", 1.0f}, {"mouthOpen", 0.75f}}},
  };
  return table;
}

}  // namespace

std::vector<MorphTarget> build_face_morphs(const Skeleton& skeleton, const Mesh& mesh, const FaceLandmarks& marks) {
  const float scale = marks.k;
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  auto at = [&](const char* name) {
    const int j = skeleton.find(name);
    if (j < 0) throw Error(std::string("face morphs: skeleton has no joint '") + name + "'");
    return vec3(model[static_cast<std::size_t>(j)][3]);
  };
  Face f{scale, at("temporomandibular"), {at("l_eyeball_joint"), at("r_eyeball_joint")}, marks};
  tabulate_eye_opening(f);
  const int jaw = skeleton.find("temporomandibular");
  if (mesh.materials.size() != mesh.vertex_count() || mesh.weights.size() != mesh.vertex_count())
    throw Error("face morphs: the mesh needs materials and skin weights");
  // Only the head moves: a generous box around the face.
  const vec3 lo = f.v(-0.11f, 1.46f, -0.02f), hi = f.v(0.11f, 1.70f, 0.16f);
  std::vector<std::uint32_t> head;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const vec3& p = mesh.positions[v];
    if (glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi))) head.push_back(static_cast<std::uint32_t>(v));
  }
  std::vector<MorphTarget> out;
  for (const MorphRecipe& recipe : recipes(f)) {
    MorphTarget m;
    m.name = recipe.name;
    for (std::uint32_t v : head) {
      float jaw_weight = 0.0f;
      for (int i = 0; i < 4; ++i)
        if (mesh.joints[v][i] == jaw) jaw_weight += mesh.weights[v][i];
      const vec3 d = recipe.field({mesh.positions[v], jaw_weight, part_of(mesh.materials[v])});
      if (glm::dot(d, d) > 1e-14f) {
        m.vertices.push_back(v);
        m.position_deltas.push_back(d);
      }
    }
    out.push_back(std::move(m));
  }
  return out;
}

void compute_morph_normal_deltas(Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  // Triangles around each vertex, to renormalise only what a morph touches.
  std::vector<std::vector<std::uint32_t>> around(n);
  for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3)
    for (int k = 0; k < 3; ++k) around[mesh.indices[f + k]].push_back(static_cast<std::uint32_t>(f / 3));
  auto vertex_normal = [&](std::uint32_t v, const std::vector<vec3>& pos) {
    vec3 sum(0.0f);
    for (std::uint32_t t : around[v]) {
      const std::uint32_t* i = &mesh.indices[3 * t];
      sum += glm::cross(pos[i[1]] - pos[i[0]], pos[i[2]] - pos[i[0]]);
    }
    return glm::length(sum) > 0.0f ? glm::normalize(sum) : vec3(0.0f);
  };
  std::vector<vec3> moved = mesh.positions;
  for (MorphTarget& m : mesh.morphs) {
    for (std::size_t i = 0; i < m.vertices.size(); ++i) moved[m.vertices[i]] += m.position_deltas[i];
    m.normal_deltas.resize(m.vertices.size());
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      m.normal_deltas[i] = vertex_normal(m.vertices[i], moved) - vertex_normal(m.vertices[i], mesh.positions);
    for (std::uint32_t v : m.vertices) moved[v] = mesh.positions[v];
  }
}

Expression parse_expression(std::string_view name) {
  for (std::size_t i = 0; i < kExpressionNames.size(); ++i)
    if (kExpressionNames[i] == name) return static_cast<Expression>(i);
  throw Error("unknown expression '" + std::string(name) + "' (neutral, joy, sadness, anger, fear, disgust, surprise)");
}

std::vector<std::pair<std::string_view, float>> expression_weights(Expression expression) {
  for (const ExpressionEntry& e : expression_table())
    if (e.expression == expression) return e.weights;
  return {};
}

std::vector<float> expression_morph_weights(const Mesh& mesh, Expression expression, float intensity) {
  std::vector<float> w(mesh.morphs.size(), 0.0f);
  for (auto [name, x] : expression_weights(expression)) {
    const int m = mesh.find_morph(std::string(name));
    if (m >= 0) w[static_cast<std::size_t>(m)] = x * intensity;
  }
  return w;
}

std::vector<vec3> apply_morphs(const Mesh& mesh, const std::vector<float>& weights) {
  if (weights.size() != mesh.morphs.size())
    throw Error("apply_morphs: " + std::to_string(weights.size()) + " weights for " +
                std::to_string(mesh.morphs.size()) + " morph targets");
  std::vector<vec3> out = mesh.positions;
  for (std::size_t m = 0; m < weights.size(); ++m) {
    if (weights[m] == 0.0f) continue;
    const MorphTarget& t = mesh.morphs[m];
    for (std::size_t i = 0; i < t.vertices.size(); ++i) out[t.vertices[i]] += weights[m] * t.position_deltas[i];
  }
  return out;
}

}  // namespace gestura
