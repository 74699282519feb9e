#include "gestura/body/face_parts.hpp"

#include <array>
#include <cmath>
#include <string>

#include "gestura/body/avatar_proportions.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

using Ring = std::vector<vec3>;

// A closed surface made of rings of equal size joined in order, each end closed by a fan around a
// tip point: a sphere from pole to pole, a swept profile from end cap to end cap. One material per
// ring (the tips take their neighbouring ring's), one joint for all. Normals are area-weighted
// face normals; the winding is made outward (positive volume).
Mesh tube(const std::vector<Ring>& rings, const std::vector<MaterialId>& ring_materials, vec3 first_tip, vec3 last_tip,
          int joint) {
  Mesh m;
  const std::size_t n = rings.front().size();
  auto add = [&m](vec3 p, MaterialId material) {
    m.positions.push_back(p);
    m.materials.push_back(static_cast<std::uint8_t>(material));
    return static_cast<std::uint32_t>(m.positions.size() - 1);
  };
  const std::uint32_t first = add(first_tip, ring_materials.front());
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (const vec3& p : rings[r]) add(p, ring_materials[r]);
  const std::uint32_t last = add(last_tip, ring_materials.back());
  auto at = [n](std::size_t ring, std::size_t i) { return static_cast<std::uint32_t>(1 + ring * n + i % n); };
  for (std::size_t i = 0; i < n; ++i) {
    m.indices.insert(m.indices.end(), {first, at(0, i + 1), at(0, i)});
    for (std::size_t r = 0; r + 1 < rings.size(); ++r)
      m.indices.insert(m.indices.end(), {at(r, i), at(r, i + 1), at(r + 1, i + 1), at(r, i), at(r + 1, i + 1), at(r + 1, i)});
    m.indices.insert(m.indices.end(), {last, at(rings.size() - 1, i), at(rings.size() - 1, i + 1)});
  }
  double volume = 0.0;
  for (std::size_t f = 0; f < m.indices.size(); f += 3)
    volume += glm::dot(m.positions[m.indices[f]],
                       glm::cross(m.positions[m.indices[f + 1]], m.positions[m.indices[f + 2]]));
  if (volume < 0.0)
    for (std::size_t f = 0; f < m.indices.size(); f += 3) std::swap(m.indices[f + 1], m.indices[f + 2]);
  m.normals.assign(m.positions.size(), vec3(0.0f));
  for (std::size_t f = 0; f < m.indices.size(); f += 3) {
    const std::uint32_t a = m.indices[f], b = m.indices[f + 1], c = m.indices[f + 2];
    const vec3 normal = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    m.normals[a] += normal, m.normals[b] += normal, m.normals[c] += normal;
  }
  for (vec3& normal : m.normals) normal = glm::normalize(normal);
  m.joints.assign(m.positions.size(), JointIndices(static_cast<std::uint16_t>(joint), 0, 0, 0));
  m.weights.assign(m.positions.size(), vec4(1, 0, 0, 0));
  return m;
}

// An eyeball looking down +Z: rings of latitude around the gaze axis, two of them a hair apart at
// the pupil's and at the iris's edge so both read as crisp circles.
Mesh eyeball(vec3 centre, float radius, int joint) {
  struct Latitude {
    float degrees;
    MaterialId material;
  };
  static constexpr std::array<Latitude, 10> latitudes{{{5.0f, MaterialId::Pupil},
                                                       {10.5f, MaterialId::Pupil},
                                                       {11.5f, MaterialId::Iris},
                                                       {20.0f, MaterialId::Iris},
                                                       {28.5f, MaterialId::Iris},
                                                       {29.5f, MaterialId::EyeWhite},
                                                       {45.0f, MaterialId::EyeWhite},
                                                       {65.0f, MaterialId::EyeWhite},
                                                       {95.0f, MaterialId::EyeWhite},
                                                       {135.0f, MaterialId::EyeWhite}}};
  constexpr int kSegments = 16;
  std::vector<Ring> rings;
  std::vector<MaterialId> materials;
  for (const Latitude& l : latitudes) {
    Ring ring;
    const float t = deg(l.degrees);
    for (int i = 0; i < kSegments; ++i) {
      const float a = 2.0f * glm::pi<float>() * static_cast<float>(i) / kSegments;
      ring.push_back(centre + radius * vec3(std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)));
    }
    rings.push_back(std::move(ring));
    materials.push_back(l.material);
  }
  return tube(rings, materials, centre + vec3(0, 0, radius), centre - vec3(0, 0, radius), joint);
}

// A row of teeth swept along its dental arch, from the last tooth on the right round to the last on
// the left. Rings sit at tooth centres and at the gaps between teeth, where the biting edge recedes
// and the crown narrows a little, so separate teeth show.
Mesh teeth_row(const proportions::DentalArch& arch, float k, int joint) {
  // Widths of central incisor, lateral incisor, canine, two premolars and a molar, as shares of
  // one side of the arch.
  static constexpr std::array<float, 6> widths{0.20f, 0.16f, 0.17f, 0.15f, 0.15f, 0.17f};
  auto arch_point = [&](float x) {
    const float u = x / arch.half_width;
    return vec3(x, 0.0f, arch.front_z - (arch.front_z - arch.back_z) * u * u);
  };
  // Arc length along one side, tabulated to place the teeth by width.
  constexpr int kSteps = 64;
  std::array<float, kSteps + 1> length{};
  for (int i = 1; i <= kSteps; ++i)
    length[i] = length[i - 1] + glm::distance(arch_point(arch.half_width * static_cast<float>(i) / kSteps),
                                              arch_point(arch.half_width * static_cast<float>(i - 1) / kSteps));
  auto x_at = [&](float share) {  // x where the arc length is `share` of the side
    const float target = share * length[kSteps];
    int i = 1;
    while (i < kSteps && length[i] < target) ++i;
    const float f = (target - length[i - 1]) / (length[i] - length[i - 1]);
    return arch.half_width * (static_cast<float>(i - 1) + f) / kSteps;
  };
  struct Station {
    float share;  // of the side's arc length
    bool gap;     // between two teeth
  };
  std::vector<Station> side;
  float s = 0.0f;
  for (std::size_t t = 0; t < widths.size(); ++t) {
    if (t < 3) side.push_back({s + 0.5f * widths[t], false});  // the front teeth get a centre ring
    s += widths[t];
    side.push_back({std::min(s, 1.0f), t + 1 < widths.size()});
  }
  std::vector<Station> stations;
  for (auto it = side.rbegin(); it != side.rend(); ++it) stations.push_back({-it->share, it->gap});
  stations.push_back({0.0f, true});  // between the central incisors
  stations.insert(stations.end(), side.begin(), side.end());

  const bool upper = arch.edge_y < arch.root_y;
  const float recede = (upper ? 1.0f : -1.0f) * 0.0008f;  // the edge moves towards the root at gaps
  std::vector<Ring> rings;
  for (const Station& st : stations) {
    const float x = (st.share < 0.0f ? -1.0f : 1.0f) * x_at(std::abs(st.share));
    const vec3 p = arch_point(x);
    const float slope = -2.0f * (arch.front_z - arch.back_z) * x / (arch.half_width * arch.half_width);
    const vec3 out = glm::normalize(vec3(-slope, 0.0f, 1.0f));  // labial side, horizontal
    const float half = 0.5f * arch.thickness * (1.0f + 0.5f * std::abs(st.share)) * (st.gap ? 0.8f : 1.0f);
    const float edge = arch.edge_y + (st.gap ? recede : 0.0f);
    const float mid = edge + 0.45f * (arch.root_y - edge);
    // Labial root, labial middle, labial edge, lingual edge, lingual middle, lingual root.
    const std::array<std::pair<float, float>, 6> profile{
        {{half, arch.root_y}, {half, mid}, {0.45f * half, edge}, {-0.45f * half, edge}, {-half, mid}, {-half, arch.root_y}}};
    Ring ring;
    for (auto [o, y] : profile) ring.push_back(vec3(p.x, y, p.z) * k + out * (o * k));
    rings.push_back(std::move(ring));
  }
  auto centroid = [](const Ring& r) {
    vec3 c(0.0f);
    for (const vec3& p : r) c += p;
    return c / static_cast<float>(r.size());
  };
  const std::vector<MaterialId> materials(rings.size(), MaterialId::Teeth);
  return tube(rings, materials, centroid(rings.front()), centroid(rings.back()), joint);
}

// The tongue: an ellipsoid lying along +Z with its tip forward, in rings across its length.
Mesh tongue(float k, int joint) {
  const vec3 c = vec3(proportions::kTongueCentre[0], proportions::kTongueCentre[1], proportions::kTongueCentre[2]) * k;
  const vec3 r = vec3(proportions::kTongueRadii[0], proportions::kTongueRadii[1], proportions::kTongueRadii[2]) * k;
  constexpr int kSegments = 10;
  std::vector<Ring> rings;
  for (float polar : {25.0f, 50.0f, 75.0f, 100.0f, 125.0f, 150.0f}) {
    const float t = deg(polar);
    Ring ring;
    for (int i = 0; i < kSegments; ++i) {
      const float a = 2.0f * glm::pi<float>() * static_cast<float>(i) / kSegments;
      ring.push_back(c + r * vec3(std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)));
    }
    rings.push_back(std::move(ring));
  }
  const std::vector<MaterialId> materials(rings.size(), MaterialId::Tongue);
  return tube(rings, materials, c + vec3(0, 0, r.z), c - vec3(0, 0, r.z), joint);
}

}  // namespace

void append_mesh(Mesh& mesh, const Mesh& part) {
  const auto base = static_cast<std::uint32_t>(mesh.vertex_count());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
  mesh.materials.insert(mesh.materials.end(), part.materials.begin(), part.materials.end());
  mesh.joints.insert(mesh.joints.end(), part.joints.begin(), part.joints.end());
  mesh.weights.insert(mesh.weights.end(), part.weights.begin(), part.weights.end());
  for (std::uint32_t i : part.indices) mesh.indices.push_back(base + i);
}

Mesh build_face_parts(const Skeleton& skeleton, float scale) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  auto joint = [&](const char* name) {
    const int j = skeleton.find(name);
    if (j < 0) throw Error(std::string("face parts: skeleton has no joint '") + name + "'");
    return j;
  };
  auto position = [&](int j) { return vec3(model[static_cast<std::size_t>(j)][3]); };
  Mesh parts;
  for (const char* eye : {"l_eyeball_joint", "r_eyeball_joint"}) {
    const int j = joint(eye);
    append_mesh(parts, eyeball(position(j), proportions::kEyeballRadius * scale, j));
  }
  append_mesh(parts, teeth_row(proportions::kUpperTeeth, scale, joint("skullbase")));
  append_mesh(parts, teeth_row(proportions::kLowerTeeth, scale, joint("temporomandibular")));
  append_mesh(parts, tongue(scale, joint("temporomandibular")));
  return parts;
}

}  // namespace gestura
