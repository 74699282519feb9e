#include "gestura/body/face_morphs.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

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

// Landmarks of the default face, from the skeleton plus fixed proportions (as avatar_volume.cpp).
struct Face {
  float k;
  vec3 jaw;          // temporomandibular joint
  vec3 eye[2];       // [0] left (+X), [1] right
  vec3 v(float x, float y, float z) const { return vec3(x, y, z) * k; }
  float mouth_y() const { return 1.5255f * k; }
};

using Field = std::function<vec3(const vec3&)>;

// --- The deformation vocabulary: every morph is a weighted sum of these ---

// Lower face (below the mouth slit) rotated about the jaw joint: opens the mouth.
vec3 jaw_open(const Face& f, const vec3& p, float degrees) {
  const float below = smoothstep(f.mouth_y() + 0.002f * f.k, f.mouth_y() - 0.004f * f.k, p.y);
  const float reach = falloff(p, f.v(0, 1.505f, 0.055f), f.v(0.075f, 0.060f, 0.080f));
  const float w = below * std::min(1.0f, 2.0f * reach);
  if (w <= 0.0f) return vec3(0.0f);
  const quat r = glm::angleAxis(deg(degrees), vec3(1, 0, 0));
  return (r * (p - f.jaw) + f.jaw - p) * w;
}

// Mouth corners out (+) or in (−) along x, lips stretched thin.
vec3 mouth_wide(const Face& f, const vec3& p, float amount) {
  vec3 d(0.0f);
  for (float s : {1.0f, -1.0f})
    d += vec3(s * 0.006f * f.k * amount, 0, -0.002f * f.k * amount) *
         falloff(p, f.v(s * 0.025f, 1.527f, 0.091f), f.v(0.026f, 0.020f, 0.025f));
  return d;
}

// Lips gathered towards the mouth centre and pushed forward.
vec3 mouth_round(const Face& f, const vec3& p, float amount) {
  const vec3 c = f.v(0, 1.5255f, 0.100f);
  const float w = falloff(p, c, f.v(0.040f, 0.028f, 0.035f));
  if (w <= 0.0f) return vec3(0.0f);
  return vec3(-(p.x - c.x) * 0.45f, -(p.y - c.y) * 0.2f, 0.008f * f.k) * (w * amount);
}

// Lips pressed together: the upper lip down, the lower up, both slightly in.
vec3 mouth_press(const Face& f, const vec3& p, float amount) {
  const vec3 up = f.v(0, 1.533f, 0.100f), lo = f.v(0, 1.518f, 0.099f);
  const vec3 r = f.v(0.030f, 0.010f, 0.020f);
  return (vec3(0, -0.0025f * f.k, -0.0015f * f.k) * falloff(p, up, r) +
          vec3(0, 0.0030f * f.k, -0.0010f * f.k) * falloff(p, lo, r)) *
         amount;
}

// Lower lip tucked up and back under the upper teeth (F, V).
vec3 lower_lip_tuck(const Face& f, const vec3& p, float amount) {
  return vec3(0, 0.004f * f.k, -0.005f * f.k) * falloff(p, f.v(0, 1.517f, 0.099f), f.v(0.028f, 0.010f, 0.020f)) * amount;
}

// Tongue forward (+z) and up (+y).
vec3 tongue(const Face& f, const vec3& p, vec3 move) {
  return move * f.k * falloff(p, f.v(0, 1.5205f, 0.086f), f.v(0.018f, 0.007f, 0.016f));
}

// Corner of the mouth up/out (smile) or down (frown) on one side, with the cheek following.
vec3 mouth_corner(const Face& f, const vec3& p, float side, vec3 move, float cheek) {
  return move * f.k * falloff(p, f.v(side * 0.025f, 1.527f, 0.091f), f.v(0.022f, 0.018f, 0.022f)) +
         vec3(0, 0.003f, 0.0015f) * (f.k * cheek) * falloff(p, f.v(side * 0.040f, 1.562f, 0.082f), f.v(0.026f, 0.022f, 0.025f));
}

vec3 brow(const Face& f, const vec3& p, float side, float x, vec3 move) {
  return move * f.k * falloff(p, f.v(side * x, 1.630f, 0.086f), f.v(0.022f, 0.020f, 0.030f));
}

// Squash the eye opening towards a line: the upper lid comes down (amount > 0) or goes up (< 0).
vec3 upper_lid(const Face& f, const vec3& p, int eye, float amount) {
  const vec3 e = f.eye[eye];
  const float lateral = falloff(vec3(p.x, e.y, p.z), vec3(e.x, e.y, e.z + 0.012f * f.k), f.v(0.022f, 1.0f, 0.016f));
  if (lateral <= 0.0f) return vec3(0.0f);
  const float base = e.y - 0.0055f * f.k;  // just above the lower lid
  const float h = p.y - base;
  if (h <= 0.0f) return vec3(0.0f);
  const float taper = 1.0f - smoothstep(0.010f * f.k, 0.022f * f.k, h);
  return vec3(0, -h * 0.92f, 0.002f * f.k * smoothstep(0.0f, 0.008f * f.k, h)) * (lateral * taper * amount);
}

vec3 lower_lid(const Face& f, const vec3& p, int eye, float amount) {
  const vec3 e = f.eye[eye];
  return vec3(0, 0.003f * f.k, 0.001f * f.k) * amount *
         falloff(p, e + vec3(0, -0.012f, 0.010f) * f.k, f.v(0.022f, 0.012f, 0.018f));
}

vec3 cheek_puff(const Face& f, const vec3& p) {
  vec3 d(0.0f);
  for (float s : {1.0f, -1.0f})
    d += vec3(s * 0.007f, -0.001f, 0.003f) * f.k * falloff(p, f.v(s * 0.042f, 1.545f, 0.070f), f.v(0.030f, 0.030f, 0.035f));
  return d;
}

struct MorphRecipe {
  std::string name;
  Field field;
};

std::vector<MorphRecipe> recipes(const Face& f) {
  std::vector<MorphRecipe> r;
  auto viseme = [&](const char* name, float open, float wide, float round, float press, float tuck, vec3 tongue_move) {
    r.push_back({name, [=, &f](const vec3& p) {
                   return jaw_open(f, p, open) + mouth_wide(f, p, wide) + mouth_round(f, p, round) +
                          mouth_press(f, p, press) + lower_lip_tuck(f, p, tuck) + tongue(f, p, tongue_move);
                 }});
  };
  //       name  jaw°  wide round press tuck  tongue (m at 1.70 m)
  viseme("sil", 0.0f, 0.0f, 0.0f, 0.3f, 0.0f, vec3(0.0f));
  viseme("PP", 0.0f, 0.0f, 0.1f, 1.0f, 0.0f, vec3(0.0f));
  viseme("FF", 3.0f, 0.2f, 0.0f, 0.0f, 1.0f, vec3(0.0f));
  viseme("TH", 6.0f, 0.2f, 0.0f, 0.0f, 0.0f, vec3(0, 0.001f, 0.010f));
  viseme("DD", 7.0f, 0.3f, 0.0f, 0.0f, 0.0f, vec3(0, 0.003f, 0.004f));
  viseme("kk", 9.0f, 0.3f, 0.0f, 0.0f, 0.0f, vec3(0, 0.002f, -0.002f));
  viseme("CH", 5.0f, 0.0f, 0.6f, 0.0f, 0.0f, vec3(0, 0.002f, 0.0f));
  viseme("SS", 3.0f, 0.6f, 0.0f, 0.0f, 0.0f, vec3(0.0f));
  viseme("nn", 6.0f, 0.2f, 0.0f, 0.0f, 0.0f, vec3(0, 0.003f, 0.003f));
  viseme("RR", 6.0f, 0.0f, 0.4f, 0.0f, 0.0f, vec3(0, 0.002f, -0.002f));
  viseme("aa", 16.0f, 0.1f, 0.0f, 0.0f, 0.0f, vec3(0.0f));
  viseme("E", 10.0f, 0.6f, 0.0f, 0.0f, 0.0f, vec3(0.0f));
  viseme("ih", 8.0f, 0.4f, 0.0f, 0.0f, 0.0f, vec3(0.0f));
  viseme("oh", 12.0f, 0.0f, 0.7f, 0.0f, 0.0f, vec3(0.0f));
  viseme("ou", 6.0f, 0.0f, 1.0f, 0.0f, 0.0f, vec3(0.0f));

  const char* suffix[2] = {"_L", "_R"};
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    const std::string sx = suffix[e];
    r.push_back({"browInnerUp" + sx, [=, &f](const vec3& p) { return brow(f, p, s, 0.016f, vec3(0, 0.007f, 0.001f)); }});
  }
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("browOuterUp") + suffix[e],
                 [=, &f](const vec3& p) { return brow(f, p, s, 0.046f, vec3(0, 0.007f, 0.0f)); }});
  }
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("browDown") + suffix[e],
                 [=, &f](const vec3& p) { return brow(f, p, s, 0.026f, vec3(-s * 0.002f, -0.006f, 0.001f)); }});
  }
  for (int e = 0; e < 2; ++e)
    r.push_back({std::string("eyeBlink") + suffix[e], [=, &f](const vec3& p) { return upper_lid(f, p, e, 1.0f); }});
  for (int e = 0; e < 2; ++e)
    r.push_back({std::string("eyeWide") + suffix[e], [=, &f](const vec3& p) { return upper_lid(f, p, e, -0.25f); }});
  for (int e = 0; e < 2; ++e)
    r.push_back({std::string("eyeSquint") + suffix[e],
                 [=, &f](const vec3& p) { return lower_lid(f, p, e, 1.0f) + upper_lid(f, p, e, 0.25f); }});
  r.push_back({"cheekPuff", [&f](const vec3& p) { return cheek_puff(f, p); }});
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("mouthSmile") + suffix[e],
                 [=, &f](const vec3& p) { return mouth_corner(f, p, s, vec3(s * 0.004f, 0.006f, -0.002f), 1.0f); }});
  }
  for (int e = 0; e < 2; ++e) {
    const float s = e == 0 ? 1.0f : -1.0f;
    r.push_back({std::string("mouthFrown") + suffix[e],
                 [=, &f](const vec3& p) { return mouth_corner(f, p, s, vec3(s * 0.001f, -0.005f, 0.0f), 0.0f); }});
  }
  r.push_back({"mouthPucker", [&f](const vec3& p) { return mouth_round(f, p, 1.0f); }});
  r.push_back({"mouthPress", [&f](const vec3& p) { return mouth_press(f, p, 1.0f); }});
  r.push_back({"mouthOpen", [&f](const vec3& p) { return jaw_open(f, p, 14.0f); }});
  r.push_back({"tongueOut", [&f](const vec3& p) { return jaw_open(f, p, 8.0f) + tongue(f, p, vec3(0, 0.0f, 0.018f)); }});
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

std::vector<MorphTarget> build_face_morphs(const Skeleton& skeleton, const Mesh& mesh, float scale) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  auto at = [&](const char* name) {
    const int j = skeleton.find(name);
    if (j < 0) throw Error(std::string("face morphs: skeleton has no joint '") + name + "'");
    return vec3(model[static_cast<std::size_t>(j)][3]);
  };
  Face f{scale, at("temporomandibular"), {at("l_eyeball_joint"), at("r_eyeball_joint")}};
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
      const vec3 d = recipe.field(mesh.positions[v]);
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
