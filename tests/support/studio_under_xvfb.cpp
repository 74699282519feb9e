#include "support/studio_under_xvfb.hpp"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "gestura/io/bvh.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "support/build_paths.hpp"

namespace gestura::test {

bool have_xvfb() { return run_command("command -v xvfb-run").status == 0; }

CliRun run_studio(const gestura::testing::TempDir& dir, const std::string& db, const std::string& script_name,
                  const std::string& script, const std::string& size) {
  const std::string path = dir.write(script_name, script);
  return run_command("timeout 300 xvfb-run -a -s '-screen 0 1400x900x24' " + cli_path() + " studio " + db + " --size " +
                     size + " --script " + path);
}

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) return nlohmann::json();
  return nlohmann::json::parse(in, nullptr, false);
}

std::string shot_dir(const gestura::testing::TempDir& dir) {
  const char* env = std::getenv("GESTURA_STUDIO_SCREENSHOTS");
  if (env && *env) {
    std::filesystem::create_directories(env);
    return env;
  }
  return dir.file("");
}

float peak_time(const gestura::BvhFile& bvh, const std::string& joint) {
  const int j = bvh.skeleton.find(joint);
  if (j < 0) return -1.0f;
  const gestura::QuatTrack& track = bvh.clip.rotations[static_cast<std::size_t>(j)];
  float best = -1.0f, at = -1.0f;
  for (std::size_t k = 0; k < track.size(); ++k) {
    const float angle = 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(track.values[k], track.values[0]))));
    if (angle > best + 1e-6f) best = angle, at = track.times[k];
  }
  return at;
}

}  // namespace gestura::test
