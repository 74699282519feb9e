#include "gestura/body/morph.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

void check(const char* what, std::size_t rest, std::size_t out, std::size_t morphs, std::size_t weights) {
  if (rest != out || morphs != weights)
    throw Error(std::string(what) + ": " + std::to_string(rest) + " rest vertices but " + std::to_string(out) +
                " outputs, " + std::to_string(morphs) + " targets but " + std::to_string(weights) + " weights");
}

void check_target(const MorphTarget& target, std::size_t deltas, std::size_t vertex_count) {
  if (target.vertices.size() != deltas)
    throw Error("morph target '" + target.name + "': " + std::to_string(target.vertices.size()) +
                " vertices but " + std::to_string(deltas) + " deltas");
  for (std::size_t e = 0; e < target.vertices.size(); ++e)
    if (target.vertices[e] >= vertex_count)
      throw Error("morph target '" + target.name + "', entry " + std::to_string(e) + ": vertex " +
                  std::to_string(target.vertices[e]) + " outside the mesh (" + std::to_string(vertex_count) +
                  " vertices)");
}

}  // namespace

void apply_morphs(std::span<const vec3> rest_positions, std::span<const MorphTarget> morphs,
                  std::span<const float> weights, std::span<vec3> out_positions) {
  check("apply_morphs", rest_positions.size(), out_positions.size(), morphs.size(), weights.size());
  std::copy(rest_positions.begin(), rest_positions.end(), out_positions.begin());
  for (std::size_t i = 0; i < morphs.size(); ++i) {
    const float w = weights[i];
    if (w == 0.0f) continue;
    const MorphTarget& target = morphs[i];
    check_target(target, target.position_deltas.size(), out_positions.size());
    for (std::size_t e = 0; e < target.vertices.size(); ++e) out_positions[target.vertices[e]] += w * target.position_deltas[e];
  }
}

void apply_morph_normals(std::span<const vec3> rest_normals, std::span<const MorphTarget> morphs,
                         std::span<const float> weights, std::span<vec3> out_normals) {
  check("apply_morph_normals", rest_normals.size(), out_normals.size(), morphs.size(), weights.size());
  std::copy(rest_normals.begin(), rest_normals.end(), out_normals.begin());
  bool any = false;
  for (std::size_t i = 0; i < morphs.size(); ++i) {
    const float w = weights[i];
    const MorphTarget& target = morphs[i];
    if (w == 0.0f || target.normal_deltas.empty()) continue;
    check_target(target, target.normal_deltas.size(), out_normals.size());
    for (std::size_t e = 0; e < target.vertices.size(); ++e) out_normals[target.vertices[e]] += w * target.normal_deltas[e];
    any = true;
  }
  if (!any) return;
  // Renormalise only what moved; normalising twice is harmless for vertices in several targets.
  for (std::size_t i = 0; i < morphs.size(); ++i) {
    if (weights[i] == 0.0f || morphs[i].normal_deltas.empty()) continue;
    for (std::uint32_t v : morphs[i].vertices) {
      const float len = glm::length(out_normals[v]);
      if (len > 0.0f) out_normals[v] /= len;
    }
  }
}

}  // namespace gestura
