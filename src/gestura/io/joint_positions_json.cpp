#include "gestura/io/joint_positions_json.hpp"

#include <cstdio>
#include <fstream>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

std::string joint_positions_json(const Skeleton& skeleton, const Clip& clip, float fps) {
  if (!(fps > 0.0f && fps <= 1000.0f)) throw Error("fps must be positive (got " + std::to_string(fps) + ")");
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
  const std::string text = joint_positions_json(skeleton, clip, fps);
  const std::string temp = path + ".part";
  {
    std::ofstream file(temp, std::ios::binary);
    if (!file) throw Error(path + ": cannot write here");
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!file) {
      std::remove(temp.c_str());
      throw Error(path + ": write failed");
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw Error(path + ": cannot replace the file");
  }
}

}  // namespace gestura
