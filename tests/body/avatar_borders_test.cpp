// Borders between materials read as clean lines: the shirt's cuff and collar
// and the eyebrows.
//
// The renderer blends vertex materials across each triangle, so the visible
// border runs through the midpoints of the edges whose ends differ in material.
// On a lattice that line is a staircase: its direction turns back and forth at
// every step. A clean cuff is a loop that turns once around the arm: total
// absolute turning 2π, a ratio of 1 (any closed curve turns at least that
// much).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_skeleton.hpp"

using namespace gestura;

namespace {

const Avatar& avatar() {
  static const Avatar a = build_avatar();
  return a;
}

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;
EdgeKey key(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

// Total absolute turning of the longest closed border loop between materials
// `a` and `b` among the triangles whose centroid `keep` accepts, divided by 2π;
// `length` receives the loop's length.
float turning_ratio(const Mesh& m, MaterialId a, MaterialId b, const std::function<bool(vec3)>& keep, float step,
                    float& length) {
  const auto ma = static_cast<std::uint8_t>(a), mb = static_cast<std::uint8_t>(b);
  std::map<EdgeKey, std::vector<EdgeKey>> links;  // border crossing edge → the crossing edges it joins
  for (std::size_t f = 0; f + 2 < m.indices.size(); f += 3) {
    const std::uint32_t t[3] = {m.indices[f], m.indices[f + 1], m.indices[f + 2]};
    bool ok = true;
    for (std::uint32_t v : t) ok = ok && (m.materials[v] == ma || m.materials[v] == mb);
    if (!ok || !keep((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0f)) continue;
    std::vector<EdgeKey> mixed;
    for (int k = 0; k < 3; ++k)
      if (m.materials[t[k]] != m.materials[t[(k + 1) % 3]]) mixed.push_back(key(t[k], t[(k + 1) % 3]));
    if (mixed.size() != 2) continue;
    links[mixed[0]].push_back(mixed[1]);
    links[mixed[1]].push_back(mixed[0]);
  }
  auto midpoint = [&](const EdgeKey& e) { return 0.5f * (m.positions[e.first] + m.positions[e.second]); };
  std::map<EdgeKey, bool> seen;
  std::vector<vec3> best;
  for (const auto& [start, _] : links) {
    if (seen[start]) continue;
    std::vector<vec3> loop;
    EdgeKey prev = start, cur = start;
    bool closed = false;
    while (true) {
      seen[cur] = true;
      loop.push_back(midpoint(cur));
      const auto& next = links[cur];
      if (next.size() != 2) break;  // an open end (the region's edge) or a junction
      const EdgeKey n = next[0] == prev && loop.size() > 1 ? next[1] : next[0];
      prev = cur;
      cur = n;
      if (cur == start) {
        closed = true;
        break;
      }
      if (seen[cur]) break;
    }
    if (closed && loop.size() > best.size()) best = loop;
  }
  length = 0.0f;
  if (best.size() < 3) return 0.0f;
  for (std::size_t i = 0; i < best.size(); ++i) length += glm::distance(best[i], best[(i + 1) % best.size()]);
  // Resampled every `step` of arc length: wiggles within the sub-millimetre
  // colour band are invisible; a staircase of lattice steps (3 mm at the hands,
  // 5 mm at the head, 16 mm on the trunk) is not.
  std::vector<vec3> even;
  float along = 0.0f;  // arc length up to best[i]
  for (std::size_t i = 0, k = 0; i < best.size(); ++i) {
    const vec3 p = best[i], q = best[(i + 1) % best.size()];
    const float seg = glm::distance(p, q);
    for (; k * step < along + seg; ++k) even.push_back(glm::mix(p, q, (k * step - along) / seg));
    along += seg;
  }
  float turning = 0.0f;
  const std::size_t n = even.size();
  if (n < 3) return 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    const vec3 d0 = even[i] - even[(i + n - 1) % n], d1 = even[(i + 1) % n] - even[i];
    const float c = glm::dot(d0, d1) / (glm::length(d0) * glm::length(d1));
    turning += std::acos(std::clamp(c, -1.0f, 1.0f));
  }
  return turning / (2.0f * std::numbers::pi_v<float>);
}

vec3 joint(const Avatar& a, const char* name) {
  return rest_joint_positions(a.skeleton)[static_cast<std::size_t>(a.skeleton.find(name))];
}

}  // namespace

TEST(AvatarBorders, CuffCollarAndBrowsAreSmoothLoops) {
  const Avatar& a = avatar();
  const Mesh& m = a.mesh;
  const vec3 wrist = joint(a, "l_wrist"), neck = joint(a, "vc7");
  struct Case {
    const char* what;
    MaterialId below, above;
    std::function<bool(vec3)> keep;
    float min_length;
    // The old lattice-following borders turned 2.9 (cuff) and 5.8 (collar) times; now 1.15, 2.5
    // (the collar has corners where it rises up the sides of the neck) and 1.2 (brow).
    float max_ratio;
  };
  const Case cases[] = {
      {"left cuff", MaterialId::Cloth, MaterialId::Skin, [&](vec3 p) { return glm::distance(p, wrist) < 0.08f; }, 0.10f,
       1.6f},
      {"collar", MaterialId::Cloth, MaterialId::Skin,
       [&](vec3 p) { return std::abs(p.x) < 0.15f && std::abs(p.y - neck.y) < 0.10f; }, 0.25f, 3.0f},
      {"left eyebrow", MaterialId::Brow, MaterialId::Skin, [](vec3 p) { return p.x > 0.0f; }, 0.06f, 1.6f},
  };
  for (const Case& c : cases) {
    float length = 0.0f;
    const float ratio = turning_ratio(m, c.below, c.above, c.keep, 0.004f, length);
    EXPECT_GT(length, c.min_length) << c.what << ": a closed border loop of plausible length";
    EXPECT_GE(ratio, 0.99f) << c.what;
    EXPECT_LT(ratio, c.max_ratio) << c.what << ": the border turns back and forth like a staircase (length " << length
                                  << " m)";
  }
}
