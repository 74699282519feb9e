#include "gestura/io/gltf_animation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/io/gltf_reader.hpp"
#include "gestura/io/json_excerpt.hpp"

namespace gestura {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// ---------------------------------------------------------------------------------------------
// Writing

class BufferWriter {
 public:
  explicit BufferWriter(json& doc) : doc_(doc) {
    doc_["bufferViews"] = json::array();
    doc_["accessors"] = json::array();
  }

  // Appends raw bytes as a buffer view (4-byte aligned); returns its index.
  int view(const void* data, std::size_t bytes, int target = 0) {
    while (buffer.size() % 4) buffer.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", bytes}};
    if (target) v["target"] = target;
    const auto* p = static_cast<const std::uint8_t*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    doc_["bufferViews"].push_back(std::move(v));
    return static_cast<int>(doc_["bufferViews"].size()) - 1;
  }

  // Float accessor of `components` per element, with min/max when asked.
  int floats(const std::vector<float>& values, int components, const char* type, bool bounds, int target = 0) {
    const std::size_t count = values.size() / static_cast<std::size_t>(components);
    json a = {{"bufferView", view(values.data(), values.size() * 4, target)},
              {"componentType", kFloat}, {"count", count}, {"type", type}};
    if (bounds) {
      std::vector<float> lo(static_cast<std::size_t>(components), INFINITY), hi(lo.size(), -INFINITY);
      for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % lo.size();
        lo[c] = std::min(lo[c], values[i]);
        hi[c] = std::max(hi[c], values[i]);
      }
      a["min"] = lo;
      a["max"] = hi;
    }
    return push(std::move(a));
  }

  int integers(const void* data, std::size_t count, int component_type, std::size_t component_bytes, int components,
               const char* type, int target) {
    json a = {{"bufferView", view(data, count * component_bytes * static_cast<std::size_t>(components), target)},
              {"componentType", component_type}, {"count", count}, {"type", type}};
    return push(std::move(a));
  }

  std::vector<std::uint8_t> buffer;

 private:
  int push(json a) {
    doc_["accessors"].push_back(std::move(a));
    return static_cast<int>(doc_["accessors"].size()) - 1;
  }
  json& doc_;
};

bool keeps_keys(Interpolation i) {
  return i == Interpolation::Step || i == Interpolation::Linear || i == Interpolation::Slerp;
}

// Key times of a track as written: its own keys, or a resampling of its span.
template <class T>
std::vector<float> written_times(const Track<T>& track, float fps) {
  if (keeps_keys(track.interpolation) || track.size() < 2) return track.times;
  std::vector<float> times;
  const float start = track.times.front(), end = track.times.back();
  const int n = static_cast<int>(std::ceil((end - start) * fps));
  for (int k = 0; k < n; ++k) times.push_back(start + float(k) / fps);
  times.push_back(end);
  return times;
}

void push_value(std::vector<float>& out, const vec3& v) { out.insert(out.end(), {v.x, v.y, v.z}); }
void push_value(std::vector<float>& out, const quat& q) {
  const quat n = glm::normalize(q);
  out.insert(out.end(), {n.x, n.y, n.z, n.w});
}

template <class T>
void add_channel(json& animation, BufferWriter& w, const Track<T>& track, int node, const char* path, float fps) {
  if (track.empty()) return;
  const std::vector<float> times = written_times(track, fps);
  std::vector<float> values;
  std::uint32_t cursor = 0;
  for (float t : times) push_value(values, keeps_keys(track.interpolation) ? track.values[cursor++] : sample_track(track, t));
  const bool is_quat = std::is_same_v<T, quat>;
  json sampler = {{"input", w.floats(times, 1, "SCALAR", true)},
                  {"output", w.floats(values, is_quat ? 4 : 3, is_quat ? "VEC4" : "VEC3", false)},
                  {"interpolation", track.interpolation == Interpolation::Step ? "STEP" : "LINEAR"}};
  animation["samplers"].push_back(std::move(sampler));
  animation["channels"].push_back(
      {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

json vec_json(const vec3& v) { return json::array({v.x, v.y, v.z}); }

void add_mesh(json& doc, BufferWriter& w, const Skeleton& skeleton, const Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  if (n == 0 || mesh.indices.empty()) throw Error("glTF export: the mesh has no vertices or triangles");
  if (mesh.joints.size() != n || mesh.weights.size() != n || (!mesh.normals.empty() && mesh.normals.size() != n))
    throw Error("glTF export: mesh arrays disagree with its " + std::to_string(n) + " vertices");
  for (std::uint32_t i : mesh.indices)
    if (i >= n) throw Error("glTF export: triangle index " + std::to_string(i) + " past the vertices");
  std::vector<float> positions, normals, weights;
  std::vector<std::uint16_t> joints;
  for (std::size_t v = 0; v < n; ++v) {
    push_value(positions, mesh.positions[v]);
    if (!mesh.normals.empty()) {
      const vec3 nm = mesh.normals[v];
      push_value(normals, glm::length(nm) > 1e-12f ? glm::normalize(nm) : vec3(0, 1, 0));
    }
    vec4 wt = glm::max(mesh.weights[v], vec4(0.0f));
    const float sum = wt.x + wt.y + wt.z + wt.w;
    wt = sum > 0.0f ? wt / sum : vec4(1, 0, 0, 0);
    for (int k = 0; k < 4; ++k) {
      const std::uint16_t j = mesh.joints[v][k];
      if (j >= skeleton.size()) throw Error("glTF export: vertex " + std::to_string(v) + " names joint " + std::to_string(j));
      joints.push_back(wt[k] > 0.0f ? j : 0);
      weights.push_back(wt[k]);
    }
  }
  json attributes = {{"POSITION", w.floats(positions, 3, "VEC3", true, kArrayBuffer)},
                     {"JOINTS_0", w.integers(joints.data(), n, kUnsignedShort, 2, 4, "VEC4", kArrayBuffer)},
                     {"WEIGHTS_0", w.floats(weights, 4, "VEC4", false, kArrayBuffer)}};
  if (!normals.empty()) attributes["NORMAL"] = w.floats(normals, 3, "VEC3", false, kArrayBuffer);
  json primitive = {{"attributes", attributes},
                    {"indices", w.integers(mesh.indices.data(), mesh.indices.size(), kUnsignedInt, 4, 1, "SCALAR",
                                           kElementArrayBuffer)},
                    {"mode", 4}};
  json names = json::array(), zero = json::array();
  for (const MorphTarget& m : mesh.morphs) {
    std::vector<float> dp(n * 3, 0.0f), dn;
    if (!m.normal_deltas.empty()) dn.assign(n * 3, 0.0f);
    for (std::size_t k = 0; k < m.vertices.size(); ++k) {
      const std::size_t v = m.vertices[k];
      if (v >= n || k >= m.position_deltas.size()) throw Error("glTF export: morph '" + m.name + "' entry " + std::to_string(k) + " is out of range");
      for (int c = 0; c < 3; ++c) dp[v * 3 + static_cast<std::size_t>(c)] = m.position_deltas[k][c];
      if (!dn.empty() && k < m.normal_deltas.size())
        for (int c = 0; c < 3; ++c) dn[v * 3 + static_cast<std::size_t>(c)] = m.normal_deltas[k][c];
    }
    json target = {{"POSITION", w.floats(dp, 3, "VEC3", true, kArrayBuffer)}};
    if (!dn.empty() && !normals.empty()) target["NORMAL"] = w.floats(dn, 3, "VEC3", false, kArrayBuffer);
    primitive["targets"].push_back(std::move(target));
    names.push_back(m.name);
    zero.push_back(0.0);
  }
  json gmesh = {{"name", "body"}, {"primitives", json::array({primitive})}};
  if (!mesh.morphs.empty()) gmesh["weights"] = zero, gmesh["extras"] = {{"targetNames", names}};
  doc["meshes"] = json::array({gmesh});

  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  std::vector<float> ibm;
  for (const mat4& m : model) {
    const mat4 inv = glm::inverse(m);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) ibm.push_back(inv[c][r]);
  }
  json joint_nodes = json::array();
  for (std::size_t j = 0; j < skeleton.size(); ++j) joint_nodes.push_back(j);
  doc["skins"] = json::array({{{"joints", joint_nodes}, {"inverseBindMatrices", w.floats(ibm, 16, "MAT4", false)}}});
  doc["nodes"].push_back({{"name", "body"}, {"mesh", 0}, {"skin", 0}});
  doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
}

// Morph weights from the clip's scalar channels named like the mesh's targets.
void add_weights_channel(json& animation, BufferWriter& w, const Clip& clip, const Mesh& mesh, int node) {
  std::vector<int> channel_of(mesh.morphs.size(), -1);
  std::set<float> times;
  for (std::size_t m = 0; m < mesh.morphs.size(); ++m) {
    channel_of[m] = clip.find_channel(mesh.morphs[m].name);
    if (channel_of[m] >= 0) {
      const FloatTrack& t = clip.channels[static_cast<std::size_t>(channel_of[m])];
      times.insert(t.times.begin(), t.times.end());
    }
  }
  if (times.empty()) return;
  const std::vector<float> input(times.begin(), times.end());
  std::vector<float> output;
  for (float t : input)
    for (int c : channel_of)
      output.push_back(c < 0 ? 0.0f : sample_track(clip.channels[static_cast<std::size_t>(c)], t));
  animation["samplers"].push_back({{"input", w.floats(input, 1, "SCALAR", true)},
                                   {"output", w.floats(output, 1, "SCALAR", false)},
                                   {"interpolation", "LINEAR"}});
  animation["channels"].push_back(
      {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", "weights"}}}});
}

}  // namespace

GltfDocument make_gltf(const Skeleton& skeleton, const Clip& clip, const Mesh* mesh, const GltfWriteOptions& options) {
  skeleton.validate();
  validate(clip, skeleton);
  if (!(options.resample_fps > 0.0f) || options.resample_fps > 1000.0f) throw Error("glTF export: resample_fps must be in (0, 1000]");
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "gestura"}}}, {"scene", 0}, {"nodes", json::array()},
              {"scenes", json::array({{{"nodes", json::array()}}})}};
  BufferWriter w(doc);
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    const quat r = glm::normalize(skeleton.rest_rotations[j]);
    json node = {{"name", skeleton.names[j]}, {"translation", vec_json(skeleton.rest_translations[j])},
                 {"rotation", {r.x, r.y, r.z, r.w}}, {"scale", vec_json(skeleton.rest_scales[j])}};
    doc["nodes"].push_back(std::move(node));
    const int p = skeleton.parents[j];
    if (p < 0) doc["scenes"][0]["nodes"].push_back(j);
    else doc["nodes"][static_cast<std::size_t>(p)]["children"].push_back(j);
  }
  if (mesh) add_mesh(doc, w, skeleton, *mesh);
  json animation = {{"name", clip.name.empty() ? "clip" : clip.name}, {"samplers", json::array()}, {"channels", json::array()}};
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    const int node = static_cast<int>(j);
    add_channel(animation, w, clip.translations[j], node, "translation", options.resample_fps);
    add_channel(animation, w, clip.rotations[j], node, "rotation", options.resample_fps);
    add_channel(animation, w, clip.scales[j], node, "scale", options.resample_fps);
  }
  if (mesh && !mesh->morphs.empty()) add_weights_channel(animation, w, clip, *mesh, static_cast<int>(skeleton.size()));
  if (!animation["channels"].empty()) doc["animations"] = json::array({animation});
  if (doc["accessors"].empty()) doc.erase("accessors"), doc.erase("bufferViews");
  GltfDocument out;
  out.buffer = std::move(w.buffer);
  while (out.buffer.size() % 4) out.buffer.push_back(0);
  if (!out.buffer.empty()) doc["buffers"] = json::array({{{"byteLength", out.buffer.size()}}});
  out.json = doc.dump();
  return out;
}

std::string pack_glb(const GltfDocument& document) {
  std::string json_chunk = document.json;
  while (json_chunk.size() % 4) json_chunk.push_back(' ');
  std::string out;
  auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  const std::size_t total = 12 + 8 + json_chunk.size() + (document.buffer.empty() ? 0 : 8 + document.buffer.size());
  if (total > 0xFFFFFFFFull) throw Error("glTF export: more than 4 GiB does not fit a GLB");
  u32(kGlbMagic);
  u32(2);
  u32(static_cast<std::uint32_t>(total));
  u32(static_cast<std::uint32_t>(json_chunk.size()));
  u32(kGlbChunkJson);
  out += json_chunk;
  if (!document.buffer.empty()) {
    u32(static_cast<std::uint32_t>(document.buffer.size()));
    u32(kGlbChunkBin);
    out.append(reinterpret_cast<const char*>(document.buffer.data()), document.buffer.size());
  }
  return out;
}

std::string pack_gltf_embedded(const GltfDocument& document) {
  json doc = json::parse(document.json);
  if (!document.buffer.empty()) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64 = "data:application/octet-stream;base64,";
    const auto& b = document.buffer;
    for (std::size_t i = 0; i < b.size(); i += 3) {
      const std::uint32_t n = (std::uint32_t(b[i]) << 16) | (i + 1 < b.size() ? std::uint32_t(b[i + 1]) << 8 : 0) |
                              (i + 2 < b.size() ? std::uint32_t(b[i + 2]) : 0);
      b64 += kAlphabet[(n >> 18) & 63];
      b64 += kAlphabet[(n >> 12) & 63];
      b64 += i + 1 < b.size() ? kAlphabet[(n >> 6) & 63] : '=';
      b64 += i + 2 < b.size() ? kAlphabet[n & 63] : '=';
    }
    doc["buffers"][0]["uri"] = b64;
  }
  return doc.dump();
}

void save_gltf(const std::string& path, const Skeleton& skeleton, const Clip& clip, const Mesh* mesh,
               const GltfWriteOptions& options) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".glb" && ext != ".gltf") throw Error(path + ": glTF files end in .glb or .gltf");
  const GltfDocument doc = make_gltf(skeleton, clip, mesh, options);
  write_file_atomically(path, ext == ".glb" ? pack_glb(doc) : pack_gltf_embedded(doc));
}

GltfAnimation read_gltf_animation(const std::string& bytes, const std::string& source) {
  const GltfReader r(bytes, source);
  const json& nodes = r.array("nodes");
  if (nodes.size() > 32767) r.fail("nodes", "more than 32767 nodes");
  // Parent of every node, checking that the children lists form a forest.
  std::vector<int> parent(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string where = "nodes[" + std::to_string(i) + "]";
    if (!nodes[i].is_object()) r.fail(where, "not an object");
    if (!nodes[i].contains("children")) continue;
    if (!nodes[i]["children"].is_array()) r.fail(where, "children is not an array");
    for (const json& c : nodes[i]["children"]) {
      if (!c.is_number_integer() || c.get<long long>() < 0 || c.get<long long>() >= static_cast<long long>(nodes.size()))
        r.fail(where, "has a child that is not a node index: " + json_excerpt(c));
      const auto ci = c.get<std::size_t>();
      if (parent[ci] >= 0 || ci == i) r.fail(where, "node " + json_excerpt(c) + " has two parents or is its own child");
      parent[ci] = static_cast<int>(i);
    }
  }
  // Node order when it already lists parents first (what we write), else depth-first from the
  // roots; a cycle leaves nodes unvisited either way.
  std::vector<int> order;
  bool parents_first = true;
  for (std::size_t i = 0; i < nodes.size(); ++i) parents_first = parents_first && parent[i] < static_cast<int>(i);
  if (parents_first)
    for (std::size_t i = 0; i < nodes.size(); ++i) order.push_back(static_cast<int>(i));
  std::vector<std::vector<int>> children(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (parent[i] >= 0) children[static_cast<std::size_t>(parent[i])].push_back(static_cast<int>(i));
  for (std::size_t i = 0; i < nodes.size() && !parents_first; ++i) {
    if (parent[i] >= 0) continue;
    std::vector<int> stack{static_cast<int>(i)};
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      order.push_back(n);
      const auto& c = children[static_cast<std::size_t>(n)];
      for (auto it = c.rbegin(); it != c.rend(); ++it) stack.push_back(*it);
    }
  }
  if (order.size() != nodes.size()) r.fail("nodes", "the children lists contain a cycle");

  GltfAnimation out;
  std::vector<int> joint_of(nodes.size(), -1);
  std::set<std::string> used;
  for (int n : order) {
    const json& node = nodes[static_cast<std::size_t>(n)];
    if (node.contains("mesh")) continue;
    const std::string where = "nodes[" + std::to_string(n) + "]";
    int p = parent[static_cast<std::size_t>(n)];
    while (p >= 0 && joint_of[static_cast<std::size_t>(p)] < 0) p = parent[static_cast<std::size_t>(p)];
    std::string name = node.contains("name") && node["name"].is_string() ? node["name"].get<std::string>() : "";
    if (name.empty() || used.contains(name)) name = (name.empty() ? "node" : name + "_") + std::to_string(n);
    used.insert(name);
    vec3 t(0.0f), s(1.0f);
    quat q(1, 0, 0, 0);
    if (node.contains("matrix")) {
      const json& m = node["matrix"];
      if (!m.is_array() || m.size() != 16) r.fail(where, "matrix needs 16 numbers");
      mat4 mm;
      for (int k = 0; k < 16; ++k) {
        if (!m[static_cast<std::size_t>(k)].is_number()) r.fail(where, "matrix needs 16 numbers");
        mm[k / 4][k % 4] = m[static_cast<std::size_t>(k)].get<float>();
      }
      t = vec3(mm[3]);
      s = vec3(glm::length(vec3(mm[0])), glm::length(vec3(mm[1])), glm::length(vec3(mm[2])));
      if (!(s.x > 0 && s.y > 0 && s.z > 0) || !is_finite(s)) r.fail(where, "matrix is singular or not finite");
      q = glm::normalize(glm::quat_cast(mat3(vec3(mm[0]) / s.x, vec3(mm[1]) / s.y, vec3(mm[2]) / s.z)));
    } else {
      t = json_vec3(r, node, "translation", vec3(0.0f), where);
      s = json_vec3(r, node, "scale", vec3(1.0f), where);
      if (node.contains("rotation")) {
        const json& a = node["rotation"];
        if (!a.is_array() || a.size() != 4) r.fail(where, "rotation needs 4 numbers");
        for (const json& x : a)
          if (!x.is_number()) r.fail(where, "rotation needs 4 numbers");
        q = quat(a[3].get<float>(), a[0].get<float>(), a[1].get<float>(), a[2].get<float>());
        if (!is_finite(q) || glm::length(q) < 1e-6f) r.fail(where, "rotation is not a usable quaternion");
        q = glm::normalize(q);
      }
    }
    const int j = out.skeleton.add_joint(name, p < 0 ? -1 : joint_of[static_cast<std::size_t>(p)], t, q);
    out.skeleton.rest_scales[static_cast<std::size_t>(j)] = s;
    joint_of[static_cast<std::size_t>(n)] = j;
    out.node_of_joint.push_back(n);
  }
  out.clip.resize_joints(out.skeleton.size());

  const json& animations = r.array("animations");
  if (!animations.empty()) {
    const json& anim = animations[0];
    if (!anim.is_object()) r.fail("animations[0]", "not an object");
    out.clip.name = anim.value("name", std::string());
    const json& samplers = anim.contains("samplers") && anim["samplers"].is_array() ? anim["samplers"] : json::array();
    const json& channels = anim.contains("channels") && anim["channels"].is_array() ? anim["channels"] : json::array();
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const std::string where = "animations[0].channels[" + std::to_string(c) + "]";
      const json& ch = channels[c];
      if (!ch.is_object() || !ch.contains("target") || !ch["target"].is_object()) r.fail(where, "needs a target");
      const json& target = ch["target"];
      const std::string path = target.value("path", std::string());
      if (!target.contains("node")) continue;  // allowed by the specification: ignore
      const json& node = target["node"];
      if (!node.is_number_integer() || node.get<long long>() < 0 || node.get<long long>() >= static_cast<long long>(nodes.size()))
        r.fail(where, "targets a missing node " + json_excerpt(node));
      const json& si = ch.contains("sampler") ? ch["sampler"] : json();
      if (!si.is_number_integer() || si.get<long long>() < 0 || si.get<long long>() >= static_cast<long long>(samplers.size()))
        r.fail(where, "refers to a missing sampler");
      const json& sampler = samplers[si.get<std::size_t>()];
      if (!sampler.is_object() || !sampler.contains("input") || !sampler.contains("output")) r.fail(where, "sampler needs input and output");
      const std::string mode = sampler.value("interpolation", std::string("LINEAR"));
      if (mode != "LINEAR" && mode != "STEP" && mode != "CUBICSPLINE") r.fail(where, "unknown interpolation " + mode);
      const int per_key = mode == "CUBICSPLINE" ? 3 : 1;
      const std::vector<float> times = r.accessor(sampler["input"], where);
      int components = 0;
      const std::vector<float> values = r.accessor(sampler["output"], where, &components);
      const Interpolation interp = mode == "STEP" ? Interpolation::Step : mode == "CUBICSPLINE" ? Interpolation::CatmullRom : Interpolation::Linear;
      auto value_at = [&](std::size_t key, int width, std::size_t element) {
        // CUBICSPLINE stores in-tangent, value, out-tangent per key: take the value.
        return (key * static_cast<std::size_t>(per_key) + (per_key == 3 ? 1 : 0)) * static_cast<std::size_t>(width) + element;
      };
      const int joint = joint_of[node.get<std::size_t>()];
      if (path == "weights") {
        const json& n = nodes[node.get<std::size_t>()];
        if (!n.contains("mesh")) r.fail(where, "animates weights of a node without a mesh");
        const json& mesh = r.item("meshes", n["mesh"], where);
        std::vector<std::string> names;
        if (mesh.contains("extras") && mesh["extras"].is_object() && mesh["extras"].contains("targetNames") &&
            mesh["extras"]["targetNames"].is_array())
          for (const json& tn : mesh["extras"]["targetNames"]) names.push_back(tn.is_string() ? tn.get<std::string>() : "");
        if (times.empty() || values.size() % (times.size() * static_cast<std::size_t>(per_key)) != 0)
          r.fail(where, "weights output does not divide into its keys");
        const std::size_t targets = values.size() / (times.size() * static_cast<std::size_t>(per_key));
        for (std::size_t t = 0; t < targets; ++t) {
          FloatTrack& track = out.clip.channel(t < names.size() && !names[t].empty() ? names[t] : "morph" + std::to_string(t));
          track = FloatTrack{};
          track.interpolation = interp;
          for (std::size_t k = 0; k < times.size(); ++k) track.add(times[k], values[value_at(k, static_cast<int>(targets), t)]);
          validate_track(track, (source + ": " + where).c_str());
        }
        continue;
      }
      if (joint < 0) continue;  // a mesh node's transform: not part of the skeleton
      const int width = path == "rotation" ? 4 : 3;
      if (path != "rotation" && path != "translation" && path != "scale") r.fail(where, "unknown path '" + path + "'");
      if (components != width || values.size() != times.size() * static_cast<std::size_t>(width * per_key))
        r.fail(where, "output accessor has " + std::to_string(values.size()) + " numbers for " + std::to_string(times.size()) + " keys of " + path);
      const auto j = static_cast<std::size_t>(joint);
      const std::string what = source + ": " + where;
      if (path == "rotation") {
        QuatTrack& track = out.clip.rotations[j];
        track = QuatTrack{};
        track.interpolation = interp == Interpolation::Linear ? Interpolation::Slerp : interp == Interpolation::CatmullRom ? Interpolation::Squad : interp;
        for (std::size_t k = 0; k < times.size(); ++k) {
          const std::size_t v = value_at(k, 4, 0);
          const quat q(values[v + 3], values[v], values[v + 1], values[v + 2]);
          if (glm::length(q) < 1e-6f) r.fail(where, "key " + std::to_string(k) + " is a zero quaternion");
          track.add(times[k], glm::normalize(q));
        }
        validate_track(track, what.c_str());
      } else {
        Vec3Track& track = path == "translation" ? out.clip.translations[j] : out.clip.scales[j];
        track = Vec3Track{};
        track.interpolation = interp;
        for (std::size_t k = 0; k < times.size(); ++k) {
          const std::size_t v = value_at(k, 3, 0);
          track.add(times[k], vec3(values[v], values[v + 1], values[v + 2]));
        }
        validate_track(track, what.c_str());
      }
    }
  }
  out.clip.duration = std::max(0.0f, out.clip.end_time());
  return out;
}

GltfAnimation load_gltf_animation(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(path + ": cannot open");
  std::ostringstream text;
  text << file.rdbuf();
  return read_gltf_animation(text.str(), path);
}

}  // namespace gestura
