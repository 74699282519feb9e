#include "gestura/world/shapes.hpp"

#include <algorithm>

namespace gestura {
namespace {

void quad(TriangleMesh& m, const vec3& a, const vec3& b, const vec3& c, const vec3& d, const vec3& n) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  for (const vec3& p : {a, b, c, d}) m.positions.push_back(p), m.normals.push_back(n);
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

TriangleMesh box(const vec3& size) {
  TriangleMesh m;
  const vec3 h = size * 0.5f;
  // Each face: four corners counter-clockwise seen from outside.
  quad(m, {h.x, -h.y, h.z}, {h.x, -h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, h.y, h.z}, {1, 0, 0});
  quad(m, {-h.x, -h.y, -h.z}, {-h.x, -h.y, h.z}, {-h.x, h.y, h.z}, {-h.x, h.y, -h.z}, {-1, 0, 0});
  quad(m, {-h.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, -h.z}, {-h.x, h.y, -h.z}, {0, 1, 0});
  quad(m, {-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z}, {-h.x, -h.y, h.z}, {0, -1, 0});
  quad(m, {-h.x, -h.y, h.z}, {h.x, -h.y, h.z}, {h.x, h.y, h.z}, {-h.x, h.y, h.z}, {0, 0, 1});
  quad(m, {h.x, -h.y, -h.z}, {-h.x, -h.y, -h.z}, {-h.x, h.y, -h.z}, {h.x, h.y, -h.z}, {0, 0, -1});
  return m;
}

TriangleMesh plane(const vec3& size) {
  TriangleMesh m;
  const float x = size.x * 0.5f, z = size.z * 0.5f;
  quad(m, {-x, 0, z}, {x, 0, z}, {x, 0, -z}, {-x, 0, -z}, {0, 1, 0});
  return m;
}

TriangleMesh cylinder(float radius, float height, int segments) {
  TriangleMesh m;
  const float h = height * 0.5f;
  auto around = [&](int i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    return vec2(std::sin(a), std::cos(a));
  };
  // The side: one quad per segment; smooth normals for round cylinders, flat for prisms (≤ 8 sides).
  const bool smooth = segments > 8;
  for (int i = 0; i < segments; ++i) {
    const vec2 a = around(i), b = around(i + 1);
    const vec3 pa0(a.x * radius, -h, a.y * radius), pb0(b.x * radius, -h, b.y * radius);
    const vec3 pa1 = pa0 + vec3(0, height, 0), pb1 = pb0 + vec3(0, height, 0);
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const vec3 flat = glm::normalize(vec3(a.x + b.x, 0.0f, a.y + b.y));
    const vec3 na = smooth ? vec3(a.x, 0, a.y) : flat, nb = smooth ? vec3(b.x, 0, b.y) : flat;
    m.positions.insert(m.positions.end(), {pa0, pb0, pb1, pa1});
    m.normals.insert(m.normals.end(), {na, nb, nb, na});
    for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + k);
  }
  // The caps as fans.
  for (int cap = 0; cap < 2; ++cap) {
    const float y = cap ? h : -h;
    const vec3 n(0, cap ? 1.0f : -1.0f, 0);
    const auto centre = static_cast<std::uint32_t>(m.positions.size());
    m.positions.push_back({0, y, 0}), m.normals.push_back(n);
    for (int i = 0; i < segments; ++i) {
      const vec2 a = around(i);
      m.positions.push_back({a.x * radius, y, a.y * radius}), m.normals.push_back(n);
    }
    for (int i = 0; i < segments; ++i) {
      const auto a = centre + 1 + static_cast<std::uint32_t>(i);
      const auto b = centre + 1 + static_cast<std::uint32_t>((i + 1) % segments);
      if (cap) m.indices.insert(m.indices.end(), {centre, a, b});
      else m.indices.insert(m.indices.end(), {centre, b, a});
    }
  }
  return m;
}

TriangleMesh sphere(float radius, int segments) {
  TriangleMesh m;
  const int rings = std::max(2, segments / 2);
  for (int r = 0; r <= rings; ++r) {
    const float theta = kPi * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(segments);
      const vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.positions.push_back(n * radius), m.normals.push_back(n);
    }
  }
  const auto row = static_cast<std::uint32_t>(segments + 1);
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const auto a = static_cast<std::uint32_t>(r) * row + static_cast<std::uint32_t>(s);
      const auto b = a + row;
      if (r > 0) m.indices.insert(m.indices.end(), {a, b, a + 1});
      if (r < rings - 1) m.indices.insert(m.indices.end(), {a + 1, b, b + 1});
    }
  return m;
}

}  // namespace

void TriangleMesh::append(const TriangleMesh& other, const mat4& transform) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  const mat3 normal_matrix = glm::transpose(glm::inverse(mat3(transform)));
  for (std::size_t i = 0; i < other.positions.size(); ++i) {
    positions.push_back(vec3(transform * vec4(other.positions[i], 1.0f)));
    const vec3 n = normal_matrix * other.normals[i];
    const float len = glm::length(n);
    normals.push_back(len > 0.0f ? n / len : vec3(0, 1, 0));
  }
  // A mirroring transform turns the winding inside out: swap two corners to keep it counter-clockwise.
  const bool mirrored = glm::determinant(mat3(transform)) < 0.0f;
  for (std::size_t t = 0; t + 2 < other.indices.size(); t += 3) {
    indices.push_back(base + other.indices[t]);
    indices.push_back(base + other.indices[t + (mirrored ? 2 : 1)]);
    indices.push_back(base + other.indices[t + (mirrored ? 1 : 2)]);
  }
}

TriangleMesh tessellate(const Shape& shape) {
  const int segments = shape.segments > 0 ? shape.segments : kDefaultSegments;
  switch (shape.kind) {
    case ShapeKind::Box: return box(shape.size);
    case ShapeKind::Plane: return plane(shape.size);
    case ShapeKind::Cylinder: return cylinder(shape.radius, shape.height, segments);
    case ShapeKind::Sphere: return sphere(shape.radius, std::max(segments, 6));
    default: return {};
  }
}

float shape_signed_distance(const Shape& shape, const vec3& p) {
  switch (shape.kind) {
    case ShapeKind::Box: {
      const vec3 q = glm::abs(p) - shape.size * 0.5f;
      return glm::length(glm::max(q, vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
    }
    case ShapeKind::Plane: {
      const vec2 q = glm::max(vec2(std::abs(p.x) - shape.size.x * 0.5f, std::abs(p.z) - shape.size.z * 0.5f), vec2(0.0f));
      return std::sqrt(q.x * q.x + q.y * q.y + p.y * p.y);
    }
    case ShapeKind::Cylinder: {
      // A prism of few segments is a polygon, not a circle: measure against its flat sides.
      const int n = shape.segments > 0 ? shape.segments : kDefaultSegments;
      float radial = std::sqrt(p.x * p.x + p.z * p.z) - shape.radius;
      if (n <= 16) {
        radial = -1e30f;
        for (int i = 0; i < n; ++i) {
          const float a = 2.0f * kPi * (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
          const vec2 normal(std::sin(a), std::cos(a));
          radial = std::max(radial, p.x * normal.x + p.z * normal.y - shape.radius * std::cos(kPi / static_cast<float>(n)));
        }
        // Outside a corner the distance is to the corner, not to the side's line.
        if (radial > 0.0f) {
          float outside = 1e30f;
          for (int i = 0; i < n; ++i) {
            const float a0 = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(n);
            const float a1 = 2.0f * kPi * static_cast<float>(i + 1) / static_cast<float>(n);
            const vec2 e0(std::sin(a0) * shape.radius, std::cos(a0) * shape.radius);
            const vec2 e1(std::sin(a1) * shape.radius, std::cos(a1) * shape.radius);
            const vec2 d = e1 - e0, q(p.x, p.z);
            const float t = std::clamp(glm::dot(q - e0, d) / glm::dot(d, d), 0.0f, 1.0f);
            outside = std::min(outside, glm::length(q - (e0 + t * d)));
          }
          radial = outside;
        }
      }
      const float axial = std::abs(p.y) - shape.height * 0.5f;
      const vec2 q(radial, axial);
      return std::min(std::max(q.x, q.y), 0.0f) + glm::length(glm::max(q, vec2(0.0f)));
    }
    case ShapeKind::Sphere: return glm::length(p) - shape.radius;
    default: return 1e30f;
  }
}

}  // namespace gestura
