// gestura compress: compress a clip into a .gcl file and report size, error and speed.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/core/error.hpp"

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

// The clip source. "synthetic[:SECONDS]" is the documented 67-joint test motion; files are read by
// the BVH loader once it is wired in here.
void load_input(const std::string& input, Skeleton& skeleton, Clip& clip) {
  if (input.rfind("synthetic", 0) == 0) {
    float seconds = 15.0f;
    if (input.size() > 9) {
      if (input[9] != ':') throw Error("input '" + input + "': expected synthetic or synthetic:SECONDS");
      seconds = parse_positive("synthetic seconds", input.substr(10));
      if (seconds > 3600.0f) throw Error("input '" + input + "': at most 3600 seconds");
    }
    skeleton = synthetic_humanoid();
    clip = synthetic_clip(skeleton, seconds, 30.0f);
    return;
  }
  throw Error(SourceLocation{input}, "reading clips from files is not wired into this command yet; use synthetic[:SECONDS]");
}

int run_compress(const std::vector<std::string>& args) {
  std::string input, output;
  CompressionSettings settings;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-o") output = cli::flag_value(args, i);
    else if (args[i] == "--error-cm") settings.max_error = parse_positive("--error-cm", cli::flag_value(args, i)) * 0.01f;
    else if (args[i] == "--rate") settings.sample_rate = parse_positive("--rate", cli::flag_value(args, i));
    else if (!args[i].empty() && args[i][0] == '-') throw Error("unknown flag '" + args[i] + "' (see gestura compress --help)");
    else if (input.empty()) input = args[i];
    else throw Error("more than one input ('" + input + "', '" + args[i] + "')");
  }
  if (input.empty()) throw Error("no input clip (see gestura compress --help)");
  Skeleton skeleton;
  Clip clip;
  load_input(input, skeleton, clip);

  CompressionReport report;
  const auto t0 = std::chrono::steady_clock::now();
  const CompressedClip compressed = compress(clip, skeleton, settings, &report);
  const double compress_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  Pose pose = rest_pose(skeleton);
  const std::uint32_t frames = compressed.frame_count();
  const auto t1 = std::chrono::steady_clock::now();
  for (std::uint32_t f = 0; f < frames; ++f) compressed.sample(static_cast<float>(f) / compressed.sample_rate(), pose);
  const double decompress_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  if (!output.empty()) save_gcl(output, compressed);
  std::printf("clip:        %s, %zu joints, %u frames at %g Hz\n", input.c_str(), skeleton.size(), frames, compressed.sample_rate());
  std::printf("bytes:       %zu (raw %zu, ratio %.2f:1)\n", report.bytes, report.raw_bytes,
              static_cast<double>(report.raw_bytes) / static_cast<double>(report.bytes));
  std::printf("error:       max %.5f cm, p99 %.5f cm (bound %.5f cm)%s\n", report.max_error * 100.0, report.p99_error * 100.0,
              settings.max_error * 100.0, report.within_bound ? "" : "  BOUND NOT MET: below float precision");
  std::printf("compress:    %.1f ms (%d passes)\n", compress_s * 1e3, report.passes);
  std::printf("decompress:  %.3f us per pose (all %u frames)\n", decompress_s * 1e6 / frames, frames);
  if (!output.empty()) std::printf("wrote %s\n", output.c_str());
  return report.within_bound ? 0 : 1;
}

const cli::Registration reg{{"compress", "compress a clip to .gcl (key reduction + quantisation within an error bound)",
                             "usage: gestura compress INPUT [-o OUT.gcl] [--error-cm E] [--rate HZ]\n"
                             "  INPUT: synthetic[:SECONDS] (the 67-joint test motion).\n"
                             "  --error-cm  largest displacement of virtual points 3 cm from every joint (default 0.01)\n"
                             "  --rate      sampling rate of the compressed clip (default 30 Hz)\n"
                             "  Prints size, ratio, max and 99th-percentile error, compression and decompression time.",
                             run_compress}};

}  // namespace
