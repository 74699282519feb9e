#include "gestura/io/pose_format.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {
namespace {

static_assert(std::endian::native == std::endian::little, "the .pose writer copies little-endian floats");

constexpr std::size_t kMaxU16 = 65535;

class Writer {
 public:
  void u16(std::size_t v, const std::string& what) {
    if (v > kMaxU16) throw Error(".pose: " + what + " is " + std::to_string(v) + ", over the format's 65535");
    const auto x = static_cast<std::uint16_t>(v);
    raw(&x, 2);
  }
  void u32(std::uint32_t v) { raw(&v, 4); }
  void f32(float v) { raw(&v, 4); }
  void str(const std::string& s, const std::string& what) {
    u16(s.size(), what + " length");
    raw(s.data(), s.size());
  }
  void floats(const std::vector<float>& v) { raw(v.data(), v.size() * sizeof(float)); }
  std::string take() { return std::move(out_); }

 private:
  void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  std::string out_;
};

std::vector<std::array<std::uint16_t, 3>> grey_colors(std::size_t n) {
  return std::vector<std::array<std::uint16_t, 3>>(n, {200, 200, 200});
}

}  // namespace

int PoseData::dims() const {
  std::size_t longest = 1;
  for (const PoseComponent& c : components) longest = std::max(longest, c.format.size());
  return static_cast<int>(longest) - 1;
}

std::size_t PoseData::point_count() const {
  std::size_t n = 0;
  for (const PoseComponent& c : components) n += c.points.size();
  return n;
}

std::string encode_pose(const PoseData& pose) {
  if (pose.components.empty()) throw Error(".pose: no component");
  if (pose.dims() < 1) throw Error(".pose: point formats need at least one dimension besides the confidence");
  const std::size_t cells = std::size_t(pose.frames) * pose.people * pose.point_count();
  if (pose.confidence.size() != cells || pose.data.size() != cells * std::size_t(pose.dims()))
    throw Error(".pose: data holds " + std::to_string(pose.data.size()) + " values and confidence " +
                std::to_string(pose.confidence.size()) + ", expected " + std::to_string(cells * std::size_t(pose.dims())) +
                " and " + std::to_string(cells));
  if (!std::isfinite(pose.fps) || !(pose.fps > 0.0f)) throw Error(".pose: fps must be positive");
  Writer w;
  w.f32(pose.version);
  w.u16(pose.width, "width");
  w.u16(pose.height, "height");
  w.u16(pose.depth, "depth");
  w.u16(pose.components.size(), "component count");
  for (const PoseComponent& c : pose.components) {
    const std::string where = "component '" + c.name + "'";
    w.str(c.name, where + " name");
    w.str(c.format, where + " format");
    w.u16(c.points.size(), where + " point count");
    w.u16(c.limbs.size(), where + " limb count");
    w.u16(c.colors.size(), where + " color count");
    for (const std::string& p : c.points) w.str(p, where + " point name");
    for (const auto& [from, to] : c.limbs) {
      if (from >= c.points.size() || to >= c.points.size())
        throw Error(".pose: " + where + " has a limb " + std::to_string(from) + "-" + std::to_string(to) +
                    " past its " + std::to_string(c.points.size()) + " points");
      w.u16(from, "limb");
      w.u16(to, "limb");
    }
    for (const auto& rgb : c.colors)
      for (std::uint16_t v : rgb) w.u16(v, "color");
  }
  w.f32(pose.fps);
  w.u32(pose.frames);
  w.u16(pose.people, "people count");
  w.floats(pose.data);
  w.floats(pose.confidence);
  return w.take();
}

void save_pose(const std::string& path, const PoseData& pose) {
  write_file_atomically(path, encode_pose(pose));
}

PoseData pose_from_clip(const Skeleton& skeleton, const Clip& clip, float fps, PoseLayout layout,
                        const PinholeCamera& camera) {
  PoseData pose;
  pose.fps = fps;
  if (layout == PoseLayout::Skeleton3D) {
    if (skeleton.size() > kMaxU16) throw Error(".pose: more than 65535 joints");
    PoseComponent c;
    c.name = "GESTURA_SKELETON";
    c.format = "XYZC";
    c.points = skeleton.names;
    for (std::size_t j = 0; j < skeleton.size(); ++j)
      if (skeleton.parents[j] >= 0)
        c.limbs.push_back({static_cast<std::uint16_t>(skeleton.parents[j]), static_cast<std::uint16_t>(j)});
    c.colors = grey_colors(c.limbs.size());
    pose.components.push_back(std::move(c));
    int frames = 0;
    const std::vector<vec3> p = sample_joint_positions(skeleton, clip, fps, &frames);
    pose.frames = static_cast<std::uint32_t>(frames);
    pose.data.reserve(p.size() * 3);
    for (const vec3& v : p) pose.data.insert(pose.data.end(), {v.x, v.y, v.z});
    pose.confidence.assign(p.size(), 1.0f);
    return pose;
  }
  pose.width = static_cast<std::uint16_t>(std::clamp(camera.width, 0, 65535));
  pose.height = static_cast<std::uint16_t>(std::clamp(camera.height, 0, 65535));
  const std::pair<KeypointSet, const char*> sets[] = {{KeypointSet::Body25, "pose_keypoints_2d"},
                                                      {KeypointSet::LeftHand, "hand_left_keypoints_2d"},
                                                      {KeypointSet::RightHand, "hand_right_keypoints_2d"}};
  std::vector<Keypoints> computed;
  for (const auto& [set, name] : sets) {
    PoseComponent c;
    c.name = name;
    c.format = "XYC";
    if (set == KeypointSet::Body25) c.points.assign(kBody25Names.begin(), kBody25Names.end());
    else c.points.assign(kHandNames.begin(), kHandNames.end());
    const auto limbs = keypoint_limbs(set);
    c.limbs.assign(limbs.begin(), limbs.end());
    c.colors = grey_colors(c.limbs.size());
    pose.components.push_back(std::move(c));
    computed.push_back(compute_keypoints(skeleton, clip, fps, set));
  }
  pose.frames = static_cast<std::uint32_t>(computed[0].frames);
  for (int f = 0; f < computed[0].frames; ++f)
    for (const Keypoints& k : computed)
      for (int i = 0; i < k.count; ++i) {
        const std::size_t at = static_cast<std::size_t>(f) * static_cast<std::size_t>(k.count) + static_cast<std::size_t>(i);
        const vec3 px = camera.project(k.positions[at]);
        const bool seen = k.confidence[at] > 0.0f && px.z > 0.0f;
        pose.data.insert(pose.data.end(), {seen ? px.x : 0.0f, seen ? px.y : 0.0f});
        pose.confidence.push_back(seen ? k.confidence[at] : 0.0f);
      }
  return pose;
}

}  // namespace gestura
