#include "gestura/app/motion_files.hpp"

#include <functional>
#include <map>

#include "gestura/app/error.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/compress/decompress_clip.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/io/bap_bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/vrm.hpp"

namespace gestura::app {
namespace {

using Reader = std::function<MotionFile(const std::string& path, const MotionReadOptions& options)>;

// Length options belong to BVH; other formats have their own units and axes.
void bvh_options_only(const MotionReadOptions& options, const std::string& path) {
  if (options.scale != 1.0f) usage_error("scale", "applies to BVH input, not " + path);
  if (options.z_up) usage_error("z_up", "applies to BVH input, not " + path);
}

MotionFile read_gltf(const std::string& path, const MotionReadOptions& options) {
  bvh_options_only(options, path);
  GltfAnimation gltf = load_gltf_animation(path);
  return {"glTF", make_bvh(gltf.skeleton, gltf.clip, 1.0f / 30.0f)};
}

const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> table{
      {".bvh", [](const std::string& path, const MotionReadOptions& options) {
         return MotionFile{"BVH", load_bvh(path, BvhReadOptions{options.scale, options.z_up})};
       }},
      {".glb", read_gltf},
      {".gltf", read_gltf},
      {".vrm", [](const std::string& path, const MotionReadOptions& options) {
         bvh_options_only(options, path);
         VrmAvatar vrm = load_vrm(path);
         Clip rest;
         rest.resize_joints(vrm.skeleton.size());
         return MotionFile{"VRM", make_bvh(vrm.skeleton, rest, 1.0f / 30.0f)};
       }},
      {".bap", [](const std::string& path, const MotionReadOptions& options) {
         bvh_options_only(options, path);
         return MotionFile{"BAP", bap_to_bvh(load_bap(path))};
       }},
      {".gcl", [](const std::string& path, const MotionReadOptions& options) {
         if (options.skeleton.empty())
           usage_error("skeleton", path + ": a .gcl stores no skeleton; give the BVH it was made from with --skeleton REF.bvh");
         require_file("skeleton", options.skeleton);
         const CompressedClip compressed = load_gcl(path);
         BvhFile bvh = load_bvh(options.skeleton, BvhReadOptions{options.scale, options.z_up});
         if (bvh.skeleton.size() != compressed.joint_count())
           throw AppError(ErrorCategory::input, Place{"skeleton", {path}},
                          "has " + std::to_string(compressed.joint_count()) + " joints, --skeleton " + options.skeleton +
                              " has " + std::to_string(bvh.skeleton.size()));
         bvh.clip = decompress_clip(compressed, path);
         bvh.frame_time = 1.0f / compressed.sample_rate();
         bvh.frame_count = static_cast<int>(compressed.frame_count());
         return MotionFile{"gcl", std::move(bvh)};
       }}};
  return table;
}

}  // namespace

std::string motion_file_extensions() {
  std::string list;
  for (const auto& [ext, read] : readers()) list += (list.empty() ? "" : ", ") + ext;
  return list;
}

bool is_motion_file(std::string_view path) { return readers().contains(lower_extension(path)); }

MotionFile read_motion_file(const std::string& path, const MotionReadOptions& options, std::string_view field) {
  const std::string ext = lower_extension(path);
  const auto it = readers().find(ext);
  if (it == readers().end())
    usage_error(field, path + ": cannot read '" + (ext.empty() ? "(no extension)" : ext) + "' motion files (" +
                           motion_file_extensions() + ")");
  require_file(field, path);
  return it->second(path, options);
}

}  // namespace gestura::app
