#include "gestura/serve/clip_glb.hpp"

#include "gestura/io/gltf_animation.hpp"

namespace gestura::serve {

std::string clip_glb(const Skeleton& skeleton, const Clip& clip, const Mesh& avatar_mesh, const nlohmann::json& extras) {
  // The stand-in: one small triangle on the root, every target a zero offset of one vertex.
  Mesh stand_in;
  stand_in.positions = {vec3(0.0f), vec3(0.001f, 0.0f, 0.0f), vec3(0.0f, 0.001f, 0.0f)};
  stand_in.joints.assign(3, JointIndices(0));
  stand_in.weights.assign(3, vec4(1, 0, 0, 0));
  stand_in.indices = {0, 1, 2};
  for (const MorphTarget& m : avatar_mesh.morphs) stand_in.morphs.push_back({m.name, {0}, {vec3(0.0f)}, {}});
  GltfDocument doc = make_gltf(skeleton, clip, stand_in.morphs.empty() ? nullptr : &stand_in);
  nlohmann::json json = nlohmann::json::parse(doc.json);
  if (json.contains("animations") && !json["animations"].empty()) json["animations"][0]["extras"] = extras;
  else json["asset"]["extras"] = extras;
  doc.json = json.dump();
  return pack_glb(doc);
}

}  // namespace gestura::serve
