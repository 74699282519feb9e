// gestura convert IN OUT [--scale S] — motion files between formats, chosen by extension.
//
// The go-between is a BvhFile (skeleton + clip + channel layout): a BVH input keeps its layout so
// BVH → BVH reproduces it; other readers can build one with make_bvh. New formats add a row to
// readers() or writers().
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bap_bvh.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/openpose_json.hpp"
#include "gestura/io/pose_format.hpp"

namespace {

using gestura::BvhFile;
using gestura::Error;

using Reader = std::function<BvhFile(const std::string& path, const gestura::BvhReadOptions& options)>;
using Writer = std::function<void(const std::string& path, const BvhFile& motion)>;

BvhFile read_gltf(const std::string& path, const gestura::BvhReadOptions& options) {
  if (options.scale != 1.0f || options.z_up) throw Error(path + ": --scale and --z-up apply to BVH input only");
  const gestura::GltfAnimation gltf = gestura::load_gltf_animation(path);
  return gestura::make_bvh(gltf.skeleton, gltf.clip, 1.0f / 30.0f);
}

const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> table{
      {".bvh", [](const std::string& path, const gestura::BvhReadOptions& options) {
         return gestura::load_bvh(path, options);
       }},
      // glTF animation: nodes become joints; BVH output samples it at 30 frames per second.
      {".glb", read_gltf},
      {".gltf", read_gltf},
      // BAP angles are on the default avatar's skeleton (io/bap_bvh.hpp); length options do not apply.
      {".bap", [](const std::string& path, const gestura::BvhReadOptions&) {
         return gestura::bap_to_bvh(gestura::load_bap(path));
       }}};
  return table;
}

const std::map<std::string, Writer>& writers() {
  static const std::map<std::string, Writer> table{
      {".bvh", gestura::save_bvh},
      {".glb", [](const std::string& path, const BvhFile& motion) { gestura::save_gltf(path, motion.skeleton, motion.clip); }},
      {".gltf", [](const std::string& path, const BvhFile& motion) { gestura::save_gltf(path, motion.skeleton, motion.clip); }},
      // Joint positions in model space (metres) for the pose-format toolkit.
      {".pose", [](const std::string& path, const BvhFile& motion) {
         gestura::save_pose(path, gestura::pose_from_clip(motion.skeleton, motion.clip, 1.0f / motion.frame_time,
                                                          gestura::PoseLayout::Skeleton3D));
       }},
      // OpenPose keypoints seen by the default front camera, one file per frame (needs --openpose).
      {".json", [](const std::string& path, const BvhFile& motion) {
         gestura::save_openpose_json(path, motion.skeleton, motion.clip, 1.0f / motion.frame_time);
       }},
      {".bap", [](const std::string& path, const BvhFile& motion) {
         gestura::save_bap(path, gestura::bvh_to_bap(motion, "gestura"));
       }}};
  return table;
}

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

template <class Table>
const typename Table::mapped_type& pick(const Table& table, const std::string& path, const char* direction) {
  const std::string ext = extension_of(path);
  const auto it = table.find(ext);
  if (it != table.end()) return it->second;
  std::string supported;
  for (const auto& [known, fn] : table) {
    if (!supported.empty()) supported += ", ";
    supported += known;
  }
  throw Error(path + ": cannot " + direction + " '" + (ext.empty() ? "(no extension)" : ext) +
              "' files (supported: " + supported + ")");
}

int run_convert(const std::vector<std::string>& args) {
  std::vector<std::string> paths;
  gestura::BvhReadOptions options;
  float& scale = options.scale;
  bool openpose = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--scale") {
      const std::string value = gestura::cli::flag_value(args, i);
      std::size_t used = 0;
      try {
        scale = std::stof(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != value.size() || !std::isfinite(scale) || !(scale > 0.0f))
        throw Error("--scale needs a positive number, got '" + value + "'");
    } else if (args[i] == "--z-up") {
      options.z_up = true;
    } else if (args[i] == "--openpose") {
      openpose = true;
    } else if (args[i].starts_with("--")) {
      throw Error("unknown flag " + args[i]);
    } else {
      paths.push_back(args[i]);
    }
  }
  if (paths.size() != 2) throw Error("usage: gestura convert IN OUT [--scale S] [--z-up] [--openpose]");
  if ((extension_of(paths[1]) == ".json") != openpose)
    throw Error(openpose ? "--openpose writes .json files" : paths[1] + ": JSON output is OpenPose keypoints; say --openpose");
  // A .pose holds positions, not joint rotations: it is re-encoded (0.1 → 0.2), not made into a motion.
  if (extension_of(paths[0]) == ".pose") {
    if (extension_of(paths[1]) != ".pose") throw Error(paths[0] + ": a .pose file holds point positions, not joint rotations; it converts to .pose only");
    const gestura::PoseData pose = gestura::load_pose(paths[0]);
    gestura::save_pose(paths[1], pose);
    std::cout << "wrote " << paths[1] << ": " << pose.point_count() << " points, " << pose.frames << " frames\n";
    return 0;
  }
  const Reader& read = pick(readers(), paths[0], "read");
  const Writer& write = pick(writers(), paths[1], "write");
  const BvhFile motion = read(paths[0], options);
  write(paths[1], motion);
  std::cout << "wrote " << paths[1] << ": " << motion.skeleton.size() << " joints and end sites, " << motion.frame_count
            << " frames\n";
  return 0;
}

gestura::cli::Registration reg{{"convert", "convert motion files (BVH, glTF, BAP → BVH, glTF, BAP, .pose, OpenPose; scale, Z-up → Y-up)",
                                "usage: gestura convert IN OUT [--scale S] [--z-up] [--openpose]\n\n"
                                "Reads IN and writes OUT, formats chosen by extension (.bvh, .glb, .gltf, .bap; written\n"
                                "also .pose: joint positions for the pose-format toolkit, and with --openpose\n"
                                "A .pose input is re-encoded as pose-format 0.2 (.pose to .pose only).\n"
                                ".json: OpenPose BODY_25 + hand keypoints from a front camera, written as\n"
                                "OUT_<frame>_keypoints.json per frame).\n"
                                ".bap       MPEG-4 BAP text, angles on the default avatar skeleton (joints\n"
                                "           matched by H-Anim name; 1e-5 rad resolution).\n"
                                "--scale S  multiplies all lengths (offsets, positions), e.g. 0.1 to turn\n"
                                "           the decimetres of MakeHuman BVH files into metres.\n"
                                "--z-up     IN is Z-up facing -Y (MakeHuman, Blender): write it +Y up,\n"
                                "           facing +Z, as gestura uses.",
                                run_convert}};

}  // namespace
