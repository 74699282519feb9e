#include "gestura/app/info.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "gestura/app/error.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/app/motion_files.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/io/bap.hpp"
#include "gestura/io/pose_format.hpp"
#include "gestura/io/vrm.hpp"

namespace gestura::app {
namespace {

std::string printed(const char* format, auto... values) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, values...);
  return buf;
}

// The joint tree down to `max_depth` (0 = all), end sites left out; deeper joints are counted.
std::vector<InfoResult::TreeLine> joint_tree(const BvhFile& bvh, int max_depth) {
  const Skeleton& skeleton = bvh.skeleton;
  const std::size_t n = skeleton.size();
  std::vector<int> depth(n, 0), hidden_below(n, 0), shown_ancestor(n, -1);
  for (std::size_t j = 0; j < n; ++j) {
    const int parent = skeleton.parents[j];
    if (parent >= 0) depth[j] = depth[static_cast<std::size_t>(parent)] + 1;
    const bool shown = max_depth <= 0 || depth[j] <= max_depth;
    // File order lists parents before children, so the shown ancestor is known.
    shown_ancestor[j] = shown ? static_cast<int>(j) : shown_ancestor[static_cast<std::size_t>(parent)];
    if (!shown && !bvh.end_site[j]) ++hidden_below[static_cast<std::size_t>(shown_ancestor[j])];
  }
  std::vector<InfoResult::TreeLine> tree;
  for (std::size_t j = 0; j < n; ++j)
    if (!bvh.end_site[j] && (max_depth <= 0 || depth[j] <= max_depth))
      tree.push_back({depth[j], skeleton.names[j], hidden_below[j]});
  return tree;
}

void describe_motion(const MotionFile& file, const InfoRequest& request, InfoResult& out) {
  const BvhFile& bvh = file.motion;
  const Skeleton& skeleton = bvh.skeleton;
  const auto end_sites = static_cast<int>(std::count(bvh.end_site.begin(), bvh.end_site.end(), 1));
  const int joints = static_cast<int>(skeleton.size()) - end_sites;
  out.facts.emplace_back("root", skeleton.names[static_cast<std::size_t>(bvh.root())]);
  out.facts.emplace_back("joints", printed("%d (plus %d end sites)", joints, end_sites));
  if (file.format == "BVH") {
    std::map<std::string, int> layouts;  // channel list → joints using it
    for (std::size_t j = 0; j < skeleton.size(); ++j) {
      if (bvh.end_site[j]) continue;
      std::string layout;
      for (int i = 0; i < bvh.channels[j].count; ++i) layout += (i ? " " : "") + std::string(to_string(bvh.channels[j][i]));
      ++layouts[layout.empty() ? "(none)" : layout];
    }
    out.facts.emplace_back("channels", printed("%d per frame", bvh.channel_count()));
    for (const auto& [layout, count] : layouts) out.facts.emplace_back("", printed("%4d x %s", count, layout.c_str()));
  }
  out.facts.emplace_back("frames", std::to_string(bvh.frame_count));
  out.facts.emplace_back("frame time", printed("%g s (%g fps)", static_cast<double>(bvh.frame_time),
                                               static_cast<double>(1.0f / bvh.frame_time)));
  out.facts.emplace_back("duration", printed("%g s (first to last frame)", static_cast<double>(bvh.clip.duration)));
  // Where the joints are at rest tells the unit and the up axis, which BVH does not name.
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  vec3 lo(1e30f), hi(-1e30f);
  for (const mat4& m : model) lo = glm::min(lo, vec3(m[3])), hi = glm::max(hi, vec3(m[3]));
  out.facts.emplace_back("rest extent", printed("x %.4g..%.4g  y %.4g..%.4g  z %.4g..%.4g (%s)", static_cast<double>(lo.x),
                                                static_cast<double>(hi.x), static_cast<double>(lo.y), static_cast<double>(hi.y),
                                                static_cast<double>(lo.z), static_cast<double>(hi.z),
                                                file.format == "BVH" ? "file units" : "metres"));
  out.tree = joint_tree(bvh, request.depth);
}

void describe_bap(const std::string& path, InfoResult& out) {
  const BapFile bap = load_bap(path);
  const std::size_t frames = bap.parameter_count > 0 ? bap.values.size() / static_cast<std::size_t>(bap.parameter_count) : 0;
  int used = 0;  // parameters nonzero in some frame
  for (int p = 0; p < bap.parameter_count; ++p)
    for (std::size_t f = 0; f < frames; ++f)
      if (bap.values[f * static_cast<std::size_t>(bap.parameter_count) + static_cast<std::size_t>(p)] != 0) {
        ++used;
        break;
      }
  out.facts.emplace_back("version", bap.version);
  out.facts.emplace_back("name", bap.name);
  out.facts.emplace_back("parameters", printed("%d per frame, %d of them moving", bap.parameter_count, used));
}

void describe_gcl(const std::string& path, InfoResult& out) {
  const CompressedClip clip = load_gcl(path);
  out.facts.emplace_back("joints", std::to_string(clip.joint_count()));
  out.facts.emplace_back("frames", std::to_string(clip.frame_count()));
  out.facts.emplace_back("rate", printed("%g Hz", static_cast<double>(clip.sample_rate())));
  out.facts.emplace_back("duration", printed("%g s (first to last frame)", static_cast<double>(clip.duration())));
  out.facts.emplace_back("bytes", std::to_string(clip.bytes().size()));
}

void describe_vrm(const std::string& path, InfoResult& out) {
  const VrmAvatar vrm = load_vrm(path);
  out.facts.emplace_back("humanoid", printed("%zu bones mapped to H-Anim joints", vrm.humanoid.size()));
  out.facts.emplace_back("mesh", printed("%zu vertices, %zu triangles, %zu morph targets", vrm.mesh.vertex_count(),
                                         vrm.mesh.triangle_count(), vrm.mesh.morphs.size()));
  std::string channels;
  for (const auto& [name, binds] : vrm.face_channels) channels += (channels.empty() ? "" : " ") + name;
  out.facts.emplace_back("expressions", channels.empty() ? "(none)" : channels);
}

// pose-format files: the header, and per component how many frames have any confident point.
void describe_pose(const std::string& path, InfoResult& out) {
  const PoseData pose = load_pose(path);
  out.facts.emplace_back("version", printed("pose-format %.1f", static_cast<double>(pose.version)));
  out.facts.emplace_back("image", printed("%d x %d (depth %d)", pose.width, pose.height, pose.depth));
  const double seconds = pose.fps > 0 ? static_cast<double>(pose.frames > 0 ? pose.frames - 1 : 0) / static_cast<double>(pose.fps) : 0.0;
  out.facts.emplace_back("frames", printed("%u at %g fps (%g s), %d people", pose.frames, static_cast<double>(pose.fps), seconds, pose.people));
  out.facts.emplace_back("components", printed("%zu, %zu points, %d dimensions", pose.components.size(), pose.point_count(), pose.dims()));
  std::size_t offset = 0;
  const std::size_t points = pose.point_count();
  const std::size_t cells = std::size_t(pose.frames) * static_cast<std::size_t>(pose.people);
  for (const PoseComponent& c : pose.components) {
    std::size_t seen = 0, placed = 0;
    for (std::size_t f = 0; f < cells; ++f) {
      std::size_t here = 0;
      for (std::size_t i = 0; i < c.points.size(); ++i) here += pose.confidence[f * points + offset + i] > 0.0f;
      seen += here > 0;
      placed += here;
    }
    out.facts.emplace_back("", printed("%-22s %-5s %4zu points %4zu limbs  in %zu of %zu frames, %.0f%% of its points placed",
                                       c.name.c_str(), c.format.c_str(), c.points.size(), c.limbs.size(), seen, cells,
                                       cells && !c.points.empty() ? 100.0 * double(placed) / double(cells * c.points.size()) : 0.0));
    offset += c.points.size();
  }
}

}  // namespace

void validate(const InfoRequest& request) {
  check_fields(request);
  if (lower_extension(request.file) == ".pose") return;
  if (!is_motion_file(request.file))
    usage_error("file", request.file + ": unsupported file type '" + lower_extension(request.file) +
                            "' (supported: " + motion_file_extensions() + ", .pose)");
}

InfoResult run(const InfoRequest& request, const RunContext&) {
  validate(request);
  require_file("file", request.file);
  InfoResult out;
  out.file = request.file;
  const std::string ext = lower_extension(request.file);
  const MotionReadOptions options{request.scale, request.z_up, request.skeleton};
  if (ext == ".pose") {  // point positions, not a skeleton's motion
    out.format = "pose-format (MediaPipe Holistic and other keypoint layouts)";
    describe_pose(request.file, out);
    return out;
  }
  if (ext == ".gcl" && request.skeleton.empty()) {
    out.format = "gcl (compressed clip)";
    describe_gcl(request.file, out);
    return out;
  }
  const MotionFile file = read_motion_file(request.file, options, "file");
  out.format = file.format;
  if (ext == ".bap") describe_bap(request.file, out);
  describe_motion(file, request, out);
  if (ext == ".gcl") out.facts.emplace_back("bytes", std::to_string(load_gcl(request.file).bytes().size()));
  if (ext == ".vrm") describe_vrm(request.file, out);
  return out;
}

nlohmann::json to_json(const InfoResult& result) {
  nlohmann::json out{{"file", result.file}, {"format", result.format}};
  auto& facts = out["facts"] = nlohmann::json::array();
  for (const auto& [label, value] : result.facts) facts.push_back({{"label", label}, {"value", value}});
  auto& tree = out["tree"] = nlohmann::json::array();
  for (const InfoResult::TreeLine& t : result.tree)
    tree.push_back({{"depth", t.depth}, {"name", t.name}, {"hidden_below", t.hidden_below}});
  return out;
}

}  // namespace gestura::app
