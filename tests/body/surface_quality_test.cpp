// The generated avatar as one smooth, mirror-symmetric skin (body/surface_quality.hpp): its face,
// hands and trunk are held to the numbers docs/avatar.md reports, for the default avatar and the
// built-in looks; and the measures themselves on shapes whose answers are known.
#include "gestura/body/surface_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_look.hpp"

using namespace gestura;

namespace {

// A closed octahedron (x-mirror symmetric): every edge bends by the same angle.
Mesh octahedron() {
  Mesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const vec3& p : m.positions) m.normals.push_back(glm::normalize(p));
  m.indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return m;
}

TEST(SurfaceQuality, OctahedronCreasesAreItsDihedralAndItIsItsOwnMirror) {
  const SurfaceQuality q = measure_surface(octahedron(), [](std::size_t) { return true; });
  // Neighbouring face normals (1,1,1)/√3 and (1,1,−1)/√3 meet at acos(1/3) = 70.5°.
  EXPECT_EQ(q.crease_degrees.count, 12);
  EXPECT_NEAR(q.crease_degrees.mean, 70.53f, 0.1f);
  EXPECT_NEAR(q.crease_degrees.max, 70.53f, 0.1f);
  EXPECT_NEAR(q.asymmetry_mm.max, 0.0f, 1e-3f);
  // Moving one vertex off the mirror makes the surface asymmetric by about that much.
  Mesh m = octahedron();
  m.positions[0].y += 0.01f;
  const SurfaceQuality moved = measure_surface(m, [](std::size_t) { return true; });
  EXPECT_GT(moved.asymmetry_mm.max, 3.0f);
}

TEST(SurfaceQuality, EmptyRegionGivesZeros) {
  const SurfaceQuality q = measure_surface(octahedron(), [](std::size_t) { return false; });
  EXPECT_EQ(q.crease_degrees.count, 0);
  EXPECT_EQ(q.roughness_degrees.count, 0);
  EXPECT_EQ(q.crease_degrees.max, 0.0f);
}

void expect_smooth_and_symmetric(const Avatar& a, const char* name) {
  const struct {
    BodyRegion region;
    const char* label;
    float crease_p95, roughness_p95, asymmetry_p95_mm;
  } limits[] = {// Measured on 2026-11-26 (docs/avatar.md) with a few degrees of room: these guard against
                // a regression; they are not goals met with ease (the face's p95 roughness is 13–18°).
                {BodyRegion::Face, "face", 24.0f, 21.0f, 1.5f},
                {BodyRegion::Hands, "hands", 32.0f, 15.0f, 1.5f},
                {BodyRegion::Trunk, "trunk", 18.0f, 9.0f, 1.5f}};
  for (const auto& l : limits) {
    const SurfaceQuality q = measure_body_region(a.mesh, a.skeleton, l.region);
    std::printf("%-8s %-6s crease mean %5.2f p95 %5.2f max %6.2f deg | roughness mean %5.2f p95 %5.2f deg | asymmetry "
                "mean %5.2f p95 %5.2f max %5.2f mm | edge %.1f mm | %d vertices\n",
                name, l.label, q.crease_degrees.mean, q.crease_degrees.p95, q.crease_degrees.max, q.roughness_degrees.mean,
                q.roughness_degrees.p95, q.asymmetry_mm.mean, q.asymmetry_mm.p95, q.asymmetry_mm.max, q.mean_edge_mm,
                q.roughness_degrees.count);
    ASSERT_GT(q.crease_degrees.count, 100) << name << " " << l.label;
    EXPECT_LT(q.crease_degrees.p95, l.crease_p95) << name << " " << l.label;
    EXPECT_LT(q.roughness_degrees.p95, l.roughness_p95) << name << " " << l.label;
    EXPECT_LT(q.asymmetry_mm.p95, l.asymmetry_p95_mm) << name << " " << l.label;
  }
}

TEST(SurfaceQuality, DefaultAvatarAndEveryLookAreSmoothAndSymmetric) {
  for (const AvatarLook& look : builtin_looks())
    expect_smooth_and_symmetric(build_avatar(look.params), std::string(look.name).c_str());
}

}  // namespace
