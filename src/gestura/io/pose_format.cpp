#include "gestura/io/pose_format.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

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

std::vector<std::array<std::uint16_t, 3>> colors(std::size_t n, std::array<std::uint16_t, 3> rgb) {
  return std::vector<std::array<std::uint16_t, 3>>(n, rgb);
}

// Bounds-checked little-endian reads that name the source and the byte offset on failure.
class Reader {
 public:
  Reader(const std::string& bytes, const std::string& source) : bytes_(bytes), source_(source) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(source_ + ": byte " + std::to_string(at_) + ": " + what);
  }
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - at_ < n) fail(std::string("the file ends inside ") + what);
  }
  std::uint16_t u16(const char* what) { return take<std::uint16_t>(what); }
  std::uint32_t u32(const char* what) { return take<std::uint32_t>(what); }
  float f32(const char* what) { return take<float>(what); }
  std::string str(const char* what) {
    const std::uint16_t n = u16(what);
    need(n, what);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  void floats(std::vector<float>& out, std::size_t n, const char* what) {
    need(n * sizeof(float), what);
    out.resize(n);
    if (n > 0) std::memcpy(out.data(), bytes_.data() + at_, n * sizeof(float));  // an empty vector's data() may be null
    at_ += n * sizeof(float);
  }
  std::size_t left() const { return bytes_.size() - at_; }

 private:
  template <class T>
  T take(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  const std::string& bytes_;
  const std::string& source_;
  std::size_t at_ = 0;
};

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
  w.f32(0.2f);  // the body below is version 0.2's, whatever version the data was read from
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

PoseData decode_pose(const std::string& bytes, const std::string& source) {
  Reader r(bytes, source);
  PoseData pose;
  pose.version = r.f32("the version");
  const double version = std::round(double(pose.version) * 1000.0) / 1000.0;
  if (version != 0.1 && version != 0.2)
    r.fail("version " + std::to_string(pose.version) + " is not read (0.1 and 0.2 are)");
  pose.width = r.u16("the width");
  pose.height = r.u16("the height");
  pose.depth = r.u16("the depth");
  const std::uint16_t components = r.u16("the component count");
  if (components == 0) r.fail("no component");
  for (std::uint16_t i = 0; i < components; ++i) {
    PoseComponent c;
    c.name = r.str("a component name");
    c.format = r.str("a point format");
    if (c.format.size() < 2 || c.format.back() != 'C')
      r.fail("component '" + c.name + "' has point format '" + c.format + "' (letters ending in C, e.g. XYZC)");
    const std::uint16_t points = r.u16("a point count"), limbs = r.u16("a limb count"), colors = r.u16("a color count");
    for (std::uint16_t p = 0; p < points; ++p) c.points.push_back(r.str("a point name"));
    for (std::uint16_t l = 0; l < limbs; ++l) {
      const std::uint16_t from = r.u16("a limb"), to = r.u16("a limb");
      if (from >= points || to >= points)
        r.fail("component '" + c.name + "' has a limb " + std::to_string(from) + "-" + std::to_string(to) + " past its " +
               std::to_string(points) + " points");
      c.limbs.push_back({from, to});
    }
    for (std::uint16_t k = 0; k < colors; ++k) {
      const std::uint16_t red = r.u16("a color"), green = r.u16("a color"), blue = r.u16("a color");
      c.colors.push_back({red, green, blue});
    }
    pose.components.push_back(std::move(c));
  }
  const std::size_t points = pose.point_count(), dims = static_cast<std::size_t>(pose.dims());
  if (version == 0.1) {
    pose.fps = static_cast<float>(r.u16("the fps"));
    r.u16("the frame count");  // 16 bits overflowed in practice: the remaining bytes tell the count
    pose.people = r.u16("the people count");
  } else {
    pose.fps = r.f32("the fps");
    pose.frames = r.u32("the frame count");
    pose.people = r.u16("the people count");
  }
  if (!std::isfinite(pose.fps) || pose.fps < 0.0f) r.fail("fps " + std::to_string(pose.fps) + " is not a rate");
  const std::size_t per_frame = std::size_t(pose.people) * points;  // < 2^32
  if (version == 0.1) pose.frames = per_frame == 0 ? 0 : static_cast<std::uint32_t>(std::min<std::size_t>(
                                                         r.left() / (per_frame * (dims + 1) * sizeof(float)), 0xFFFFFFFFu));
  const double bytes_needed = double(pose.frames) * double(per_frame) * double(dims + 1) * sizeof(float);
  if (bytes_needed > double(std::size_t(1) << 31)) r.fail("the body would hold over 2 GiB of numbers");
  if (double(r.left()) < bytes_needed)
    r.fail(std::to_string(pose.frames) + " frames of " + std::to_string(pose.people) + " people × " + std::to_string(points) +
           " points need " + std::to_string(static_cast<std::size_t>(bytes_needed)) + " bytes; " +
           std::to_string(r.left()) + " are left");
  r.floats(pose.data, std::size_t(pose.frames) * per_frame * dims, "the data");
  r.floats(pose.confidence, std::size_t(pose.frames) * per_frame, "the confidence");
  return pose;
}

PoseData load_pose(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(path + ": cannot open");
  std::ostringstream bytes;
  bytes << file.rdbuf();
  return decode_pose(bytes.str(), path);
}

int pose_component_offset(const PoseData& pose, const std::string& name) {
  std::size_t offset = 0;
  for (const PoseComponent& c : pose.components) {
    if (c.name == name) return static_cast<int>(offset);
    offset += c.points.size();
  }
  return -1;
}

PoseData holistic_pose(const HolisticTrack& track, std::span<const PinholeCamera> cameras, float fps) {
  if (!std::isfinite(fps) || !(fps > 0.0f)) throw Error(".pose: fps must be positive");
  if (cameras.size() != 1 && cameras.size() != static_cast<std::size_t>(track.frames))
    throw Error(".pose: " + std::to_string(cameras.size()) + " cameras for " + std::to_string(track.frames) +
                " frames (give one, or one per frame)");
  const PinholeCamera& first = cameras[0];
  PoseData pose;
  pose.fps = fps;
  pose.width = static_cast<std::uint16_t>(std::clamp(first.width, 0, 65535));
  pose.height = static_cast<std::uint16_t>(std::clamp(first.height, 0, 65535));
  const auto component = [](const char* name, std::span<const char* const> points, std::span<const std::array<std::uint16_t, 2>> limbs,
                            std::array<std::uint16_t, 3> rgb) {
    PoseComponent c;
    c.name = name;
    c.format = "XYZC";
    c.points.assign(points.begin(), points.end());
    c.limbs.assign(limbs.begin(), limbs.end());
    c.colors = colors(c.limbs.size(), rgb);
    return c;
  };
  std::vector<std::string> face_names;
  for (int i = 0; i < kHolisticFaceCount; ++i) face_names.push_back(std::to_string(i));
  PoseComponent face;
  face.name = "FACE_LANDMARKS";
  face.format = "XYZC";
  face.points = face_names;
  const auto face_limbs = holistic_face_limbs();
  face.limbs.assign(face_limbs.begin(), face_limbs.end());
  face.colors = colors(face.limbs.size(), {128, 0, 0});
  pose.components = {component("POSE_LANDMARKS", kHolisticBodyNames, holistic_body_limbs(), {255, 0, 0}), face,
                     component("LEFT_HAND_LANDMARKS", kHandNames, holistic_hand_limbs(), {0, 255, 0}),
                     component("RIGHT_HAND_LANDMARKS", kHandNames, holistic_hand_limbs(), {0, 0, 255}),
                     component("POSE_WORLD_LANDMARKS", kHolisticBodyNames, holistic_body_limbs(), {255, 0, 0})};
  pose.frames = static_cast<std::uint32_t>(track.frames);

  for (int f = 0; f < track.frames; ++f) {
    const PinholeCamera& camera = cameras[cameras.size() == 1 ? 0 : static_cast<std::size_t>(f)];
    const vec3 forward = glm::normalize(camera.target - camera.position);
    const vec3 right = glm::normalize(glm::cross(forward, vec3(0.0f, 1.0f, 0.0f)));
    const vec3 down = -glm::cross(right, forward);
    const float focal = 0.5f * float(camera.height) / std::tan(0.5f * camera.vertical_fov);
    const float width = float(std::max(1, camera.width));
    // Image landmarks: pixels, and depth about `reference` in image-width units at its distance.
    const auto image = [&](std::span<const vec3> points, std::span<const float> confidence, const vec3& reference) {
      const float ref_depth = glm::dot(reference - camera.position, forward);
      for (std::size_t i = 0; i < points.size(); ++i) {
        const vec3 px = camera.project(points[i]);
        const bool seen = confidence[i] > 0.0f && px.z > 0.0f && ref_depth > 0.0f;
        const float z = seen ? (px.z - ref_depth) * focal / (ref_depth * width) : 0.0f;
        pose.data.insert(pose.data.end(), {seen ? px.x : 0.0f, seen ? px.y : 0.0f, z});
        pose.confidence.push_back(seen ? 1.0f : 0.0f);
      }
    };
    const auto slice = [f](const std::vector<vec3>& v, int count) {
      return std::span<const vec3>(v).subspan(static_cast<std::size_t>(f) * static_cast<std::size_t>(count), static_cast<std::size_t>(count));
    };
    const auto cslice = [f](const std::vector<float>& v, int count) {
      return std::span<const float>(v).subspan(static_cast<std::size_t>(f) * static_cast<std::size_t>(count), static_cast<std::size_t>(count));
    };
    const auto body = slice(track.body, kHolisticBodyCount);
    const auto body_conf = cslice(track.body_confidence, kHolisticBodyCount);
    const vec3 hips = 0.5f * (body[23] + body[24]);
    image(body, body_conf, hips);
    const auto face_points = slice(track.face, kHolisticFaceCount);
    const auto face_conf = cslice(track.face_confidence, kHolisticFaceCount);
    vec3 face_centre(0.0f);
    float placed = 0.0f;
    for (int i = 0; i < kHolisticFaceCount; ++i)
      if (face_conf[static_cast<std::size_t>(i)] > 0.0f) face_centre += face_points[static_cast<std::size_t>(i)], placed += 1.0f;
    image(face_points, face_conf, placed > 0.0f ? face_centre / placed : body[0]);
    const auto left = slice(track.left_hand, kHolisticHandCount), right_hand = slice(track.right_hand, kHolisticHandCount);
    image(left, cslice(track.left_confidence, kHolisticHandCount), left[0]);
    image(right_hand, cslice(track.right_confidence, kHolisticHandCount), right_hand[0]);
    for (std::size_t i = 0; i < body.size(); ++i) {
      const vec3 d = body[i] - hips;
      const bool seen = body_conf[i] > 0.0f;
      pose.data.insert(pose.data.end(), {seen ? glm::dot(d, right) * float(camera.width) : 0.0f,
                                         seen ? glm::dot(d, down) * float(camera.height) : 0.0f,
                                         seen ? glm::dot(d, forward) : 0.0f});
      pose.confidence.push_back(seen ? 1.0f : 0.0f);
    }
  }
  return pose;
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
