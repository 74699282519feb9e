#include "gestura/compress/compress.hpp"

#include <algorithm>
#include <cstring>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// --- Raw samples --------------------------------------------------------------------------------

struct RawClip {
  std::uint32_t frames = 0;
  float rate = 30.0f;
  std::vector<Pose> poses;          // per frame
  std::vector<mat4> model;          // frames × joints
};

RawClip sample_raw(const Clip& clip, const Skeleton& skeleton, float rate) {
  const double count = std::floor(static_cast<double>(clip.duration) * rate + 0.5) + 1.0;
  if (count > 65535.0) throw Error("compress: clip '" + clip.name + "' has more than 65535 frames at " + std::to_string(rate) + " Hz");
  RawClip raw;
  raw.rate = rate;
  raw.frames = std::max<std::uint32_t>(2, static_cast<std::uint32_t>(count));
  const Pose rest = rest_pose(skeleton);
  const std::size_t n = skeleton.size();
  raw.poses.resize(raw.frames);
  raw.model.resize(std::size_t{raw.frames} * n);
  for (std::uint32_t f = 0; f < raw.frames; ++f) {
    const float t = std::min(static_cast<float>(f) / rate, clip.duration);
    sample_clip(clip, t, WrapMode::Clamp, rest, raw.poses[f]);
    for (quat& q : raw.poses[f].rotations) q = glm::normalize(q);
    local_to_model(skeleton, raw.poses[f], std::span<mat4>(raw.model.data() + std::size_t{f} * n, n));
  }
  return raw;
}

// --- One track ----------------------------------------------------------------------------------

// Angle between unit quaternions from the chord |a ∓ b| = 2 sin(θ/4): accurate for tiny angles,
// where acos of a dot product is not.
float angle_between(const quat& a, const quat& b) {
  const float s = glm::dot(a, b) < 0.0f ? -1.0f : 1.0f;
  const vec4 d(a.x - s * b.x, a.y - s * b.y, a.z - s * b.z, a.w - s * b.w);
  return 4.0f * std::asin(std::min(1.0f, 0.5f * glm::length(d)));
}

struct EncodedTrack {
  GclTrackKind kind = GclTrackKind::Identity;
  vec4 constant{0.0f, 0.0f, 0.0f, 1.0f};
  std::uint8_t bits = 0, dropped = 0;
  vec3 min{0.0f}, extent{0.0f};
  std::vector<std::uint32_t> keys;           // frame indices
  std::vector<std::uint32_t> quantised;      // keys × 3
  std::size_t cost_bits(std::uint32_t frames) const {
    return keys.size() * 3 * bits + (keys.size() < frames ? ((frames + 63) / 64) * 64 : 0);
  }
};

// Components of a track's samples as 3-vectors, with the decode that turns them back into values.
struct TrackSamples {
  bool rotation = false;
  std::uint8_t dropped = 0;
  std::vector<vec3> kept;       // per frame, what gets quantised
  std::vector<quat> quats;      // per frame (rotation tracks): the original
  std::vector<vec3> values;     // per frame (vector tracks): the original
};

float sample_error(const TrackSamples& s, std::uint32_t f, const vec3& a, const vec3& b, float alpha) {
  if (s.rotation) return angle_between(s.quats[f], nlerp(rebuild_quat(a, s.dropped), rebuild_quat(b, s.dropped), alpha));
  return glm::length(s.values[f] - glm::mix(a, b, alpha));
}

// Quantises at `bits` and picks keys; false when some key cannot be held within `tolerance`.
bool encode_at(const TrackSamples& s, std::uint8_t bits, float tolerance, EncodedTrack& out,
               std::vector<vec3>& decoded, std::vector<std::uint32_t>& codes, std::vector<std::uint32_t>& stack) {
  const std::uint32_t frames = static_cast<std::uint32_t>(s.kept.size());
  vec3 lo(1e30f), hi(-1e30f);
  for (const vec3& v : s.kept) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const float steps = static_cast<float>((1u << bits) - 1u);
  const vec3 extent = hi - lo;
  const vec3 step = extent / steps;
  decoded.resize(frames);
  codes.resize(std::size_t{frames} * 3);
  for (std::uint32_t f = 0; f < frames; ++f)
    for (int c = 0; c < 3; ++c) {
      const float q = extent[c] > 0.0f ? std::round((s.kept[f][c] - lo[c]) / extent[c] * steps) : 0.0f;
      codes[f * 3 + c] = static_cast<std::uint32_t>(std::clamp(q, 0.0f, steps));
      decoded[f][c] = lo[c] + static_cast<float>(codes[f * 3 + c]) * step[c];
    }
  auto key_ok = [&](std::uint32_t f) { return sample_error(s, f, decoded[f], decoded[f], 0.0f) <= tolerance; };
  out.keys.clear();
  if (!key_ok(0) || !key_ok(frames - 1)) return false;
  // Recursive split, iteratively: segments on a stack, keys collected then sorted.
  out.keys.push_back(0);
  out.keys.push_back(frames - 1);
  stack.clear();
  stack.push_back(0);
  stack.push_back(frames - 1);
  while (!stack.empty()) {
    const std::uint32_t b = stack.back();
    stack.pop_back();
    const std::uint32_t a = stack.back();
    stack.pop_back();
    float worst = tolerance;
    std::uint32_t worst_frame = 0;
    for (std::uint32_t f = a + 1; f < b; ++f) {
      const float alpha = static_cast<float>(f - a) / static_cast<float>(b - a);
      const float e = sample_error(s, f, decoded[a], decoded[b], alpha);
      if (e > worst) worst = e, worst_frame = f;
    }
    if (worst_frame == 0) continue;
    if (!key_ok(worst_frame)) return false;
    out.keys.push_back(worst_frame);
    stack.push_back(a), stack.push_back(worst_frame), stack.push_back(worst_frame), stack.push_back(b);
  }
  std::sort(out.keys.begin(), out.keys.end());
  out.kind = GclTrackKind::Animated;
  out.bits = bits;
  out.dropped = s.dropped;
  out.min = lo;
  out.extent = extent;
  out.quantised.resize(out.keys.size() * 3);
  for (std::size_t k = 0; k < out.keys.size(); ++k)
    for (int c = 0; c < 3; ++c) out.quantised[k * 3 + c] = codes[out.keys[k] * 3 + c];
  return true;
}

EncodedTrack encode_track(const TrackSamples& s, float tolerance, const vec4& identity) {
  const std::uint32_t frames = static_cast<std::uint32_t>(s.kept.size());
  EncodedTrack best;
  // Identity or constant?
  auto within = [&](auto&& distance) {
    for (std::uint32_t f = 0; f < frames; ++f)
      if (distance(f) > tolerance) return false;
    return true;
  };
  if (s.rotation) {
    const quat id(identity.w, identity.x, identity.y, identity.z), first = s.quats[0];
    if (within([&](std::uint32_t f) { return angle_between(s.quats[f], id); })) return best;
    if (within([&](std::uint32_t f) { return angle_between(s.quats[f], first); })) {
      best.kind = GclTrackKind::Constant;
      best.constant = vec4(first.x, first.y, first.z, first.w);
      return best;
    }
  } else {
    const vec3 id(identity), first = s.values[0];
    best.constant = identity;
    if (within([&](std::uint32_t f) { return glm::length(s.values[f] - id); })) return best;
    if (within([&](std::uint32_t f) { return glm::length(s.values[f] - first); })) {
      best.kind = GclTrackKind::Constant;
      best.constant = vec4(first, 0.0f);
      return best;
    }
  }
  EncodedTrack trial;
  std::vector<vec3> decoded;
  std::vector<std::uint32_t> codes, stack;
  std::size_t best_cost = ~std::size_t{0};
  for (std::uint8_t bits = 1; bits <= 24; ++bits) {
    if (!encode_at(s, bits, tolerance, trial, decoded, codes, stack)) continue;
    const std::size_t cost = trial.cost_bits(frames);
    if (cost < best_cost) best_cost = cost, best = trial;
    // Past the first feasible depth, each extra bit saves keys only while keys are being removed.
    if (trial.keys.size() == 2) break;
  }
  if (best_cost == ~std::size_t{0}) encode_at(s, 24, 1e30f, best, decoded, codes, stack);  // tightest there is
  return best;
}

// --- Assembly -----------------------------------------------------------------------------------

struct ByteWriter {
  std::vector<std::uint8_t> bytes;
  template <class T>
  void put(T value) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(bytes.data() + at, &value, sizeof(T));
  }
};

std::vector<std::uint8_t> assemble(const std::vector<EncodedTrack>& tracks, std::uint32_t joints, std::uint32_t frames,
                                   float rate, float max_error) {
  ByteWriter w;
  for (char c : {'G', 'C', 'L', '\0'}) w.put(c);
  w.put<std::uint16_t>(kGclVersion);
  w.put<std::uint16_t>(0);
  w.put<std::uint32_t>(joints);
  w.put<std::uint32_t>(frames);
  w.put<float>(rate);
  w.put<float>(max_error);
  std::size_t data_bytes = 0;
  for (const EncodedTrack& t : tracks)
    if (t.kind == GclTrackKind::Animated) data_bytes += (t.keys.size() * 3 * t.bits + 7) / 8;
  w.put<std::uint32_t>(static_cast<std::uint32_t>(data_bytes));
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const EncodedTrack& t = tracks[i];
    w.put<std::uint8_t>(static_cast<std::uint8_t>(t.kind));
    if (t.kind == GclTrackKind::Constant) {
      for (int c = 0; c < (i % 3 == 0 ? 4 : 3); ++c) w.put<float>(t.constant[c]);
    } else if (t.kind == GclTrackKind::Animated) {
      w.put<std::uint8_t>(t.bits);
      w.put<std::uint8_t>(t.dropped);
      w.put<std::uint16_t>(static_cast<std::uint16_t>(t.keys.size()));
      for (int c = 0; c < 3; ++c) w.put<float>(t.min[c]);
      for (int c = 0; c < 3; ++c) w.put<float>(t.extent[c]);
    }
  }
  for (const EncodedTrack& t : tracks) {
    if (t.kind != GclTrackKind::Animated || t.keys.size() == frames) continue;
    std::vector<std::uint64_t> set((frames + 63) / 64, 0);
    for (std::uint32_t k : t.keys) set[k / 64] |= 1ull << (k % 64);
    for (std::uint64_t word : set) w.put(word);
  }
  for (const EncodedTrack& t : tracks) {
    if (t.kind != GclTrackKind::Animated) continue;
    std::vector<std::uint8_t> packed((t.keys.size() * 3 * t.bits + 7) / 8, 0);
    std::uint64_t bit = 0;
    for (std::uint32_t q : t.quantised)
      for (unsigned b = 0; b < t.bits; ++b, ++bit)
        if ((q >> b) & 1u) packed[bit >> 3] |= static_cast<std::uint8_t>(1u << (bit & 7));
    w.bytes.insert(w.bytes.end(), packed.begin(), packed.end());
  }
  w.bytes.resize(w.bytes.size() + 8, 0);
  return std::move(w.bytes);
}

// Per frame and joint, the largest virtual-point displacement between raw and decoded model poses.
void frame_errors(const RawClip& raw, const Skeleton& skeleton, const CompressedClip& c, float distance,
                  std::vector<float>& errors) {
  const std::size_t n = skeleton.size();
  Pose pose = rest_pose(skeleton);
  std::vector<mat4> model(n);
  errors.clear();
  errors.reserve(std::size_t{raw.frames} * n);
  for (std::uint32_t f = 0; f < raw.frames; ++f) {
    c.sample(static_cast<float>(f) / raw.rate, pose);
    local_to_model(skeleton, pose, model);
    for (std::size_t j = 0; j < n; ++j) {
      const mat4& a = raw.model[std::size_t{f} * n + j];
      const mat4& b = model[j];
      const vec3 dp = vec3(a[3]) - vec3(b[3]);
      float worst = 0.0f;
      for (int axis = 0; axis < 3; ++axis) worst = std::max(worst, glm::length(dp + distance * (vec3(a[axis]) - vec3(b[axis]))));
      errors.push_back(worst);
    }
  }
}

ClipError summarise(std::vector<float>& errors) {
  ClipError e;
  if (errors.empty()) return e;
  const std::size_t p = std::min(errors.size() - 1, static_cast<std::size_t>(0.99 * static_cast<double>(errors.size())));
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(p), errors.end());
  e.p99 = errors[p];
  e.max = *std::max_element(errors.begin(), errors.end());
  return e;
}

}  // namespace

CompressedClip compress(const Clip& clip, const Skeleton& skeleton, const CompressionSettings& settings,
                        CompressionReport* report) {
  if (!(settings.max_error > 0.0f) || !std::isfinite(settings.max_error)) throw Error("compress: max error must be > 0");
  if (!(settings.sample_rate > 0.0f) || settings.sample_rate > 10000.0f) throw Error("compress: sample rate must be in (0, 10000] Hz");
  if (!(settings.virtual_point_distance >= 0.0f)) throw Error("compress: virtual point distance must be ≥ 0");
  skeleton.validate();
  validate(clip, skeleton);
  const RawClip raw = sample_raw(clip, skeleton, settings.sample_rate);
  const std::size_t n = skeleton.size();
  const std::uint32_t frames = raw.frames;

  // Lever arm per joint: the longest bone path below it (largest translation seen per bone) plus
  // the virtual-point distance.
  std::vector<float> lever(n, settings.virtual_point_distance);
  for (std::size_t j = n; j-- > 1;) {
    const int p = skeleton.parents[j];
    if (p < 0) continue;
    float bone = 0.0f;
    for (const Pose& pose : raw.poses) bone = std::max(bone, glm::length(pose.translations[j] * pose.scales[static_cast<std::size_t>(p)]));
    lever[static_cast<std::size_t>(p)] = std::max(lever[static_cast<std::size_t>(p)], bone + lever[j]);
  }

  // Track samples, prepared once.
  std::vector<TrackSamples> samples(n * 3);
  for (std::size_t j = 0; j < n; ++j) {
    TrackSamples& r = samples[j * 3];
    r.rotation = true;
    r.quats.resize(frames);
    for (std::uint32_t f = 0; f < frames; ++f) r.quats[f] = raw.poses[f].rotations[j];
    // Drop the component whose smallest magnitude over the track is largest: it is rebuilt from the
    // others, which is exact and well conditioned only while it stays away from zero.
    float best = -1.0f;
    for (std::uint8_t c = 0; c < 4; ++c) {
      float smallest = 1.0f;
      for (const quat& q : r.quats) smallest = std::min(smallest, std::abs(q[c]));
      if (smallest > best) best = smallest, r.dropped = c;
    }
    r.kept.resize(frames);
    for (std::uint32_t f = 0; f < frames; ++f) {
      quat& q = r.quats[f];
      if (q[r.dropped] < 0.0f) q = -q;
      int k = 0;
      for (int c = 0; c < 4; ++c)
        if (c != r.dropped) r.kept[f][k++] = q[c];
    }
    for (int c = 1; c < 3; ++c) {
      TrackSamples& v = samples[j * 3 + static_cast<std::size_t>(c)];
      v.values.resize(frames);
      for (std::uint32_t f = 0; f < frames; ++f) v.values[f] = c == 1 ? raw.poses[f].translations[j] : raw.poses[f].scales[j];
      v.kept = v.values;
    }
  }

  auto encode_all = [&](float s) {
    std::vector<EncodedTrack> tracks(n * 3);
    for (std::size_t j = 0; j < n; ++j) {
      tracks[j * 3] = encode_track(samples[j * 3], s * settings.max_error / lever[j], vec4(0, 0, 0, 1));
      tracks[j * 3 + 1] = encode_track(samples[j * 3 + 1], s * settings.max_error, vec4(0.0f));
      tracks[j * 3 + 2] = encode_track(samples[j * 3 + 2], s * settings.max_error / lever[j], vec4(1, 1, 1, 0));
    }
    return tracks;
  };
  auto build = [&](const std::vector<EncodedTrack>& tracks) {
    return CompressedClip::from_bytes(assemble(tracks, static_cast<std::uint32_t>(n), frames, settings.sample_rate, settings.max_error));
  };

  // Search the tolerance factor: bracket between a factor that holds the bound and one that breaks it.
  std::vector<float> errors;
  std::vector<EncodedTrack> best_tracks;
  CompressedClip best;   // smallest encoding within the bound; or, while none is, the most accurate
  ClipError best_error;
  bool have_valid = false;
  float good = 0.0f, bad = 0.0f, s = 1.0f;
  int passes = 0;
  while (passes < 16) {
    std::vector<EncodedTrack> tracks = encode_all(s);
    CompressedClip trial = build(tracks);
    ++passes;
    frame_errors(raw, skeleton, trial, settings.virtual_point_distance, errors);
    const ClipError e = summarise(errors);
    const bool valid = e.max <= settings.max_error;
    if (valid) good = s;
    else bad = s;
    const bool better = valid ? !have_valid || trial.bytes().size() <= best.bytes().size()
                              : !have_valid && (best.bytes().empty() || e.max < best_error.max);
    if (better) best = std::move(trial), best_tracks = std::move(tracks), best_error = e, have_valid = have_valid || valid;
    if (good > 0.0f && bad > 0.0f && bad / good < 1.08f) break;
    s = bad == 0.0f ? s * 2.0f : good == 0.0f ? s * 0.3f : std::sqrt(good * bad);
    if (s > 1e4f || s < 1e-6f) break;
  }

  // The shared factor leaves slack wherever a track is not on the worst chain: take bits away track
  // by track (same keys, same ranges) while the measured error still holds the bound.
  if (have_valid) {
    for (std::size_t t = 0; t < best_tracks.size(); ++t) {
      while (best_tracks[t].kind == GclTrackKind::Animated && best_tracks[t].bits > 1) {
        EncodedTrack& track = best_tracks[t];
        const EncodedTrack kept = track;
        const std::uint8_t bits = static_cast<std::uint8_t>(track.bits - 1);
        const float steps = static_cast<float>((1u << bits) - 1u);
        for (std::size_t k = 0; k < track.keys.size(); ++k)
          for (int c = 0; c < 3; ++c) {
            const float v = samples[t].kept[track.keys[k]][c];
            const float q = track.extent[c] > 0.0f ? std::round((v - track.min[c]) / track.extent[c] * steps) : 0.0f;
            track.quantised[k * 3 + static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(std::clamp(q, 0.0f, steps));
          }
        track.bits = bits;
        CompressedClip trial = build(best_tracks);
        ++passes;
        frame_errors(raw, skeleton, trial, settings.virtual_point_distance, errors);
        const ClipError e = summarise(errors);
        if (e.max > settings.max_error) {
          track = kept;
          break;
        }
        best = std::move(trial), best_error = e;
      }
    }
  }
  if (report) {
    report->raw_bytes = std::size_t{frames} * n * 10 * sizeof(float);
    report->bytes = best.bytes().size();
    report->max_error = best_error.max;
    report->p99_error = best_error.p99;
    report->passes = passes;
    report->within_bound = have_valid;
  }
  return best;
}

ClipError measure_error(const Clip& clip, const Skeleton& skeleton, const CompressedClip& compressed,
                        float virtual_point_distance) {
  if (compressed.joint_count() != skeleton.size())
    throw Error("measure_error: compressed clip has " + std::to_string(compressed.joint_count()) + " joints, skeleton " +
                std::to_string(skeleton.size()));
  const RawClip raw = sample_raw(clip, skeleton, compressed.sample_rate());
  std::vector<float> errors;
  frame_errors(raw, skeleton, compressed, virtual_point_distance, errors);
  return summarise(errors);
}

}  // namespace gestura
