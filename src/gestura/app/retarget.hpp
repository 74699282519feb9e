#pragma once
// retarget: a motion played on another skeleton — the default avatar, an avatar from assets, or a
// BVH's skeleton — joints paired by name (H-Anim, VRM, MakeHuman, CMU spellings), rest poses
// aligned (anim/retarget.hpp), written like any motion (motion_output.hpp).
#include <string>

#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"

namespace gestura::app {

struct RetargetRequest {
  std::string input;
  std::string to = "avatar";  // avatar | makehuman:DIR | FILE.bvh
  float scale = 1.0f;
  bool z_up = false;
  bool end_effectors = false;
  MotionOutput output;  // required; keeps the source's frame rate unless fps is given

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.input, FieldInfo{.name = "input", .help = "the motion to retarget (.bvh, .glb, .gltf, .bap)", .value = "IN", .positional = true, .required = true});
    visit(self.to, FieldInfo{.name = "to", .help = "avatar, makehuman:DIR (the MakeHuman avatar) or a BVH file whose skeleton receives the motion", .value = "T"});
    visit(self.scale, FieldInfo{.name = "scale", .help = "multiplies lengths of IN (and of a --to file), e.g. 0.1 for MakeHuman decimetres", .value = "S", .min = 1e-6, .max = 1e6});
    visit(self.z_up, FieldInfo{.name = "z_up", .help = "IN (and a --to file) is Z-up facing -Y (MakeHuman, Blender)"});
    visit(self.end_effectors, FieldInfo{.name = "end_effectors", .help = "keep wrists and ankles where the source has them relative to its root (scaled)"});
    MotionOutput::fields(self.output, visit);
  }
};

struct RetargetResult {
  Skeleton target;
  Clip clip;
  int driven = 0;  // target joints the source moves
  WrittenFile written;
};

void validate(const RetargetRequest& request);
RetargetResult run(const RetargetRequest& request, const RunContext& context = {});
nlohmann::json to_json(const RetargetResult& result);

}  // namespace gestura::app
