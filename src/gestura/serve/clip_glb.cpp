#include "gestura/serve/clip_glb.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gestura/anim/track.hpp"
#include "gestura/io/gltf_animation.hpp"

namespace gestura::serve {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kShort = 5122;

struct Writer {
  json doc;
  std::vector<std::uint8_t> buffer;

  int view(const void* data, std::size_t bytes) {
    while (buffer.size() % 4) buffer.push_back(0);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", bytes}});
    const auto* p = static_cast<const std::uint8_t*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    return static_cast<int>(doc["bufferViews"].size()) - 1;
  }
  int accessor(json a) {
    doc["accessors"].push_back(std::move(a));
    return static_cast<int>(doc["accessors"].size()) - 1;
  }
  int floats(const std::vector<float>& v, int components, const char* type, bool bounds) {
    json a{{"bufferView", view(v.data(), v.size() * 4)}, {"componentType", kFloat}, {"count", v.size() / static_cast<std::size_t>(components)}, {"type", type}};
    if (bounds && !v.empty()) a["min"] = {*std::min_element(v.begin(), v.end())}, a["max"] = {*std::max_element(v.begin(), v.end())};
    return accessor(std::move(a));
  }
  int shorts(const std::vector<std::int16_t>& v, const char* type) {
    return accessor({{"bufferView", view(v.data(), v.size() * 2)}, {"componentType", kShort}, {"normalized", true}, {"count", v.size() / 4}, {"type", type}});
  }
};

std::vector<float> frame_times(float duration, float fps) {
  const int n = std::max(1, static_cast<int>(std::ceil(duration * fps - 1e-4f)));
  std::vector<float> t;
  for (int k = 0; k < n; ++k) t.push_back(static_cast<float>(k) / fps);
  t.push_back(duration);
  return t;
}

float angle_between(const quat& a, const quat& b) {
  return 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(glm::normalize(a), glm::normalize(b)))));
}

std::int16_t to_snorm16(float v) { return static_cast<std::int16_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f)); }

}  // namespace

std::string clip_glb(const Skeleton& skeleton, const Clip& clip, const Mesh& avatar_mesh, const json& extras,
                     const ClipGlbOptions& options) {
  Writer w;
  w.doc = {{"asset", {{"version", "2.0"}, {"generator", "gestura serve"}}}, {"scene", 0}, {"bufferViews", json::array()},
           {"accessors", json::array()}, {"nodes", json::array()}};
  const std::size_t nj = skeleton.size();
  std::vector<json> children(nj, json::array());
  json roots = json::array();
  for (std::size_t j = 0; j < nj; ++j)
    if (skeleton.parents[j] >= 0) children[static_cast<std::size_t>(skeleton.parents[j])].push_back(j);
    else roots.push_back(j);
  for (std::size_t j = 0; j < nj; ++j) {
    const vec3 t = skeleton.rest_translations[j];
    const quat q = glm::normalize(skeleton.rest_rotations[j]);
    json node{{"name", skeleton.names[j]}, {"translation", {t.x, t.y, t.z}}, {"rotation", {q.x, q.y, q.z, q.w}}};
    if (!children[j].empty()) node["children"] = children[j];
    w.doc["nodes"].push_back(std::move(node));
  }

  const std::vector<float> times = frame_times(clip.duration, options.fps);
  const std::size_t nf = times.size();
  json animation{{"name", clip.name.empty() ? "gestura" : clip.name}, {"samplers", json::array()}, {"channels", json::array()}};
  const auto add = [&](int input, int output, json target) {
    animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    animation["channels"].push_back({{"sampler", animation["samplers"].size() - 1}, {"target", std::move(target)}});
  };
  const auto key_times = [&](const std::vector<std::size_t>& kept) {
    std::vector<float> t;
    for (std::size_t k : kept) t.push_back(times[k]);
    return w.floats(t, 1, "SCALAR", true);
  };

  const float max_angle = glm::radians(options.rotation_tolerance);
  for (std::size_t j = 0; j < nj && j < clip.rotations.size(); ++j) {
    const QuatTrack& track = clip.rotations[j];
    if (track.empty()) continue;
    std::vector<quat> q(nf);
    std::uint32_t cursor = 0;
    for (std::size_t f = 0; f < nf; ++f) {
      q[f] = glm::normalize(sample_track(track, times[f], &cursor));
      if (f > 0 && glm::dot(q[f], q[f - 1]) < 0.0f) q[f] = -q[f];  // the short way, as slerp takes it
    }
    const auto kept = reduce_keys(nf, [&](std::size_t a, std::size_t b, std::size_t i) {
      const float x = (times[i] - times[a]) / (times[b] - times[a]);
      return angle_between(glm::slerp(q[a], q[b], x), q[i]);
    }, max_angle);
    std::vector<std::int16_t> values;
    for (std::size_t k : kept)
      for (float c : {q[k].x, q[k].y, q[k].z, q[k].w}) values.push_back(to_snorm16(c));
    add(key_times(kept), w.shorts(values, "VEC4"), {{"node", j}, {"path", "rotation"}});
  }
  for (std::size_t j = 0; j < nj && j < clip.translations.size(); ++j) {
    const Vec3Track& track = clip.translations[j];
    if (track.empty()) continue;
    std::vector<vec3> p(nf);
    std::uint32_t cursor = 0;
    for (std::size_t f = 0; f < nf; ++f) p[f] = sample_track(track, times[f], &cursor);
    const auto kept = reduce_keys(nf, [&](std::size_t a, std::size_t b, std::size_t i) {
      const float x = (times[i] - times[a]) / (times[b] - times[a]);
      return glm::length(glm::mix(p[a], p[b], x) - p[i]);
    }, options.translation_tolerance);
    std::vector<float> values;
    for (std::size_t k : kept) values.insert(values.end(), {p[k].x, p[k].y, p[k].z});
    add(key_times(kept), w.floats(values, 3, "VEC3", false), {{"node", j}, {"path", "translation"}});
  }

  // The face: the stand-in mesh's weights, one vector per key.
  const std::size_t nm = avatar_mesh.morphs.size();
  std::vector<int> channel(nm, -1);
  bool any = false;
  for (std::size_t m = 0; m < nm; ++m) any |= (channel[m] = clip.find_channel(avatar_mesh.morphs[m].name)) >= 0;
  json scene_nodes = roots;
  if (any) {
    std::vector<float> weights(nf * nm, 0.0f);
    for (std::size_t m = 0; m < nm; ++m) {
      if (channel[m] < 0) continue;
      const FloatTrack& track = clip.channels[static_cast<std::size_t>(channel[m])];
      std::uint32_t cursor = 0;
      for (std::size_t f = 0; f < nf; ++f) weights[f * nm + m] = track.empty() ? 0.0f : sample_track(track, times[f], &cursor);
    }
    const auto kept = reduce_keys(nf, [&](std::size_t a, std::size_t b, std::size_t i) {
      const float x = (times[i] - times[a]) / (times[b] - times[a]);
      float worst = 0.0f;
      for (std::size_t m = 0; m < nm; ++m)
        worst = std::max(worst, std::abs(weights[a * nm + m] + x * (weights[b * nm + m] - weights[a * nm + m]) - weights[i * nm + m]));
      return worst;
    }, options.weight_tolerance);
    std::vector<float> values;
    for (std::size_t k : kept) values.insert(values.end(), weights.begin() + static_cast<std::ptrdiff_t>(k * nm), weights.begin() + static_cast<std::ptrdiff_t>((k + 1) * nm));
    const std::vector<float> triangle{0, 0, 0, 0.001f, 0, 0, 0, 0.001f, 0}, zero(9, 0.0f);
    json position = {{"bufferView", w.view(triangle.data(), triangle.size() * 4)}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"},
                     {"min", {0, 0, 0}}, {"max", {0.001f, 0.001f, 0}}};
    const int positions = w.accessor(position);
    json offset = {{"bufferView", w.view(zero.data(), zero.size() * 4)}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"},
                   {"min", {0, 0, 0}}, {"max", {0, 0, 0}}};
    const int offsets = w.accessor(offset);
    json targets = json::array(), names = json::array();
    for (const MorphTarget& m : avatar_mesh.morphs) targets.push_back({{"POSITION", offsets}}), names.push_back(m.name);
    w.doc["meshes"] = json::array({{{"name", "face_weights"},
                                    {"primitives", json::array({{{"attributes", {{"POSITION", positions}}}, {"targets", targets}}})},
                                    {"weights", std::vector<float>(nm, 0.0f)},
                                    {"extras", {{"targetNames", names}}}}});
    w.doc["nodes"].push_back({{"name", "face_weights"}, {"mesh", 0}});
    scene_nodes.push_back(w.doc["nodes"].size() - 1);
    add(key_times(kept), w.floats(values, 1, "SCALAR", false), {{"node", w.doc["nodes"].size() - 1}, {"path", "weights"}});
  }
  w.doc["scenes"] = json::array({{{"nodes", scene_nodes}}});
  animation["extras"] = extras;
  w.doc["animations"] = json::array({animation});
  while (w.buffer.size() % 4) w.buffer.push_back(0);
  w.doc["buffers"] = json::array({{{"byteLength", w.buffer.size()}}});
  return pack_glb(GltfDocument{w.doc.dump(), std::move(w.buffer)});
}

}  // namespace gestura::serve
