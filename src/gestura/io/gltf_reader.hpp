#pragma once
// Reading glTF 2.0 containers safely: the .glb chunk layout, buffers (GLB chunk or base64 data
// URIs), and accessors, with every index and byte range checked before any data is touched, so
// malformed or hostile files give a gestura::Error naming the object ("accessors[3]: ...")
// instead of a crash. Shared by the animation reader and the VRM importer.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gestura/core/math.hpp"

namespace gestura {

inline constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
inline constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A;
inline constexpr std::uint32_t kGlbChunkBin = 0x004E4942;

// The pieces of a glTF container: the JSON text and the binary chunk (empty for .gltf).
struct GltfContainer {
  std::string json;
  std::string bin;
};
GltfContainer unpack_gltf(const std::string& bytes, const std::string& source);

class GltfReader {
 public:
  // Parses the container and JSON, checks asset.version == "2.0" and loads the buffers.
  GltfReader(const std::string& bytes, std::string source);

  [[noreturn]] void fail(const std::string& where, const std::string& what) const;
  const nlohmann::json& doc() const { return doc_; }
  const std::string& source() const { return source_; }

  // doc[key] as an array (empty when absent); throws when it is not an array.
  const nlohmann::json& array(const char* key) const;
  // doc[key][index] as an object; `referrer` names who asked, for the error.
  const nlohmann::json& item(const char* key, const nlohmann::json& index, const std::string& referrer) const;
  // A finite, non-negative number member.
  double number(const nlohmann::json& object, const char* key, const std::string& where) const;
  // Every element of an accessor as floats (normalised integer types scaled to [0,1] / [-1,1]);
  // `components` receives the element width (1 SCALAR … 16 MAT4).
  // Sparse accessors are read too (their values replace the base's elements).
  std::vector<float> accessor(const nlohmann::json& index, const std::string& referrer, int* components = nullptr) const;

 private:
  std::vector<float> elements(const nlohmann::json& view, double offset, std::size_t count, int components, int ct,
                              bool normalized, const std::string& where) const;
  std::string source_;
  nlohmann::json doc_;
  std::vector<std::string> buffers_;
};

// node[key] as three finite numbers, or `fallback` when absent.
vec3 json_vec3(const GltfReader& reader, const nlohmann::json& node, const char* key, vec3 fallback,
               const std::string& where);

}  // namespace gestura
