// gestura's side of every workload, through the library's public API only.
#include <map>
#include <memory>
#include <stdexcept>

#include "gestura/anim/blend.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/compress/playback_context.hpp"
#include "gestura/ik/aim.hpp"
#include "gestura/ik/two_bone.hpp"
#include "harness.hpp"

namespace anchors {

namespace {

void sample_forward(std::size_t n) {
  const Subject& s = subject();
  static Sampler sampler(s.clip);
  static Pose pose = s.rest;
  static float t = 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    sampler.sample(t, WrapMode::Loop, s.rest, pose);
    keep(pose.rotations.data());
    t += 1.0f / 30.0f;
    if (t > s.clip.duration) t -= s.clip.duration;
  }
}

void random_seek(std::size_t n) {
  const Subject& s = subject();
  static Sampler sampler(s.clip);
  static Pose pose = s.rest;
  static std::size_t k = 0;
  const std::vector<float>& times = random_times();
  for (std::size_t i = 0; i < n; ++i) {
    sampler.sample(times[k++ & 4095], WrapMode::Clamp, s.rest, pose);
    keep(pose.rotations.data());
  }
}

void local_to_model_pose(std::size_t n) {
  const Subject& s = subject();
  static std::vector<mat4> model(s.skeleton.size());
  for (std::size_t i = 0; i < n; ++i) {
    local_to_model(s.skeleton.parents, s.blend_a.translations, s.blend_a.rotations, s.blend_a.scales, model);
    keep(model.data());
  }
}

void blend_three(std::size_t n) {
  const Subject& s = subject();
  static Pose out;
  const BlendLayer layers[] = {{&s.blend_a, 0.5f}, {&s.blend_b, 0.3f}, {&s.blend_c, 0.2f}};
  for (std::size_t i = 0; i < n; ++i) {
    blend_layers(layers, s.rest, out);
    keep(out.rotations.data());
  }
}

void blend_masked_additive(std::size_t n) {
  const Subject& s = subject();
  static Pose out;
  const BlendLayer layers[] = {{&s.blend_a, 1.0f, {}, 0}, {&s.blend_b, 1.0f, s.upper_body, 1}, {&s.additive, 0.7f, {}, 0, true}};
  for (std::size_t i = 0; i < n; ++i) {
    blend_layers(layers, s.rest, out);
    keep(out.rotations.data());
  }
}

void two_bone(std::size_t n) {
  static const TwoBoneCase c;
  TwoBoneInput in;
  in.start = c.start, in.mid = c.mid, in.end = c.end;
  in.start_rotation = in.mid_rotation = quat(1, 0, 0, 0);
  in.mid_axis = c.mid_axis;
  in.pole = c.pole;
  in.soften = c.soften;
  static std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    in.target = c.targets[k++ & 3];
    keep(in.target);
    const TwoBoneResult r = solve_two_bone(in);
    keep(r);
  }
}

void aim(std::size_t n) {
  static const AimCase c;
  AimInput in;
  in.position = c.position;
  in.rotation = c.rotation;
  in.parent_rotation = c.parent_rotation;
  static std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    in.target = c.targets[k++ & 3];
    keep(in.target);
    const quat q = aim_local_rotation(in);
    keep(q);
  }
}

Side skin(bool normals, SkinningPath path) {
  return {"gestura", [normals, path](std::size_t n) {
            const Subject& s = subject();
            static std::vector<vec3> positions(s.mesh.vertex_count()), out_normals(s.mesh.vertex_count());
            for (std::size_t i = 0; i < n; ++i) {
              if (normals)
                skin_positions_normals(s.skinning, s.mesh.joints, s.mesh.weights, s.mesh.positions, s.mesh.normals,
                                       positions, out_normals, path);
              else
                skin_positions(s.skinning, s.mesh.joints, s.mesh.weights, s.mesh.positions, positions, path);
              keep(positions.data());
              keep(out_normals.data());
            }
          }};
}

CompressionSettings settings_for(float bound) {
  CompressionSettings settings;
  settings.max_error = bound;
  settings.sample_rate = subject().rate;
  settings.virtual_point_distance = kVirtualPointDistance;
  return settings;
}

Side compress_side(float bound) {
  return {"gestura", [bound](std::size_t n) {
            const Subject& s = subject();
            for (std::size_t i = 0; i < n; ++i) {
              CompressedClip c = compress(s.clip, s.skeleton, settings_for(bound));
              keep(c.bytes().data());
            }
          }};
}

// The compressed clip at a bound, built once; notes its size and error.
const CompressedClip& compressed(float bound) {
  static std::map<float, std::unique_ptr<CompressedClip>> cache;
  std::unique_ptr<CompressedClip>& c = cache[bound];
  if (!c) {
    const Subject& s = subject();
    CompressionReport report;
    c = std::make_unique<CompressedClip>(compress(s.clip, s.skeleton, settings_for(bound), &report));
    char line[256];
    std::snprintf(line, sizeof line, "gestura at %.2f cm: %zu bytes of %zu raw, max error %.4f cm (p99 %.4f cm), %s",
                  bound * 100.0, report.bytes, report.raw_bytes, report.max_error * 100.0, report.p99_error * 100.0,
                  report.within_bound ? "within the bound" : "BOUND BROKEN");
    note(line);
  }
  return *c;
}

Side decompress_forward(float bound) {
  struct State {
    PlaybackContext context;
    Pose pose = subject().rest;
    float t = 0.0f;
  };
  auto state = std::make_shared<State>();
  return {"gestura", [bound, state](std::size_t n) {
            const CompressedClip& c = compressed(bound);
            for (std::size_t i = 0; i < n; ++i) {
              state->context.sample(c, state->t, state->pose);
              keep(state->pose.rotations.data());
              state->t += kForwardStep;
              if (state->t > c.duration()) state->t = 0.0f;
            }
          }};
}

Side decompress_random(float bound) {
  struct State {
    PlaybackContext context;
    Pose pose = subject().rest;
    std::size_t k = 0;
  };
  auto state = std::make_shared<State>();
  return {"gestura", [bound, state](std::size_t n) {
            const CompressedClip& c = compressed(bound);
            const std::vector<float>& times = random_times();
            for (std::size_t i = 0; i < n; ++i) {
              state->context.sample(c, times[state->k++ & 4095], state->pose);
              keep(state->pose.rotations.data());
            }
          }};
}

}  // namespace

Side gestura_side(const std::string& key) {
  static const std::map<std::string, std::function<Side()>> sides = {
      {"W1_SampleForward30Hz", [] { return Side{"gestura", sample_forward}; }},
      {"W1_LocalToModel", [] { return Side{"gestura", local_to_model_pose}; }},
      {"W2_RandomSeek", [] { return Side{"gestura", random_seek}; }},
      {"W3_Blend3Layers", [] { return Side{"gestura", blend_three}; }},
      {"W3_Blend2MaskedPlusAdditive", [] { return Side{"gestura", blend_masked_additive}; }},
      {"W4_TwoBone", [] { return Side{"gestura", two_bone}; }},
      {"W4_Aim", [] { return Side{"gestura", aim}; }},
      {"W5_LbsPositions/avx2", [] { return skin(false, SkinningPath::Auto); }},
      {"W5_LbsPositions/portable", [] { return skin(false, SkinningPath::Portable); }},
      {"W5_LbsPositionsNormals/avx2", [] { return skin(true, SkinningPath::Auto); }},
      {"W5_LbsPositionsNormals/portable", [] { return skin(true, SkinningPath::Portable); }},
      {"W7_Compress/0.01cm", [] { return compress_side(kFineBound); }},
      {"W7_Compress/0.3cm", [] { return compress_side(kCoarseBound); }},
      {"W8_DecompressForward/0.01cm", [] { return decompress_forward(kFineBound); }},
      {"W8_DecompressForward/0.3cm", [] { return decompress_forward(kCoarseBound); }},
      {"W8_DecompressRandom/0.01cm", [] { return decompress_random(kFineBound); }},
      {"W8_DecompressRandom/0.3cm", [] { return decompress_random(kCoarseBound); }},
  };
  const auto it = sides.find(key);
  if (it == sides.end()) throw std::runtime_error("no gestura side for workload " + key);
  return it->second();
}

}  // namespace anchors
