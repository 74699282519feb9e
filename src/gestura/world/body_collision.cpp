#include "gestura/world/body_collision.hpp"

#include <algorithm>

#include "gestura/body/avatar_skeleton.hpp"

namespace gestura {
namespace {

bool below(const Skeleton& s, int joint, int ancestor) {
  for (int j = joint; j >= 0; j = s.parents[static_cast<std::size_t>(j)])
    if (j == ancestor) return true;
  return false;
}

}  // namespace

BodyVolumes make_body_volumes(const Avatar& avatar) {
  const Skeleton& s = avatar.skeleton;
  const Mesh& m = avatar.mesh;
  const std::vector<vec3> at = rest_joint_positions(s);
  // Vertices by their strongest joint.
  std::vector<std::vector<vec3>> carried(s.size());
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (m.weights[v][k] > m.weights[v][best]) best = k;
    carried[m.joints[v][best]].push_back(m.positions[v]);
  }
  const int left_ankle = s.find("l_ankle"), right_ankle = s.find("r_ankle");
  BodyVolumes out;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const std::vector<vec3>& skin = carried[j];
    if (skin.size() < 8) continue;
    vec3 a = at[j], b(0.0f);
    int children = 0;
    for (std::size_t c = j + 1; c < s.size(); ++c)
      if (s.parents[c] == static_cast<std::int16_t>(j)) b += at[c], ++children;
    if (children > 0) {
      b /= static_cast<float>(children);
    } else {
      // An end segment: along its skin's extent from the joint.
      vec3 far = a;
      for (const vec3& p : skin)
        if (glm::length(p - a) > glm::length(far - a)) far = p;
      b = a + (far - a) * 0.75f;
    }
    // Distances of the skin to the segment; the 95th percentile as the radius.
    std::vector<float> d;
    d.reserve(skin.size());
    const vec3 ab = b - a;
    const float len2 = std::max(glm::dot(ab, ab), 1e-12f);
    for (const vec3& p : skin) {
      const float t = std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f);
      d.push_back(glm::length(p - (a + ab * t)));
    }
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() * 95 / 100), d.end());
    const float radius = d[d.size() * 95 / 100];
    BodyCapsule c;
    c.name = s.names[j];
    c.joint = static_cast<int>(j);
    c.a = a - at[j];  // offsets in model axes; turned into the joint's rest frame below
    c.b = b - at[j];
    c.radius = std::max(radius, 0.004f);
    c.foot = (left_ankle >= 0 && below(s, static_cast<int>(j), left_ankle)) || (right_ankle >= 0 && below(s, static_cast<int>(j), right_ankle));
    out.capsules.push_back(c);
  }
  // Joint frames at rest may be rotated: undo the rest model rotation.
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  // The soles: per foot joint, its skin's lowest vertex when it lies near the ground.
  float floor = 1e30f;
  for (const vec3& p : m.positions) floor = std::min(floor, p.y);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const bool foot = (left_ankle >= 0 && below(s, static_cast<int>(j), left_ankle)) || (right_ankle >= 0 && below(s, static_cast<int>(j), right_ankle));
    if (!foot || carried[j].empty()) continue;
    const vec3 lowest = *std::min_element(carried[j].begin(), carried[j].end(), [](const vec3& a, const vec3& b) { return a.y < b.y; });
    if (lowest.y > floor + 0.01f) continue;
    out.soles.push_back({static_cast<int>(j), vec3(glm::inverse(model[j]) * vec4(lowest, 1.0f))});
  }
  for (BodyCapsule& c : out.capsules) {
    const mat3 r = glm::transpose(mat3(model[static_cast<std::size_t>(c.joint)]));
    c.a = r * c.a, c.b = r * c.b;
  }
  return out;
}

void place_capsules(const BodyVolumes& volumes, std::span<const mat4> model, std::vector<WorldCapsule>& out) {
  out.resize(volumes.capsules.size());
  for (std::size_t i = 0; i < volumes.capsules.size(); ++i) {
    const BodyCapsule& c = volumes.capsules[i];
    const mat4& m = model[static_cast<std::size_t>(c.joint)];
    out[i] = WorldCapsule{vec3(m * vec4(c.a, 1.0f)), vec3(m * vec4(c.b, 1.0f)), c.radius, static_cast<int>(i), c.foot};
  }
}

std::optional<Contact> deepest_contact(const Environment& env, const WorldCapsule& c, float margin) {
  Aabb box;
  box.grow(c.a), box.grow(c.b);
  const vec3 grow(c.radius + margin);
  box.min -= grow, box.max += grow;
  std::optional<Contact> best;
  env.bvh.query(box, [&](std::uint32_t t) {
    if (c.foot && env.triangle_walkable[t]) return;
    vec3 a, b, d;
    env.bvh.triangle(t, a, b, d);
    vec3 on_segment, on_triangle;
    const float dist = segment_triangle_distance(c.a, c.b, a, b, d, &on_segment, &on_triangle);
    const float depth = c.radius - dist;
    if (depth < -margin || (best && depth <= best->depth)) return;
    Contact k;
    k.depth = depth;
    k.point = on_triangle;
    const vec3 n = on_segment - on_triangle;
    k.normal = glm::length(n) > 1e-7f ? glm::normalize(n) : env.triangle_normal(t);
    k.capsule = c.capsule;
    k.object = env.triangle_object[t];
    best = k;
  });
  return best;
}

std::vector<Contact> body_contacts(const Environment& env, std::span<const WorldCapsule> body, float tolerance) {
  std::vector<Contact> out;
  for (const WorldCapsule& c : body)
    if (const auto k = deepest_contact(env, c); k && k->depth > tolerance) out.push_back(*k);
  return out;
}

float body_overlap(std::span<const WorldCapsule> a, std::span<const WorldCapsule> b, int* capsule_a, int* capsule_b) {
  // Broad phase: the bodies' boxes.
  Aabb ba, bb;
  for (const WorldCapsule& c : a) ba.grow(c.a - vec3(c.radius)), ba.grow(c.a + vec3(c.radius)), ba.grow(c.b - vec3(c.radius)), ba.grow(c.b + vec3(c.radius));
  for (const WorldCapsule& c : b) bb.grow(c.a - vec3(c.radius)), bb.grow(c.a + vec3(c.radius)), bb.grow(c.b - vec3(c.radius)), bb.grow(c.b + vec3(c.radius));
  if (!ba.overlaps(bb)) {
    const vec3 gap = glm::max(glm::max(ba.min - bb.max, bb.min - ba.max), vec3(0.0f));
    return -glm::length(gap);
  }
  float best = -1e30f;
  for (const WorldCapsule& x : a)
    for (const WorldCapsule& y : b) {
      const float depth = x.radius + y.radius - segment_segment_distance(x.a, x.b, y.a, y.b);
      if (depth > best) {
        best = depth;
        if (capsule_a) *capsule_a = x.capsule;
        if (capsule_b) *capsule_b = y.capsule;
      }
    }
  return best;
}

float sole_penetration(const Environment& env, const BodyVolumes& volumes, std::span<const mat4> model) {
  float worst = -1e30f;
  for (const BodyPoint& s : volumes.soles) {
    const vec3 p = vec3(model[static_cast<std::size_t>(s.joint)] * vec4(s.local, 1.0f));
    const auto g = ground_below(env, vec3(p.x, p.y + 0.3f, p.z), 1.0f);
    if (g) worst = std::max(worst, g->height - p.y);
  }
  return worst;
}

}  // namespace gestura
