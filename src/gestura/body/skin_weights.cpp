#include "gestura/body/skin_weights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// Neighbour lists of a triangle mesh (compressed rows).
struct Adjacency {
  std::vector<std::uint32_t> offsets, neighbours;

  explicit Adjacency(const Mesh& mesh) {
    const std::size_t n = mesh.vertex_count();
    std::vector<std::vector<std::uint32_t>> lists(n);
    for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = mesh.indices[f + k], b = mesh.indices[f + (k + 1) % 3];
        lists[a].push_back(b);
        lists[b].push_back(a);
      }
    offsets.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) {
      std::sort(lists[v].begin(), lists[v].end());
      lists[v].erase(std::unique(lists[v].begin(), lists[v].end()), lists[v].end());
      offsets[v + 1] = offsets[v] + static_cast<std::uint32_t>(lists[v].size());
    }
    neighbours.reserve(offsets[n]);
    for (auto& l : lists) neighbours.insert(neighbours.end(), l.begin(), l.end());
  }
  std::span<const std::uint32_t> of(std::size_t v) const {
    return {neighbours.data() + offsets[v], neighbours.data() + offsets[v + 1]};
  }
};

// A sparse per-vertex weight vector while weights are being assembled.
struct Influences {
  std::vector<std::pair<int, float>> items;
  void add(int joint, float w) {
    if (!(w > 0.0f)) return;
    for (auto& [j, x] : items)
      if (j == joint) {
        x += w;
        return;
      }
    items.emplace_back(joint, w);
  }
};

// Keeps the four largest, normalised; `fallback` takes everything when nothing is left.
void store(const Influences& in, int fallback, JointIndices& joints, vec4& weights) {
  auto items = in.items;
  std::sort(items.begin(), items.end(), [](auto& a, auto& b) { return a.second > b.second || (a.second == b.second && a.first < b.first); });
  if (items.size() > 4) items.resize(4);
  float total = 0.0f;
  for (auto& [j, w] : items) total += w;
  joints = JointIndices(0);
  weights = vec4(0.0f);
  if (!(total > 0.0f)) {
    joints[0] = static_cast<std::uint16_t>(fallback);
    weights[0] = 1.0f;
    return;
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    joints[static_cast<int>(i)] = static_cast<std::uint16_t>(items[i].first);
    weights[static_cast<int>(i)] = items[i].second / total;
  }
}

// Size of a primitive: the radius that sets how far its influence blends.
float primitive_size(const Primitive& p) {
  switch (p.shape) {
    case PrimitiveShape::Capsule: return 0.5f * (p.radius_a + p.radius_b);
    case PrimitiveShape::Ellipsoid: return std::min(p.radii.x, std::min(p.radii.y, p.radii.z));
    case PrimitiveShape::RoundBox: return p.radius_a + std::min(p.radii.x, std::min(p.radii.y, p.radii.z));
    case PrimitiveShape::Sculpt: return p.sculpt->size();
    case PrimitiveShape::HalfSpace: break;
  }
  return 0.0f;
}

struct NearPrimitives {
  std::vector<int> label;                          // joint of the nearest skinned primitive
  std::vector<std::vector<std::pair<int, float>>> near;  // (primitive, distance) within reach
};

NearPrimitives near_primitives(const ImplicitBody& body, const Mesh& mesh, float reach) {
  NearPrimitives out;
  const std::size_t n = mesh.vertex_count();
  out.label.assign(n, 0);
  out.near.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const vec3 p = mesh.positions[v];
    float best = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < body.primitives.size(); ++i) {
      const Primitive& s = body.primitives[i];
      if (!s.skinned) continue;
      if (p.x < s.lo.x - reach || p.y < s.lo.y - reach || p.z < s.lo.z - reach || p.x > s.hi.x + reach ||
          p.y > s.hi.y + reach || p.z > s.hi.z + reach)
        continue;
      const float d = primitive_distance(s, p);
      if (d > reach) continue;
      out.near[v].emplace_back(static_cast<int>(i), d);
      if (d < best) {
        best = d;
        out.label[v] = s.joint;
      }
    }
  }
  return out;
}

void influence_spheres(const Skeleton& skeleton, const ImplicitBody& body, const NearPrimitives& near, Mesh& mesh) {
  const std::size_t nj = skeleton.size();
  std::vector<mat4> model(nj);
  local_to_model(skeleton, rest_pose(skeleton), model);
  // ρ of a joint: the girth of the limb starting there (its primitives' size), a little enlarged.
  std::vector<float> rho(nj, 0.0f);
  for (const Primitive& s : body.primitives)
    if (s.skinned) rho[static_cast<std::size_t>(s.joint)] = std::max(rho[static_cast<std::size_t>(s.joint)], primitive_size(s));
  for (float& r : rho) r *= 1.8f;  // the sphere must reach the skin around the joint
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const int label = near.label[v];
    Influences in;
    bool in_sphere = false;
    for (std::size_t j = 0; j < nj; ++j) {
      const int parent = skeleton.parents[j];
      if (parent < 0 || rho[j] <= 0.0f) continue;
      const float alpha = label == static_cast<int>(j) ? 1.0f : label == parent ? -1.0f : 0.0f;
      if (alpha == 0.0f) continue;
      const float d = glm::length(mesh.positions[v] - vec3(model[j][3]));
      if (d >= rho[j]) continue;
      const float w = 0.5f * (rho[j] + alpha * d) / rho[j];
      in.add(static_cast<int>(j), w);
      in.add(parent, 1.0f - w);
      in_sphere = true;
    }
    if (!in_sphere) in.add(label, 1.0f);
    store(in, label, mesh.joints[v], mesh.weights[v]);
  }
}

void two_layer_bending(const NearPrimitives& near, const Adjacency& adj, Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  // Layer 1: vertices with a neighbour on another segment (shared by two segments).
  std::vector<int> other(n, -1);
  for (std::size_t v = 0; v < n; ++v)
    for (std::uint32_t u : adj.of(v))
      if (near.label[u] != near.label[v]) {
        other[v] = near.label[u];
        break;
      }
  for (std::size_t v = 0; v < n; ++v) {
    Influences in;
    const int own = near.label[v];
    if (other[v] >= 0) {
      in.add(own, 0.5f);
      in.add(other[v], 0.5f);
    } else {
      // Layer 2: next to a shared vertex, bending 0.8 / 0.2 towards that vertex's other segment.
      int second = -1;
      for (std::uint32_t u : adj.of(v))
        if (other[u] >= 0 && other[u] != own) {
          second = other[u];
          break;
        }
      in.add(own, second >= 0 ? 0.8f : 1.0f);
      if (second >= 0) in.add(second, 0.2f);
    }
    store(in, own, mesh.joints[v], mesh.weights[v]);
  }
}

// The bones a vertex may follow: those within two steps, in the skeleton tree, of the bone it lies
// on. A farther bone can be near in space only — the upper arm hanging beside the chest wall — and
// its share is handed to the bone two steps along the tree path towards it (the clavicle, for the
// chest), which bends the region between without dragging it along: with the arm raised the chest
// wall stays put and the armpit folds instead of stretching into a web.
class TreeReach {
 public:
  explicit TreeReach(const Skeleton& skeleton) : parents_(skeleton.parents.begin(), skeleton.parents.end()) {}

  int stand_in(int own, int joint) const {
    // Steps from `own` up to each ancestor, then from `joint` up to the first shared one.
    std::vector<int> up_own;
    for (int a = own; a >= 0; a = parents_[static_cast<std::size_t>(a)]) up_own.push_back(a);
    std::vector<int> up_joint;
    int lca_steps = -1;
    for (int a = joint; a >= 0; a = parents_[static_cast<std::size_t>(a)]) {
      const auto it = std::find(up_own.begin(), up_own.end(), a);
      if (it != up_own.end()) {
        lca_steps = static_cast<int>(it - up_own.begin());
        break;
      }
      up_joint.push_back(a);
    }
    if (lca_steps < 0) return own;  // separate trees
    const int from_own = lca_steps, from_joint = static_cast<int>(up_joint.size());
    if (from_own + from_joint <= 2) return joint;
    if (from_own >= 2) return up_own[2];
    // Two steps from `own`, going down towards `joint` (up_joint lists joint … child of the LCA).
    return up_joint[static_cast<std::size_t>(from_joint - (2 - from_own))];
  }

 private:
  std::vector<std::int16_t> parents_;
};

void field_diffused(const Skeleton& skeleton, const ImplicitBody& body, const NearPrimitives& near, const Adjacency& adj,
                    Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  // Dense per-vertex weights over the few joints near each vertex, kept sparse as Influences.
  std::vector<Influences> w(n);
  for (std::size_t v = 0; v < n; ++v) {
    float best = std::numeric_limits<float>::infinity();
    float best_size = 0.0f;
    for (auto [i, d] : near.near[v])
      if (d < best) best = d, best_size = primitive_size(body.primitives[static_cast<std::size_t>(i)]);
    for (auto [i, d] : near.near[v]) {
      const Primitive& s = body.primitives[static_cast<std::size_t>(i)];
      const float sigma = 0.6f * std::min(primitive_size(s), best_size) + 1e-4f;
      const float x = std::max(0.0f, 1.0f - (d - best) / sigma);
      w[v].add(s.joint, x * x);
    }
    if (w[v].items.empty()) w[v].add(near.label[v], 1.0f);
  }
  // Normalise, then diffuse: each round moves every vertex halfway to its neighbours' mean.
  auto normalise = [](Influences& in) {
    float t = 0.0f;
    for (auto& [j, x] : in.items) t += x;
    for (auto& [j, x] : in.items) x /= t;
  };
  for (auto& in : w) normalise(in);
  auto diffuse = [&](int rounds) {
    for (int round = 0; round < rounds; ++round) {
      std::vector<Influences> next(n);
      for (std::size_t v = 0; v < n; ++v) {
        const auto nb = adj.of(v);
        for (auto [j, x] : w[v].items) next[v].add(j, 0.5f * x);
        if (nb.empty()) continue;
        const float share = 0.5f / static_cast<float>(nb.size());
        for (std::uint32_t u : nb)
          for (auto [j, x] : w[u].items) next[v].add(j, share * x);
      }
      // Drop negligible influences so the vectors stay short.
      for (auto& in : next) {
        std::erase_if(in.items, [](auto& item) { return item.second < 0.01f; });
        normalise(in);
      }
      w = std::move(next);
    }
  };
  diffuse(6);
  // Only bones near in the skeleton; two more rounds soften the fold this leaves at the armpit.
  const TreeReach reach(skeleton);
  for (std::size_t v = 0; v < n; ++v) {
    Influences kept;
    for (auto [j, x] : w[v].items) kept.add(reach.stand_in(near.label[v], j), x);
    w[v] = std::move(kept);
  }
  diffuse(2);
  for (std::size_t v = 0; v < n; ++v) store(w[v], near.label[v], mesh.joints[v], mesh.weights[v]);
}

}  // namespace

std::string_view to_string(SkinWeightMethod method) {
  switch (method) {
    case SkinWeightMethod::InfluenceSpheres: return "spheres";
    case SkinWeightMethod::TwoLayerBending: return "two-layer";
    case SkinWeightMethod::FieldDiffused: break;
  }
  return "field";
}

SkinWeightMethod parse_skin_weight_method(std::string_view text) {
  for (SkinWeightMethod m :
       {SkinWeightMethod::InfluenceSpheres, SkinWeightMethod::TwoLayerBending, SkinWeightMethod::FieldDiffused})
    if (to_string(m) == text) return m;
  throw Error("skin weight method '" + std::string(text) + "' is not one of spheres, two-layer, field");
}

void compute_skin_weights(const Skeleton& skeleton, const ImplicitBody& body, SkinWeightMethod method, Mesh& mesh) {
  mesh.joints.assign(mesh.vertex_count(), JointIndices(0));
  mesh.weights.assign(mesh.vertex_count(), vec4(0.0f));
  const NearPrimitives near = near_primitives(body, mesh, 0.05f);
  switch (method) {
    case SkinWeightMethod::InfluenceSpheres: influence_spheres(skeleton, body, near, mesh); break;
    case SkinWeightMethod::TwoLayerBending: two_layer_bending(near, Adjacency(mesh), mesh); break;
    case SkinWeightMethod::FieldDiffused: field_diffused(skeleton, body, near, Adjacency(mesh), mesh); break;
  }
}

}  // namespace gestura
