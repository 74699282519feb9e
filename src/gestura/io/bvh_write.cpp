// BVH writer: hierarchy in depth-first order, then one line of channel values per frame sampled
// from the clip. Rotations become Euler angles near the previous frame's, so sequences stay smooth.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/io/bvh.hpp"

namespace gestura {

namespace {

// Shortest fixed-point text that reads back as the same float ("0.6394", "-12.5", "0").
void append_number(std::string& out, float value) {
  if (value == 0.0f) value = 0.0f;  // no "-0"
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  out.append(buffer, result.ptr);
}

void append_vec3(std::string& out, const vec3& v) {
  for (int a = 0; a < 3; ++a) {
    out += ' ';
    append_number(out, v[a]);
  }
}

bool is_unit_scale(const vec3& s) { return glm::all(glm::lessThanEqual(glm::abs(s - vec3(1.0f)), vec3(1e-5f))); }

// A name reads back the same only without braces and control bytes, and with single inner spaces.
bool is_writable_name(const std::string& name) {
  if (name.empty() || name.front() == ' ' || name.back() == ' ' || name.find("  ") != std::string::npos) return false;
  return std::none_of(name.begin(), name.end(), [](char c) {
    return c == '{' || c == '}' || (static_cast<unsigned char>(c) < 0x20) || c == 0x7F;
  });
}

void check_writable(const BvhFile& bvh) {
  const Skeleton& skeleton = bvh.skeleton;
  skeleton.validate();
  const std::size_t n = skeleton.size();
  if (bvh.end_site.size() != n || bvh.channels.size() != n)
    throw Error("BVH layout has " + std::to_string(bvh.channels.size()) + " channel lists and " +
                std::to_string(bvh.end_site.size()) + " end-site flags for " + std::to_string(n) + " joints");
  if (n == 0) throw Error("cannot write a BVH file without joints");
  int roots = 0;
  for (std::size_t j = 0; j < n; ++j) roots += skeleton.parents[j] < 0;
  if (roots != 1)
    throw Error("a BVH file has one ROOT, the skeleton has " + std::to_string(roots) + " root joints");
  for (std::size_t j = 0; j < n; ++j) {
    const int parent = skeleton.parents[j];
    if (parent >= 0 && bvh.end_site[static_cast<std::size_t>(parent)])
      throw Error("joint '" + skeleton.names[j] + "' has an End Site as parent");
    if (bvh.end_site[j] && (parent < 0 || bvh.channels[j].count != 0))
      throw Error("End Site '" + skeleton.names[j] + "' must be a leaf without channels and not the root");
    if (bvh.channels[j].count > 6) throw Error("joint '" + skeleton.names[j] + "' has more than 6 channels");
    if (!bvh.end_site[j] && !is_writable_name(skeleton.names[j]))
      throw Error("joint name '" + skeleton.names[j] + "' cannot be written to BVH (braces, control characters or odd spaces)");
    if (!is_unit_scale(skeleton.rest_scales[j]))
      throw Error("joint '" + skeleton.names[j] + "' has a rest scale; BVH cannot store scale");
  }
  if (!std::isfinite(bvh.frame_time) || !(bvh.frame_time > 0.0f)) throw Error("BVH frame time must be positive");
  if (bvh.frame_count < 0 || bvh.frame_count > kBvhMaxFrames) throw Error("BVH frame count out of range");
  validate(bvh.clip, skeleton);
  for (std::size_t j = 0; j < n; ++j)
    for (const vec3& s : bvh.clip.scales[j].values)
      if (!is_unit_scale(s)) throw Error("clip scales joint '" + skeleton.names[j] + "'; BVH cannot store scale");
}

// Joints in depth-first order (children in index order): the order of the BVH hierarchy and of
// the values on each motion line.
std::vector<int> depth_first_order(const Skeleton& skeleton) {
  const std::size_t n = skeleton.size();
  std::vector<std::vector<int>> children(n);
  int root = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (skeleton.parents[j] < 0) root = static_cast<int>(j);
    else children[static_cast<std::size_t>(skeleton.parents[j])].push_back(static_cast<int>(j));
  }
  std::vector<int> order;
  order.reserve(n);
  std::vector<int> stack{root};
  while (!stack.empty()) {
    const int j = stack.back();
    stack.pop_back();
    order.push_back(j);
    const auto& kids = children[static_cast<std::size_t>(j)];
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back(*it);
  }
  return order;
}

void write_hierarchy(std::string& out, const BvhFile& bvh, const std::vector<int>& order) {
  const Skeleton& skeleton = bvh.skeleton;
  std::vector<int> depth(skeleton.size(), 0);
  std::vector<int> open;  // joints whose '}' is still to be written, innermost last
  out += "HIERARCHY\n";
  auto close_until = [&](int depth_to_keep) {
    while (static_cast<int>(open.size()) > depth_to_keep) {
      out.append(open.size() - 1, '\t');
      out += "}\n";
      open.pop_back();
    }
  };
  for (const int j : order) {
    const auto ju = static_cast<std::size_t>(j);
    const int parent = skeleton.parents[ju];
    depth[ju] = parent < 0 ? 0 : depth[static_cast<std::size_t>(parent)] + 1;
    close_until(depth[ju]);
    const std::string indent(static_cast<std::size_t>(depth[ju]), '\t');
    if (bvh.end_site[ju]) out += indent + "End Site\n";
    else out += indent + (parent < 0 ? "ROOT " : "JOINT ") + skeleton.names[ju] + "\n";
    out += indent + "{\n" + indent + "\tOFFSET";
    append_vec3(out, skeleton.rest_translations[ju]);
    out += '\n';
    if (!bvh.end_site[ju]) {
      const BvhChannels& c = bvh.channels[ju];
      out += indent + "\tCHANNELS " + std::to_string(c.count);
      for (int i = 0; i < c.count; ++i) out.append(" ").append(to_string(c[i]));
      out += '\n';
    }
    open.push_back(j);
  }
  close_until(0);
}

void write_motion(std::string& out, const BvhFile& bvh, const std::vector<int>& order) {
  const Skeleton& skeleton = bvh.skeleton;
  const Clip& clip = bvh.clip;
  out += "MOTION\nFrames: " + std::to_string(bvh.frame_count) + "\nFrame Time: ";
  append_number(out, bvh.frame_time);
  out += '\n';
  std::vector<vec3> previous(skeleton.size(), vec3(0.0f));  // Euler hints, radians
  std::vector<std::uint32_t> rotation_cursor(skeleton.size(), 0), translation_cursor(skeleton.size(), 0);
  for (int f = 0; f < bvh.frame_count; ++f) {
    // Same expression as the reader, so sampling hits the keys of a clip read from BVH exactly.
    const auto t = static_cast<float>(static_cast<double>(f) * bvh.frame_time);
    bool first = true;
    for (const int j : order) {
      const auto ju = static_cast<std::size_t>(j);
      const BvhChannels& c = bvh.channels[ju];
      if (c.count == 0) continue;
      const vec3 translation = clip.translations[ju].empty()
                                   ? skeleton.rest_translations[ju]
                                   : sample_track(clip.translations[ju], t, &translation_cursor[ju]);
      vec3 angles(0.0f);
      if (c.has_rotation()) {
        const quat rotation = clip.rotations[ju].empty() ? skeleton.rest_rotations[ju]
                                                         : sample_track(clip.rotations[ju], t, &rotation_cursor[ju]);
        angles = previous[ju] = quat_to_euler_near(rotation, c.rotation_order(), previous[ju]);
      }
      for (int i = 0; i < c.count; ++i) {
        const int axis = axis_of(c[i]);
        if (!first) out += ' ';
        first = false;
        append_number(out, is_position(c[i]) ? translation[axis] - skeleton.rest_translations[ju][axis]
                                             : to_degrees(angles[axis]));
      }
    }
    out += '\n';
  }
}

}  // namespace

BvhFile make_bvh(const Skeleton& skeleton, const Clip& clip, float frame_time) {
  if (!std::isfinite(frame_time) || !(frame_time > 0.0f)) throw Error("BVH frame time must be positive");
  BvhFile bvh;
  bvh.skeleton = skeleton;
  bvh.clip = clip;
  bvh.clip.resize_joints(skeleton.size());
  bvh.frame_time = frame_time;
  bvh.end_site.assign(skeleton.size(), 0);
  bvh.channels.resize(skeleton.size());
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    BvhChannels& c = bvh.channels[j];
    if (skeleton.parents[j] < 0 || !bvh.clip.translations[j].empty())
      for (BvhChannel p : {BvhChannel::Xposition, BvhChannel::Yposition, BvhChannel::Zposition}) c.push(p);
    for (BvhChannel r : {BvhChannel::Zrotation, BvhChannel::Xrotation, BvhChannel::Yrotation}) c.push(r);
  }
  const double span = std::max(clip.duration, clip.end_time());
  check_output_length(span, 1.0 / frame_time, "BVH clip '" + clip.name + "'");
  const double frames = std::floor(span / frame_time + 0.5) + 1.0;
  if (!(frames <= static_cast<double>(kBvhMaxFrames)))
    throw Error("clip '" + clip.name + "' needs more than " + std::to_string(kBvhMaxFrames) + " BVH frames");
  bvh.frame_count = static_cast<int>(frames);
  return bvh;
}

std::string write_bvh(const BvhFile& bvh) {
  check_writable(bvh);
  const std::vector<int> order = depth_first_order(bvh.skeleton);
  std::string out;
  out.reserve(bvh.skeleton.size() * 96 + static_cast<std::size_t>(bvh.frame_count) *
                                             static_cast<std::size_t>(bvh.channel_count()) * 10);
  write_hierarchy(out, bvh, order);
  write_motion(out, bvh, order);
  return out;
}

void save_bvh(const std::string& path, const BvhFile& bvh) {
  write_file_atomically(path, write_bvh(bvh));
}

}  // namespace gestura
