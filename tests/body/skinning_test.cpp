#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gestura/body/morph.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

constexpr SkinningPath kPaths[] = {SkinningPath::Portable, SkinningPath::Avx2};

bool available(SkinningPath path) { return path != SkinningPath::Avx2 || cpu_has_avx2_fma(); }

void expect_near(const vec3& a, const vec3& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// A random cloud of vertices with up to four random influences over `joints` joints.
struct Cloud {
  std::vector<vec3> positions, normals;
  std::vector<JointIndices> joints;
  std::vector<vec4> weights;
};

Cloud random_cloud(std::size_t count, int joint_count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_int_distribution<int> pick(0, joint_count - 1);
  Cloud c;
  for (std::size_t v = 0; v < count; ++v) {
    c.positions.push_back(vec3(u(rng), u(rng) + 1.0f, u(rng)));
    c.normals.push_back(glm::normalize(vec3(u(rng), u(rng), u(rng)) + vec3(0.0f, 0.0f, 2.0f)));
    c.joints.push_back(JointIndices(pick(rng), pick(rng), pick(rng), pick(rng)));
    vec4 w(std::abs(u(rng)), std::abs(u(rng)), std::abs(u(rng)), v % 3 == 0 ? 0.0f : std::abs(u(rng)));
    c.weights.push_back(w / (w.x + w.y + w.z + w.w));
  }
  return c;
}

std::vector<mat4> random_pose_matrices(int joint_count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<mat4> m;
  for (int j = 0; j < joint_count; ++j) {
    const quat r = glm::angleAxis(u(rng) * 0.6f, glm::normalize(vec3(u(rng), u(rng), u(rng)) + vec3(0.01f)));
    m.push_back(Transform{vec3(u(rng), u(rng), u(rng)) * 0.2f, r, vec3(1.0f)}.matrix());
  }
  return m;
}

}  // namespace

TEST(Skinning, IdentityMatricesReproduceTheRestMesh) {
  const Cloud c = random_cloud(101, 5, 1);
  const std::vector<mat4> identity(5, mat4(1.0f));
  std::vector<DualQuat> dq(5);
  skinning_dual_quaternions(identity, dq);
  for (SkinningPath path : kPaths) {
    if (!available(path)) continue;
    std::vector<vec3> p(c.positions.size()), n(c.positions.size()), p2(p.size()), n2(p.size());
    skin_positions_normals(identity, c.joints, c.weights, c.positions, c.normals, p, n, path);
    skin_dual_quaternion(dq, c.joints, c.weights, c.positions, c.normals, p2, n2, path);
    for (std::size_t v = 0; v < p.size(); ++v) {
      expect_near(p[v], c.positions[v]);
      expect_near(n[v], c.normals[v]);
      expect_near(p2[v], c.positions[v]);
      expect_near(n2[v], c.normals[v]);
    }
  }
}

TEST(Skinning, LbsAndDqsAgreeOnRigidSingleInfluence) {
  Cloud c = random_cloud(64, 4, 2);
  for (std::size_t v = 0; v < c.weights.size(); ++v) {
    c.weights[v] = vec4(1.0f, 0.0f, 0.0f, 0.0f);  // other slots keep their (irrelevant) joints
  }
  const std::vector<mat4> skin = random_pose_matrices(4, 3);
  std::vector<DualQuat> dq(4);
  skinning_dual_quaternions(skin, dq);
  for (SkinningPath path : kPaths) {
    if (!available(path)) continue;
    std::vector<vec3> p(64), n(64), p2(64), n2(64);
    skin_positions_normals(skin, c.joints, c.weights, c.positions, c.normals, p, n, path);
    skin_dual_quaternion(dq, c.joints, c.weights, c.positions, c.normals, p2, n2, path);
    for (std::size_t v = 0; v < 64; ++v) {
      const mat4& m = skin[c.joints[v].x];
      expect_near(p[v], vec3(m * vec4(c.positions[v], 1.0f)));
      expect_near(p2[v], p[v]);
      expect_near(n2[v], n[v]);
    }
  }
}

TEST(Skinning, TwoJointsHalfAndHalfByHand) {
  // Joint 0 stays; joint 1 turns 90° about +Z around the point (1, 0, 0).
  // Vertex (2, 0, 0): under joint 0 it stays at (2, 0, 0); under joint 1 it goes to (1, 1, 0).
  // LBS with 0.5/0.5 averages the two: (1.5, 0.5, 0).
  // DQS blends the motions instead: half of the identity and half of the 90° turn is a 45° turn about
  // the same pivot, which takes (2, 0, 0) to (1 + cos45°, sin45°, 0).
  const mat4 pivot_turn = glm::translate(mat4(1.0f), vec3(1, 0, 0)) *
                          glm::rotate(mat4(1.0f), kPi / 2.0f, vec3(0, 0, 1)) *
                          glm::translate(mat4(1.0f), vec3(-1, 0, 0));
  const std::vector<mat4> skin{mat4(1.0f), pivot_turn};
  std::vector<DualQuat> dq(2);
  skinning_dual_quaternions(skin, dq);
  const std::vector<vec3> rest{vec3(2, 0, 0)};
  const std::vector<vec3> normal{vec3(1, 0, 0)};
  const std::vector<JointIndices> joints{JointIndices(0, 1, 0, 0)};
  const std::vector<vec4> weights{vec4(0.5f, 0.5f, 0.0f, 0.0f)};
  const float h = std::sqrt(0.5f);
  for (SkinningPath path : kPaths) {
    if (!available(path)) continue;
    std::vector<vec3> p(1), n(1);
    skin_positions_normals(skin, joints, weights, rest, normal, p, n, path);
    expect_near(p[0], vec3(1.5f, 0.5f, 0.0f));
    expect_near(n[0], vec3(h, h, 0.0f));  // (1,0,0) and (0,1,0) averaged, renormalised
    skin_dual_quaternion(dq, joints, weights, rest, normal, p, n, path);
    expect_near(p[0], vec3(1.0f + h, h, 0.0f));
    expect_near(n[0], vec3(h, h, 0.0f));
  }
}

TEST(Skinning, NormalsStayUnitAndRotate) {
  const Cloud c = random_cloud(200, 6, 4);
  const std::vector<mat4> skin = random_pose_matrices(6, 5);
  std::vector<DualQuat> dq(6);
  skinning_dual_quaternions(skin, dq);
  for (SkinningPath path : kPaths) {
    if (!available(path)) continue;
    std::vector<vec3> p(200), n(200), n2(200);
    skin_positions_normals(skin, c.joints, c.weights, c.positions, c.normals, p, n, path);
    skin_dual_quaternion(dq, c.joints, c.weights, c.positions, c.normals, p, n2, path);
    int rotated = 0;
    for (std::size_t v = 0; v < 200; ++v) {
      EXPECT_NEAR(glm::length(n[v]), 1.0f, 1e-5f);
      EXPECT_NEAR(glm::length(n2[v]), 1.0f, 1e-5f);
      rotated += glm::dot(n[v], c.normals[v]) < 0.999f;
    }
    EXPECT_GT(rotated, 150);
  }
  // A pure 90° turn about +Y takes +Z to +X.
  const std::vector<mat4> turn{glm::rotate(mat4(1.0f), kPi / 2.0f, vec3(0, 1, 0))};
  const std::vector<vec3> rest{vec3(0, 1, 0)}, normal{vec3(0, 0, 1)};
  const std::vector<JointIndices> j{JointIndices(0)};
  const std::vector<vec4> w{vec4(1, 0, 0, 0)};
  std::vector<vec3> p(1), n(1);
  skin_positions_normals(turn, j, w, rest, normal, p, n);
  expect_near(n[0], vec3(1, 0, 0));
}

TEST(Skinning, Avx2AndPortableAgree) {
  if (!cpu_has_avx2_fma()) GTEST_SKIP() << "CPU without AVX2+FMA";
  const Cloud c = random_cloud(1003, 20, 6);  // odd count: exercises the tail
  const std::vector<mat4> skin = random_pose_matrices(20, 7);
  std::vector<DualQuat> dq(20);
  skinning_dual_quaternions(skin, dq);
  std::vector<vec3> pa(1003), na(1003), pb(1003), nb(1003), qa(1003), qb(1003);
  skin_positions(skin, c.joints, c.weights, c.positions, pa, SkinningPath::Portable);
  skin_positions(skin, c.joints, c.weights, c.positions, pb, SkinningPath::Avx2);
  for (std::size_t v = 0; v < pa.size(); ++v) expect_near(pa[v], pb[v]);
  skin_positions_normals(skin, c.joints, c.weights, c.positions, c.normals, pa, na, SkinningPath::Portable);
  skin_positions_normals(skin, c.joints, c.weights, c.positions, c.normals, pb, nb, SkinningPath::Avx2);
  for (std::size_t v = 0; v < pa.size(); ++v) {
    expect_near(pa[v], pb[v]);
    expect_near(na[v], nb[v]);
  }
  skin_dual_quaternion(dq, c.joints, c.weights, c.positions, c.normals, pa, na, SkinningPath::Portable);
  skin_dual_quaternion(dq, c.joints, c.weights, c.positions, c.normals, pb, nb, SkinningPath::Avx2);
  skin_dual_quaternion(dq, c.joints, c.weights, c.positions, {}, qa, {}, SkinningPath::Avx2);
  for (std::size_t v = 0; v < pa.size(); ++v) {
    expect_near(pa[v], pb[v]);
    expect_near(na[v], nb[v]);
    expect_near(qa[v], pb[v]);
  }
}

TEST(Skinning, DqsHandlesAntipodalQuaternions) {
  // The same rotation stored as q and −q on two joints must blend to that rotation, not cancel.
  // Nine vertices: the AVX2 path does eight at a time and the rest one by one.
  const mat4 turn = glm::translate(mat4(1.0f), vec3(0.1f, 0.0f, 0.2f)) * glm::rotate(mat4(1.0f), 0.7f, vec3(0, 1, 0));
  std::vector<DualQuat> dq(2);
  skinning_dual_quaternions(std::vector<mat4>{turn, turn}, dq);
  dq[1].real = -dq[1].real;
  dq[1].dual = -dq[1].dual;
  std::vector<vec3> rest, normal;
  for (int v = 0; v < 9; ++v) {
    rest.push_back(vec3(0.3f, 0.2f * static_cast<float>(v), 1.0f));
    normal.push_back(glm::normalize(vec3(1.0f, 0.1f * static_cast<float>(v), 0.0f)));
  }
  const std::vector<JointIndices> j(9, JointIndices(0, 1, 0, 0));
  const std::vector<vec4> w(9, vec4(0.5f, 0.5f, 0, 0));
  for (SkinningPath path : kPaths) {
    if (!available(path)) continue;
    std::vector<vec3> p(9), n(9);
    skin_dual_quaternion(dq, j, w, rest, normal, p, n, path);
    for (int v = 0; v < 9; ++v) {
      expect_near(p[v], vec3(turn * vec4(rest[v], 1.0f)));
      expect_near(n[v], vec3(turn * vec4(normal[v], 0.0f)));
    }
  }
}

TEST(Skinning, SizeMismatchAndBadInfluencesAreErrors) {
  const std::vector<mat4> skin(2, mat4(1.0f));
  const std::vector<vec3> rest(3, vec3(0.0f));
  std::vector<vec3> out(2);
  const std::vector<JointIndices> j(3, JointIndices(0));
  const std::vector<vec4> w(3, vec4(1, 0, 0, 0));
  EXPECT_THROW(skin_positions(skin, j, w, rest, out), Error);
  std::vector<JointIndices> bad = j;
  bad[2] = JointIndices(0, 5, 0, 0);
  EXPECT_NO_THROW(check_influences(j, w, 2));
  try {
    check_influences(bad, w, 2);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 2 slot 1"), std::string::npos) << e.what();
  }
  std::vector<vec4> unnormalised = w;
  unnormalised[1] = vec4(0.5f, 0.2f, 0, 0);
  EXPECT_THROW(check_influences(j, unnormalised, 2), Error);
}

TEST(Morph, ZeroWeightsGiveRestAndUnitWeightAddsTheDelta) {
  const std::vector<vec3> rest{vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
  std::vector<MorphTarget> morphs(2);
  morphs[0] = {"smile", {1}, {vec3(0, 0.5f, 0)}, {}};
  morphs[1] = {"frown", {0, 2}, {vec3(0.1f, 0, 0), vec3(0, -0.2f, 0.3f)}, {}};
  std::vector<vec3> out(3);
  apply_morphs(rest, morphs, std::vector<float>{0.0f, 0.0f}, out);
  for (int v = 0; v < 3; ++v) expect_near(out[v], rest[v]);
  apply_morphs(rest, morphs, std::vector<float>{0.0f, 1.0f}, out);
  expect_near(out[0], vec3(0.1f, 0, 0));
  expect_near(out[1], vec3(1, 0, 0));
  expect_near(out[2], vec3(0, 0.8f, 0.3f));
  apply_morphs(rest, morphs, std::vector<float>{0.5f, 1.0f}, out);
  expect_near(out[1], vec3(1, 0.25f, 0));
  morphs[0].vertices[0] = 7;
  EXPECT_THROW(apply_morphs(rest, morphs, std::vector<float>{1.0f, 0.0f}, out), Error);
}

TEST(Morph, NormalDeltasAreRenormalised) {
  const std::vector<vec3> rest{vec3(0, 0, 1), vec3(0, 1, 0)};
  std::vector<MorphTarget> morphs(1);
  morphs[0] = {"bulge", {0}, {vec3(0)}, {vec3(1, 0, -1)}};
  std::vector<vec3> out(2);
  apply_morph_normals(rest, morphs, std::vector<float>{1.0f}, out);
  expect_near(out[0], vec3(1, 0, 0));
  expect_near(out[1], vec3(0, 1, 0));
}

// Vertices in runs of one to four influences (as skinned meshes have them, rigid parts next to
// blended ones), some with a weightless slot before a weighted one, against the LBS formula written
// out per vertex; with few joints and with more than the portable path keeps as rows on the stack.
TEST(Skinning, LbsMatchesTheFormulaForEveryInfluenceCount) {
  for (int joint_count : {12, 300}) {
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), share(0.1f, 1.0f);
    std::uniform_int_distribution<int> pick(0, joint_count - 1);
    Cloud c;
    for (std::size_t v = 0; v < 803; ++v) {
      c.positions.push_back(vec3(u(rng), u(rng) + 1.0f, u(rng)));
      c.normals.push_back(glm::normalize(vec3(u(rng), u(rng), u(rng)) + vec3(0.0f, 0.0f, 2.0f)));
      c.joints.push_back(JointIndices(pick(rng), pick(rng), pick(rng), pick(rng)));
      const int influences = 1 + static_cast<int>(v / 9 % 4);  // runs of 9 vertices
      vec4 w(0.0f);
      for (int k = 0; k < influences; ++k) w[k] = share(rng);
      if (v % 7 == 0 && influences >= 3) w[1] = 0.0f;  // a hole before a weighted slot
      c.weights.push_back(w / (w.x + w.y + w.z + w.w));
    }
    const std::vector<mat4> skin = random_pose_matrices(joint_count, 8);
    for (SkinningPath path : kPaths) {
      if (!available(path)) continue;
      std::vector<vec3> p(c.positions.size()), n(c.positions.size()), q(c.positions.size());
      skin_positions_normals(skin, c.joints, c.weights, c.positions, c.normals, p, n, path);
      skin_positions(skin, c.joints, c.weights, c.positions, q, path);
      for (std::size_t v = 0; v < p.size(); ++v) {
        mat4 m(0.0f);
        for (int k = 0; k < 4; ++k) m += c.weights[v][k] * skin[c.joints[v][k]];
        SCOPED_TRACE("vertex " + std::to_string(v) + ", " + std::to_string(joint_count) + " joints");
        expect_near(p[v], vec3(m * vec4(c.positions[v], 1.0f)));
        expect_near(q[v], p[v]);
        expect_near(n[v], glm::normalize(vec3(m * vec4(c.normals[v], 0.0f))));
      }
    }
  }
}
