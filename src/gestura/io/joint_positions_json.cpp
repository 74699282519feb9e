#include "gestura/io/joint_positions_json.hpp"

#include <cstdio>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {

std::string joint_positions_json(const Skeleton& skeleton, const Clip& clip, float fps) {
  if (!(fps > 0.0f && fps <= 1000.0f)) throw Error("fps must be positive (got " + std::to_string(fps) + ")");
  check_output_length(clip.duration, fps, "joint positions");
  const int frames = static_cast<int>(std::floor(clip.duration * fps + 1e-4f)) + 1;
  std::string out = "{\"fps\": " + std::to_string(static_cast<int>(std::lround(fps))) + ", \"joints\": [";
  for (std::size_t j = 0; j < skeleton.size(); ++j) out += (j ? ", \"" : "\"") + skeleton.names[j] + "\"";
  out += "], \"frames\": [";
  Sampler sampler(clip);
  const Pose rest = rest_pose(skeleton);
  Pose pose;
  std::vector<mat4> model(skeleton.size());
  char buf[96];
  for (int f = 0; f < frames; ++f) {
    sampler.sample(static_cast<float>(f) / fps, WrapMode::Clamp, rest, pose);
    local_to_model(skeleton, pose, model);
    out += f ? ",\n[" : "\n[";
    for (std::size_t j = 0; j < skeleton.size(); ++j) {
      std::snprintf(buf, sizeof buf, "%s[%.5f, %.5f, %.5f]", j ? ", " : "", model[j][3].x, model[j][3].y, model[j][3].z);
      out += buf;
    }
    out += "]";
  }
  out += "]}\n";
  return out;
}

void write_joint_positions_json(const std::string& path, const Skeleton& skeleton, const Clip& clip, float fps) {
  write_file_atomically(path, joint_positions_json(skeleton, clip, fps));
}

}  // namespace gestura
