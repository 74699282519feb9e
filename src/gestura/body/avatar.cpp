#include "gestura/body/avatar.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "gestura/body/avatar_look.hpp"
#include "gestura/body/avatar_material_borders.hpp"
#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/avatar_volume.hpp"
#include "gestura/body/face_morphs.hpp"
#include "gestura/body/face_parts.hpp"
#include "gestura/body/head_sculpt.hpp"
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

// The sculpted head among the body's primitives (there is one on the default avatar).
const HeadSculpt* find_head(const ImplicitBody& body) {
  for (const Primitive& p : body.primitives)
    if (p.shape == PrimitiveShape::Sculpt)
      if (const auto* head = dynamic_cast<const HeadSculpt*>(p.sculpt.get())) return head;
  return nullptr;
}

// How far below the hairline (metres at 1.70 m) hair standing off the scalp can still be: the
// hair's shell ends 4 mm below the line, rounded over 2 mm. A bob's curtain is exempt: its line is
// taken on the scalp under it, well above its hanging edge.
constexpr float kLooseHairBelowLine = 0.006f;
constexpr int kLipSmoothingRounds = 10;  // Taubin rounds on the lip vertices (smooth_lips)
bool loose_hair_reaches(HairStyle style, const vec3& p, float k) {
  return style == HairStyle::Bob || hair_field(p, k, style) < kLooseHairBelowLine * k;
}

// Material of each vertex: that of the nearest union primitive (a sculpt's own regions: the lips'
// vermilion and the mouth's lining on the head), with hair, brows and lashes drawn by their fields
// instead (avatar_material_borders.hpp), so their edges follow smooth curves.
std::vector<std::uint8_t> surface_materials(const ImplicitBody& body, const Mesh& mesh, const AvatarParams& params,
                                            std::array<vec3, 2> eyes, const NailPlates& nails,
                                            const std::vector<bool>& below_the_waist, const HeadSculpt* head) {
  const float k = params.height / 1.70f;
  std::vector<std::uint8_t> out(mesh.vertex_count(), static_cast<std::uint8_t>(MaterialId::Skin));
  std::vector<float> d(body.primitives.size());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const vec3 p = mesh.positions[v];
    body.distances(p, d);
    std::size_t best = 0;
    for (std::size_t i = 1; i < d.size(); ++i)
      if (d[i] < d[best]) best = i;
    auto m = static_cast<MaterialId>(primitive_material(body.primitives[best], p));
    // Below the top's hem the trunk and legs wear the trousers (not the arms hanging beside them).
    if (m == MaterialId::Cloth && p.y < params.hem * params.height &&
        below_the_waist[static_cast<std::size_t>(body.primitives[best].joint)])
      m = MaterialId::Trousers;
    // Hair that stands off the scalp (a bob's curtain, its underside) is hair wherever it hangs,
    // though never below the hairline, where the hair's shell is cut off (HairSculpt): there the
    // skin stands off the head's sculpt where the neck blends into it, and the shell's cut, nearest
    // by a few millimetres, had left specks of hair on the nape.
    const bool loose_hair = m == MaterialId::Hair && body.primitives[best].shape == PrimitiveShape::Sculpt && head &&
                            head->distance(p) > 0.002f * k && loose_hair_reaches(params.hair, p, k);
    if (!loose_hair && (m == MaterialId::Skin || m == MaterialId::Hair || m == MaterialId::Nail)) {
      m = hair_field(p, k, params.hair) < 0.0f                                          ? MaterialId::Hair
          : eyebrow_field(p, k) < 0.0f                                                  ? MaterialId::Brow
          : lash_field(p, eyes[0], k) < 0.0f || lash_field(p, eyes[1], k) < 0.0f ? MaterialId::Brow
          : nails.field(p) < 0.0f                                                       ? MaterialId::Nail
                                                                                        : MaterialId::Skin;
    }
    out[v] = static_cast<std::uint8_t>(m);
  }
  return out;
}

// The jaw's share of every vertex on the head: the hinge warp's weight at its (open-mouthed)
// position, taken out of the skull's weight.
void add_jaw_weights(const Skeleton& skeleton, const HeadSculpt& head, Mesh& mesh) {
  const int skull = skeleton.find("skullbase"), jaw = skeleton.find("temporomandibular");
  if (skull < 0 || jaw < 0) return;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const float w = head.jaw_weight(mesh.positions[v]);
    if (w <= 0.0f) continue;
    float items[5];
    int joints[5];
    int n = 0;
    float moved = 0.0f;
    for (int i = 0; i < 4; ++i) {
      if (mesh.weights[v][i] <= 0.0f) continue;
      joints[n] = mesh.joints[v][i];
      items[n] = mesh.weights[v][i];
      if (joints[n] == skull) {
        moved = items[n] * w;
        items[n] -= moved;
      }
      ++n;
    }
    if (moved <= 0.0f) continue;
    bool merged = false;
    for (int i = 0; i < n; ++i)
      if (joints[i] == jaw) items[i] += moved, merged = true;
    if (!merged) joints[n] = jaw, items[n] = moved, ++n;
    // Keep the four largest, sorted, normalised.
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (items[j] > items[i]) std::swap(items[i], items[j]), std::swap(joints[i], joints[j]);
    n = std::min(n, 4);
    float total = 0.0f;
    for (int i = 0; i < n; ++i) total += items[i];
    mesh.joints[v] = JointIndices(0);
    mesh.weights[v] = vec4(0.0f);
    for (int i = 0; i < n; ++i) {
      if (items[i] <= 0.0f) continue;
      mesh.joints[v][i] = static_cast<std::uint16_t>(joints[i]);
      mesh.weights[v][i] = items[i] / total;
    }
  }
}

// Turns every vertex about the jaw joint by `degrees` times its jaw weight, as skinning would move
// it (negative closes). Normals turn with it when there are any.
void turn_jaw(const Skeleton& skeleton, float degrees, Mesh& mesh) {
  const int jaw = skeleton.find("temporomandibular");
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  const vec3 pivot(model[static_cast<std::size_t>(jaw)][3]);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    float w = 0.0f;
    for (int i = 0; i < 4; ++i)
      if (mesh.joints[v][i] == jaw) w += mesh.weights[v][i];
    if (w <= 0.0f) continue;
    const quat turn = glm::angleAxis(deg(degrees) * w, vec3(1, 0, 0));
    mesh.positions[v] = pivot + turn * (mesh.positions[v] - pivot);
    if (!mesh.normals.empty()) mesh.normals[v] = turn * mesh.normals[v];
  }
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
  for (int round = 0; round < 24; ++round) {
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

// The lips are cut from a coarse sampling of a sharply curved field (the slit, the rolled
// vermilion, the corners): their vertices keep facets and spikes a few millimetres wide that read as
// jagged lips in close-ups. Taubin's smoothing (a shrinking and an inflating Laplacian step in
// turn, so the lips keep their volume) on the lip vertices only; the skin and the mouth's lining
// around them stay where they are, so the lips stay joined to the face.
void smooth_lips(Mesh& mesh) {
  const auto lips = static_cast<std::uint8_t>(MaterialId::Lips);
  std::vector<std::vector<std::uint32_t>> ring(mesh.vertex_count());
  for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3)
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.indices[f + e], b = mesh.indices[f + (e + 1) % 3];
      if (mesh.materials[a] == lips || mesh.materials[b] == lips) ring[a].push_back(b), ring[b].push_back(a);
    }
  // The lips' meeting line (vertices beside the mouth's lining) stays: it is where the lips touch
  // and where the sites between them are found.
  const auto lining = static_cast<std::uint8_t>(MaterialId::Mouth);
  std::vector<std::uint32_t> moving;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
    if (mesh.materials[v] == lips && !ring[v].empty() &&
        std::none_of(ring[v].begin(), ring[v].end(), [&](std::uint32_t u) { return mesh.materials[u] == lining; }))
      moving.push_back(v);
  std::vector<vec3> next(moving.size());
  for (int step = 0; step < 2 * kLipSmoothingRounds; ++step) {
    const float weight = step % 2 == 0 ? 0.50f : -0.53f;
    for (std::size_t i = 0; i < moving.size(); ++i) {
      const std::uint32_t v = moving[i];
      vec3 centre(0.0f);
      for (std::uint32_t u : ring[v]) centre += mesh.positions[u];
      centre /= static_cast<float>(ring[v].size());
      next[i] = mesh.positions[v] + weight * (centre - mesh.positions[v]);
    }
    for (std::size_t i = 0; i < moving.size(); ++i) mesh.positions[moving[i]] = next[i];
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
  const auto joints = rest_joint_positions(avatar.skeleton);
  const std::array<vec3, 2> eyes{joints[static_cast<std::size_t>(avatar.skeleton.find("l_eyeball_joint"))],
                                 joints[static_cast<std::size_t>(avatar.skeleton.find("r_eyeball_joint"))]};
  const HeadSculpt* head = find_head(body);
  const NailPlates nails(avatar.skeleton, params);
  // The joints the trousers can cover: the trunk and the legs, not the arms (nor the neck and head).
  std::vector<bool> below_the_waist(avatar.skeleton.size(), true);
  for (std::size_t j = 0; j < avatar.skeleton.size(); ++j)
    for (int a = static_cast<int>(j); a >= 0; a = avatar.skeleton.parents[static_cast<std::size_t>(a)])
      if (avatar.skeleton.names[static_cast<std::size_t>(a)].find("sternoclavicular") != std::string::npos ||
          avatar.skeleton.names[static_cast<std::size_t>(a)] == "vc7")
        below_the_waist[j] = false;
  mesh.materials = surface_materials(body, mesh, params, eyes, nails, below_the_waist, head);
  std::vector<MaterialBorder> borders = avatar_material_borders(body, k, params.hair, eyes);
  // The hairline, except where hair stands off the scalp (it stays hair there).
  for (MaterialBorder& border : borders)
    if (border.below == MaterialId::Hair && head)
      // One continuous field (min for "or", max for "and" of the negative sides), so the cut
      // follows a smooth level line: the yes/no test it replaces put the colour's edge wherever
      // the triangles happened to lie, a ragged hairline in side views.
      border.field = [head, k, style = params.hair](const vec3& p) {
        const float line = hair_field(p, k, style);
        const float standing_off = 0.002f * k - head->distance(p);
        const float reaches = style == HairStyle::Bob ? -1.0f : line - kLooseHairBelowLine * k;
        return std::min(line, std::max(standing_off, reaches));
      };
  borders.push_back({MaterialId::Nail, MaterialId::Skin, [&nails](const vec3& p) { return nails.field(p); }});
  const float hem = params.hem * params.height;
  borders.push_back({MaterialId::Trousers, MaterialId::Cloth, [hem](const vec3& p) { return p.y - hem; }});
  if (head)
    borders.push_back({MaterialId::Lips, MaterialId::Skin, [head](const vec3& p) { return head->vermilion(p); }});
  sharpen_material_borders(borders, 0.0005f * k, mesh.positions, mesh.indices, mesh.materials);
  compute_skin_weights(avatar.skeleton, body, options.weights, mesh);
  if (head) add_jaw_weights(avatar.skeleton, *head, mesh);
  // Close the mouth: the jaw's weights undo the hinge warp the surface was made with, so the
  // closed mesh lies on the closed head's field, whose gradient gives the normals; then the lips
  // press together a little more.
  turn_jaw(avatar.skeleton, -proportions::kBindJawOpenDegrees, mesh);
  mesh.normals = surface_normals(build_avatar_volume(avatar.skeleton, params, 0.0f), mesh);
  turn_jaw(avatar.skeleton, -proportions::kLipPressDegrees, mesh);
  unfold(mesh);
  smooth_lips(mesh);
  unfold(mesh);
  append_mesh(mesh, build_face_parts(avatar.skeleton, k));
  mesh.material_colors = material_colors(params.colors);
  mesh.morphs = build_face_morphs(avatar.skeleton, mesh,
                                  head ? head->landmarks() : face_landmarks(params, joints[static_cast<std::size_t>(avatar.skeleton.find("temporomandibular"))]));
  compute_morph_normal_deltas(mesh);
  return avatar;
}

}  // namespace gestura
