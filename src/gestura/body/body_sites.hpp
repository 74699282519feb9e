#pragma once
// Named places on the body where signs are made (HamNoSys locations: forehead, nose, chin, chest,
// upper arm, palm, …), found on the *current* avatar's surface so the same sign works on any avatar.
//
// Each site is found once at bind pose by casting a ray from inside the body (a point derived from the
// skeleton: joint positions and the face's proportions from the eyes to the crown) towards the
// outside and taking the first surface hit. It is then stored relative to the joint that carries it,
// so it follows the body as it moves: position = model[joint] · local_offset.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct BodySite {
  std::string name;      // e.g. "forehead", "l_cheek", "chest", "r_palm"
  int joint = -1;        // the joint that carries the site
  vec3 local_offset{0};  // in the joint's bind-pose frame
  vec3 local_normal{0};  // outward surface normal, same frame
};

// Finds every site whose anchor joints exist in `skeleton` (H-Anim names; an avatar lacking e.g. eyes
// gets no eye sites). Contract: `mesh` is at bind pose in the skeleton's model space; rays that miss
// the mesh (a broken or partial mesh) drop the site rather than invent one.
std::vector<BodySite> find_body_sites(const Skeleton& skeleton, const Mesh& mesh);

const BodySite* find_site(std::span<const BodySite> sites, const std::string& name);

// A point on a surface and the direction the surface faces there (outward): where a hand meets a
// body site, a part of the other hand or a part of itself.
struct SurfacePoint {
  vec3 point{0.0f};
  vec3 normal{0.0f, 0.0f, 1.0f};
};

// Model-space position / normal of a site for joint model matrices `model` (from local_to_model).
vec3 site_position(const BodySite& site, std::span<const mat4> model);
vec3 site_normal(const BodySite& site, std::span<const mat4> model);
SurfacePoint site_surface(const BodySite& site, std::span<const mat4> model);

// The sites at bind pose as JSON: {"sites": {"forehead": {"position": [x, y, z], "normal": [...],
// "joint": "skullbase"}, …}} in metres, +Y up, the avatar facing +Z.
std::string body_sites_json(const Skeleton& skeleton, std::span<const BodySite> sites);

// First intersection of the ray origin + t·direction (t > 0) with the mesh; nullopt when it misses.
struct RayHit {
  float distance;
  vec3 point;
  // The surface's normal there: the mesh's vertex normals interpolated across the hit triangle when
  // it has them (for a polygonised avatar, the field's gradient: the surface's own direction, not
  // its tessellation's), else the triangle's from its winding (outward for counter-clockwise meshes).
  vec3 normal;
};
std::optional<RayHit> cast_ray(const Mesh& mesh, const vec3& origin, const vec3& direction);

}  // namespace gestura
