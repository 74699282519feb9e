#include "gestura/body/implicit_body.hpp"

#include <algorithm>
#include <limits>

namespace gestura {
namespace {

// Polynomial smooth minimum: equals min(a, b) once |a − b| ≥ k, rounds the crease within k.
float smooth_min(float a, float b, float k) {
  if (k <= 0.0f) return std::min(a, b);
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}
float smooth_max(float a, float b, float k) { return -smooth_min(-a, -b, k); }

float apply(BlendOp op, float field, float d, float k) {
  switch (op) {
    case BlendOp::Union: return smooth_min(field, d, k);
    case BlendOp::Subtract: return smooth_max(field, -d, k);
    case BlendOp::Intersect: return smooth_max(field, d, k);
  }
  return field;
}

bool outside_box(const Primitive& s, const vec3& p, float margin) {
  return p.x < s.lo.x - margin || p.y < s.lo.y - margin || p.z < s.lo.z - margin || p.x > s.hi.x + margin ||
         p.y > s.hi.y + margin || p.z > s.hi.z + margin;
}

}  // namespace

float primitive_distance(const Primitive& s, const vec3& p) {
  switch (s.shape) {
    case PrimitiveShape::Capsule: {
      const vec3 ba = s.b - s.a, pa = p - s.a;
      const float len2 = glm::dot(ba, ba);
      const float t = len2 > 0.0f ? std::clamp(glm::dot(pa, ba) / len2, 0.0f, 1.0f) : 0.0f;
      return glm::length(pa - ba * t) - (s.radius_a + (s.radius_b - s.radius_a) * t);
    }
    case PrimitiveShape::Ellipsoid: {
      const vec3 q = glm::transpose(s.axes) * (p - s.a);
      const float k0 = glm::length(q / s.radii);
      const float k1 = glm::length(q / (s.radii * s.radii));
      if (k1 <= 0.0f) return -std::min(s.radii.x, std::min(s.radii.y, s.radii.z));
      return k0 * (k0 - 1.0f) / k1;
    }
    case PrimitiveShape::RoundBox: {
      const vec3 q = glm::abs(glm::transpose(s.axes) * (p - s.a)) - s.radii;
      return glm::length(glm::max(q, vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f) - s.radius_a;
    }
    case PrimitiveShape::HalfSpace: return glm::dot(p - s.a, s.axes[1]);
    case PrimitiveShape::Sculpt: return s.sculpt->distance(glm::transpose(s.axes) * (p - s.a));
  }
  return std::numeric_limits<float>::infinity();
}

std::uint8_t primitive_material(const Primitive& s, const vec3& p) {
  if (s.shape == PrimitiveShape::Sculpt) {
    const int m = s.sculpt->material(glm::transpose(s.axes) * (p - s.a));
    if (m >= 0) return static_cast<std::uint8_t>(m);
  }
  return s.material;
}

void ImplicitBody::finish() {
  constexpr float inf = std::numeric_limits<float>::infinity();
  lo = vec3(inf);
  hi = vec3(-inf);
  for (Primitive& s : primitives) {
    vec3 extent(0.0f);
    switch (s.shape) {
      case PrimitiveShape::Capsule:
        s.lo = glm::min(s.a - s.radius_a, s.b - s.radius_b);
        s.hi = glm::max(s.a + s.radius_a, s.b + s.radius_b);
        break;
      case PrimitiveShape::Ellipsoid:
      case PrimitiveShape::RoundBox: {
        const float round = s.shape == PrimitiveShape::RoundBox ? s.radius_a : 0.0f;
        for (int i = 0; i < 3; ++i) {
          float e = 0.0f;
          for (int j = 0; j < 3; ++j) e += std::abs(s.axes[j][i]) * s.radii[j];
          extent[i] = e + round;
        }
        s.lo = s.a - extent;
        s.hi = s.a + extent;
        break;
      }
      case PrimitiveShape::HalfSpace:
        s.lo = vec3(-inf);
        s.hi = vec3(inf);
        break;
      case PrimitiveShape::Sculpt: {
        vec3 box_lo, box_hi;
        s.sculpt->bounds(box_lo, box_hi);
        s.lo = vec3(inf);
        s.hi = vec3(-inf);
        for (int c = 0; c < 8; ++c) {
          const vec3 corner(c & 1 ? box_hi.x : box_lo.x, c & 2 ? box_hi.y : box_lo.y, c & 4 ? box_hi.z : box_lo.z);
          const vec3 q = s.a + s.axes * corner;
          s.lo = glm::min(s.lo, q);
          s.hi = glm::max(s.hi, q);
        }
        break;
      }
    }
    if (s.op == BlendOp::Union) {
      lo = glm::min(lo, s.lo);
      hi = glm::max(hi, s.hi);
    }
  }

  coarse_index.build(*this, 0.05f, 0.04f);
  fine_index.build(*this, 0.012f, 0.016f);
}

void ImplicitBody::Index::build(const ImplicitBody& body, float reach, float cell_size) {
  *this = Index{};
  const auto& primitives = body.primitives;
  if (primitives.empty() || primitives.size() > 65535 || !(body.lo.x <= body.hi.x)) return;
  band = reach;
  cell = cell_size;
  origin = body.lo - vec3(band + cell);
  cells = glm::ivec3(glm::ceil((body.hi + vec3(band + cell) - origin) / cell));
  const std::size_t n = static_cast<std::size_t>(cells.x) * cells.y * cells.z;
  std::vector<std::uint32_t> count(n + 1, 0);
  // Two passes (count, then fill) over each primitive's cells, in primitive order.
  auto cell_range = [&](const Primitive& s, glm::ivec3& a, glm::ivec3& b) {
    a = glm::ivec3(0);
    b = cells - 1;
    if (s.op == BlendOp::Intersect) return;
    const float m = band + s.blend;
    a = glm::max(glm::ivec3(glm::floor((s.lo - vec3(m) - origin) / cell)), glm::ivec3(0));
    b = glm::min(glm::ivec3(glm::floor((s.hi + vec3(m) - origin) / cell)), cells - 1);
  };
  auto id = [&](int x, int y, int z) {
    return static_cast<std::size_t>(x) + static_cast<std::size_t>(cells.x) * (y + static_cast<std::size_t>(cells.y) * z);
  };
  for (const Primitive& s : primitives) {
    glm::ivec3 a, b;
    cell_range(s, a, b);
    for (int z = a.z; z <= b.z; ++z)
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) ++count[id(x, y, z) + 1];
  }
  for (std::size_t c = 0; c < n; ++c) count[c + 1] += count[c];
  start = count;
  items.resize(count[n]);
  std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    glm::ivec3 a, b;
    cell_range(primitives[i], a, b);
    for (int z = a.z; z <= b.z; ++z)
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) items[fill[id(x, y, z)]++] = static_cast<std::uint16_t>(i);
  }
}

bool ImplicitBody::Index::find(const vec3& p, float reach, std::uint32_t& first, std::uint32_t& last) const {
  if (start.empty() || reach > band) return false;
  const glm::ivec3 c = glm::ivec3(glm::floor((p - origin) / cell));
  if (!glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) || !glm::all(glm::lessThan(c, cells))) return false;
  const std::size_t i = static_cast<std::size_t>(c.x) + static_cast<std::size_t>(cells.x) * (c.y + static_cast<std::size_t>(cells.y) * c.z);
  first = start[i];
  last = start[i + 1];
  return true;
}

float ImplicitBody::field(const vec3& p, float band) const {
  float f = band;
  // Within an index, only the primitives listed for p's cell can matter: primitives farther than
  // band + blend leave the field as it is, exactly, and the index keeps all nearer than its band.
  std::uint32_t first = 0, last = 0;
  const Index* index = fine_index.find(p, band, first, last) ? &fine_index : coarse_index.find(p, band, first, last) ? &coarse_index : nullptr;
  if (index) {
    for (std::uint32_t i = first; i < last; ++i) {
      const Primitive& s = primitives[index->items[i]];
      if (s.op != BlendOp::Intersect && outside_box(s, p, band + s.blend)) continue;
      f = apply(s.op, f, primitive_distance(s, p), s.blend);
    }
    return std::clamp(f, -band, band);
  }
  for (const Primitive& s : primitives) {
    if (s.op != BlendOp::Intersect && outside_box(s, p, band + s.blend)) continue;
    f = apply(s.op, f, primitive_distance(s, p), s.blend);
  }
  return std::clamp(f, -band, band);
}

vec3 ImplicitBody::gradient(const vec3& p, float step) const {
  const float band = 0.01f;  // the gradient is asked for near the surface
  const vec3 dx(step, 0, 0), dy(0, step, 0), dz(0, 0, step);
  return vec3(field(p + dx, band) - field(p - dx, band), field(p + dy, band) - field(p - dy, band),
              field(p + dz, band) - field(p - dz, band)) /
         (2.0f * step);
}

void ImplicitBody::distances(const vec3& p, std::span<float> out) const {
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const Primitive& s = primitives[i];
    out[i] = s.op == BlendOp::Union ? primitive_distance(s, p) : std::numeric_limits<float>::infinity();
  }
}

}  // namespace gestura
