#pragma once
// convert: motion files between formats, both chosen by extension (any case). Reads what
// motion_files.hpp reads; writes .bvh, .glb, .gltf, .bap, .pose and (with openpose) OpenPose
// .json keypoints. BAP angles belong to the H-Anim joints of the default avatar: a motion whose
// joints have other names (MakeHuman, CMU, VRM) is mapped to H-Anim through the joint-name tables
// and retargeted onto the avatar's skeleton first.
#include <string>
#include <vector>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/app/notice.hpp"

namespace gestura::app {

struct ConvertRequest {
  std::string input, output;
  float scale = 1.0f;
  bool z_up = false;
  bool openpose = false;
  std::string skeleton;  // .gcl input: the BVH it was made from

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.input, FieldInfo{.name = "input", .help = "the motion to read (.bvh, .glb, .gltf, .vrm, .bap, .gcl; a .pose converts to .pose only)", .value = "IN", .positional = true, .required = true});
    visit(self.output, FieldInfo{.name = "output", .help = "the file to write (.bvh, .glb, .gltf, .bap, .pose, .json with --openpose)", .value = "OUT", .positional = true, .required = true});
    visit(self.scale, FieldInfo{.name = "scale", .help = "BVH input: multiplies all lengths (0.1 turns MakeHuman decimetres into metres)", .value = "S", .min = 1e-6, .max = 1e6});
    visit(self.z_up, FieldInfo{.name = "z_up", .help = "BVH input is Z-up facing -Y (MakeHuman, Blender): written +Y up facing +Z"});
    visit(self.openpose, FieldInfo{.name = "openpose", .help = ".json output: OpenPose BODY_25 + hand keypoints, one file per frame"});
    visit(self.skeleton, FieldInfo{.name = "skeleton", .help = ".gcl input: the BVH it was compressed from", .value = "REF.bvh"});
  }
};

struct ConvertResult {
  std::string format_in, format_out;
  std::size_t joints = 0;  // joints and end sites written
  int frames = 0;
  std::vector<std::string> written;  // OpenPose writes one file per frame
  std::vector<Notice> notices;       // e.g. joints renamed to H-Anim and retargeted
};

void validate(const ConvertRequest& request);
ConvertResult run(const ConvertRequest& request, const RunContext& context = {});

nlohmann::json to_json(const ConvertResult& result);

}  // namespace gestura::app
