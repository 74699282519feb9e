#include "gestura/io/gltf_reader.hpp"

#include <cmath>
#include <cstring>
#include <map>

#include "gestura/core/error.hpp"
#include "gestura/io/json_excerpt.hpp"

namespace gestura {
namespace {

using nlohmann::json;

std::uint32_t read_u32(const std::string& b, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

std::string base64_decode(std::string_view text, const std::string& where) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  int bits = 0, acc = 0;
  for (char c : text) {
    if (c == '=') break;
    const int v = value(c);
    if (v < 0) throw Error(where + ": bad base64 character");
    acc = (acc << 6) | v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xFF));
    }
  }
  return out;
}

}  // namespace

GltfContainer unpack_gltf(const std::string& bytes, const std::string& source) {
  GltfContainer c;
  if (bytes.size() >= 4 && read_u32(bytes, 0) == kGlbMagic) {
    if (bytes.size() < 20) throw Error(source + ": GLB shorter than its 12-byte header and first chunk header");
    if (read_u32(bytes, 4) != 2) throw Error(source + ": GLB version " + std::to_string(read_u32(bytes, 4)) + " (only 2 is read)");
    const std::uint32_t total = read_u32(bytes, 8);
    if (total > bytes.size()) throw Error(source + ": GLB header says " + std::to_string(total) + " bytes, the file has " + std::to_string(bytes.size()) + " (truncated)");
    std::size_t at = 12;
    int chunk = 0;
    while (at < total) {
      if (at + 8 > total) throw Error(source + ": GLB chunk " + std::to_string(chunk) + " header is truncated");
      const std::uint32_t length = read_u32(bytes, at), type = read_u32(bytes, at + 4);
      if (std::size_t(length) > total - at - 8) throw Error(source + ": GLB chunk " + std::to_string(chunk) + " runs past the end of the file");
      const std::string body = bytes.substr(at + 8, length);
      if (chunk == 0 && type != kGlbChunkJson) throw Error(source + ": the first GLB chunk is not JSON");
      if (chunk == 0) c.json = body;
      else if (chunk == 1 && type == kGlbChunkBin) c.bin = body;
      at += 8 + std::size_t(length);
      ++chunk;
    }
    if (chunk == 0) throw Error(source + ": GLB has no JSON chunk");
    return c;
  }
  c.json = bytes;
  return c;
}

GltfReader::GltfReader(const std::string& bytes, std::string source) : source_(std::move(source)) {
  const GltfContainer c = unpack_gltf(bytes, source_);
  try {
    doc_ = json::parse(c.json);
  } catch (const json::exception& e) {
    fail("", std::string("bad JSON: ") + e.what());
  }
  if (!doc_.is_object()) fail("", "the JSON is not an object");
  if (!doc_.contains("asset") || doc_["asset"].value("version", std::string()) != "2.0")
    fail("asset", "not a glTF 2.0 asset (asset.version must be \"2.0\")");
  for (std::size_t i = 0; i < array("buffers").size(); ++i) {
    const json& b = array("buffers")[i];
    const std::string where = "buffers[" + std::to_string(i) + "]";
    std::string data;
    if (!b.is_object()) fail(where, "not an object");
    if (b.contains("uri")) {
      const std::string uri = b["uri"].is_string() ? b["uri"].get<std::string>() : "";
      const auto comma = uri.find(',');
      if (!uri.starts_with("data:") || comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos)
        fail(where, "external buffer files are not read (only data: URIs and the GLB chunk)");
      data = base64_decode(std::string_view(uri).substr(comma + 1), source_ + ": " + where);
    } else {
      if (i != 0 || c.bin.empty()) fail(where, "has no uri and there is no GLB binary chunk");
      data = c.bin;
    }
    const double length = number(b, "byteLength", where);
    if (length > double(data.size())) fail(where, "byteLength " + std::to_string(length) + " exceeds the " + std::to_string(data.size()) + " bytes present");
    buffers_.push_back(std::move(data));
  }
}

void GltfReader::fail(const std::string& where, const std::string& what) const {
  throw Error(source_ + ": " + (where.empty() ? "" : where + ": ") + what);
}


const json& GltfReader::array(const char* key) const {
  static const json empty = json::array();
  if (!doc_.contains(key)) return empty;
  if (!doc_[key].is_array()) fail(key, "is not an array");
  return doc_[key];
}

const json& GltfReader::item(const char* key, const json& index, const std::string& referrer) const {
  const json& a = array(key);
  if (!index.is_number_integer() || index.get<long long>() < 0 || index.get<long long>() >= static_cast<long long>(a.size()))
    fail(referrer, std::string("refers to a missing ") + key + " entry " + json_excerpt(index));
  const json& o = a[index.get<std::size_t>()];
  if (!o.is_object()) fail(std::string(key) + "[" + json_excerpt(index) + "]", "not an object");
  return o;
}

double GltfReader::number(const json& o, const char* key, const std::string& where) const {
  if (!o.contains(key) || !o[key].is_number()) fail(where, std::string("needs a number '") + key + "'");
  const double v = o[key].get<double>();
  if (!std::isfinite(v) || v < 0) fail(where, std::string("'") + key + "' must be a non-negative number");
  return v;
}

// Every element of an accessor as floats (normalised integer types scaled to [0,1] / [-1,1]).
std::vector<float> GltfReader::accessor(const json& index, const std::string& referrer, int* components_out) const {
  const json& a = item("accessors", index, referrer);
  const std::string where = "accessors[" + json_excerpt(index) + "]";
  static const std::map<std::string, int> kTypes = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT4", 16}};
  const std::string type = a.value("type", std::string());
  const auto t = kTypes.find(type);
  if (t == kTypes.end()) fail(where, "unknown or missing type '" + type + "'");
  const int components = t->second;
  if (components_out) *components_out = components;
  const double count_d = number(a, "count", where);
  if (count_d > 1e8) fail(where, "count over 100,000,000");
  const auto count = static_cast<std::size_t>(count_d);
  if (!a.contains("componentType") || !a["componentType"].is_number_integer()) fail(where, "needs componentType");
  const int ct = a["componentType"].get<int>();
  const bool normalized = a.value("normalized", false);
  std::vector<float> out(count * static_cast<std::size_t>(components), 0.0f);  // all zeros without a bufferView
  if (a.contains("bufferView"))
    out = elements(a["bufferView"], a.contains("byteOffset") ? number(a, "byteOffset", where) : 0.0, count, components, ct,
                   normalized, where);
  // Sparse: (index, value) pairs replace elements of the base.
  if (a.contains("sparse")) {
    const json& sp = a["sparse"];
    const std::string swhere = where + ".sparse";
    if (!sp.is_object() || !sp.contains("indices") || !sp.contains("values") || !sp["indices"].is_object() ||
        !sp["values"].is_object())
      fail(swhere, "needs count, indices and values");
    const double changed_d = number(sp, "count", swhere);
    if (changed_d < 1 || changed_d > count_d) fail(swhere, "count must be 1.." + std::to_string(count));
    const auto changed = static_cast<std::size_t>(changed_d);
    const json& ix = sp["indices"];
    const json& vx = sp["values"];
    if (!ix.contains("bufferView") || !vx.contains("bufferView")) fail(swhere, "indices and values need a bufferView");
    if (!ix.contains("componentType") || !ix["componentType"].is_number_integer()) fail(swhere + ".indices", "needs componentType");
    const int ict = ix["componentType"].get<int>();
    if (ict != 5121 && ict != 5123 && ict != 5125) fail(swhere + ".indices", "componentType must be an unsigned integer type");
    const std::vector<float> indices = elements(ix["bufferView"], ix.contains("byteOffset") ? number(ix, "byteOffset", swhere) : 0.0,
                                                changed, 1, ict, false, swhere + ".indices");
    const std::vector<float> values = elements(vx["bufferView"], vx.contains("byteOffset") ? number(vx, "byteOffset", swhere) : 0.0,
                                               changed, components, ct, normalized, swhere + ".values");
    for (std::size_t k = 0; k < changed; ++k) {
      const float i = indices[k];
      if (!(i >= 0.0f) || i >= static_cast<float>(count)) fail(swhere, "index " + std::to_string(i) + " past the " + std::to_string(count) + " elements");
      for (int c = 0; c < components; ++c)
        out[static_cast<std::size_t>(i) * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
            values[k * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
    }
  }
  return out;
}

// `count` elements of `components` values of type `ct` from a buffer view, starting `offset`
// bytes in, every byte range checked.
std::vector<float> GltfReader::elements(const json& view, double offset, std::size_t count, int components, int ct,
                                        bool normalized, const std::string& where) const {
  const std::size_t size = ct == 5120 || ct == 5121 ? 1 : ct == 5122 || ct == 5123 ? 2 : ct == 5125 || ct == 5126 ? 4 : 0;
  if (size == 0) fail(where, "unknown componentType " + std::to_string(ct));
  std::vector<float> out(count * static_cast<std::size_t>(components), 0.0f);
  const json& v = item("bufferViews", view, where);
  const std::string vwhere = "bufferViews[" + json_excerpt(view) + "]";
  const json& b = v.contains("buffer") ? v["buffer"] : json();
  if (!b.is_number_integer() || b.get<long long>() < 0 || b.get<long long>() >= static_cast<long long>(buffers_.size()))
    fail(vwhere, "refers to a missing buffer");
  const std::string& data = buffers_[b.get<std::size_t>()];
  const double view_offset = v.contains("byteOffset") ? number(v, "byteOffset", vwhere) : 0.0;
  const double view_length = number(v, "byteLength", vwhere);
  if (view_offset + view_length > double(data.size())) fail(vwhere, "byte range runs past the end of its buffer");
  const std::size_t element = size * static_cast<std::size_t>(components);
  const double stride = v.contains("byteStride") ? number(v, "byteStride", vwhere) : double(element);
  if (stride < double(element)) fail(vwhere, "byteStride smaller than one element");
  if (count > 0 && offset + stride * double(count - 1) + double(element) > view_length)
    fail(where, "elements run past the end of " + vwhere);
  const char* base = data.data() + static_cast<std::size_t>(view_offset + offset);
  for (std::size_t e = 0; e < count; ++e)
    for (int c = 0; c < components; ++c) {
      const char* p = base + e * static_cast<std::size_t>(stride) + static_cast<std::size_t>(c) * size;
      float f = 0.0f;
      switch (ct) {
        case 5120: { std::int8_t x; std::memcpy(&x, p, 1); f = normalized ? std::max(x / 127.0f, -1.0f) : x; break; }
        case 5121: { std::uint8_t x; std::memcpy(&x, p, 1); f = normalized ? x / 255.0f : x; break; }
        case 5122: { std::int16_t x; std::memcpy(&x, p, 2); f = normalized ? std::max(x / 32767.0f, -1.0f) : x; break; }
        case 5123: { std::uint16_t x; std::memcpy(&x, p, 2); f = normalized ? x / 65535.0f : x; break; }
        case 5125: { std::uint32_t x; std::memcpy(&x, p, 4); f = static_cast<float>(x); break; }
        default: std::memcpy(&f, p, 4);
      }
      if (!std::isfinite(f)) fail(where, "element " + std::to_string(e) + " is not finite");
      out[e * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] = f;
    }
  return out;
}

vec3 json_vec3(const GltfReader& r, const json& node, const char* key, vec3 fallback, const std::string& where) {
  if (!node.contains(key)) return fallback;
  const json& a = node[key];
  if (!a.is_array() || a.size() != 3) r.fail(where, std::string(key) + " needs 3 numbers");
  vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!a[static_cast<std::size_t>(i)].is_number()) r.fail(where, std::string(key) + " needs 3 numbers");
    v[i] = a[static_cast<std::size_t>(i)].get<float>();
  }
  if (!is_finite(v)) r.fail(where, std::string(key) + " is not finite");
  return v;
}

}  // namespace gestura
