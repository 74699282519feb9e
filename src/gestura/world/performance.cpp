#include "gestura/world/performance.hpp"

#include "gestura/anim/track.hpp"

namespace gestura {

std::vector<mat4> object_transforms_at(const Scene& scene, const ScenePerformance& performance, float t) {
  std::vector<mat4> out;
  out.reserve(scene.objects.size());
  for (const SceneObject& o : scene.objects) out.push_back(object_matrix(o, o.door ? o.door->angle : 0.0f));
  for (const DoorMotion& d : performance.doors) {
    if (d.object < 0 || static_cast<std::size_t>(d.object) >= scene.objects.size() || d.angle.empty()) continue;
    out[static_cast<std::size_t>(d.object)] = object_matrix(scene.objects[static_cast<std::size_t>(d.object)], sample_track(d.angle, t));
  }
  return out;
}

}  // namespace gestura
