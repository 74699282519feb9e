// gestura compress / decompress: clips to and from .gcl files, reporting size, error and speed.
//
// A .gcl holds transforms per joint index, not the skeleton, so reading one back needs the skeleton
// it was made for: --skeleton REF.bvh (the BVH it was compressed from, read with the same --scale /
// --z-up) supplies names, hierarchy and channel layout.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/compress/decompress_clip.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"

namespace {

using namespace gestura;

float parse_positive(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const float v = std::stof(text, &used);
    if (used == text.size() && v > 0.0f && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw Error(flag + ": expected a positive number, got '" + text + "'");
}

bool ends_with_gcl(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".gcl";
}

// The skeleton of a .gcl, from the BVH it came from; the .gcl must have one track set per joint.
BvhFile reference_for(const CompressedClip& compressed, const std::string& gcl_path, const std::string& skeleton_path,
                      const BvhReadOptions& options) {
  if (skeleton_path.empty())
    throw Error(gcl_path + ": a .gcl stores no skeleton; give the BVH it was made from with --skeleton REF.bvh");
  BvhFile reference = load_bvh(skeleton_path, options);
  if (reference.skeleton.size() != compressed.joint_count())
    throw Error(gcl_path + ": has " + std::to_string(compressed.joint_count()) + " joints, --skeleton " + skeleton_path +
                " has " + std::to_string(reference.skeleton.size()));
  return reference;
}

struct Input {
  Skeleton skeleton;
  Clip clip;
  float rate = 30.0f;  // the source's own frame rate
};

// "synthetic[:SECONDS]" (the 67-joint test motion), a BVH file, or a .gcl with --skeleton.
Input load_input(const std::string& input, const std::string& skeleton_path, const BvhReadOptions& options) {
  Input in;
  if (input.rfind("synthetic", 0) == 0 && !ends_with_gcl(input) && input.find('.') == std::string::npos) {
    float seconds = 15.0f;
    if (input.size() > 9) {
      if (input[9] != ':') throw Error("input '" + input + "': expected synthetic or synthetic:SECONDS");
      seconds = parse_positive("synthetic seconds", input.substr(10));
      if (seconds > 3600.0f) throw Error("input '" + input + "': at most 3600 seconds");
    }
    in.skeleton = synthetic_humanoid();
    in.clip = synthetic_clip(in.skeleton, seconds, 30.0f);
    return in;
  }
  if (ends_with_gcl(input)) {
    const CompressedClip compressed = load_gcl(input);
    in.skeleton = reference_for(compressed, input, skeleton_path, options).skeleton;
    in.clip = decompress_clip(compressed, input);
    in.rate = compressed.sample_rate();
    return in;
  }
  BvhFile bvh = load_bvh(input, options);
  in.skeleton = std::move(bvh.skeleton);
  in.clip = std::move(bvh.clip);
  in.rate = 1.0f / bvh.frame_time;
  return in;
}

// Flags shared by both commands; returns false for an argument it does not know.
bool read_motion_flag(const std::vector<std::string>& args, std::size_t& i, BvhReadOptions& options,
                      std::string& skeleton_path) {
  if (args[i] == "--scale") {
    options.scale = parse_positive("--scale", cli::flag_value(args, i));
    if (options.scale < 1e-6f || options.scale > 1e6f) throw Error("--scale: expected 1e-6..1e6");
  } else if (args[i] == "--z-up") {
    options.z_up = true;
  } else if (args[i] == "--skeleton") {
    skeleton_path = cli::flag_value(args, i);
  } else {
    return false;
  }
  return true;
}

int run_compress(const std::vector<std::string>& args) {
  std::string input, output, skeleton_path;
  BvhReadOptions options;
  CompressionSettings settings;
  bool rate_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (read_motion_flag(args, i, options, skeleton_path)) continue;
    if (args[i] == "-o") output = cli::flag_value(args, i);
    else if (args[i] == "--error-cm") settings.max_error = parse_positive("--error-cm", cli::flag_value(args, i)) * 0.01f;
    else if (args[i] == "--rate") settings.sample_rate = parse_positive("--rate", cli::flag_value(args, i)), rate_given = true;
    else if (!args[i].empty() && args[i][0] == '-') throw Error("unknown flag '" + args[i] + "' (see gestura compress --help)");
    else if (input.empty()) input = args[i];
    else throw Error("more than one input ('" + input + "', '" + args[i] + "')");
  }
  if (input.empty()) throw Error("no input clip (see gestura compress --help)");
  const Input in = load_input(input, skeleton_path, options);
  if (!rate_given) settings.sample_rate = in.rate;

  CompressionReport report;
  const auto t0 = std::chrono::steady_clock::now();
  const CompressedClip compressed = compress(in.clip, in.skeleton, settings, &report);
  const double compress_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  Pose pose = rest_pose(in.skeleton);
  const std::uint32_t frames = compressed.frame_count();
  const auto t1 = std::chrono::steady_clock::now();
  for (std::uint32_t f = 0; f < frames; ++f) compressed.sample(static_cast<float>(f) / compressed.sample_rate(), pose);
  const double decompress_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  if (!output.empty()) save_gcl(output, compressed);
  std::printf("clip:        %s, %zu joints, %u frames at %g Hz\n", input.c_str(), in.skeleton.size(), frames,
              compressed.sample_rate());
  std::printf("bytes:       %zu (raw %zu, ratio %.2f:1)\n", report.bytes, report.raw_bytes,
              static_cast<double>(report.raw_bytes) / static_cast<double>(report.bytes));
  std::printf("error:       max %.5f cm, p99 %.5f cm (bound %.5f cm)%s\n", report.max_error * 100.0, report.p99_error * 100.0,
              settings.max_error * 100.0, report.within_bound ? "" : "  BOUND NOT MET: below float precision");
  std::printf("compress:    %.1f ms (%d passes)\n", compress_s * 1e3, report.passes);
  std::printf("decompress:  %.3f us per pose (all %u frames)\n", decompress_s * 1e6 / frames, frames);
  if (!output.empty()) std::printf("wrote %s\n", output.c_str());
  return report.within_bound ? 0 : 1;
}

int run_decompress(const std::vector<std::string>& args) {
  std::string input, output, skeleton_path;
  BvhReadOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (read_motion_flag(args, i, options, skeleton_path)) continue;
    if (args[i] == "-o") output = cli::flag_value(args, i);
    else if (!args[i].empty() && args[i][0] == '-') throw Error("unknown flag '" + args[i] + "' (see gestura decompress --help)");
    else if (input.empty()) input = args[i];
    else throw Error("more than one input ('" + input + "', '" + args[i] + "')");
  }
  if (input.empty() || output.empty()) throw Error("usage: gestura decompress IN.gcl --skeleton REF.bvh -o OUT.bvh");
  const CompressedClip compressed = load_gcl(input);
  // Keep the reference's channel layout, so the output reads like the file that was compressed.
  BvhFile bvh = reference_for(compressed, input, skeleton_path, options);
  bvh.clip = decompress_clip(compressed, input);
  bvh.frame_time = 1.0f / compressed.sample_rate();
  bvh.frame_count = static_cast<int>(compressed.frame_count());
  save_bvh(output, bvh);
  std::printf("wrote %s: %zu joints, %u frames at %g Hz\n", output.c_str(), bvh.skeleton.size(), compressed.frame_count(),
              compressed.sample_rate());
  return 0;
}

const cli::Registration reg{{"compress", "compress a clip to .gcl (key reduction + quantisation within an error bound)",
                             "usage: gestura compress INPUT [-o OUT.gcl] [--error-cm E] [--rate HZ]\n"
                             "                        [--scale S] [--z-up] [--skeleton REF.bvh]\n"
                             "  INPUT: synthetic[:SECONDS] (the 67-joint test motion), a .bvh file, or a .gcl\n"
                             "         file with --skeleton (the BVH it was made from).\n"
                             "  --error-cm  largest displacement of virtual points 3 cm from every joint, in model\n"
                             "              space through the hierarchy (default 0.01)\n"
                             "  --rate      sampling rate of the compressed clip (default: the input's frame rate)\n"
                             "  --scale S, --z-up  as in gestura convert (MakeHuman BVH: --scale 0.1 --z-up)\n"
                             "  Prints size, ratio, max and 99th-percentile error, compression and decompression time.",
                             run_compress}};

const cli::Registration reg_decompress{{"decompress", "decode a .gcl clip to BVH (skeleton from a reference BVH)",
                                        "usage: gestura decompress IN.gcl --skeleton REF.bvh -o OUT.bvh [--scale S] [--z-up]\n"
                                        "  REF.bvh is the file IN.gcl was compressed from (read with the same --scale /\n"
                                        "  --z-up); OUT.bvh has its hierarchy and channel layout and IN.gcl's frames.",
                                        run_decompress}};

}  // namespace
