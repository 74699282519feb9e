#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gestura/body/avatar.hpp"
#include "gestura/body/body_sites.hpp"

using namespace gestura;

namespace {

// A UV sphere of radius r around c, triangles wound counter-clockwise seen from outside.
void add_sphere(Mesh& m, vec3 c, float r) {
  const int rings = 24, segments = 32;
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const float th = kPi * static_cast<float>(i) / rings, ph = 2 * kPi * static_cast<float>(j) / segments;
      m.positions.push_back(c + r * vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)));
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t a = base + static_cast<std::uint32_t>(i * (segments + 1) + j), b = a + segments + 1;
      m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
}

Skeleton head_skeleton() {
  Skeleton s;
  const int skull = s.add_joint("skullbase", -1, vec3(0, 1.5f, 0));
  s.add_joint("l_eyeball_joint", skull, vec3(0.03f, 0.1f, 0.08f));
  s.add_joint("r_eyeball_joint", skull, vec3(-0.03f, 0.1f, 0.08f));
  s.add_joint("skull_tip", skull, vec3(0, 0.2f, 0));
  return s;
}

}  // namespace

TEST(BodySites, FaceSitesLieOnTheSurfaceInTheirAnatomicalOrder) {
  Mesh head;
  const vec3 centre(0, 1.6f, 0);
  add_sphere(head, centre, 0.1f);
  const Skeleton s = head_skeleton();
  const auto sites = find_body_sites(s, head);
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  for (const char* name : {"forehead", "nose", "chin", "l_cheek", "r_cheek", "l_ear", "head_top"}) {
    const BodySite* site = find_site(sites, name);
    ASSERT_NE(site, nullptr) << name;
    const vec3 p = site_position(*site, model);
    EXPECT_NEAR(glm::distance(p, centre), 0.1f, 0.003f) << name;  // on the (tessellated) surface
    EXPECT_GT(glm::dot(site_normal(*site, model), glm::normalize(p - centre)), 0.95f) << name;
  }
  const auto y = [&](const char* n) { return site_position(*find_site(sites, n), model).y; };
  EXPECT_GT(y("head_top"), y("forehead"));
  EXPECT_GT(y("forehead"), y("nose"));
  EXPECT_GT(y("nose"), y("chin"));
  EXPECT_GT(site_position(*find_site(sites, "l_cheek"), model).x, 0.0f);  // the avatar's left is +X
  EXPECT_LT(site_position(*find_site(sites, "r_ear"), model).x, -0.09f);
  EXPECT_GT(site_position(*find_site(sites, "forehead"), model).z, 0.05f);  // the face looks along +Z
}

TEST(BodySites, SitesFollowTheJointThatCarriesThem) {
  Mesh head;
  add_sphere(head, vec3(0, 1.6f, 0), 0.1f);
  const Skeleton s = head_skeleton();
  const auto sites = find_body_sites(s, head);
  Pose pose = rest_pose(s);
  pose.rotations[0] = glm::angleAxis(kPi / 2, vec3(0, 1, 0));  // turn the head to its left
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  const vec3 nose = site_position(*find_site(sites, "nose"), model);
  EXPECT_GT(nose.x, 0.08f);  // the nose now points along +X
  EXPECT_NEAR(nose.z, 0.0f, 0.01f);
}

TEST(BodySites, MissingJointsOrMeshGiveNoSitesRatherThanInventedOnes) {
  Skeleton s;
  s.add_joint("humanoid_root", -1, vec3(0, 1, 0));
  Mesh empty;
  EXPECT_TRUE(find_body_sites(s, empty).empty());
  Mesh head;
  add_sphere(head, vec3(0, 1.6f, 0), 0.1f);
  EXPECT_TRUE(find_body_sites(s, head).empty());
}

TEST(BodySites, RayCastFindsTheNearestHit) {
  Mesh m;
  add_sphere(m, vec3(0), 1.0f);
  const auto hit = cast_ray(m, vec3(0, 0, -5), vec3(0, 0, 1));
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->distance, 4.0f, 0.01f);
  EXPECT_LT(hit->normal.z, -0.99f);  // outward normal where the ray enters from −Z
  EXPECT_FALSE(cast_ray(m, vec3(0, 0, -5), vec3(0, 1, 0)).has_value());
}

TEST(BodySites, OnTheAvatarTheChinIsTheJawsFrontWithUnderChinBeneathIt) {
  // The default avatar's chin stands 5-6 cm in front of its throat. The chin site is its front
  // (a slanted ray once slid under it onto the jaw line), under_chin the jaw's underside (a ray
  // from inside the head once went down the neck to the chest, 23 cm low), the neck the throat.
  const Avatar avatar = build_avatar();
  const Skeleton& s = avatar.skeleton;
  const auto sites = find_body_sites(s, avatar.mesh);
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  for (const char* n : {"chin", "under_chin", "neck", "lower_lip", "lips"}) ASSERT_NE(find_site(sites, n), nullptr) << n;
  const auto at = [&](const char* n) { return site_position(*find_site(sites, n), model); };
  const auto normal = [&](const char* n) { return site_normal(*find_site(sites, n), model); };
  const vec3 chin = at("chin"), under = at("under_chin"), neck = at("neck");
  EXPECT_GT(chin.z, neck.z + 0.03f);
  EXPECT_NEAR(chin.z, at("lower_lip").z, 0.015f);  // the chin's front is about as far forward as the lips
  EXPECT_GT(normal("chin").z, 0.8f);
  EXPECT_LT(under.y, chin.y);
  EXPECT_GT(under.y, chin.y - 0.04f);
  EXPECT_LT(under.z, chin.z - 0.01f);
  EXPECT_GT(under.z, neck.z);
  EXPECT_LT(normal("under_chin").y, -0.7f);  // faces down
  EXPECT_LT(neck.y, under.y - 0.01f);
  // A site's normal is the surface's around it, not one triangle's: the closed lips' seam once
  // gave the lips a normal 57° off the face's forward direction.
  EXPECT_GT(normal("lips").z, 0.8f);
}

TEST(BodySites, OnTheAvatarMidlineNormalsFaceStraightAndPairsMirror) {
  // The avatar is mirror-symmetric, so a site on the midline faces straight ahead (no sideways
  // lean) and a left site's normal mirrors its right twin's. The nose's normal once leaned 16° to
  // the left: it was the tip's triangle normals, which follow how marching cubes cut a small,
  // sharp feature, not the surface.
  const Avatar avatar = build_avatar();
  const Skeleton& s = avatar.skeleton;
  const auto sites = find_body_sites(s, avatar.mesh);
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  const auto normal = [&](const std::string& n) {
    const BodySite* site = find_site(sites, n.c_str());
    EXPECT_NE(site, nullptr) << n;
    return site ? site_normal(*site, model) : vec3(0.0f);
  };
  for (const char* n : {"forehead", "eyebrows", "nose", "upper_lip", "lips", "lower_lip", "chin", "chest", "upper_chest"})
    EXPECT_LT(std::abs(normal(n).x), std::sin(glm::radians(5.0f))) << n << " leans sideways";
  for (const char* n : {"eye", "cheek", "ear", "temple", "shoulder_top", "upper_arm", "elbow", "forearm", "palm",
                        "back_of_hand", "index_tip"}) {
    const vec3 l = normal(std::string("l_") + n), r = normal(std::string("r_") + n);
    EXPECT_GT(glm::dot(l, vec3(-r.x, r.y, r.z)), std::cos(glm::radians(8.0f))) << n << ": left and right differ";
  }
}
