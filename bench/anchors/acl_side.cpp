// ACL's side: the subject's frames as one qvvf track per joint (in centimetres, ACL's default units,
// so its default constant thresholds apply as documented), compressed with the default settings and
// the qvvf error metric, decompressed with the default transform decompression settings.
#include <map>
#include <memory>

#include "acl/compression/compress.h"
#include "acl/compression/track_array.h"
#include "acl/core/ansi_allocator.h"
#include "acl/decompression/decompress.h"
#include "harness.hpp"

namespace anchors {

namespace {

constexpr float kCm = 100.0f;  // metres → ACL's centimetres

acl::ansi_allocator& allocator() {
  static acl::ansi_allocator a;
  return a;
}

acl::track_array_qvvf raw_tracks(float bound) {
  const Subject& s = subject();
  const std::size_t n = s.skeleton.size();
  const auto frames = static_cast<std::uint32_t>(s.frames.size());
  acl::track_array_qvvf tracks(allocator(), static_cast<std::uint32_t>(n));
  for (std::size_t j = 0; j < n; ++j) {
    acl::track_desc_transformf desc;
    desc.output_index = static_cast<std::uint32_t>(j);
    desc.parent_index = s.skeleton.parents[j] < 0 ? acl::k_invalid_track_index : static_cast<std::uint32_t>(s.skeleton.parents[j]);
    desc.precision = bound * kCm;
    desc.shell_distance = kVirtualPointDistance * kCm;
    acl::track_qvvf track = acl::track_qvvf::make_reserve(desc, allocator(), frames, s.rate);
    for (std::uint32_t f = 0; f < frames; ++f) {
      const quat q = s.frames[f].rotations[j];
      const vec3 t = s.frames[f].translations[j] * kCm, sc = s.frames[f].scales[j];
      track[f] = rtm::qvv_set(rtm::quat_set(q.x, q.y, q.z, q.w), rtm::vector_set(t.x, t.y, t.z),
                              rtm::vector_set(sc.x, sc.y, sc.z));
    }
    tracks[static_cast<std::uint32_t>(j)] = std::move(track);
  }
  return tracks;
}

acl::compressed_tracks* compress_clip(const acl::track_array_qvvf& tracks) {
  acl::compression_settings settings = acl::get_default_compression_settings();
  static acl::qvvf_transform_error_metric metric;
  settings.error_metric = &metric;
  acl::output_stats stats;
  acl::compressed_tracks* out = nullptr;
  const acl::error_result result = acl::compress_track_list(allocator(), tracks, settings, out, stats);
  if (result.any()) throw std::runtime_error(std::string("ACL compression failed: ") + result.c_str());
  return out;
}

// Writes ACL's output into a gestura pose (metres), as an engine would into its own pose type.
struct PoseWriter : acl::track_writer {
  Pose* pose;
  explicit PoseWriter(Pose& p) : pose(&p) {}
  void RTM_SIMD_CALL write_rotation(uint32_t i, rtm::quatf_arg0 r) { rtm::quat_store(r, &pose->rotations[i].x); }
  void RTM_SIMD_CALL write_translation(uint32_t i, rtm::vector4f_arg0 t) {
    rtm::vector_store3(rtm::vector_mul(t, 1.0f / kCm), &pose->translations[i].x);
  }
  void RTM_SIMD_CALL write_scale(uint32_t i, rtm::vector4f_arg0 s) { rtm::vector_store3(s, &pose->scales[i].x); }
};

struct AclClip {
  acl::compressed_tracks* tracks = nullptr;
  ~AclClip() {
    if (tracks) allocator().deallocate(tracks, tracks->get_size());
  }
};

const acl::compressed_tracks& compressed(float bound) {
  static std::map<float, std::unique_ptr<AclClip>> cache;
  std::unique_ptr<AclClip>& c = cache[bound];
  if (!c) {
    c = std::make_unique<AclClip>();
    c->tracks = compress_clip(raw_tracks(bound));
    const Subject& s = subject();
    acl::decompression_context<acl::default_transform_decompression_settings> context;
    context.initialize(*c->tracks);
    std::vector<Pose> decoded(s.frames.size(), s.rest);
    for (std::size_t f = 0; f < s.frames.size(); ++f) {
      PoseWriter writer(decoded[f]);
      context.seek(static_cast<float>(f) / s.rate, acl::sample_rounding_policy::none);
      context.decompress_tracks(writer);
    }
    const float error = max_virtual_point_error(s.skeleton, s.frames, decoded, kVirtualPointDistance);
    char line[256];
    std::snprintf(line, sizeof line, "ACL at precision %.2f cm, shell %.0f cm (default settings): %u bytes, max error %.4f cm",
                  bound * 100.0, kVirtualPointDistance * 100.0, c->tracks->get_size(), error * 100.0);
    note(line);
  }
  return *c->tracks;
}

Side compress_side(float bound) {
  return {"ACL", [bound](std::size_t n) {
            const acl::track_array_qvvf tracks = raw_tracks(bound);  // input prepared outside the timing on gestura's side too
            for (std::size_t i = 0; i < n; ++i) {
              AclClip c;
              c.tracks = compress_clip(tracks);
              keep(c.tracks);
            }
          }};
}

Side decompress(float bound, bool forward) {
  struct State {
    acl::decompression_context<acl::default_transform_decompression_settings> context;
    Pose pose = subject().rest;
    float t = 0.0f;
    std::size_t k = 0;
    bool ready = false;
  };
  auto state = std::make_shared<State>();
  return {"ACL", [bound, forward, state](std::size_t n) {
            const acl::compressed_tracks& tracks = compressed(bound);
            if (!state->ready) state->context.initialize(tracks), state->ready = true;
            const float duration = tracks.get_finite_duration();
            const std::vector<float>& times = random_times();
            PoseWriter writer(state->pose);
            for (std::size_t i = 0; i < n; ++i) {
              float t;
              if (forward) {
                state->t += kForwardStep;
                if (state->t > duration) state->t = 0.0f;
                t = state->t;
              } else {
                t = times[state->k++ & 4095];
              }
              state->context.seek(t, acl::sample_rounding_policy::none);
              state->context.decompress_tracks(writer);
              keep(state->pose.rotations.data());
            }
          }};
}

}  // namespace

void add_acl_workloads(std::vector<Workload>& out) {
  auto add = [&](const std::string& key, const std::string& what, Side anchor, bool heavy = false) {
    out.push_back({key, what, gestura_side(key), std::move(anchor), heavy});
  };
  add("W7_Compress/0.01cm", "compress the clip at 0.01 cm (ACL: precision 0.01 cm)", compress_side(kFineBound), true);
  add("W7_Compress/0.3cm", "compress the clip at 0.3 cm", compress_side(kCoarseBound), true);
  add("W8_DecompressForward/0.01cm", "decompress the pose playing forward at 60 fps", decompress(kFineBound, true));
  add("W8_DecompressForward/0.3cm", "the same at 0.3 cm", decompress(kCoarseBound, true));
  add("W8_DecompressRandom/0.01cm", "decompress the pose at random times", decompress(kFineBound, false));
}

}  // namespace anchors
