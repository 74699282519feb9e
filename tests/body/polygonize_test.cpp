#include "gestura/body/polygonize.hpp"

#include <gtest/gtest.h>

#include "gestura/body/mesh_simplify.hpp"
#include "gestura/body/mesh_topology.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

// Two balls joined by a bar along x: a dumbbell, 0.4 m long.
ImplicitBody dumbbell() {
  ImplicitBody body;
  Primitive ball;
  ball.shape = PrimitiveShape::Ellipsoid;
  ball.radii = vec3(0.06f);
  ball.a = vec3(-0.2f, 0, 0);
  body.primitives.push_back(ball);
  ball.a = vec3(0.2f, 0, 0);
  body.primitives.push_back(ball);
  Primitive bar;
  bar.shape = PrimitiveShape::Capsule;
  bar.a = vec3(-0.2f, 0, 0);
  bar.b = vec3(0.2f, 0, 0);
  bar.radius_a = bar.radius_b = 0.025f;
  bar.blend = 0.02f;
  body.primitives.push_back(bar);
  body.finish();
  return body;
}

}  // namespace

TEST(Polygonize, UniformLatticeGivesAClosedSphereLikeSurface) {
  PolygonizeOptions o;
  o.cell = 0.012f;
  const Polygonization p = polygonize(dumbbell(), o);
  const MeshTopology t = audit_topology(p.positions, p.indices);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.degenerate_triangles, 0);
  // Two balls of radius 6 cm plus the bar: about 2·0.905 + 0.3·π·0.025² litres.
  EXPECT_NEAR(t.signed_volume, 2 * 4.18879 * 0.06 * 0.06 * 0.06 + 0.28 * kPi * 0.025 * 0.025, 0.0004);
  // Beyond the bar's blend the right ball is a sphere of radius 6 cm.
  for (const vec3& v : p.positions) {
    if (v.x > 0.26f) {
      ASSERT_NEAR(glm::length(v - vec3(0.2f, 0, 0)), 0.06f, 0.003f);
    }
  }
}

TEST(Polygonize, DetailBoxIsZippedIntoTheSameClosedSurface) {
  PolygonizeOptions o;
  o.cell = 0.012f;
  DetailBox box;
  box.lo = vec3(0.12f, -0.08f, -0.08f);
  box.hi = vec3(0.3f, 0.08f, 0.08f);
  box.open_axis = 0;
  box.open_side = -1;  // the bar enters from −x
  box.refine = 3;
  o.detail.push_back(box);
  const Polygonization coarse = polygonize(dumbbell(), PolygonizeOptions{0.012f, {}});
  const Polygonization p = polygonize(dumbbell(), o);
  const MeshTopology t = audit_topology(p.positions, p.indices);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.degenerate_triangles, 0);
  EXPECT_GT(t.triangles, coarse.indices.size() / 3 + 1000);  // the right ball is finer
}

TEST(Polygonize, RejectsBadOptionsAndBoxesTheSurfaceCrossesTwice) {
  EXPECT_THROW(polygonize(dumbbell(), PolygonizeOptions{0.0f, {}}), Error);
  PolygonizeOptions o;
  o.cell = 0.012f;
  DetailBox across;  // the bar runs straight through: it crosses two faces
  across.lo = vec3(-0.05f, -0.05f, -0.05f);
  across.hi = vec3(0.05f, 0.05f, 0.05f);
  across.open_axis = 0;
  across.open_side = -1;
  o.detail.push_back(across);
  EXPECT_THROW(polygonize(dumbbell(), o), Error);
  o.detail[0].refine = 0;
  EXPECT_THROW(polygonize(dumbbell(), o), Error);
}

TEST(MeshTopology, FindsHolesFlipsAndDegenerates) {
  // A tetrahedron, outward.
  const std::vector<vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<std::uint32_t> i{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  MeshTopology t = audit_topology(p, i);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_NEAR(t.signed_volume, 1.0 / 6.0, 1e-9);
  auto flipped = i;
  std::swap(flipped[0], flipped[1]);
  t = audit_topology(p, flipped);
  EXPECT_EQ(t.misoriented_edges, 3);
  auto holed = std::vector<std::uint32_t>(i.begin(), i.end() - 3);
  t = audit_topology(p, holed);
  EXPECT_EQ(t.boundary_edges, 3);
  auto bad = i;
  bad.insert(bad.end(), {0, 0, 1, 0, 1, 9});
  t = audit_topology(p, bad);
  EXPECT_EQ(t.degenerate_triangles, 1);
  EXPECT_EQ(t.out_of_range_indices, 1);
}

TEST(MeshSimplify, CollapsingShortEdgesKeepsTheSurfaceClosed) {
  PolygonizeOptions o;
  o.cell = 0.01f;
  Polygonization p = polygonize(dumbbell(), o);
  const std::size_t before = p.indices.size();
  const int collapses = collapse_short_edges(p.positions, p.indices, 0.4f);
  EXPECT_GT(collapses, 0);
  EXPECT_EQ(p.indices.size(), before - 6u * static_cast<std::size_t>(collapses));
  const MeshTopology t = audit_topology(p.positions, p.indices);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.degenerate_triangles, 0);
}
