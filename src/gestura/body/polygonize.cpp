#include "gestura/body/polygonize.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

constexpr int kBlock = 8;
constexpr int kBlockNodes = kBlock + 1;

// Cube corners: bit 0 = +x, bit 1 = +y, bit 2 = +z.
constexpr std::array<std::array<int, 2>, 12> kEdgeCorners{{{0, 1}, {2, 3}, {4, 5}, {6, 7},  // x
                                                           {0, 2}, {1, 3}, {4, 6}, {5, 7},  // y
                                                           {0, 4}, {1, 5}, {2, 6}, {3, 7}}};  // z
constexpr int edge_axis(int e) { return e / 4; }

int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((kEdgeCorners[e][0] == a && kEdgeCorners[e][1] == b) || (kEdgeCorners[e][0] == b && kEdgeCorners[e][1] == a))
      return e;
  return -1;
}

struct Face {
  std::array<int, 4> corners;  // cyclic
  vec3 normal;                 // outward
};
constexpr std::array<Face, 6> kFaces{{{{0, 2, 6, 4}, {-1, 0, 0}},
                                      {{1, 3, 7, 5}, {1, 0, 0}},
                                      {{0, 1, 5, 4}, {0, -1, 0}},
                                      {{2, 3, 7, 6}, {0, 1, 0}},
                                      {{0, 1, 3, 2}, {0, 0, -1}},
                                      {{4, 5, 7, 6}, {0, 0, 1}}}};

vec3 corner_position(int c) { return vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); }

bool inside(float v) { return v < 0.0f; }

float crossing(float v0, float v1) { return std::clamp(v0 / (v0 - v1), 1e-3f, 1.0f - 1e-3f); }

// Polygon edges of one cube: next[e] = the crossing edge that follows e around its polygon.
// Returns false when the cube has no crossing.
bool cube_cycles(const std::array<float, 8>& v, std::array<int, 12>& next) {
  next.fill(-1);
  bool any = false;
  std::array<vec3, 12> point{};
  for (int e = 0; e < 12; ++e) {
    const int a = kEdgeCorners[e][0], b = kEdgeCorners[e][1];
    if (inside(v[a]) == inside(v[b])) continue;
    any = true;
    point[e] = glm::mix(corner_position(a), corner_position(b), crossing(v[a], v[b]));
  }
  if (!any) return false;
  for (const Face& f : kFaces) {
    std::array<int, 4> edges{};
    std::array<int, 4> crossing_slots{};
    int n = 0;
    for (int m = 0; m < 4; ++m) {
      const int a = f.corners[m], b = f.corners[(m + 1) % 4];
      edges[m] = edge_between(a, b);
      if (inside(v[a]) != inside(v[b])) crossing_slots[n++] = m;
    }
    std::array<std::array<int, 2>, 2> segments{};
    int segment_count = 0;
    if (n == 2) {
      segments[0] = {edges[crossing_slots[0]], edges[crossing_slots[1]]};
      segment_count = 1;
    } else if (n == 4) {
      const float a = v[f.corners[0]], b = v[f.corners[1]], c = v[f.corners[2]], d = v[f.corners[3]];
      const float denom = a + c - b - d;
      const float saddle = denom != 0.0f ? (a * c - b * d) / denom : a;
      if (inside(saddle) == inside(a)) {  // corners 0 and 2 connected: cut off corners 1 and 3
        segments[0] = {edges[0], edges[1]};
        segments[1] = {edges[2], edges[3]};
      } else {  // cut off corners 0 and 2
        segments[0] = {edges[3], edges[0]};
        segments[1] = {edges[1], edges[2]};
      }
      segment_count = 2;
    }
    for (int s = 0; s < segment_count; ++s) {
      const int ep = segments[s][0], eq = segments[s][1];
      const vec3 p = point[ep], q = point[eq];
      const int c = kEdgeCorners[ep][0];
      const vec3 d = q - p;
      vec3 w = corner_position(c) - p;
      w -= d * (glm::dot(w, d) / glm::dot(d, d));
      const vec3 outward = inside(v[c]) ? -w : w;
      // Counter-clockwise seen from outside the surface keeps the polygon's interior (inside the
      // cube) on the left: the direction of travel is outward × face normal.
      if (glm::dot(d, glm::cross(outward, f.normal)) > 0.0f)
        next[ep] = eq;
      else
        next[eq] = ep;
    }
  }
  return true;
}

}  // namespace


namespace {

// One lattice: nodes origin + h·(i, j, k), `cells` cells per axis; only cells for which `emit`
// is true produce triangles. Blocks of 8³ cells far from the surface are skipped.
template <class Emit>
void polygonize_lattice(const ImplicitBody& body, vec3 origin, float h, glm::ivec3 cells, Emit emit,
                        Polygonization& out) {
  const int bx = (cells.x + kBlock - 1) / kBlock, by = (cells.y + kBlock - 1) / kBlock, bz = (cells.z + kBlock - 1) / kBlock;
  const std::size_t block_count = static_cast<std::size_t>(bx) * by * bz;
  auto block_id = [&](int i, int j, int k) {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(bx) * (j + static_cast<std::size_t>(by) * k);
  };
  auto node = [&](int i, int j, int k) { return origin + h * vec3(i, j, k); };

  // Coarse pass: a block whose centre is farther from the surface than its half-diagonal has one
  // sign (the field is about 1-Lipschitz).
  const float half_diagonal = 0.5f * std::sqrt(3.0f) * kBlock * h;
  std::vector<float> centre_value(block_count);
  std::vector<int> state(block_count, -1);  // -1 culled, 0 queued or done
  std::vector<std::array<int, 3>> queue;
  for (int k = 0; k < bz; ++k)
    for (int j = 0; j < by; ++j)
      for (int i = 0; i < bx; ++i) {
        const float f = body.field(node(i * kBlock, j * kBlock, k * kBlock) + 0.5f * kBlock * h, 2.0f * half_diagonal);
        centre_value[block_id(i, j, k)] = f;
        if (std::abs(f) <= 1.25f * half_diagonal) {
          queue.push_back({i, j, k});
          state[block_id(i, j, k)] = 0;
        }
      }

  // Fine pass over active blocks; a block whose boundary disagrees with a culled neighbour's sign
  // activates that neighbour, so a culled block can never cut the surface.
  const float band = 2.0f * h;
  std::vector<std::vector<float>> values;
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const auto [bi, bj, bk] = queue[q];
    std::vector<float> vals(kBlockNodes * kBlockNodes * kBlockNodes);
    for (int k = 0; k < kBlockNodes; ++k)
      for (int j = 0; j < kBlockNodes; ++j)
        for (int i = 0; i < kBlockNodes; ++i)
          vals[i + kBlockNodes * (j + kBlockNodes * k)] =
              body.field(node(bi * kBlock + i, bj * kBlock + j, bk * kBlock + k), band);
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        std::array<int, 3> nb{bi, bj, bk};
        nb[axis] += side ? 1 : -1;
        if (nb[0] < 0 || nb[1] < 0 || nb[2] < 0 || nb[0] >= bx || nb[1] >= by || nb[2] >= bz) continue;
        const std::size_t id = block_id(nb[0], nb[1], nb[2]);
        if (state[id] != -1) continue;
        const bool nb_inside = inside(centre_value[id]);
        bool differs = false;
        for (int s = 0; s < kBlockNodes && !differs; ++s)
          for (int t = 0; t < kBlockNodes && !differs; ++t) {
            std::array<int, 3> n{};
            n[axis] = side ? kBlock : 0;
            n[(axis + 1) % 3] = s;
            n[(axis + 2) % 3] = t;
            differs = inside(vals[n[0] + kBlockNodes * (n[1] + kBlockNodes * n[2])]) != nb_inside;
          }
        if (differs) {
          state[id] = 0;
          queue.push_back(nb);
        }
      }
    values.push_back(std::move(vals));
  }
  out.active_blocks += static_cast<int>(queue.size());

  const std::uint64_t nx = static_cast<std::uint64_t>(bx) * kBlock + 1, ny = static_cast<std::uint64_t>(by) * kBlock + 1;
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_edge;
  vertex_of_edge.reserve(queue.size() * 256);
  for (std::size_t a = 0; a < queue.size(); ++a) {
    const auto [bi, bj, bk] = queue[a];
    const std::vector<float>& vv = values[a];
    for (int k = 0; k < kBlock; ++k)
      for (int j = 0; j < kBlock; ++j)
        for (int i = 0; i < kBlock; ++i) {
          const int gi = bi * kBlock + i, gj = bj * kBlock + j, gk = bk * kBlock + k;
          if (gi >= cells.x || gj >= cells.y || gk >= cells.z || !emit(gi, gj, gk)) continue;
          std::array<float, 8> v{};
          for (int c = 0; c < 8; ++c)
            v[c] = vv[(i + (c & 1)) + kBlockNodes * ((j + ((c >> 1) & 1)) + kBlockNodes * (k + ((c >> 2) & 1)))];
          std::array<int, 12> next{};
          if (!cube_cycles(v, next)) continue;
          auto vertex = [&](int e) {
            const int c0 = kEdgeCorners[e][0];
            const std::uint64_t ni = gi + (c0 & 1), nj = gj + ((c0 >> 1) & 1), nk = gk + ((c0 >> 2) & 1);
            const std::uint64_t key = ((nk * ny + nj) * nx + ni) * 3 + static_cast<std::uint64_t>(edge_axis(e));
            auto [it, fresh] = vertex_of_edge.try_emplace(key, static_cast<std::uint32_t>(out.positions.size()));
            if (fresh) {
              const int c1 = kEdgeCorners[e][1];
              const vec3 local = glm::mix(corner_position(c0), corner_position(c1), crossing(v[c0], v[c1]));
              out.positions.push_back(node(gi, gj, gk) + h * local);
            }
            return it->second;
          };
          std::array<bool, 12> used{};
          for (int e = 0; e < 12; ++e) {
            if (next[e] < 0 || used[e]) continue;
            std::array<int, 12> cycle{};
            int n = 0;
            for (int x = e; !used[x] && n < 12; x = next[x]) {
              used[x] = true;
              cycle[n++] = x;
              if (next[x] < 0) throw Error("polygonize: open polygon in a cube (inconsistent orientation)");
            }
            const std::uint32_t first = vertex(cycle[0]);
            for (int m = 1; m + 1 < n; ++m) {
              out.indices.push_back(first);
              out.indices.push_back(vertex(cycle[m]));
              out.indices.push_back(vertex(cycle[m + 1]));
            }
          }
        }
  }
}

// The primitives that can affect the field inside [lo, hi] (others are farther than `band` plus
// their blend), in their original order: the same field there, much cheaper to evaluate.
ImplicitBody primitives_near(const ImplicitBody& body, vec3 lo, vec3 hi, float band) {
  ImplicitBody near;
  for (const Primitive& p : body.primitives) {
    const float m = band + p.blend;
    const bool overlaps = p.op == BlendOp::Intersect ||
                          (p.lo.x <= hi.x + m && p.hi.x >= lo.x - m && p.lo.y <= hi.y + m && p.hi.y >= lo.y - m &&
                           p.lo.z <= hi.z + m && p.hi.z >= lo.z - m);
    if (overlaps) near.primitives.push_back(p);
  }
  near.finish();
  return near;
}

// Boundary loops of an open mesh, each in the direction its triangles traverse it.
std::vector<std::vector<std::uint32_t>> boundary_loops(const Polygonization& mesh) {
  std::unordered_map<std::uint64_t, int> uses;
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  };
  for (std::size_t f = 0; f < mesh.indices.size(); f += 3)
    for (int k = 0; k < 3; ++k) ++uses[key(mesh.indices[f + k], mesh.indices[f + (k + 1) % 3])];
  std::unordered_map<std::uint32_t, std::uint32_t> next;
  for (std::size_t f = 0; f < mesh.indices.size(); f += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[f + k], b = mesh.indices[f + (k + 1) % 3];
      if (uses[key(a, b)] != 1) continue;
      if (!next.emplace(a, b).second) throw Error("polygonize: boundary loops touch at a vertex");
    }
  std::vector<std::vector<std::uint32_t>> loops;
  while (!next.empty()) {
    std::vector<std::uint32_t> loop;
    std::uint32_t v = next.begin()->first;
    while (true) {
      auto it = next.find(v);
      if (it == next.end()) break;
      loop.push_back(v);
      v = it->second;
      next.erase(it);
    }
    if (loop.empty() || v != loop.front()) throw Error("polygonize: boundary is not a closed loop");
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Closes the gap between two boundary loops around the same tube with a band of triangles,
// always advancing on the loop that gives the shorter new diagonal.
void zip_loops(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b, Polygonization& mesh) {
  const std::size_t na = a.size(), nb = b.size();
  const auto& P = mesh.positions;
  std::size_t jb = 0;
  for (std::size_t j = 1; j < nb; ++j)
    if (glm::distance(P[b[j]], P[a[0]]) < glm::distance(P[b[jb]], P[a[0]])) jb = j;
  std::size_t ia = 0, steps_a = 0, steps_b = 0;
  while (steps_a < na || steps_b < nb) {
    const std::size_t prev_a = (ia + na - 1) % na, next_b = (jb + 1) % nb;
    const bool advance_a =
        steps_b == nb || (steps_a < na && glm::distance(P[a[prev_a]], P[b[jb]]) <= glm::distance(P[a[ia]], P[b[next_b]]));
    if (advance_a) {
      mesh.indices.insert(mesh.indices.end(), {a[ia], a[prev_a], b[jb]});
      ia = prev_a;
      ++steps_a;
    } else {
      mesh.indices.insert(mesh.indices.end(), {b[next_b], b[jb], a[ia]});
      jb = next_b;
      ++steps_b;
    }
  }
}

}  // namespace

Polygonization polygonize(const ImplicitBody& body, const PolygonizeOptions& options) {
  const float h = options.cell;
  if (!(h > 0.0f) || !std::isfinite(h)) throw Error("polygonize: cell size must be positive");
  vec3 lo = body.lo, hi = body.hi;
  for (const DetailBox& box : options.detail) {
    if (box.refine < 1 || box.refine > 16) throw Error("polygonize: detail box refine must be 1 .. 16");
    if (box.open_axis < 0 || box.open_axis > 2) throw Error("polygonize: detail box open_axis must be 0, 1 or 2");
    lo = glm::min(lo, box.lo);
    hi = glm::max(hi, box.hi);
  }
  const vec3 origin = lo - vec3(2.0f * h);
  const glm::ivec3 cells = glm::ivec3(glm::ceil((hi + vec3(2.0f * h) - origin) / h));

  // Boxes snapped outwards to coarse lattice planes; the coarse pass also leaves one cell of gap
  // beyond the open face, which the zipper band closes.
  struct Snapped {
    glm::ivec3 lo, hi;  // cells [lo, hi)
    glm::ivec3 gap_lo, gap_hi;
  };
  std::vector<Snapped> boxes;
  for (const DetailBox& box : options.detail) {
    Snapped s;
    s.lo = glm::ivec3(glm::floor((box.lo - origin) / h));
    s.hi = glm::ivec3(glm::ceil((box.hi - origin) / h));
    s.gap_lo = s.lo;
    s.gap_hi = s.hi;
    (box.open_side > 0 ? s.gap_hi[box.open_axis] : s.gap_lo[box.open_axis]) += box.open_side > 0 ? 1 : -1;
    boxes.push_back(s);
  }
  Polygonization out;
  polygonize_lattice(body, origin, h, cells,
                     [&](int i, int j, int k) {
                       for (const Snapped& s : boxes)
                         if (i >= s.gap_lo.x && i < s.gap_hi.x && j >= s.gap_lo.y && j < s.gap_hi.y && k >= s.gap_lo.z &&
                             k < s.gap_hi.z)
                           return false;
                       return true;
                     },
                     out);
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const int m = options.detail[b].refine;
    const vec3 box_lo = origin + h * vec3(boxes[b].lo), box_hi = origin + h * vec3(boxes[b].hi);
    polygonize_lattice(primitives_near(body, box_lo, box_hi, 4.0f * h), box_lo, h / static_cast<float>(m),
                       (boxes[b].hi - boxes[b].lo) * m, [](int, int, int) { return true; }, out);
  }
  if (boxes.empty()) return out;

  // Each box must leave exactly two loops: the fine one on its open face and the coarse one a
  // cell further out.
  const auto loops = boundary_loops(out);
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const DetailBox& box = options.detail[b];
    const int axis = box.open_axis;
    const int face = box.open_side > 0 ? boxes[b].hi[axis] : boxes[b].lo[axis];
    const float fine_plane = origin[axis] + h * static_cast<float>(face);
    const float coarse_plane = fine_plane + h * static_cast<float>(box.open_side > 0 ? 1 : -1);
    const std::vector<std::uint32_t>*fine = nullptr, *coarse = nullptr;
    int count = 0;
    for (const auto& loop : loops) {
      const vec3 p = out.positions[loop.front()];
      const bool in_box = [&] {
        for (int a = 0; a < 3; ++a)
          if (a != axis && (p[a] < origin[a] + h * boxes[b].lo[a] - 1e-4f || p[a] > origin[a] + h * boxes[b].hi[a] + 1e-4f))
            return false;
        return true;
      }();
      if (!in_box) continue;
      if (std::abs(p[axis] - fine_plane) < 1e-4f) fine = &loop, ++count;
      if (std::abs(p[axis] - coarse_plane) < 1e-4f) coarse = &loop, ++count;
    }
    if (!fine || !coarse || count != 2)
      throw Error("polygonize: detail box " + std::to_string(b) +
                  " must be entered by the surface through its open face only, once (found " + std::to_string(count) +
                  " loops, fine " + (fine ? "yes" : "no") + ", coarse " + (coarse ? "yes" : "no") + ")");
    zip_loops(*fine, *coarse, out);
  }
  if (boundary_loops(out).size() != 0)
    throw Error("polygonize: the surface leaves a detail box through a face other than its open face");
  return out;
}

}  // namespace gestura
