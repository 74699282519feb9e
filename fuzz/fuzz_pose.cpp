// Fuzz target: a pose-format .pose file (binary, versions 0.1 and 0.2). What decodes must encode
// again and decode to the same header and body: `info` and `convert` read it, and `convert` writes it.
#include <cstdlib>

#include "fuzz_target.hpp"
#include "gestura/io/pose_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(gestura::fuzz::text_of(data, size));
  gestura::fuzz::expect_result_or_error([&] {
    const gestura::PoseData pose = gestura::decode_pose(bytes, "fuzz.pose");
    for (const gestura::PoseComponent& c : pose.components) (void)gestura::pose_component_offset(pose, c.name);
    const gestura::PoseData again = gestura::decode_pose(gestura::encode_pose(pose), "again.pose");
    // A file that reads must survive its own round trip unchanged.
    if (again.frames != pose.frames || again.people != pose.people || again.point_count() != pose.point_count() ||
        again.data.size() != pose.data.size() || again.confidence.size() != pose.confidence.size())
      std::abort();
  });
  return 0;
}
