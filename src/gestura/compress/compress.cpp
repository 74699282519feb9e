#include "gestura/compress/compress.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

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

// The ACL metric at one joint and frame: the largest displacement of the virtual points
// `distance` along the joint's three axes between the raw and the decoded model matrix.
float virtual_point_error(const mat4& a, const mat4& b, float distance) {
  const vec3 dp = vec3(a[3]) - vec3(b[3]);
  float worst = 0.0f;
  for (int axis = 0; axis < 3; ++axis) worst = std::max(worst, glm::length(dp + distance * (vec3(a[axis]) - vec3(b[axis]))));
  return worst;
}

// --- One track ----------------------------------------------------------------------------------

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

// What a track must reproduce, per frame, as 3-vectors that get quantised.
struct TrackSamples {
  bool rotation = false;
  std::uint8_t dropped = 0;
  std::vector<vec3> kept;       // per frame, what gets quantised
  std::vector<quat> quats;      // per frame (rotation tracks): the target, q[dropped] ≥ 0
  std::vector<vec3> values;     // per frame (vector tracks): the target
};

// Rotation targets → quats and kept components (the dropped one made non-negative).
void set_rotation_targets(TrackSamples& s, const quat* targets, std::uint32_t frames) {
  s.quats.resize(frames);
  s.kept.resize(frames);
  for (std::uint32_t f = 0; f < frames; ++f) {
    quat q = targets[f];
    if (q[s.dropped] < 0.0f) q = -q;
    s.quats[f] = q;
    int k = 0;
    for (int c = 0; c < 4; ++c)
      if (c != s.dropped) s.kept[f][k++] = q[c];
  }
}

// Errors while encoding are compared squared: for rotations the chord |a ∓ b| (the angle between
// unit quaternions is 4·asin(chord / 2), so the chord orders errors the same way and a tolerance
// becomes a chord once), for vectors the distance.
float squared_error(const TrackSamples& s, std::uint32_t f, const vec3& a, const vec3& b, float alpha) {
  if (s.rotation) {
    const quat q = nlerp(rebuild_quat(a, s.dropped), rebuild_quat(b, s.dropped), alpha);
    const quat& r = s.quats[f];
    const float sign = glm::dot(r, q) < 0.0f ? -1.0f : 1.0f;
    const vec4 d(r.x - sign * q.x, r.y - sign * q.y, r.z - sign * q.z, r.w - sign * q.w);
    return glm::dot(d, d);
  }
  const vec3 d = s.values[f] - glm::mix(a, b, alpha);
  return glm::dot(d, d);
}

float squared_tolerance(bool rotation, float tolerance) {
  if (!rotation) return tolerance * tolerance;
  const float chord = 2.0f * std::sin(std::min(tolerance, 3.0f) * 0.25f);
  return chord * chord;
}

struct Scratch {
  std::vector<vec3> decoded;
  std::vector<std::uint32_t> codes, stack;
};

// The per-track quantisation grid: range over all frames, 2^bits − 1 steps per component.
void quantise_all(const TrackSamples& s, std::uint8_t bits, vec3& lo, vec3& extent, Scratch& scratch) {
  const std::uint32_t frames = static_cast<std::uint32_t>(s.kept.size());
  lo = vec3(1e30f);
  vec3 hi(-1e30f);
  for (const vec3& v : s.kept) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const float steps = static_cast<float>((1u << bits) - 1u);
  extent = hi - lo;
  const vec3 step = extent / steps;
  scratch.decoded.resize(frames);
  scratch.codes.resize(std::size_t{frames} * 3);
  for (std::uint32_t f = 0; f < frames; ++f)
    for (int c = 0; c < 3; ++c) {
      const float q = extent[c] > 0.0f ? std::round((s.kept[f][c] - lo[c]) / extent[c] * steps) : 0.0f;
      scratch.codes[f * 3 + c] = static_cast<std::uint32_t>(std::clamp(q, 0.0f, steps));
      scratch.decoded[f][c] = lo[c] + static_cast<float>(scratch.codes[f * 3 + c]) * step[c];
    }
}

// Quantises at `bits` and picks keys by recursive splitting at the worst frame; false when some key
// itself cannot be held within the (squared) tolerance.
bool encode_at(const TrackSamples& s, std::uint8_t bits, float tolerance2, EncodedTrack& out, Scratch& scratch) {
  const std::uint32_t frames = static_cast<std::uint32_t>(s.kept.size());
  vec3 lo, extent;
  quantise_all(s, bits, lo, extent, scratch);
  const std::vector<vec3>& decoded = scratch.decoded;
  auto key_ok = [&](std::uint32_t f) { return squared_error(s, f, decoded[f], decoded[f], 0.0f) <= tolerance2; };
  out.keys.clear();
  if (!key_ok(0) || !key_ok(frames - 1)) return false;
  out.keys.push_back(0);
  out.keys.push_back(frames - 1);
  std::vector<std::uint32_t>& stack = scratch.stack;
  stack.clear();
  stack.push_back(0);
  stack.push_back(frames - 1);
  while (!stack.empty()) {
    const std::uint32_t b = stack.back();
    stack.pop_back();
    const std::uint32_t a = stack.back();
    stack.pop_back();
    float worst = tolerance2;
    std::uint32_t worst_frame = 0;
    for (std::uint32_t f = a + 1; f < b; ++f) {
      const float alpha = static_cast<float>(f - a) / static_cast<float>(b - a);
      const float e = squared_error(s, f, decoded[a], decoded[b], alpha);
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
    for (int c = 0; c < 3; ++c) out.quantised[k * 3 + c] = scratch.codes[out.keys[k] * 3 + c];
  return true;
}

// The same keys at another bit depth (or on moved targets): range and codes recomputed.
void requantise(const TrackSamples& s, std::uint8_t bits, EncodedTrack& track, Scratch& scratch) {
  vec3 lo, extent;
  quantise_all(s, bits, lo, extent, scratch);
  track.bits = bits;
  track.min = lo;
  track.extent = extent;
  track.quantised.resize(track.keys.size() * 3);
  for (std::size_t k = 0; k < track.keys.size(); ++k)
    for (int c = 0; c < 3; ++c) track.quantised[k * 3 + c] = scratch.codes[track.keys[k] * 3 + c];
}

// The cheapest encoding within `tolerance`: identity, constant, or animated at the bit depth that
// costs least. Depths are searched from `hint` (the last pass's depth): down while feasible, then
// up while deeper depths drop enough keys to pay for themselves.
EncodedTrack encode_track(const TrackSamples& s, float tolerance, const vec4& identity, std::uint8_t hint, Scratch& scratch) {
  const std::uint32_t frames = static_cast<std::uint32_t>(s.kept.size());
  const float tolerance2 = squared_tolerance(s.rotation, tolerance);
  EncodedTrack best;
  auto within = [&](auto&& distance2) {
    for (std::uint32_t f = 0; f < frames; ++f)
      if (distance2(f) > tolerance2) return false;
    return true;
  };
  auto chord2 = [](const quat& a, const quat& b) {
    const float sign = glm::dot(a, b) < 0.0f ? -1.0f : 1.0f;
    const vec4 d(a.x - sign * b.x, a.y - sign * b.y, a.z - sign * b.z, a.w - sign * b.w);
    return glm::dot(d, d);
  };
  if (s.rotation) {
    const quat id(identity.w, identity.x, identity.y, identity.z), first = s.quats[0];
    if (within([&](std::uint32_t f) { return chord2(s.quats[f], id); })) return best;
    if (within([&](std::uint32_t f) { return chord2(s.quats[f], first); })) {
      best.kind = GclTrackKind::Constant;
      best.constant = vec4(first.x, first.y, first.z, first.w);
      return best;
    }
  } else {
    const vec3 id(identity), first = s.values[0];
    best.constant = identity;
    auto d2 = [](const vec3& a, const vec3& b) { return glm::dot(a - b, a - b); };
    if (within([&](std::uint32_t f) { return d2(s.values[f], id); })) return best;
    if (within([&](std::uint32_t f) { return d2(s.values[f], first); })) {
      best.kind = GclTrackKind::Constant;
      best.constant = vec4(first, 0.0f);
      return best;
    }
  }
  EncodedTrack trial;
  // The shallowest feasible depth: from the hint down while feasible, else up until feasible.
  std::uint8_t bits = static_cast<std::uint8_t>(std::clamp<int>(hint ? hint : 12, 1, 24));
  if (encode_at(s, bits, tolerance2, trial, scratch)) {
    best = trial;
    while (bits > 1 && encode_at(s, static_cast<std::uint8_t>(bits - 1), tolerance2, trial, scratch)) --bits, best = trial;
  } else {
    while (bits < 24 && !encode_at(s, ++bits, tolerance2, trial, scratch)) {
    }
    if (trial.kind != GclTrackKind::Animated || trial.bits != bits) {
      encode_at(s, 24, 1e30f, best, scratch);  // nothing holds the tolerance: the tightest there is
      return best;
    }
    best = trial;
  }
  // Deeper depths cost more per key but may need fewer keys.
  std::size_t best_cost = best.cost_bits(frames);
  for (std::uint8_t b = static_cast<std::uint8_t>(bits + 1); b <= 24 && best.keys.size() > 2; ++b) {
    if (!encode_at(s, b, tolerance2, trial, scratch)) continue;
    const std::size_t cost = trial.cost_bits(frames);
    if (cost >= best_cost) break;
    best_cost = cost, best = trial;
  }
  return best;
}

// --- Decoding, exactly as CompressedClip::sample does -----------------------------------------

// Writes the track's value at every frame position into out[f * stride] (a quat or a vec3).
class TrackDecoder {
 public:
  TrackDecoder(std::uint32_t frames, float rate) : positions_(frames) {
    for (std::uint32_t f = 0; f < frames; ++f) positions_[f] = frame_position(static_cast<float>(f) / rate, rate, frames);
  }

  void rotation(const EncodedTrack& t, quat* out, std::size_t stride) const {
    if (t.kind != GclTrackKind::Animated) {
      const vec4 c = t.kind == GclTrackKind::Constant ? t.constant : vec4(0, 0, 0, 1);
      for (std::size_t f = 0; f < positions_.size(); ++f) out[f * stride] = quat(c.w, c.x, c.y, c.z);
      return;
    }
    each_pair(t, [&](std::size_t f, const vec3& a, const vec3& b, float alpha) {
      out[f * stride] = nlerp(rebuild_quat(a, t.dropped), rebuild_quat(b, t.dropped), alpha);
    });
  }

  void vector(const EncodedTrack& t, const vec3& identity, vec3* out, std::size_t stride) const {
    if (t.kind != GclTrackKind::Animated) {
      const vec3 c = t.kind == GclTrackKind::Constant ? vec3(t.constant) : identity;
      for (std::size_t f = 0; f < positions_.size(); ++f) out[f * stride] = c;
      return;
    }
    each_pair(t, [&](std::size_t f, const vec3& a, const vec3& b, float alpha) { out[f * stride] = glm::mix(a, b, alpha); });
  }

 private:
  template <class Emit>
  void each_pair(const EncodedTrack& t, Emit&& emit) const {
    const vec3 scale = t.extent / static_cast<float>((1u << t.bits) - 1u);  // as CompressedClip::from_bytes
    auto key = [&](std::size_t k) {
      return vec3(t.min.x + static_cast<float>(t.quantised[k * 3]) * scale.x, t.min.y + static_cast<float>(t.quantised[k * 3 + 1]) * scale.y,
                  t.min.z + static_cast<float>(t.quantised[k * 3 + 2]) * scale.z);
    };
    const bool every_frame = t.keys.size() == positions_.size();
    std::size_t k = 0;
    vec3 a = key(0), b = key(1);
    for (std::size_t f = 0; f < positions_.size(); ++f) {
      const FramePosition p = positions_[f];
      while (t.keys[k + 1] <= p.frame) ++k, a = b, b = key(k + 1);
      const float alpha = every_frame ? p.x - static_cast<float>(p.frame)
                                      : (p.x - static_cast<float>(t.keys[k])) / static_cast<float>(t.keys[k + 1] - t.keys[k]);
      emit(f, a, b, alpha);
    }
  }

  std::vector<FramePosition> positions_;
};

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
  // Key data: each track's codes packed LSB first from a byte boundary, 64 bits at a time.
  for (const EncodedTrack& t : tracks) {
    if (t.kind != GclTrackKind::Animated) continue;
    const std::size_t at = w.bytes.size(), size = (t.keys.size() * 3 * t.bits + 7) / 8;
    w.bytes.resize(at + size + 8, 0);  // 8 spare bytes for the last word, trimmed below
    std::uint8_t* out = w.bytes.data() + at;
    std::uint64_t word = 0, bit = 0;
    unsigned used = 0;
    for (std::uint32_t q : t.quantised) {
      word |= std::uint64_t{q} << used;
      used += t.bits;
      if (used >= 32) {  // flush 32 bits, keep the rest (t.bits ≤ 24, so nothing is lost)
        const std::uint32_t low = static_cast<std::uint32_t>(word);
        std::memcpy(out + bit / 8, &low, 4);
        word >>= 32, used -= 32, bit += 32;
      }
    }
    std::memcpy(out + bit / 8, &word, 8);
    w.bytes.resize(at + size);
  }
  w.bytes.resize(w.bytes.size() + 8, 0);
  return std::move(w.bytes);
}

// Per frame and joint, the largest virtual-point displacement between raw and decoded model poses,
// decoded by CompressedClip::sample (the final check and measure_error).
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
    for (std::size_t j = 0; j < n; ++j) errors.push_back(virtual_point_error(raw.model[std::size_t{f} * n + j], model[j], distance));
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

// --- The encoder's working state ----------------------------------------------------------------
//
// Every track encoded, decoded at every frame (bit for bit what the runtime decodes), the decoded
// model matrices and each joint's worst error over the frames. A change to one track re-decodes
// that track and re-measures only its joint's subtree; a rotation change also re-aims the
// rotations below it (see Compensation).
//
// Compensation: each joint's rotation is quantised toward the local rotation that puts its decoded
// model orientation on the raw one, given its parent's decoded orientation, r* = R̂_parent⁻¹ · R_raw.
// Orientation errors then do not add up down a chain: a joint's quantisation error moves its own
// virtual points and, through its bone, the positions below it, no longer everything below it
// turned by the sum of its ancestors' errors. So a rotation's tolerance scales with its bone, not
// with the longest path below it.
class Encoder {
 public:
  Encoder(const RawClip& raw, const Skeleton& skeleton, const CompressionSettings& settings, float bound)
      : raw_(raw), skeleton_(skeleton), settings_(settings), bound_(bound), n_(skeleton.size()), frames_(raw.frames),
        decoder_(raw.frames, raw.rate) {
    prepare_samples();
    prepare_levers();
    prepare_subtrees();
    tracks_.resize(n_ * 3);
    decoded_.assign(frames_, rest_pose(skeleton));
    model_.resize(std::size_t{frames_} * n_);
    orientation_.resize(std::size_t{frames_} * n_);
    joint_error_.assign(n_, 0.0f);
    undo_model_.resize(model_.size());
  }

  // Encodes every track at the tolerances of factor s and measures everything; returns the max error.
  float encode_all(float s) {
    for (std::size_t j = 0; j < n_; ++j) {
      for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t t = j * 3 + c;
        if (c == 0) aim_rotation(j);
        tracks_[t] = encode_track(samples_[t], s * tolerance_unit(t), identity(c), tracks_[t].bits, scratch_);
        decode(t);
      }
      orient(j);
    }
    remodel(all_);
    return max_error();
  }

  // Tries `bits` on animated track t; keeps it when the bound holds, else restores. Returns whether kept.
  bool try_bits(std::size_t t, std::uint8_t bits) {
    const std::size_t j = t / 3;
    const std::vector<std::size_t>& below = subtree_[j];
    save(t, below);
    requantise(samples_[t], bits, tracks_[t], scratch_);
    decode(t);
    if (t % 3 == 0) {
      orient(j);
      for (std::size_t k = 1; k < below.size(); ++k) {  // re-aim the rotations below at their bit depths and keys
        const std::size_t d = below[k], dt = d * 3;
        if (tracks_[dt].kind == GclTrackKind::Animated) {
          aim_rotation(d);
          requantise(samples_[dt], tracks_[dt].bits, tracks_[dt], scratch_);
          decode(dt);
        }
        orient(d);
      }
    }
    remodel(below);
    if (max_error() <= bound_) return true;
    restore(t, below);
    return false;
  }

  float max_error() const { return *std::max_element(joint_error_.begin(), joint_error_.end()); }
  const std::vector<EncodedTrack>& tracks() const { return tracks_; }

  // Restores a whole state (tracks) saved earlier by copying tracks(): re-decodes and re-measures all.
  void reset_to(const std::vector<EncodedTrack>& tracks) {
    tracks_ = tracks;
    for (std::size_t j = 0; j < n_; ++j) {
      aim_rotation(j);  // the targets those rotations were quantised toward
      for (std::size_t c = 0; c < 3; ++c) decode(j * 3 + c);
      orient(j);
    }
    remodel(all_);
  }

 private:
  static vec4 identity(std::size_t c) { return c == 0 ? vec4(0, 0, 0, 1) : c == 1 ? vec4(0.0f) : vec4(1, 1, 1, 0); }

  // Tolerance of track t at factor 1: rotations over their lever, translations 1:1, scales over the path below.
  float tolerance_unit(std::size_t t) const {
    const std::size_t j = t / 3;
    return t % 3 == 0 ? settings_.max_error / rotation_lever_[j]
                      : t % 3 == 1 ? settings_.max_error : settings_.max_error / path_lever_[j];
  }

  void prepare_samples() {
    samples_.resize(n_ * 3);
    std::vector<quat> raw_local(frames_);
    raw_orientation_.resize(std::size_t{frames_} * n_);
    for (std::size_t j = 0; j < n_; ++j) {
      const int p = skeleton_.parents[j];
      for (std::uint32_t f = 0; f < frames_; ++f) {
        const quat r = raw_.poses[f].rotations[j];
        raw_orientation_[f * n_ + j] = p < 0 ? r : glm::normalize(raw_orientation_[f * n_ + static_cast<std::size_t>(p)] * r);
      }
      TrackSamples& r = samples_[j * 3];
      r.rotation = true;
      // Drop the component whose smallest magnitude over the track is largest: it is rebuilt from the
      // others, which is exact and well conditioned only while it stays away from zero.
      float best = -1.0f;
      for (std::uint8_t c = 0; c < 4; ++c) {
        float smallest = 1.0f;
        for (std::uint32_t f = 0; f < frames_; ++f) smallest = std::min(smallest, std::abs(raw_.poses[f].rotations[j][c]));
        if (smallest > best) best = smallest, r.dropped = c;
      }
      for (std::uint32_t f = 0; f < frames_; ++f) raw_local[f] = raw_.poses[f].rotations[j];
      set_rotation_targets(r, raw_local.data(), frames_);
      still_.push_back(std::all_of(raw_local.begin(), raw_local.end(), [&](const quat& q) { return q == raw_local[0]; }));
      for (std::size_t c = 1; c < 3; ++c) {
        TrackSamples& v = samples_[j * 3 + c];
        v.values.resize(frames_);
        for (std::uint32_t f = 0; f < frames_; ++f) v.values[f] = c == 1 ? raw_.poses[f].translations[j] : raw_.poses[f].scales[j];
        v.kept = v.values;
      }
    }
  }

  // Lever arms: a rotation error at j moves j's virtual points (distance d) and, through the longest
  // bone to a child, the positions below (compensation keeps it from growing further); a scale error
  // moves everything below by up to the longest path. Bones are the largest translation seen.
  void prepare_levers() {
    const float d = settings_.virtual_point_distance;
    rotation_lever_.assign(n_, d);
    path_lever_.assign(n_, d);
    for (std::size_t j = n_; j-- > 1;) {
      const int p = skeleton_.parents[j];
      if (p < 0) continue;
      const std::size_t pp = static_cast<std::size_t>(p);
      float bone = 0.0f;
      for (const Pose& pose : raw_.poses) bone = std::max(bone, glm::length(pose.translations[j] * pose.scales[pp]));
      rotation_lever_[pp] = std::max(rotation_lever_[pp], bone + d);
      path_lever_[pp] = std::max(path_lever_[pp], bone + path_lever_[j]);
    }
  }

  void prepare_subtrees() {
    subtree_.resize(n_);
    for (std::size_t j = 0; j < n_; ++j) {
      subtree_[j].push_back(j);
      for (std::size_t k = j + 1; k < n_; ++k) {  // parents come first: k is below j if its parent is
        const int p = skeleton_.parents[k];
        if (p >= 0 && std::find(subtree_[j].begin(), subtree_[j].end(), static_cast<std::size_t>(p)) != subtree_[j].end())
          subtree_[j].push_back(k);
      }
      all_.push_back(j);
    }
  }

  // Rotation targets of joint j from its parent's decoded orientation (compensation). Roots and
  // joints that hold still keep their raw rotation as the target (a still joint stays a constant).
  void aim_rotation(std::size_t j) {
    const int p = skeleton_.parents[j];
    if (p < 0 || still_[j]) return;
    targets_.resize(frames_);
    for (std::uint32_t f = 0; f < frames_; ++f)
      targets_[f] = glm::normalize(glm::conjugate(orientation_[f * n_ + static_cast<std::size_t>(p)]) * raw_orientation_[f * n_ + j]);
    set_rotation_targets(samples_[j * 3], targets_.data(), frames_);
  }

  void decode(std::size_t t) {
    if (t % 3 == 0) decode_strided_rotation(t);
    else decode_strided_vector(t);
  }

  // Poses are per frame, so a track's values are strided across them: decode into a row, then scatter.
  void decode_strided_rotation(std::size_t t) {
    row_quat_.resize(frames_);
    decoder_.rotation(tracks_[t], row_quat_.data(), 1);
    for (std::uint32_t f = 0; f < frames_; ++f) decoded_[f].rotations[t / 3] = row_quat_[f];
  }
  void decode_strided_vector(std::size_t t) {
    row_vec_.resize(frames_);
    const std::size_t j = t / 3, c = t % 3;
    decoder_.vector(tracks_[t], vec3(identity(c)), row_vec_.data(), 1);
    for (std::uint32_t f = 0; f < frames_; ++f) (c == 1 ? decoded_[f].translations[j] : decoded_[f].scales[j]) = row_vec_[f];
  }

  // Decoded orientation chain of joint j (for the targets of the joints below).
  void orient(std::size_t j) {
    const int p = skeleton_.parents[j];
    for (std::uint32_t f = 0; f < frames_; ++f) {
      const quat r = decoded_[f].rotations[j];
      orientation_[f * n_ + j] = p < 0 ? r : glm::normalize(orientation_[f * n_ + static_cast<std::size_t>(p)] * r);
    }
  }

  // Model matrices and worst errors of `joints` (in index order), as local_to_model computes them.
  void remodel(const std::vector<std::size_t>& joints) {
    const float d = settings_.virtual_point_distance;
    for (std::size_t j : joints) joint_error_[j] = 0.0f;
    for (std::uint32_t f = 0; f < frames_; ++f) {
      const Pose& pose = decoded_[f];
      mat4* model = model_.data() + std::size_t{f} * n_;
      const mat4* raw = raw_.model.data() + std::size_t{f} * n_;
      for (std::size_t j : joints) {
        const int p = skeleton_.parents[j];
        const std::int16_t root = -1;
        local_to_model(std::span<const std::int16_t>(&root, 1), std::span<const vec3>(&pose.translations[j], 1),
                       std::span<const quat>(&pose.rotations[j], 1), std::span<const vec3>(&pose.scales[j], 1),
                       std::span<mat4>(&model[j], 1), p < 0 ? mat4(1.0f) : model[static_cast<std::size_t>(p)]);
        joint_error_[j] = std::max(joint_error_[j], virtual_point_error(raw[j], model[j], d));
      }
    }
  }

  // Undo for try_bits: the tracks it may change and everything decoded and measured below.
  void save(std::size_t t, const std::vector<std::size_t>& below) {
    undo_tracks_.clear();
    undo_tracks_.push_back(tracks_[t]);
    if (t % 3 == 0)
      for (std::size_t k = 1; k < below.size(); ++k) undo_tracks_.push_back(tracks_[below[k] * 3]);
    undo_rows_.resize(std::size_t{frames_} * below.size());
    undo_vectors_.resize(std::size_t{frames_} * below.size() * 2);
    undo_orientation_.resize(std::size_t{frames_} * below.size());
    undo_error_.resize(below.size());
    for (std::uint32_t f = 0; f < frames_; ++f)
      for (std::size_t k = 0; k < below.size(); ++k) {
        const std::size_t j = below[k], at = std::size_t{f} * below.size() + k;
        undo_rows_[at] = decoded_[f].rotations[j];
        undo_vectors_[at * 2] = decoded_[f].translations[j];
        undo_vectors_[at * 2 + 1] = decoded_[f].scales[j];
        undo_orientation_[at] = orientation_[f * n_ + j];
        undo_model_[at] = model_[f * n_ + j];
      }
    for (std::size_t k = 0; k < below.size(); ++k) undo_error_[k] = joint_error_[below[k]];
  }

  void restore(std::size_t t, const std::vector<std::size_t>& below) {
    tracks_[t] = std::move(undo_tracks_[0]);
    if (t % 3 == 0)
      for (std::size_t k = 1; k < below.size(); ++k) tracks_[below[k] * 3] = std::move(undo_tracks_[k]);
    for (std::uint32_t f = 0; f < frames_; ++f)
      for (std::size_t k = 0; k < below.size(); ++k) {
        const std::size_t j = below[k], at = std::size_t{f} * below.size() + k;
        decoded_[f].rotations[j] = undo_rows_[at];
        decoded_[f].translations[j] = undo_vectors_[at * 2];
        decoded_[f].scales[j] = undo_vectors_[at * 2 + 1];
        orientation_[f * n_ + j] = undo_orientation_[at];
        model_[f * n_ + j] = undo_model_[at];
      }
    for (std::size_t k = 0; k < below.size(); ++k) joint_error_[below[k]] = undo_error_[k];
  }

  const RawClip& raw_;
  const Skeleton& skeleton_;
  const CompressionSettings& settings_;
  const float bound_;  // what trials must hold: the requested bound less a margin for float noise
  const std::size_t n_;
  const std::uint32_t frames_;
  TrackDecoder decoder_;
  std::vector<TrackSamples> samples_;
  std::vector<float> rotation_lever_, path_lever_;
  std::vector<bool> still_;  // per joint: the raw rotation never changes
  std::vector<std::vector<std::size_t>> subtree_;
  std::vector<std::size_t> all_;
  std::vector<quat> raw_orientation_, orientation_, targets_, row_quat_;
  std::vector<vec3> row_vec_;
  std::vector<EncodedTrack> tracks_;
  std::vector<Pose> decoded_;
  std::vector<mat4> model_;
  std::vector<float> joint_error_;
  Scratch scratch_;
  // try_bits undo
  std::vector<EncodedTrack> undo_tracks_;
  std::vector<quat> undo_rows_, undo_orientation_;
  std::vector<vec3> undo_vectors_;
  std::vector<mat4> undo_model_;
  std::vector<float> undo_error_;
};

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
  // The encoder aims a little inside the bound: model positions carry float rounding of a few ulps of
  // their size, which a check computed in another order (an independent measure) may land on.
  float reach = settings.virtual_point_distance;
  for (const mat4& m : raw.model) reach = std::max(reach, glm::length(vec3(m[3])) + settings.virtual_point_distance);
  const float margin = std::max(0.005f * settings.max_error, 4.0f * std::numeric_limits<float>::epsilon() * reach);
  const float bound = std::max(0.5f * settings.max_error, settings.max_error - margin);
  Encoder encoder(raw, skeleton, settings, bound);
  auto bytes_of = [&](const std::vector<EncodedTrack>& tracks) {  // key data and keysets, what the factor changes
    std::size_t bits = 0;
    for (const EncodedTrack& t : tracks)
      if (t.kind == GclTrackKind::Animated) bits += t.cost_bits(frames);
    return bits;
  };

  // Search the tolerance factor: bracket between a factor that holds the bound and one that breaks it.
  std::vector<EncodedTrack> best_tracks;  // smallest encoding within the bound; or, while none is, the most accurate
  float best_error = 0.0f;
  bool have_valid = false;
  float good = 0.0f, bad = 0.0f, s = 1.0f;
  int passes = 0;
  while (passes < 16) {
    const float e = encoder.encode_all(s);
    ++passes;
    const bool valid = e <= bound;
    if (valid) good = s;
    else bad = s;
    const bool better = valid ? !have_valid || bytes_of(encoder.tracks()) <= bytes_of(best_tracks)
                              : !have_valid && (best_tracks.empty() || e < best_error);
    if (better) best_tracks = encoder.tracks(), best_error = e, have_valid = have_valid || valid;
    if (good > 0.0f && bad > 0.0f && bad / good < 1.08f) break;
    s = bad == 0.0f ? s * 2.0f : good == 0.0f ? s * 0.3f : std::sqrt(good * bad);
    if (s > 1e4f || s < 1e-6f) break;
  }

  // The shared factor leaves slack wherever a track is not on the worst chain: take bits away track
  // by track, leaves first (same keys), while the measured error holds the bound. Each trial
  // re-measures only the track's subtree. From a track's depth b: b − 1, then halving the distance
  // to 1 while it holds, bisecting back when it breaks.
  if (have_valid) {
    encoder.reset_to(best_tracks);
    for (std::size_t j = n; j-- > 0;)
      for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t t = j * 3 + c;
        if (encoder.tracks()[t].kind != GclTrackKind::Animated) continue;
        int hi = encoder.tracks()[t].bits, lo = 0;  // hi holds; lo breaks (0: no depth below 1)
        int step = 1;
        bool bracketed = false;
        while (hi - lo > 1) {
          const int probe = bracketed ? (lo + hi) / 2 : std::max(lo + 1, hi - step);
          ++passes;
          if (encoder.try_bits(t, static_cast<std::uint8_t>(probe))) hi = probe, step *= 2;
          else lo = probe, bracketed = true;
        }
      }
    best_tracks = encoder.tracks();
  }

  CompressedClip best =
      CompressedClip::from_bytes(assemble(best_tracks, static_cast<std::uint32_t>(n), frames, settings.sample_rate, settings.max_error));
  std::vector<float> errors;
  frame_errors(raw, skeleton, best, settings.virtual_point_distance, errors);  // the runtime decoder's own measure
  const ClipError measured = summarise(errors);
  if (report) {
    report->raw_bytes = std::size_t{frames} * n * 10 * sizeof(float);
    report->bytes = best.bytes().size();
    report->max_error = measured.max;
    report->p99_error = measured.p99;
    report->passes = passes;
    report->within_bound = measured.max <= settings.max_error;
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
