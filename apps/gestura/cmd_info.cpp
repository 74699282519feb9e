// gestura info FILE — what a file holds, one describer per file format (chosen by extension).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/pose_format.hpp"

namespace {

using gestura::BvhFile;
using gestura::Error;

// The joint tree down to `max_depth` (0 = all), end sites left out; deeper joints are counted.
void print_tree(const BvhFile& bvh, int max_depth) {
  const auto& skeleton = bvh.skeleton;
  const std::size_t n = skeleton.size();
  std::vector<int> depth(n, 0), hidden_below(n, 0);
  for (std::size_t j = 0; j < n; ++j) {
    const int parent = skeleton.parents[j];
    if (parent >= 0) depth[j] = depth[static_cast<std::size_t>(parent)] + 1;
  }
  // Count the joints hidden under each shown joint (file order lists parents before children).
  std::vector<int> shown_ancestor(n, -1);
  for (std::size_t j = 0; j < n; ++j) {
    const int parent = skeleton.parents[j];
    const bool shown = max_depth <= 0 || depth[j] <= max_depth;
    shown_ancestor[j] = shown ? static_cast<int>(j) : shown_ancestor[static_cast<std::size_t>(parent)];
    if (!shown && !bvh.end_site[j]) ++hidden_below[static_cast<std::size_t>(shown_ancestor[j])];
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (bvh.end_site[j] || (max_depth > 0 && depth[j] > max_depth)) continue;
    std::cout << "  " << std::string(2 * static_cast<std::size_t>(depth[j]), ' ') << skeleton.names[j];
    if (hidden_below[j] > 0) std::cout << "  (+" << hidden_below[j] << " below)";
    std::cout << "\n";
  }
}

int describe_bvh(const std::string& path, int tree_depth) {
  const BvhFile bvh = gestura::load_bvh(path);
  const auto& skeleton = bvh.skeleton;
  const auto end_sites = static_cast<int>(std::count(bvh.end_site.begin(), bvh.end_site.end(), 1));
  const int joints = static_cast<int>(skeleton.size()) - end_sites;
  std::map<std::string, int> layouts;  // channel list → joints using it
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    if (bvh.end_site[j]) continue;
    std::string layout;
    for (int i = 0; i < bvh.channels[j].count; ++i) {
      if (i > 0) layout += ' ';
      layout += to_string(bvh.channels[j][i]);
    }
    ++layouts[layout.empty() ? "(none)" : layout];
  }
  const float fps = 1.0f / bvh.frame_time;
  std::printf("file:       %s\nformat:     BVH\n", path.c_str());
  std::printf("root:       %s\n", skeleton.names[static_cast<std::size_t>(bvh.root())].c_str());
  std::printf("joints:     %d (plus %d end sites)\n", joints, end_sites);
  std::printf("channels:   %d per frame\n", bvh.channel_count());
  for (const auto& [layout, count] : layouts) std::printf("            %4d x %s\n", count, layout.c_str());
  std::printf("frames:     %d\n", bvh.frame_count);
  std::printf("frame time: %g s (%g fps)\n", static_cast<double>(bvh.frame_time), static_cast<double>(fps));
  std::printf("duration:   %g s (first to last frame)\n", static_cast<double>(bvh.clip.duration));
  // Where the joints are at rest tells the unit and the up axis, which BVH does not name.
  std::vector<gestura::mat4> model(skeleton.size());
  gestura::local_to_model(skeleton, gestura::rest_pose(skeleton), model);
  gestura::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& m : model) lo = glm::min(lo, gestura::vec3(m[3])), hi = glm::max(hi, gestura::vec3(m[3]));
  std::printf("rest extent: x %.4g..%.4g  y %.4g..%.4g  z %.4g..%.4g (file units)\n", static_cast<double>(lo.x),
              static_cast<double>(hi.x), static_cast<double>(lo.y), static_cast<double>(hi.y),
              static_cast<double>(lo.z), static_cast<double>(hi.z));
  std::printf("tree:\n");
  std::fflush(stdout);
  print_tree(bvh, tree_depth);
  return 0;
}

// pose-format files: the header, and per component how many frames have any confident point.
int describe_pose(const std::string& path, int) {
  const gestura::PoseData pose = gestura::load_pose(path);
  std::printf("file:       %s\nformat:     pose-format %.1f\n", path.c_str(), static_cast<double>(pose.version));
  std::printf("image:      %d x %d (depth %d)\n", pose.width, pose.height, pose.depth);
  std::printf("frames:     %u at %g fps (%g s), %d people\n", pose.frames, static_cast<double>(pose.fps),
              pose.fps > 0 ? static_cast<double>(pose.frames > 0 ? pose.frames - 1 : 0) / static_cast<double>(pose.fps) : 0.0,
              pose.people);
  std::printf("components: %zu, %zu points, %d dimensions\n", pose.components.size(), pose.point_count(), pose.dims());
  std::size_t offset = 0;
  const std::size_t points = pose.point_count();
  for (const gestura::PoseComponent& c : pose.components) {
    std::size_t seen = 0, placed = 0;
    for (std::size_t f = 0; f < std::size_t(pose.frames) * pose.people; ++f) {
      std::size_t here = 0;
      for (std::size_t i = 0; i < c.points.size(); ++i) here += pose.confidence[f * points + offset + i] > 0.0f;
      seen += here > 0;
      placed += here;
    }
    const std::size_t cells = std::size_t(pose.frames) * pose.people;
    std::printf("  %-22s %-5s %4zu points %4zu limbs  in %zu of %zu frames, %.0f%% of its points placed\n", c.name.c_str(),
                c.format.c_str(), c.points.size(), c.limbs.size(), seen, cells,
                cells && !c.points.empty() ? 100.0 * double(placed) / double(cells * c.points.size()) : 0.0);
    offset += c.points.size();
  }
  return 0;
}

// Extension (lower case, with the dot) → describer. New formats add a row here.
const std::map<std::string, std::function<int(const std::string&, int)>>& describers() {
  static const std::map<std::string, std::function<int(const std::string&, int)>> table{{".bvh", describe_bvh},
                                                                                         {".pose", describe_pose}};
  return table;
}

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string supported_extensions() {
  std::string list;
  for (const auto& [ext, describe] : describers()) {
    if (!list.empty()) list += ", ";
    list += ext;
  }
  return list;
}

int run_info(const std::vector<std::string>& args) {
  std::string path;
  int depth = 3;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--depth") {
      const std::string value = gestura::cli::flag_value(args, i);
      try {
        depth = std::stoi(value);
      } catch (const std::exception&) {
        throw Error("--depth needs a whole number, got '" + value + "'");
      }
    } else if (args[i].starts_with("--")) {
      throw Error("unknown flag " + args[i]);
    } else if (path.empty()) {
      path = args[i];
    } else {
      throw Error("info takes one file, got '" + path + "' and '" + args[i] + "'");
    }
  }
  if (path.empty()) throw Error("usage: gestura info FILE [--depth N]");
  const std::string ext = extension_of(path);
  const auto it = describers().find(ext);
  if (it == describers().end())
    throw Error(path + ": unsupported file type '" + ext + "' (supported: " + supported_extensions() + ")");
  return it->second(path, depth);
}

gestura::cli::Registration reg{{"info", "describe a file (BVH: joints, channels, frames, fps, tree; .pose: components)",
                                "usage: gestura info FILE [--depth N]\n\n"
                                "Prints what FILE holds. For .bvh: root, joints and end sites, channel\n"
                                "layouts, frames, frame time, fps, duration and the joint tree down to\n"
                                "depth N (default 3; 0 prints every joint). For .pose (pose-format 0.1/0.2): image\n"
                                "size, fps, frames and each component with the share of its points placed.",
                                run_info}};

}  // namespace
