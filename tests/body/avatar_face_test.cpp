// The default avatar's face: teeth and tongue in the mouth, lids over rigid eyeballs, clean lips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/body_sites.hpp"
#include "gestura/body/face_morphs.hpp"

using namespace gestura;

namespace {

const Avatar& avatar() {
  static const Avatar a = build_avatar();
  return a;
}

MaterialId material(const Mesh& m, std::size_t v) { return static_cast<MaterialId>(m.materials[v]); }

bool is_eyeball(MaterialId id) { return id == MaterialId::EyeWhite || id == MaterialId::Iris || id == MaterialId::Pupil; }

vec3 joint_position(const Avatar& a, const char* name) {
  const int j = a.skeleton.find(name);
  EXPECT_GE(j, 0) << name;
  return rest_joint_positions(a.skeleton)[static_cast<std::size_t>(j)];
}

float weight_of(const Mesh& mesh, std::size_t v, int joint) {
  float w = 0.0f;
  for (int k = 0; k < 4; ++k)
    if (mesh.joints[v][k] == joint) w += mesh.weights[v][k];
  return w;
}

std::vector<vec3> morphed(const Mesh& m, std::initializer_list<std::pair<const char*, float>> weights) {
  std::vector<float> w(m.morphs.size(), 0.0f);
  for (auto [name, x] : weights) {
    const int i = m.find_morph(name);
    EXPECT_GE(i, 0) << name;
    w[static_cast<std::size_t>(i)] = x;
  }
  return apply_morphs(m, w);
}

// The material at the first surface a ray meets (that of the hit triangle's vertex nearest to the
// hit), or nothing.
std::optional<MaterialId> first_hit(const Mesh& m, const std::vector<vec3>& positions, vec3 origin, vec3 dir) {
  float best = 1e9f;
  std::optional<MaterialId> out;
  for (std::size_t f = 0; f < m.indices.size(); f += 3) {
    const vec3 a = positions[m.indices[f]], b = positions[m.indices[f + 1]], c = positions[m.indices[f + 2]];
    const vec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14f) continue;
    const vec3 s = origin - a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f) continue;
    const vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) / det;
    if (v < 0.0f || u + v > 1.0f) continue;
    const float t = glm::dot(e2, q) / det;
    if (t <= 0.0f || t >= best) continue;
    best = t;
    const float bary[3] = {1.0f - u - v, u, v};
    const int corner = static_cast<int>(std::max_element(bary, bary + 3) - bary);
    out = material(m, m.indices[f + static_cast<std::size_t>(corner)]);
  }
  return out;
}

// Front-most z of the lips at rest, near the mouth's middle.
float lip_front(const Mesh& m) {
  float z = -1.0f;
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    if (material(m, v) == MaterialId::Lips && std::abs(m.positions[v].x) < 0.01f) z = std::max(z, m.positions[v].z);
  return z;
}

}  // namespace

TEST(AvatarFace, TeethAndTongueSitInTheMouthBehindClosedLips) {
  const Avatar& a = avatar();
  const Mesh& m = a.mesh;
  const int skull = a.skeleton.find("skullbase"), jaw = a.skeleton.find("temporomandibular");
  const vec3 jaw_joint = joint_position(a, "temporomandibular");
  const float lips = lip_front(m);
  ASSERT_GT(lips, 0.09f);
  float upper_lowest = 1e9f, lower_highest = -1e9f, upper_mean = 0.0f, lower_mean = 0.0f;
  int upper = 0, lower = 0, tongue = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const MaterialId id = material(m, v);
    if (id != MaterialId::Teeth && id != MaterialId::Tongue) continue;
    const vec3 p = m.positions[v];
    // Inside the head, in front of the jaw joint, behind the lips, within the mouth's width.
    EXPECT_LT(std::abs(p.x), 0.03f);
    EXPECT_GT(p.z, jaw_joint.z);
    EXPECT_LT(p.z, lips - 0.008f) << "behind the lips";
    EXPECT_GT(p.y, 1.49f);
    EXPECT_LT(p.y, 1.55f);
    if (id == MaterialId::Tongue) {
      ++tongue;
      EXPECT_FLOAT_EQ(weight_of(m, v, jaw), 1.0f) << "the tongue rides the jaw";
    } else if (weight_of(m, v, skull) == 1.0f) {
      ++upper, upper_lowest = std::min(upper_lowest, p.y), upper_mean += p.y;
    } else {
      EXPECT_FLOAT_EQ(weight_of(m, v, jaw), 1.0f) << "teeth ride the skull or the jaw";
      ++lower, lower_highest = std::max(lower_highest, p.y), lower_mean += p.y;
    }
  }
  ASSERT_GT(upper, 50);
  ASSERT_GT(lower, 50);
  ASSERT_GT(tongue, 30);
  // Upper teeth above the mouth line, lower below it, overlapping by a bite of a few millimetres.
  EXPECT_GT(upper_mean / static_cast<float>(upper), 1.5255f + 0.003f);
  EXPECT_LT(lower_mean / static_cast<float>(lower), 1.5255f - 0.003f);
  EXPECT_LT(upper_lowest, lower_highest);
  EXPECT_GT(upper_lowest, lower_highest - 0.005f);

  // With the mouth closed, the lips hide them: rays from the front across the mouth meet skin or
  // lips, at most the dark line where the lips meet, never teeth or tongue.
  int covered = 0, rays = 0;
  for (float x = -0.012f; x <= 0.0121f; x += 0.004f)
    for (float y = 1.515f; y <= 1.5361f; y += 0.003f) {
      const auto hit = first_hit(m, m.positions, vec3(x, y, 0.3f), vec3(0, 0, -1));
      ASSERT_TRUE(hit);
      ++rays;
      covered += *hit == MaterialId::Skin || *hit == MaterialId::Lips;
      EXPECT_NE(*hit, MaterialId::Teeth) << x << " " << y;
      EXPECT_NE(*hit, MaterialId::Tongue) << x << " " << y;
    }
  EXPECT_GE(covered, rays * 9 / 10);
}

TEST(AvatarFace, OpeningTheMouthShowsTeethTongueAndTheDarkCavity) {
  const Mesh& m = avatar().mesh;
  const auto open = morphed(m, {{"mouthOpen", 1.0f}});
  std::set<MaterialId> seen;
  for (float x = -0.012f; x <= 0.0121f; x += 0.002f)
    for (float y = 1.500f; y <= 1.5301f; y += 0.0015f)
      if (const auto hit = first_hit(m, open, vec3(x, y, 0.3f), vec3(0, 0, -1))) seen.insert(*hit);
  EXPECT_TRUE(seen.count(MaterialId::Teeth));
  EXPECT_TRUE(seen.count(MaterialId::Tongue));
  EXPECT_TRUE(seen.count(MaterialId::Mouth));
}

TEST(AvatarFace, TheJawBoneAndTheOpenMorphMoveLowerTeethAndTongueButNotTheUpperTeeth) {
  const Avatar& a = avatar();
  const Mesh& m = a.mesh;
  const int skull = a.skeleton.find("skullbase");
  const vec3 jaw = joint_position(a, "temporomandibular");
  const auto open = morphed(m, {{"mouthOpen", 1.0f}});
  float lower_front = -1.0f;  // the lower incisors' labial face
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    if (material(m, v) == MaterialId::Teeth && weight_of(m, v, skull) < 1.0f) lower_front = std::max(lower_front, m.positions[v].z);
  float incisor_drop = 0.0f;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const MaterialId id = material(m, v);
    if (id == MaterialId::Teeth && weight_of(m, v, skull) == 1.0f) {
      EXPECT_EQ(open[v], m.positions[v]) << "upper teeth stay";
    } else if (id == MaterialId::Teeth || id == MaterialId::Tongue) {
      // Lower teeth and tongue turn rigidly about the jaw joint, downwards in front.
      EXPECT_NEAR(glm::distance(open[v], jaw), glm::distance(m.positions[v], jaw), 1e-5f);
      EXPECT_NE(open[v], m.positions[v]);
      if (id == MaterialId::Teeth && m.positions[v].z > lower_front - 0.004f)
        incisor_drop = std::max(incisor_drop, m.positions[v].y - open[v].y);
    }
  }
  EXPECT_GT(incisor_drop, 0.009f) << "the lower incisors drop about a centimetre";
}

TEST(AvatarFace, TongueOutPushesTheTipPastTheLips) {
  const Mesh& m = avatar().mesh;
  const auto out = morphed(m, {{"tongueOut", 1.0f}});
  float tip_rest = -1.0f, tip_out = -1.0f, lower_teeth_front = -1.0f;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    if (material(m, v) == MaterialId::Teeth && m.positions[v].y < 1.5255f)
      lower_teeth_front = std::max(lower_teeth_front, m.positions[v].z);
    if (material(m, v) != MaterialId::Tongue) continue;
    tip_rest = std::max(tip_rest, m.positions[v].z);
    tip_out = std::max(tip_out, out[v].z);
  }
  EXPECT_LT(tip_rest, lower_teeth_front) << "at rest the tongue lies behind the lower teeth";
  EXPECT_GT(tip_out, lip_front(m) + 0.002f) << "out: past the lips";
  // …and it is seen from the front, between the lips.
  bool seen = false;
  for (float y = 1.505f; y <= 1.530f; y += 0.001f) {
    const auto hit = first_hit(m, out, vec3(0.0f, y, 0.3f), vec3(0, 0, -1));
    seen = seen || (hit && *hit == MaterialId::Tongue);
  }
  EXPECT_TRUE(seen);
}

TEST(AvatarFace, EyeballsAreRigidOnTheirEyeJoints) {
  const Avatar& a = avatar();
  const Mesh& m = a.mesh;
  const char* joints[2] = {"l_eyeball_joint", "r_eyeball_joint"};
  int count[2] = {0, 0};
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    if (!is_eyeball(material(m, v))) continue;
    const int side = m.positions[v].x > 0.0f ? 0 : 1;
    ++count[side];
    EXPECT_FLOAT_EQ(weight_of(m, v, a.skeleton.find(joints[side])), 1.0f) << "gaze turns the whole eyeball";
    EXPECT_NEAR(glm::distance(m.positions[v], joint_position(a, joints[side])), 0.013f, 0.0005f) << "a sphere";
  }
  EXPECT_GT(count[0], 50);
  EXPECT_EQ(count[0], count[1]);
  // No morph deforms an eyeball.
  for (const MorphTarget& t : m.morphs)
    for (std::uint32_t v : t.vertices) ASSERT_FALSE(is_eyeball(material(m, v))) << t.name;
}

TEST(AvatarFace, BlinkSlidesTheLidOverTheEye) {
  const Avatar& a = avatar();
  const Mesh& m = a.mesh;
  for (const char* side : {"l_", "r_"}) {
    const vec3 eye = joint_position(a, (std::string(side) + "eyeball_joint").c_str());
    const std::string blink = std::string("eyeBlink_") + (side[0] == 'l' ? "L" : "R");
    const auto closed = morphed(m, {{blink.c_str(), 1.0f}});
    // Rays from the front through the pupil and round the iris.
    std::vector<vec3> targets{eye};
    for (int i = 0; i < 8; ++i) {
      const float t = glm::two_pi<float>() * static_cast<float>(i) / 8.0f;
      targets.push_back(eye + 0.004f * vec3(std::cos(t), std::sin(t), 0.0f));
    }
    const auto pupil = first_hit(m, m.positions, eye + vec3(0, 0, 0.3f), vec3(0, 0, -1));
    ASSERT_TRUE(pupil);
    EXPECT_EQ(*pupil, MaterialId::Pupil) << side << " open: the pupil is seen";
    int iris_seen = 0;
    for (const vec3& target : targets) {
      const auto open_hit = first_hit(m, m.positions, target + vec3(0, 0, 0.3f), vec3(0, 0, -1));
      iris_seen += open_hit && is_eyeball(*open_hit);
      const auto hit = first_hit(m, closed, target + vec3(0, 0, 0.3f), vec3(0, 0, -1));
      ASSERT_TRUE(hit);
      // The lid's skin, or the lashes along its margin (the brows' material).
      EXPECT_TRUE(*hit == MaterialId::Skin || *hit == MaterialId::Brow) << side << " closed: the lid covers the eye";
    }
    EXPECT_GE(iris_seen, 7) << side;
  }
}

TEST(AvatarFace, LipsAreOneCleanRegion) {
  const Mesh& m = avatar().mesh;
  // Lip vertices joined along mesh edges form at most the upper and the lower lip (here one ring
  // through the corners), with no stray lip-coloured vertices elsewhere.
  std::vector<std::uint32_t> parent(m.vertex_count());
  for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
  auto root = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  auto lip = [&](std::uint32_t v) { return material(m, v) == MaterialId::Lips; };
  for (std::size_t f = 0; f < m.indices.size(); f += 3)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.indices[f + static_cast<std::size_t>(i)], b = m.indices[f + static_cast<std::size_t>((i + 1) % 3)];
      if (lip(a) && lip(b)) parent[root(a)] = root(b);
    }
  std::map<std::uint32_t, int> regions;
  int lips = 0;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
    if (lip(v)) {
      ++lips;
      ++regions[root(v)];
      EXPECT_LT(std::abs(m.positions[v].x), 0.032f);
      EXPECT_NEAR(m.positions[v].y, 1.5255f, 0.015f);
    }
  EXPECT_GT(lips, 40);
  EXPECT_LE(regions.size(), 2u) << "lip colour in patches";
}

TEST(AvatarFace, FaceSitesLieOnTheOuterSurfaceNotOnWhatIsInside) {
  const Avatar& a = avatar();
  const auto sites = find_body_sites(a.skeleton, a.mesh);
  std::vector<mat4> model(a.skeleton.size());
  local_to_model(a.skeleton, rest_pose(a.skeleton), model);
  float inside_front = -1.0f;  // the front-most tooth or tongue vertex
  for (std::size_t v = 0; v < a.mesh.vertex_count(); ++v)
    if (material(a.mesh, v) == MaterialId::Teeth || material(a.mesh, v) == MaterialId::Tongue)
      inside_front = std::max(inside_front, a.mesh.positions[v].z);
  for (const char* name : {"upper_lip", "lips", "lower_lip"}) {
    const BodySite* site = find_site(sites, name);
    ASSERT_NE(site, nullptr) << name;
    // The lips stand 5–6 mm in front of the incisors where they meet, over 10 mm at their fullest.
    EXPECT_GT(site_position(*site, model).z, inside_front + 0.005f) << name << " lies on the lips, in front of the teeth";
  }
  for (const char* side : {"l_", "r_"}) {
    const BodySite* site = find_site(sites, std::string(side) + "eye");
    ASSERT_NE(site, nullptr) << side;
    const vec3 eye = joint_position(a, (std::string(side) + "eyeball_joint").c_str());
    EXPECT_NEAR(site_position(*site, model).z, eye.z + 0.013f, 0.001f) << side << "eye: the front of the eyeball";
  }
}

// How jagged the lips are: at each lip vertex, the distance from the centre of its neighbours
// (the umbrella vector) over their mean distance. On a smooth, evenly sampled surface this is
// small (the curvature over the edge length); facets and spikes at the slit and the corners make
// it large. Mean and 90th percentile over the lip vertices.
TEST(AvatarFace, LipsAreSmooth) {
  const Mesh& m = avatar().mesh;
  std::vector<std::set<std::uint32_t>> ring(m.vertex_count());
  for (std::size_t f = 0; f + 2 < m.indices.size(); f += 3)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.indices[f + static_cast<std::size_t>(i)], b = m.indices[f + static_cast<std::size_t>((i + 1) % 3)];
      ring[a].insert(b), ring[b].insert(a);
    }
  std::vector<float> rough;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    if (material(m, v) != MaterialId::Lips || ring[v].size() < 3) continue;
    vec3 centre(0.0f);
    float spacing = 0.0f;
    for (std::uint32_t u : ring[v]) centre += m.positions[u], spacing += glm::length(m.positions[u] - m.positions[v]);
    centre /= static_cast<float>(ring[v].size());
    spacing /= static_cast<float>(ring[v].size());
    if (spacing > 0.0f) rough.push_back(glm::length(m.positions[v] - centre) / spacing);
  }
  ASSERT_GT(rough.size(), 40u);
  std::sort(rough.begin(), rough.end());
  float mean = 0.0f;
  for (float r : rough) mean += r;
  mean /= static_cast<float>(rough.size());
  const float p90 = rough[rough.size() * 9 / 10];
  std::printf("lips: %zu vertices, umbrella/spacing mean %.3f, 90th percentile %.3f, max %.3f\n", rough.size(), mean, p90,
              rough.back());
  // Before the lips were smoothed (Taubin, the meeting line kept): mean 0.365, 90th percentile 0.561,
  // max 0.934; after: 0.200, 0.402, 0.602.
  EXPECT_LT(mean, 0.25f);
  EXPECT_LT(p90, 0.45f);
}
