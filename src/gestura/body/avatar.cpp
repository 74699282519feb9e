#include "gestura/body/avatar.hpp"

#include <cmath>
#include <limits>

#include "gestura/body/avatar_material_borders.hpp"
#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/avatar_volume.hpp"
#include "gestura/body/face_morphs.hpp"
#include "gestura/body/face_parts.hpp"
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

// Material of each vertex: that of the nearest union primitive, with regions drawn by distance
// or by field instead: the lips wherever the surface lies on a lip primitive (not only where one is
// nearest, which patched the border), the mouth's lining on the carved oral cavity, and hair and
// brows by their fields (avatar_material_borders.hpp), so their edges follow smooth curves.
std::vector<std::uint8_t> surface_materials(const ImplicitBody& body, const Mesh& mesh, float k) {
  std::vector<std::uint8_t> out(mesh.vertex_count(), static_cast<std::uint8_t>(MaterialId::Skin));
  std::vector<float> d(body.primitives.size());
  std::vector<std::size_t> lips, cavity;
  for (std::size_t i = 0; i < body.primitives.size(); ++i) {
    const Primitive& prim = body.primitives[i];
    if (prim.material == static_cast<std::uint8_t>(MaterialId::Lips) && prim.op == BlendOp::Union) lips.push_back(i);
    if (prim.material == static_cast<std::uint8_t>(MaterialId::Mouth) && prim.op == BlendOp::Subtract) cavity.push_back(i);
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const vec3 p = mesh.positions[v];
    body.distances(p, d);
    std::size_t best = 0;
    for (std::size_t i = 1; i < d.size(); ++i)
      if (d[i] < d[best]) best = i;
    auto m = static_cast<MaterialId>(body.primitives[best].material);
    if (m == MaterialId::Lips) m = MaterialId::Skin;
    for (std::size_t i : lips)
      if (d[i] < 0.0012f * k) m = MaterialId::Lips;
    for (std::size_t i : cavity)
      if (primitive_distance(body.primitives[i], p) < 0.0015f * k) m = MaterialId::Mouth;
    if (m == MaterialId::Skin || m == MaterialId::Hair) {
      m = hair_field(p, k) < 0.0f ? MaterialId::Hair : eyebrow_field(p, k) < 0.0f ? MaterialId::Brow : MaterialId::Skin;
    }
    out[v] = static_cast<std::uint8_t>(m);
  }
  return out;
}

// Closes the mouth the surface was polygonised with (open by kBindJawOpenDegrees, and a little
// more: kLipPressDegrees): every vertex turns back about the jaw joint by its jaw weight, as
// skinning would move it.
void close_jaw(const Skeleton& skeleton, Mesh& mesh) {
  const int jaw = skeleton.find("temporomandibular");
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  const vec3 pivot(model[static_cast<std::size_t>(jaw)][3]);
  const quat close = glm::angleAxis(deg(-proportions::kBindJawOpenDegrees - proportions::kLipPressDegrees), vec3(1, 0, 0));
  std::vector<bool> partly(mesh.vertex_count(), false);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    float w = 0.0f;
    for (int i = 0; i < 4; ++i)
      if (mesh.joints[v][i] == jaw) w += mesh.weights[v][i];
    if (w <= 0.0f) continue;
    const vec3 p = mesh.positions[v];
    mesh.positions[v] = glm::mix(p, pivot + close * (p - pivot), w);
    mesh.normals[v] = glm::normalize(glm::mix(mesh.normals[v], close * mesh.normals[v], w));
    partly[v] = w < 1.0f;
  }
  // Where the jaw's share changes (the mouth's corners and lining) the closing squeezes the
  // surface, and the field's normal no longer fits it: take the tessellation's there.
  std::vector<vec3> face_sum(mesh.vertex_count(), vec3(0.0f));
  for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
    const std::uint32_t a = mesh.indices[f], b = mesh.indices[f + 1], c = mesh.indices[f + 2];
    if (!partly[a] && !partly[b] && !partly[c]) continue;
    const vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    face_sum[a] += n, face_sum[b] += n, face_sum[c] += n;
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (partly[v] && glm::length(face_sum[v]) > 0.0f && glm::dot(glm::normalize(face_sum[v]), mesh.normals[v]) < 0.8f)
      mesh.normals[v] = glm::normalize(face_sum[v]);
}

// Closing squeezes the mouth's corners, where the jaw's share falls off within a few millimetres,
// and can fold a triangle there against its neighbours: relax the corners of folded triangles
// towards their neighbours' centre until none is left (a few rounds).
void unfold(Mesh& mesh) {
  std::vector<std::vector<std::uint32_t>> ring(mesh.vertex_count());
  for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3)
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.indices[f + e], b = mesh.indices[f + (e + 1) % 3];
      ring[a].push_back(b), ring[b].push_back(a);
    }
  for (int round = 0; round < 8; ++round) {
    std::vector<std::uint32_t> folded;
    for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
      const std::uint32_t a = mesh.indices[f], b = mesh.indices[f + 1], c = mesh.indices[f + 2];
      const vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
      if (glm::dot(n, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]) <= 0.0f) folded.insert(folded.end(), {a, b, c});
    }
    if (folded.empty()) return;
    for (std::uint32_t v : folded) {
      vec3 centre(0.0f);
      for (std::uint32_t u : ring[v]) centre += mesh.positions[u];
      mesh.positions[v] = glm::mix(mesh.positions[v], centre / static_cast<float>(ring[v].size()), 0.5f);
    }
  }
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
  const ImplicitBody body = build_avatar_volume(avatar.skeleton, params, proportions::kBindJawOpenDegrees);
  const float k = params.height / 1.70f;
  PolygonizeOptions poly;
  poly.cell = options.cell * k;
  poly.detail = avatar_detail_boxes(avatar.skeleton, params);
  Polygonization surface = polygonize_with_detail(body, poly);
  collapse_short_edges(surface.positions, surface.indices, 0.5f);
  Mesh& mesh = avatar.mesh;
  mesh.positions = std::move(surface.positions);
  mesh.indices = std::move(surface.indices);
  mesh.materials = surface_materials(body, mesh, k);
  sharpen_material_borders(avatar_material_borders(body, k), 0.0005f * k, mesh.positions, mesh.indices, mesh.materials);
  mesh.normals = surface_normals(body, mesh);
  compute_skin_weights(avatar.skeleton, body, options.weights, mesh);
  close_jaw(avatar.skeleton, mesh);
  unfold(mesh);
  append_mesh(mesh, build_face_parts(avatar.skeleton, k));
  mesh.morphs = build_face_morphs(avatar.skeleton, mesh, k);
  compute_morph_normal_deltas(mesh);
  return avatar;
}

}  // namespace gestura
