#include "gestura/body/avatar.hpp"

#include <cmath>
#include <limits>

#include "gestura/body/avatar_material_borders.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/avatar_volume.hpp"
#include "gestura/body/face_morphs.hpp"
#include "gestura/body/mesh_simplify.hpp"
#include "gestura/body/polygonize.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// Outward normals from the field gradient (smooth across the tessellation), falling back to
// area-weighted face normals where the gradient vanishes.
std::vector<vec3> surface_normals(const ImplicitBody& body, const Mesh& mesh) {
  std::vector<vec3> face_sum(mesh.vertex_count(), vec3(0.0f));
  for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
    const std::uint32_t a = mesh.indices[f], b = mesh.indices[f + 1], c = mesh.indices[f + 2];
    const vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    face_sum[a] += n;
    face_sum[b] += n;
    face_sum[c] += n;
  }
  std::vector<vec3> normals(mesh.vertex_count());
  for (std::size_t v = 0; v < normals.size(); ++v) {
    const vec3 g = body.gradient(mesh.positions[v]);
    const float len = glm::length(g);
    const vec3 fallback = glm::length(face_sum[v]) > 0.0f ? glm::normalize(face_sum[v]) : vec3(0, 1, 0);
    // The gradient is trusted where it agrees with the tessellation (creases between fingers and
    // lips are saddles where it can point along the surface).
    normals[v] = len > 1e-3f && glm::dot(g / len, fallback) > 0.8f ? g / len : fallback;
  }
  return normals;
}

// Material of each vertex: that of the nearest union primitive; on eyeballs the iris and pupil
// are the caps around the gaze direction (+Z at rest); hair and brows are drawn by their fields.
std::vector<std::uint8_t> surface_materials(const Skeleton& skeleton, const ImplicitBody& body, const Mesh& mesh,
                                            float k) {
  std::vector<std::uint8_t> out(mesh.vertex_count(), static_cast<std::uint8_t>(MaterialId::Skin));
  std::vector<float> d(body.primitives.size());
  const int l_eye = skeleton.find("l_eyeball_joint"), r_eye = skeleton.find("r_eyeball_joint");
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const vec3 p = mesh.positions[v];
    body.distances(p, d);
    std::size_t best = 0;
    for (std::size_t i = 1; i < d.size(); ++i)
      if (d[i] < d[best]) best = i;
    const Primitive& prim = body.primitives[best];
    auto m = static_cast<MaterialId>(prim.material);
    // Lips only where the surface lies on the lip primitives themselves, not on the skin they
    // blend into (the vermilion border).
    if (m == MaterialId::Lips && d[best] > 0.0012f * k) m = MaterialId::Skin;
    if (m == MaterialId::EyeWhite && (prim.joint == l_eye || prim.joint == r_eye)) {
      const vec3 dir = glm::normalize(p - prim.a);
      if (dir.z > std::cos(deg(13.0f)))
        m = MaterialId::Pupil;
      else if (dir.z > std::cos(deg(30.0f)))
        m = MaterialId::Iris;
    } else if (m == MaterialId::Skin || m == MaterialId::Hair) {
      m = hair_field(p, k) < 0.0f ? MaterialId::Hair : eyebrow_field(p, k) < 0.0f ? MaterialId::Brow : MaterialId::Skin;
    }
    out[v] = static_cast<std::uint8_t>(m);
  }
  return out;
}

// Polygonises with all detail boxes; a body so heavy that a box cannot be isolated (the shoulders
// reach the neck cut, the hips the hand box) loses that box's extra detail rather than failing.
Polygonization polygonize_with_detail(const ImplicitBody& body, PolygonizeOptions options) {
  while (true) {
    try {
      return polygonize(body, options);
    } catch (const Error&) {
      if (options.detail.empty()) throw;
      options.detail.pop_back();  // the head box first, then the hands
    }
  }
}

}  // namespace

Avatar build_avatar(const AvatarParams& params, const AvatarOptions& options) {
  params.validate();
  if (!(options.cell >= 0.006f && options.cell <= 0.05f))
    throw Error("avatar cell size " + std::to_string(options.cell) + " m is outside 0.006 .. 0.05 m");
  Avatar avatar;
  avatar.params = params;
  avatar.skeleton = build_avatar_skeleton(params);
  const ImplicitBody body = build_avatar_volume(avatar.skeleton, params);
  const float k = params.height / 1.70f;
  PolygonizeOptions poly;
  poly.cell = options.cell * k;
  poly.detail = avatar_detail_boxes(avatar.skeleton, params);
  Polygonization surface = polygonize_with_detail(body, poly);
  collapse_short_edges(surface.positions, surface.indices, 0.5f);
  Mesh& mesh = avatar.mesh;
  mesh.positions = std::move(surface.positions);
  mesh.indices = std::move(surface.indices);
  mesh.materials = surface_materials(avatar.skeleton, body, mesh, k);
  sharpen_material_borders(avatar_material_borders(body, k), 0.0005f * k, mesh.positions, mesh.indices, mesh.materials);
  mesh.normals = surface_normals(body, mesh);
  compute_skin_weights(avatar.skeleton, body, options.weights, mesh);
  mesh.morphs = build_face_morphs(avatar.skeleton, mesh, k);
  compute_morph_normal_deltas(mesh);
  return avatar;
}

}  // namespace gestura
