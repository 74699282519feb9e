#include "gestura/render/occluders.hpp"

#include <algorithm>
#include <string>

#include "gestura/skeleton/joint_names.hpp"

namespace gestura {
namespace {

// The distance of p from segment ab.
float segment_distance(const vec3& p, const vec3& a, const vec3& b) {
  const vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

}  // namespace

OccluderSet find_occluders(const Skeleton& skeleton, const Mesh& mesh) {
  OccluderSet out;
  const std::vector<std::string> hanim = guess_hanim_names(skeleton);
  const auto find = [&](const std::string& name) {
    const auto it = std::find(hanim.begin(), hanim.end(), name);
    return it == hanim.end() ? -1 : static_cast<int>(it - hanim.begin());
  };
  out.joint_part.assign(skeleton.size(), BodyPart::Trunk);
  const auto mark = [&](int root, BodyPart part) {
    if (root < 0) return;
    for (std::size_t j = 0; j < skeleton.size(); ++j)
      for (int p = static_cast<int>(j); p >= 0; p = skeleton.parents[static_cast<std::size_t>(p)])
        if (p == root) { out.joint_part[j] = part; break; }
  };
  mark(find("l_shoulder"), BodyPart::LeftArm);
  mark(find("r_shoulder"), BodyPart::RightArm);
  mark(find("skullbase"), BodyPart::Head);

  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  const auto at = [&](int j) { return vec3(model[static_cast<std::size_t>(j)][3]); };
  // The dominant joint of every vertex.
  std::vector<int> dominant(mesh.positions.size(), -1);
  for (std::size_t v = 0; v < mesh.positions.size() && v < mesh.joints.size() && v < mesh.weights.size(); ++v) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (mesh.weights[v][k] > mesh.weights[v][best]) best = k;
    dominant[v] = mesh.joints[v][best];
  }
  // A capsule from joint `from` to joint `to`, carried by `carrier`, as thick as the skin of the
  // vertices that `skin` joints dominate (the 60th percentile of their distance from the axis).
  const auto capsule = [&](const std::string& from, const std::string& to, const std::string& carrier,
                           std::initializer_list<std::string> skin, BodyPart part) {
    const int a = find(from), b = find(to), c = find(carrier);
    if (a < 0 || b < 0 || c < 0 || out.capsules.size() >= kMaxOccluders) return;
    std::vector<int> joints;
    for (const std::string& s : skin)
      if (const int j = find(s); j >= 0) joints.push_back(j);
    std::vector<float> distances;
    for (std::size_t v = 0; v < dominant.size(); ++v)
      if (std::find(joints.begin(), joints.end(), dominant[v]) != joints.end())
        distances.push_back(segment_distance(mesh.positions[v], at(a), at(b)));
    if (distances.size() < 8) return;
    const auto nth = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() * 6 / 10);
    std::nth_element(distances.begin(), nth, distances.end());
    out.capsules.push_back({c, at(a), at(b), *nth, part});
  };
  for (const auto& [side, part] : {std::pair{std::string("l_"), BodyPart::LeftArm}, std::pair{std::string("r_"), BodyPart::RightArm}}) {
    capsule(side + "shoulder", side + "elbow", side + "shoulder", {side + "shoulder"}, part);
    capsule(side + "elbow", side + "wrist", side + "elbow", {side + "elbow"}, part);
    capsule(side + "wrist", side + "middle1", side + "wrist", {side + "wrist"}, part);
    capsule(side + "middle1", side + "middle_tip", side + "middle1",
            {side + "index1", side + "index2", side + "index3", side + "middle1", side + "middle2", side + "middle3",
             side + "ring1", side + "ring2", side + "ring3", side + "pinky1", side + "pinky2", side + "pinky3"},
            part);
    capsule(side + "thumb2", side + "thumb_tip", side + "thumb2", {side + "thumb2", side + "thumb3"}, part);
  }
  // No capsule for the head: a sphere that coarse shades the neck with a visible seam where the
  // head's own vertices (which it may not shade) meet the trunk's.
  if (out.capsules.empty()) return {};
  return out;
}

}  // namespace gestura
