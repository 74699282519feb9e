// Wavefront OBJ reader for the MakeHuman base mesh (and any simple OBJ): positions, polygons, groups.
#include <charconv>
#include <cmath>
#include <string>
#include <unordered_map>

#include "gestura/core/error.hpp"
#include "gestura/io/makehuman.hpp"
#include "gestura/io/makehuman_files.hpp"

namespace gestura {

int GroupedMesh::find_group(std::string_view name) const {
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (groups[i] == name) return static_cast<int>(i);
  return -1;
}

namespace {

// A cursor over one line that reports errors at file:line:column.
struct LineCursor {
  std::string_view line;
  std::size_t pos = 0;
  const std::string& file;
  int number;

  [[noreturn]] void fail(const std::string& message) const {
    throw Error(SourceLocation{file, number, static_cast<int>(pos) + 1}, message);
  }
  void skip_space() {
    while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t' || line[pos] == '\r')) ++pos;
  }
  bool at_end() {
    skip_space();
    return pos >= line.size();
  }
  std::string_view word() {
    skip_space();
    const std::size_t start = pos;
    while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t' && line[pos] != '\r') ++pos;
    return line.substr(start, pos - start);
  }
  float number_float() {
    skip_space();
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(line.data() + pos, line.data() + line.size(), value);
    if (ec != std::errc() || !std::isfinite(value)) fail("expected a finite number");
    pos = static_cast<std::size_t>(end - line.data());
    return value;
  }
  // One 1-based (or negative, relative) index resolved against `count` defined elements.
  std::uint32_t index(std::size_t count, const char* what) {
    long value = 0;
    const auto [end, ec] = std::from_chars(line.data() + pos, line.data() + line.size(), value);
    if (ec != std::errc() || value == 0) fail(std::string("expected a ") + what + " index");
    const long resolved = value > 0 ? value - 1 : static_cast<long>(count) + value;
    if (resolved < 0 || resolved >= static_cast<long>(count))
      fail(std::string(what) + " index " + std::to_string(value) + " out of range (" + std::to_string(count) +
           " defined)");
    pos = static_cast<std::size_t>(end - line.data());
    return static_cast<std::uint32_t>(resolved);
  }
};

void compute_normals(Mesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    // The cross product's length is twice the area: big triangles weigh more.
    const vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    mesh.normals[a] += n;
    mesh.normals[b] += n;
    mesh.normals[c] += n;
  }
  for (vec3& n : mesh.normals) {
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : vec3(0.0f, 0.0f, 1.0f);  // vertices on no (or degenerate) faces
  }
}

}  // namespace

GroupedMesh parse_grouped_obj(std::string_view text, const std::string& name, float unit) {
  GroupedMesh out;
  Mesh& mesh = out.mesh;
  std::size_t texcoords = 0, normals = 0;
  int group = -1;
  std::uint32_t corners[64];
  int line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    LineCursor c{text.substr(start, end - start), 0, name, ++line_number};
    start = end + 1;
    const std::string_view keyword = c.word();
    if (keyword.empty() || keyword[0] == '#') continue;
    if (keyword == "v") {
      const float x = c.number_float(), y = c.number_float(), z = c.number_float();
      mesh.positions.push_back(vec3(x, y, z) * unit);
    } else if (keyword == "vt") {
      c.number_float();
      c.number_float();
      ++texcoords;
    } else if (keyword == "vn") {
      c.number_float();
      c.number_float();
      c.number_float();
      ++normals;
    } else if (keyword == "g") {
      std::string group_name(c.word());
      if (group_name.empty()) group_name = "default";
      group = out.find_group(group_name);
      if (group < 0) {
        if (out.groups.size() >= 65535) c.fail("too many groups");
        out.groups.push_back(std::move(group_name));
        group = static_cast<int>(out.groups.size() - 1);
      }
    } else if (keyword == "f") {
      int n = 0;
      while (!c.at_end()) {
        if (n == 64) c.fail("polygon with more than 64 corners");
        corners[n++] = c.index(mesh.positions.size(), "vertex");
        if (c.pos < c.line.size() && c.line[c.pos] == '/') {
          ++c.pos;
          if (c.pos < c.line.size() && c.line[c.pos] != '/') c.index(texcoords, "texture coordinate");
          if (c.pos < c.line.size() && c.line[c.pos] == '/') {
            ++c.pos;
            c.index(normals, "normal");
          }
        }
        if (c.pos < c.line.size() && c.line[c.pos] != ' ' && c.line[c.pos] != '\t' && c.line[c.pos] != '\r')
          c.fail("unexpected character in face corner");
      }
      if (n < 3) c.fail("face with fewer than 3 corners");
      if (group < 0) {
        out.groups.push_back("default");
        group = static_cast<int>(out.groups.size() - 1);
      }
      for (int k = 1; k + 1 < n; ++k) {  // fan: quads become (0 1 2) (0 2 3)
        mesh.indices.insert(mesh.indices.end(), {corners[0], corners[k], corners[k + 1]});
        out.triangle_groups.push_back(static_cast<std::uint16_t>(group));
      }
    }
    // s, o, usemtl, mtllib, l, p and others carry nothing we keep.
  }
  if (mesh.positions.empty()) throw Error(SourceLocation{name}, "no vertices");
  compute_normals(mesh);
  mesh.materials.assign(mesh.positions.size(), static_cast<std::uint8_t>(MaterialId::Skin));
  return out;
}

GroupedMesh read_grouped_obj(const std::string& path, float unit) {
  return parse_grouped_obj(makehuman_detail::read_file(path), path, unit);
}

GroupedMesh keep_groups(const GroupedMesh& source, std::span<const std::string_view> groups,
                        std::vector<std::uint32_t>* original_vertex) {
  std::vector<bool> keep_group(source.groups.size(), false);
  for (std::string_view g : groups) {
    const int index = source.find_group(g);
    if (index < 0) throw Error("keep_groups: no group '" + std::string(g) + "'");
    keep_group[static_cast<std::size_t>(index)] = true;
  }
  const Mesh& from = source.mesh;
  constexpr std::uint32_t kDropped = ~std::uint32_t{0};
  std::vector<std::uint32_t> remap(from.positions.size(), kDropped);
  for (std::size_t t = 0; t < source.triangle_groups.size(); ++t)
    if (keep_group[source.triangle_groups[t]])
      for (int k = 0; k < 3; ++k) remap[from.indices[3 * t + k]] = 0;
  GroupedMesh out;
  Mesh& to = out.mesh;
  std::vector<std::uint32_t> kept;
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == kDropped) continue;
    remap[v] = static_cast<std::uint32_t>(kept.size());
    kept.push_back(static_cast<std::uint32_t>(v));
  }
  auto carry = [&](const auto& in, auto& result) {
    if (in.size() != from.positions.size()) return;  // absent arrays stay absent
    result.reserve(kept.size());
    for (std::uint32_t v : kept) result.push_back(in[v]);
  };
  carry(from.positions, to.positions);
  carry(from.normals, to.normals);
  carry(from.materials, to.materials);
  carry(from.joints, to.joints);
  carry(from.weights, to.weights);
  std::vector<int> group_map(source.groups.size(), -1);
  for (std::size_t t = 0; t < source.triangle_groups.size(); ++t) {
    const std::uint16_t g = source.triangle_groups[t];
    if (!keep_group[g]) continue;
    if (group_map[g] < 0) {
      group_map[g] = static_cast<int>(out.groups.size());
      out.groups.push_back(source.groups[g]);
    }
    for (int k = 0; k < 3; ++k) to.indices.push_back(remap[from.indices[3 * t + k]]);
    out.triangle_groups.push_back(static_cast<std::uint16_t>(group_map[g]));
  }
  for (const MorphTarget& morph : from.morphs) {
    MorphTarget m{morph.name, {}, {}, {}};
    for (std::size_t e = 0; e < morph.vertices.size(); ++e) {
      if (morph.vertices[e] >= remap.size() || remap[morph.vertices[e]] == kDropped) continue;
      m.vertices.push_back(remap[morph.vertices[e]]);
      m.position_deltas.push_back(morph.position_deltas[e]);
      if (!morph.normal_deltas.empty()) m.normal_deltas.push_back(morph.normal_deltas[e]);
    }
    to.morphs.push_back(std::move(m));
  }
  if (original_vertex) *original_vertex = std::move(kept);
  return out;
}

}  // namespace gestura
