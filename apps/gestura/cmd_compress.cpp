// gestura compress / decompress: clips to and from .gcl, reporting size, error and speed
// (app/compress.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/compress.hpp"

namespace gestura::cli {
namespace {

Invocation prepare_compress() {
  auto request = std::make_shared<app::CompressRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::CompressResult r = app::run(*request, context);
    const CompressionReport& report = r.report;
    std::printf("clip:        %s, %zu joints, %u frames at %g Hz\n", request->input.c_str(), r.joints, r.frames,
                static_cast<double>(r.rate));
    std::printf("bytes:       %zu (raw %zu, ratio %.2f:1)\n", report.bytes, report.raw_bytes,
                static_cast<double>(report.raw_bytes) / static_cast<double>(report.bytes));
    std::printf("error:       max %.5f cm, p99 %.5f cm (bound %.5f cm)%s\n", report.max_error * 100.0, report.p99_error * 100.0,
                r.bound * 100.0, report.within_bound ? "" : "  BOUND NOT MET: below float precision");
    std::printf("compress:    %.1f ms (%d passes)\n", r.compress_seconds * 1e3, report.passes);
    std::printf("decompress:  %.3f us per pose (all %u frames)\n", r.decompress_seconds * 1e6 / r.frames, r.frames);
    if (!r.written.empty()) std::printf("wrote %s\n", r.written.c_str());
    return report.within_bound ? 0 : 1;
  };
  return invocation;
}

Invocation prepare_decompress() {
  auto request = std::make_shared<app::DecompressRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::DecompressResult r = app::run(*request, context);
    std::printf("wrote %s: %zu joints, %u frames at %g Hz\n", r.written.c_str(), r.joints, r.frames, static_cast<double>(r.rate));
    return 0;
  };
  return invocation;
}

const Registration reg{{"compress", "compress a clip to .gcl (key reduction + quantisation within an error bound)",
                        "INPUT: synthetic[:SECONDS] (the 67-joint test motion), a motion file (.bvh, .glb, .gltf,\n"
                        "       .bap), or a .gcl file with --skeleton (the BVH it was made from).\n"
                        "--error-cm is the largest displacement of virtual points 3 cm from every joint, in model\n"
                        "space through the hierarchy. Prints size, ratio, max and 99th-percentile error,\n"
                        "compression and decompression time. Exit status 1 when the bound cannot be met.",
                        prepare_compress}};

const Registration reg_decompress{{"decompress", "decode a .gcl clip to BVH (skeleton from a reference BVH)",
                                   "REF.bvh is the file IN.gcl was compressed from (read with the same --scale / --z-up);\n"
                                   "OUT.bvh has its hierarchy and channel layout and IN.gcl's frames.",
                                   prepare_decompress}};

}  // namespace
}  // namespace gestura::cli
