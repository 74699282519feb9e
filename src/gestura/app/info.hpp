#pragma once
// info: what a file holds — any motion file gestura reads (motion_files.hpp): format, joints,
// frames, rate, duration, extent at rest and the joint tree; for BVH its channel layouts; for a
// .gcl without its skeleton, its counts and size; for VRM, the body too.
#include <string>
#include <utility>
#include <vector>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"

namespace gestura::app {

struct InfoRequest {
  std::string file;
  int depth = 3;  // joint tree depth shown; 0: every joint
  float scale = 1.0f;
  bool z_up = false;
  std::string skeleton;  // .gcl: the BVH it was made from

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.file, FieldInfo{.name = "file", .help = "the file to describe", .value = "FILE", .positional = true, .required = true});
    visit(self.depth, FieldInfo{.name = "depth", .help = "joint tree depth shown; 0 shows every joint", .value = "N", .min = 0, .max = 1000});
    visit(self.scale, FieldInfo{.name = "scale", .help = "BVH: multiplies all lengths (0.1 for MakeHuman decimetres)", .value = "S", .min = 1e-6, .max = 1e6});
    visit(self.z_up, FieldInfo{.name = "z_up", .help = "BVH: the file is Z-up facing -Y (MakeHuman, Blender)"});
    visit(self.skeleton, FieldInfo{.name = "skeleton", .help = ".gcl: the BVH it was compressed from (for the joint tree)", .value = "REF.bvh"});
  }
};

struct InfoResult {
  std::string file;
  std::string format;
  // Facts in the order they are shown ("joints", "12 (plus 5 end sites)"); an empty label continues
  // the fact above it.
  std::vector<std::pair<std::string, std::string>> facts;
  struct TreeLine {
    int depth = 0;
    std::string name;
    int hidden_below = 0;  // joints below it that the depth limit hides
  };
  std::vector<TreeLine> tree;  // empty when the file has no skeleton
};

void validate(const InfoRequest& request);
InfoResult run(const InfoRequest& request, const RunContext& context = {});

nlohmann::json to_json(const InfoResult& result);

}  // namespace gestura::app
