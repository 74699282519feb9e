#include "gestura/io/openpose_json.hpp"

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {

std::vector<std::string> openpose_json_frames(const Skeleton& skeleton, const Clip& clip, float fps,
                                              const PinholeCamera& camera) {
  const Keypoints body = compute_keypoints(skeleton, clip, fps, KeypointSet::Body25);
  const Keypoints left = compute_keypoints(skeleton, clip, fps, KeypointSet::LeftHand);
  const Keypoints right = compute_keypoints(skeleton, clip, fps, KeypointSet::RightHand);
  auto flat = [&](const Keypoints& k, int frame) {
    nlohmann::json values = nlohmann::json::array();
    for (int i = 0; i < k.count; ++i) {
      const std::size_t at = static_cast<std::size_t>(frame) * static_cast<std::size_t>(k.count) + static_cast<std::size_t>(i);
      const vec3 px = camera.project(k.positions[at]);
      const bool seen = k.confidence[at] > 0.0f && px.z > 0.0f;
      values.push_back(seen ? px.x : 0.0f);
      values.push_back(seen ? px.y : 0.0f);
      values.push_back(seen ? k.confidence[at] : 0.0f);
    }
    return values;
  };
  std::vector<std::string> frames;
  for (int f = 0; f < body.frames; ++f) {
    nlohmann::json person = {{"person_id", {-1}},
                             {"pose_keypoints_2d", flat(body, f)},
                             {"face_keypoints_2d", nlohmann::json::array()},
                             {"hand_left_keypoints_2d", flat(left, f)},
                             {"hand_right_keypoints_2d", flat(right, f)},
                             {"pose_keypoints_3d", nlohmann::json::array()},
                             {"face_keypoints_3d", nlohmann::json::array()},
                             {"hand_left_keypoints_3d", nlohmann::json::array()},
                             {"hand_right_keypoints_3d", nlohmann::json::array()}};
    const nlohmann::json doc = {{"version", 1.3}, {"people", nlohmann::json::array({person})}};
    frames.push_back(doc.dump());
  }
  return frames;
}

std::vector<std::string> save_openpose_json(const std::string& path, const Skeleton& skeleton, const Clip& clip,
                                            float fps, const PinholeCamera& camera) {
  const std::vector<std::string> frames = openpose_json_frames(skeleton, clip, fps, camera);
  const std::filesystem::path base(path);
  // All frames or none: a failure half-way must not leave a shorter sequence that looks complete.
  StagedFileGroup group(base.parent_path().string(), base.stem().string());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    char number[48];
    std::snprintf(number, sizeof number, "_%012zu_keypoints.json", f);
    group.write(base.stem().string() + number, frames[f]);
  }
  return group.commit();
}

}  // namespace gestura
