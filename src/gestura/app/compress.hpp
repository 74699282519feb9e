#pragma once
// compress / decompress: clips to and from .gcl (key reduction and quantisation within an error
// bound), with the size, error and speed measured. A .gcl holds transforms per joint index, not the
// skeleton: reading one back needs the BVH it was made from (skeleton).
#include <optional>
#include <string>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/compress/compress.hpp"

namespace gestura::app {

struct CompressRequest {
  std::string input;  // synthetic[:SECONDS], a motion file (motion_files.hpp), or a .gcl with skeleton
  std::string output;
  float error_cm = 0.01f;
  std::optional<float> rate;  // Hz; default: the input's own rate
  float scale = 1.0f;
  bool z_up = false;
  std::string skeleton;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.input, FieldInfo{.name = "input", .help = "synthetic[:SECONDS] (the 67-joint test motion), a motion file, or a .gcl with --skeleton", .value = "INPUT", .positional = true, .required = true});
    visit(self.output, FieldInfo{.name = "output", .help = "the .gcl to write", .value = "OUT.gcl", .short_flag = 'o'});
    visit(self.error_cm, FieldInfo{.name = "error_cm", .help = "largest displacement of virtual points 3 cm from every joint, in model space (cm)", .value = "E", .min = 1e-6, .max = 100});
    visit(self.rate, FieldInfo{.name = "rate", .help = "sampling rate of the compressed clip", .value = "HZ", .min = 0.1, .max = 1000, .unset = "the input's frame rate"});
    visit(self.scale, FieldInfo{.name = "scale", .help = "BVH input: multiplies all lengths (MakeHuman: 0.1)", .value = "S", .min = 1e-6, .max = 1e6});
    visit(self.z_up, FieldInfo{.name = "z_up", .help = "BVH input is Z-up facing -Y (MakeHuman, Blender)"});
    visit(self.skeleton, FieldInfo{.name = "skeleton", .help = ".gcl input: the BVH it was compressed from", .value = "REF.bvh"});
  }
};

struct CompressResult {
  std::size_t joints = 0;
  std::uint32_t frames = 0;
  float rate = 0.0f;
  CompressionReport report;
  float bound = 0.0f;            // metres
  double compress_seconds = 0.0;
  double decompress_seconds = 0.0;  // all frames
  std::string written;           // empty without output
};

void validate(const CompressRequest& request);
CompressResult run(const CompressRequest& request, const RunContext& context = {});
nlohmann::json to_json(const CompressResult& result);

struct DecompressRequest {
  std::string input;
  std::string skeleton;
  std::string output;
  float scale = 1.0f;
  bool z_up = false;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.input, FieldInfo{.name = "input", .help = "the .gcl to decode", .value = "IN.gcl", .positional = true, .required = true});
    visit(self.skeleton, FieldInfo{.name = "skeleton", .help = "the BVH it was compressed from (read with the same --scale / --z-up)", .value = "REF.bvh", .required = true});
    visit(self.output, FieldInfo{.name = "output", .help = "the .bvh to write: REF.bvh's hierarchy and channels, IN.gcl's frames", .value = "OUT.bvh", .short_flag = 'o', .required = true});
    visit(self.scale, FieldInfo{.name = "scale", .help = "multiplies all lengths of REF.bvh", .value = "S", .min = 1e-6, .max = 1e6});
    visit(self.z_up, FieldInfo{.name = "z_up", .help = "REF.bvh is Z-up facing -Y"});
  }
};

struct DecompressResult {
  std::size_t joints = 0;
  std::uint32_t frames = 0;
  float rate = 0.0f;
  std::string written;
};

void validate(const DecompressRequest& request);
DecompressResult run(const DecompressRequest& request, const RunContext& context = {});
nlohmann::json to_json(const DecompressResult& result);

}  // namespace gestura::app
