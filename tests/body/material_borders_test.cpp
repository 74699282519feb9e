#include "gestura/body/material_borders.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "gestura/body/level_split.hpp"
#include "gestura/body/mesh_topology.hpp"
#include "gestura/body/polygonize.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

// A ball of radius 0.1 m on a 12 mm lattice.
Polygonization ball() {
  ImplicitBody body;
  Primitive p;
  p.shape = PrimitiveShape::Ellipsoid;
  p.radii = vec3(0.1f);
  body.primitives.push_back(p);
  body.finish();
  PolygonizeOptions o;
  o.cell = 0.012f;
  return polygonize(body, o);
}

}  // namespace

TEST(LevelSplit, CutsAlongTheLevelAndKeepsTheSurfaceClosed) {
  Polygonization b = ball();
  const std::size_t before = b.positions.size();
  std::vector<float> height(before);
  for (std::size_t v = 0; v < before; ++v) height[v] = b.positions[v].y;
  std::vector<std::uint8_t> eligible(before, 1);
  const std::size_t added = split_at_level({b.positions, b.indices, height, eligible}, 0.03f, 0.001f);
  // The circle y = 0.03 on the ball, about 2π · 0.095 m long, crosses an edge every few millimetres.
  EXPECT_GT(added, 50u);
  ASSERT_EQ(b.positions.size(), before + added);
  // On the level, but for vertices that lay within the snap distance of it: their values were pushed
  // off it, which moves the cut by at most that much.
  for (std::size_t v = before; v < b.positions.size(); ++v) EXPECT_NEAR(b.positions[v].y, 0.03f, 0.001f);
  // No triangle straddles the level any more, and the surface is as closed as before.
  for (std::size_t f = 0; f < b.indices.size(); f += 3) {
    float lo = 1.0f, hi = -1.0f;
    for (int k = 0; k < 3; ++k) lo = std::min(lo, height[b.indices[f + k]]), hi = std::max(hi, height[b.indices[f + k]]);
    EXPECT_FALSE(lo < 0.03f && hi > 0.03f) << "triangle " << f / 3;
  }
  const MeshTopology t = audit_topology(b.positions, b.indices);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_EQ(t.degenerate_triangles, 0);
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(LevelSplit, IneligibleVerticesKeepTheirEdgesWhole) {
  Polygonization b = ball();
  std::vector<float> height(b.positions.size());
  std::vector<std::uint8_t> eligible(b.positions.size());
  for (std::size_t v = 0; v < height.size(); ++v) {
    height[v] = b.positions[v].y;
    eligible[v] = b.positions[v].x > 0.0f;  // only the +x half may be cut
  }
  const std::size_t before = b.positions.size();
  EXPECT_GT(split_at_level({b.positions, b.indices, height, eligible}, 0.0f, 0.001f), 20u);
  for (std::size_t v = before; v < b.positions.size(); ++v) EXPECT_GT(b.positions[v].x, 0.0f);
  EXPECT_TRUE(audit_topology(b.positions, b.indices).closed_manifold());
}

TEST(LevelSplit, MismatchedSizesAreErrors) {
  Polygonization b = ball();
  std::vector<float> values(3);
  std::vector<std::uint8_t> eligible(b.positions.size(), 1);
  EXPECT_THROW(split_at_level({b.positions, b.indices, values, eligible}, 0.0f, 0.001f), Error);
}

TEST(MaterialBorders, BorderFollowsTheFieldNotTheLattice) {
  Polygonization b = ball();
  std::vector<std::uint8_t> materials(b.positions.size());
  // A tilted plane: cloth below, skin above; the first labels are deliberately coarse (by lattice
  // row), as a nearest-primitive labelling would give.
  const vec3 n = glm::normalize(vec3(0.3f, 1.0f, 0.2f));
  for (std::size_t v = 0; v < materials.size(); ++v)
    materials[v] = static_cast<std::uint8_t>(glm::dot(b.positions[v], n) < 0.0f ? MaterialId::Cloth : MaterialId::Skin);
  const MaterialBorder border{MaterialId::Cloth, MaterialId::Skin, [n](const vec3& p) { return glm::dot(p, n); }};
  sharpen_material_borders({&border, 1}, 0.0005f, b.positions, b.indices, materials);
  ASSERT_EQ(materials.size(), b.positions.size());
  EXPECT_TRUE(audit_topology(b.positions, b.indices).closed_manifold());
  // Every edge between the two materials crosses the plane within the band, so the colour changes
  // inside a 1 mm strip along it.
  int mixed = 0;
  for (std::size_t f = 0; f < b.indices.size(); f += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = b.indices[f + k], w = b.indices[f + (k + 1) % 3];
      if (materials[u] == materials[w]) continue;
      ++mixed;
      EXPECT_LT(std::abs(glm::dot(b.positions[u], n)), 0.0008f);
      EXPECT_LT(std::abs(glm::dot(b.positions[w], n)), 0.0008f);
    }
  EXPECT_GT(mixed, 50);
  std::vector<std::uint8_t> short_list(2);
  EXPECT_THROW(sharpen_material_borders({&border, 1}, 0.0005f, b.positions, b.indices, short_list), Error);
}
