// The subject both sides work on, built once: gestura's synthetic 67-joint clip (15 s at 30 Hz)
// and the MakeHuman base mesh from the shared data.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "gestura/anim/blend.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/io/makehuman.hpp"
#include "harness.hpp"

namespace anchors {

namespace {

Subject build() {
  Subject s;
  s.skeleton = synthetic_humanoid();
  s.clip = synthetic_clip(s.skeleton, 15.0f, s.rate);
  s.rest = rest_pose(s.skeleton);
  const auto frame_count = static_cast<std::size_t>(s.clip.duration * s.rate + 0.5f) + 1;
  s.frames.resize(frame_count);
  for (std::size_t f = 0; f < frame_count; ++f) {
    sample_clip(s.clip, std::min(static_cast<float>(f) / s.rate, s.clip.duration), WrapMode::Clamp, s.rest, s.frames[f]);
    for (quat& q : s.frames[f].rotations) q = glm::normalize(q);
  }
  sample_clip(s.clip, 1.0f, WrapMode::Clamp, s.rest, s.blend_a);
  sample_clip(s.clip, 5.0f, WrapMode::Clamp, s.rest, s.blend_b);
  sample_clip(s.clip, 9.0f, WrapMode::Clamp, s.rest, s.blend_c);
  make_additive(s.rest, s.blend_c, s.additive);
  s.upper_body.assign(s.skeleton.size(), 0.0f);
  for (std::size_t j = 0; j < s.skeleton.size(); ++j) {
    const std::string& n = s.skeleton.names[j];
    const bool leg = n.find("hip") != std::string::npos || n.find("knee") != std::string::npos ||
                     n.find("ankle") != std::string::npos || n.find("midtarsal") != std::string::npos;
    s.upper_body[j] = leg ? 0.0f : 1.0f;
  }

  // W5: the same mesh and pose as bench/skinning.cpp.
  const char* env = std::getenv("GESTURA_SHARED_DATA");
  const std::string dir = std::string(env && *env ? env : GESTURA_SHARED_DATA) + "/makehuman";
  if (std::filesystem::exists(dir + "/base.obj")) {
    MakeHumanBody body = load_makehuman(dir);
    const Skeleton& sk = body.rig.skeleton;
    Pose pose = rest_pose(sk);
    for (std::size_t j = 0; j < sk.size(); ++j) {
      const float k = static_cast<float>(j);
      const vec3 axis = glm::normalize(vec3(std::sin(k), std::cos(1.3f * k), 0.5f));
      pose.rotations[j] = glm::angleAxis(deg(2.0f + 4.0f * std::abs(std::sin(0.7f * k))), axis) * pose.rotations[j];
    }
    std::vector<mat4> model(sk.size());
    local_to_model(sk, pose, model);
    s.skinning.resize(sk.size());
    skinning_matrices(model, body.rig.inverse_bind, s.skinning);
    s.mesh = std::move(body.mesh.mesh);
    s.has_mesh = true;
  } else {
    std::fprintf(stderr, "no MakeHuman data in %s (set GESTURA_SHARED_DATA): skinning workloads skipped\n", dir.c_str());
  }
  return s;
}

std::vector<std::string>& notes() {
  static std::vector<std::string> n;
  return n;
}

}  // namespace

const Subject& subject() {
  static const Subject s = build();
  return s;
}

void note(const std::string& line) { notes().push_back(line); }

const std::vector<std::string>& all_notes() { return notes(); }

float max_virtual_point_error(const Skeleton& skeleton, const std::vector<Pose>& reference,
                              const std::vector<Pose>& decoded, float distance) {
  const std::size_t n = skeleton.size();
  std::vector<mat4> a(n), b(n);
  float worst = 0.0f;
  for (std::size_t f = 0; f < reference.size() && f < decoded.size(); ++f) {
    local_to_model(skeleton, reference[f], a);
    local_to_model(skeleton, decoded[f], b);
    for (std::size_t j = 0; j < n; ++j) {
      const vec3 dp = vec3(a[j][3]) - vec3(b[j][3]);
      for (int axis = 0; axis < 3; ++axis)
        worst = std::max(worst, glm::length(dp + distance * (vec3(a[j][axis]) - vec3(b[j][axis]))));
    }
  }
  return worst;
}

}  // namespace anchors

#include <random>

namespace anchors {

const std::vector<float>& random_times() {
  static const std::vector<float> times = [] {
    std::vector<float> t(4096);
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> any(0.0f, subject().clip.duration);
    for (float& x : t) x = any(rng);
    return t;
  }();
  return times;
}

}  // namespace anchors
