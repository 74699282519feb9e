#include "gestura/compress/compressed_clip.hpp"

#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {
namespace {

// Reads the header and descriptors with bounds checks; every failure names the byte offset.
class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  template <class T>
  T read(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  float read_finite(const char* what) {
    const std::size_t here = at_;
    const float v = read<float>(what);
    if (!std::isfinite(v)) fail(here, std::string(what) + " is not a finite number");
    return v;
  }
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - at_ < n) fail(at_, std::string("truncated: ") + what + " needs " + std::to_string(n) + " bytes, " +
                                           std::to_string(bytes_.size() - at_) + " left");
  }
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw Error(SourceLocation{source_}, "byte " + std::to_string(offset) + ": " + message);
  }
  std::size_t at() const { return at_; }
  void skip(std::size_t n) { at_ += n; }

 private:
  const std::vector<std::uint8_t>& bytes_;
  const std::string& source_;
  std::size_t at_ = 0;
};

constexpr std::size_t kMaxJoints = 32767;
constexpr std::uint32_t kMaxFrames = 65535;

}  // namespace

CompressedClip CompressedClip::from_bytes(std::vector<std::uint8_t> bytes, const std::string& source) {
  CompressedClip clip;
  clip.bytes_ = std::move(bytes);
  Reader in(clip.bytes_, source);
  char magic[4];
  in.need(4, "magic");
  std::memcpy(magic, clip.bytes_.data(), 4);
  if (std::memcmp(magic, "GCL\0", 4) != 0) in.fail(0, "not a gestura compressed clip (magic is not \"GCL\\0\")");
  in.skip(4);
  const std::uint16_t version = in.read<std::uint16_t>("version");
  if (version != kGclVersion)
    in.fail(4, "unsupported version " + std::to_string(version) + " (this build reads " + std::to_string(kGclVersion) + ")");
  in.read<std::uint16_t>("reserved");
  const std::size_t joints_at = in.at();
  const std::uint32_t joints = in.read<std::uint32_t>("joint count");
  if (joints == 0 || joints > kMaxJoints) in.fail(joints_at, "joint count " + std::to_string(joints) + " outside 1.." + std::to_string(kMaxJoints));
  const std::size_t frames_at = in.at();
  const std::uint32_t frames = in.read<std::uint32_t>("frame count");
  if (frames < 1 || frames > kMaxFrames) in.fail(frames_at, "frame count " + std::to_string(frames) + " outside 1.." + std::to_string(kMaxFrames));
  const std::size_t rate_at = in.at();
  const float rate = in.read_finite("sample rate");
  if (!(rate > 0.0f && rate <= 10000.0f)) in.fail(rate_at, "sample rate must be in (0, 10000] Hz");
  clip.max_error_ = in.read_finite("max error");
  const std::size_t data_bytes_at = in.at();
  const std::uint32_t data_bytes = in.read<std::uint32_t>("data size");
  clip.joint_count_ = joints;
  clip.frame_count_ = frames;
  clip.sample_rate_ = rate;

  // Descriptors.
  clip.tracks_.resize(std::size_t{joints} * 3);
  std::size_t keyset_words = 0, data_needed = 0;
  for (std::size_t t = 0; t < clip.tracks_.size(); ++t) {
    GclTrack& track = clip.tracks_[t];
    const bool rotation = t % 3 == 0;
    const std::size_t kind_at = in.at();
    const std::uint8_t kind = in.read<std::uint8_t>("track kind");
    const std::string which = "joint " + std::to_string(t / 3) + " " + (rotation ? "rotation" : t % 3 == 1 ? "translation" : "scale");
    if (kind > 2) in.fail(kind_at, which + ": unknown track kind " + std::to_string(kind));
    track.kind = static_cast<GclTrackKind>(kind);
    if (track.kind == GclTrackKind::Identity) {
      track.constant = rotation ? vec4(0, 0, 0, 1) : t % 3 == 1 ? vec4(0.0f) : vec4(1, 1, 1, 0);
    } else if (track.kind == GclTrackKind::Constant) {
      for (int c = 0; c < (rotation ? 4 : 3); ++c) track.constant[c] = in.read_finite("constant value");
    } else {
      const std::size_t bits_at = in.at();
      track.bits = in.read<std::uint8_t>("bit count");
      if (track.bits < 1 || track.bits > 24) in.fail(bits_at, which + ": bit count " + std::to_string(track.bits) + " outside 1..24");
      const std::size_t dropped_at = in.at();
      track.dropped = in.read<std::uint8_t>("dropped component");
      if (track.dropped > (rotation ? 3 : 0)) in.fail(dropped_at, which + ": bad dropped component " + std::to_string(track.dropped));
      const std::size_t keys_at = in.at();
      track.key_count = in.read<std::uint16_t>("key count");
      if (track.key_count < 2 || track.key_count > frames)
        in.fail(keys_at, which + ": key count " + std::to_string(track.key_count) + " outside 2.." + std::to_string(frames));
      for (int c = 0; c < 3; ++c) track.min[c] = in.read_finite("range minimum");
      for (int c = 0; c < 3; ++c) {
        const std::size_t extent_at = in.at();
        const float extent = in.read_finite("range extent");
        if (extent < 0.0f) in.fail(extent_at, which + ": negative range extent");
        track.scale[c] = extent / static_cast<float>((1u << track.bits) - 1u);
      }
      if (track.key_count < frames) keyset_words += (frames + 63) / 64;
      data_needed += (std::size_t{track.key_count} * 3 * track.bits + 7) / 8;
    }
  }
  // Keysets.
  const std::size_t keysets_at = in.at();
  in.need(keyset_words * 8, "keysets");
  if (data_bytes != data_needed)
    in.fail(data_bytes_at, "data size " + std::to_string(data_bytes) + " disagrees with the tracks (" + std::to_string(data_needed) + ")");
  const std::size_t data_at = keysets_at + keyset_words * 8;
  in.skip(keyset_words * 8);
  in.need(data_needed + 8, "key data and padding");
  if (clip.bytes_.size() != data_at + data_needed + 8)
    in.fail(data_at + data_needed + 8, "unexpected " + std::to_string(clip.bytes_.size() - (data_at + data_needed + 8)) + " trailing bytes");

  // Index: pointers into the bytes and rank tables for the keysets. The keysets are copied into an
  // aligned array so decoding reads whole u64 words.
  const std::size_t words_per_set = (frames + 63) / 64;
  clip.ranks_.assign(keyset_words, 0);
  clip.keysets_.assign(keyset_words, 0);
  std::uint16_t* ranks = clip.ranks_.data();
  std::uint64_t* words = clip.keysets_.data();
  if (keyset_words) std::memcpy(words, clip.bytes_.data() + keysets_at, keyset_words * 8);
  std::size_t set = 0, data_offset = data_at;
  for (std::size_t t = 0; t < clip.tracks_.size(); ++t) {
    GclTrack& track = clip.tracks_[t];
    if (track.kind != GclTrackKind::Animated) continue;
    if (track.key_count < frames) {
      const std::size_t at = keysets_at + set * words_per_set * 8;
      const std::uint64_t* w = words + set * words_per_set;
      std::uint16_t* r = ranks + set * words_per_set;
      std::uint32_t count = 0;
      for (std::size_t i = 0; i < words_per_set; ++i) {
        r[i] = static_cast<std::uint16_t>(count);
        std::uint64_t word = w[i];
        if (i == words_per_set - 1 && frames % 64) word &= (1ull << (frames % 64)) - 1;
        if (word != w[i]) in.fail(at + i * 8, "joint " + std::to_string(t / 3) + ": keyset has bits past the last frame");
        count += static_cast<std::uint32_t>(std::popcount(word));
      }
      if (!(w[0] & 1) || !((w[(frames - 1) / 64] >> ((frames - 1) % 64)) & 1))
        in.fail(at, "joint " + std::to_string(t / 3) + ": keyset lacks the first or last frame");
      if (count != track.key_count)
        in.fail(at, "joint " + std::to_string(t / 3) + ": keyset has " + std::to_string(count) + " keys, descriptor says " +
                        std::to_string(track.key_count));
      track.keyset = w;
      track.rank = r;
      ++set;
    }
    track.data = clip.bytes_.data() + data_offset;
    data_offset += (std::size_t{track.key_count} * 3 * track.bits + 7) / 8;
  }
  return clip;
}

namespace {

inline vec3 decode_key(const GclTrack& track, std::uint32_t key) {
  const std::uint64_t bit = std::uint64_t{key} * 3u * track.bits;
  return vec3(track.min.x + static_cast<float>(read_bits(track.data, bit, track.bits)) * track.scale.x,
              track.min.y + static_cast<float>(read_bits(track.data, bit + track.bits, track.bits)) * track.scale.y,
              track.min.z + static_cast<float>(read_bits(track.data, bit + 2u * track.bits, track.bits)) * track.scale.z);
}

// The keys around frame position x (frame ≤ x < frame + 1) and the blend weight between them.
struct KeyPair {
  std::uint32_t k0, k1;
  float alpha;
};

inline KeyPair find_keys(const GclTrack& track, std::uint32_t frame, float x) {
  if (!track.keyset) return {frame, frame + 1, x - static_cast<float>(frame)};
  const std::uint32_t word = frame >> 6, bit = frame & 63;
  const std::uint64_t upto = ~0ull >> (63 - bit);  // bits 0..bit
  const std::uint64_t before = track.keyset[word] & upto;  // never 0 in word 0 (frame 0 is a key)
  std::uint32_t w0 = word;
  std::uint64_t m0 = before;
  std::uint32_t k0 = track.rank[word] + static_cast<std::uint32_t>(std::popcount(before)) - 1u;
  while (m0 == 0) m0 = track.keyset[--w0];  // previous key lies in an earlier word
  const std::uint32_t f0 = 64u * w0 + 63u - static_cast<std::uint32_t>(std::countl_zero(m0));
  std::uint32_t w1 = word;
  std::uint64_t m1 = track.keyset[word] & ~upto;
  while (m1 == 0) m1 = track.keyset[++w1];  // the last frame is a key, so this ends
  const std::uint32_t f1 = 64u * w1 + static_cast<std::uint32_t>(std::countr_zero(m1));
  return {k0, k0 + 1, (x - static_cast<float>(f0)) / static_cast<float>(f1 - f0)};
}

}  // namespace

void CompressedClip::sample(float time, Pose& out) const {
  const auto [x, frame] = frame_position(time, sample_rate_, frame_count_);
  const GclTrack* track = tracks_.data();
  for (std::size_t j = 0; j < joint_count_; ++j, track += 3) {
    const GclTrack& r = track[0];
    if (r.kind == GclTrackKind::Animated) {
      const KeyPair k = find_keys(r, frame, x);
      out.rotations[j] = nlerp(rebuild_quat(decode_key(r, k.k0), r.dropped), rebuild_quat(decode_key(r, k.k1), r.dropped), k.alpha);
    } else {
      out.rotations[j] = quat(r.constant.w, r.constant.x, r.constant.y, r.constant.z);
    }
    for (int c = 1; c < 3; ++c) {
      const GclTrack& v = track[c];
      vec3 value;
      if (v.kind == GclTrackKind::Animated) {
        const KeyPair k = find_keys(v, frame, x);
        value = glm::mix(decode_key(v, k.k0), decode_key(v, k.k1), k.alpha);
      } else {
        value = vec3(v.constant);
      }
      (c == 1 ? out.translations[j] : out.scales[j]) = value;
    }
  }
}

CompressedClip load_gcl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot open file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0 || size > (std::streamoff{1} << 31)) throw Error(SourceLocation{path}, "file too large for a compressed clip");
  in.seekg(0);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), size);
  if (!in) throw Error(SourceLocation{path}, "read failed");
  return CompressedClip::from_bytes(std::move(bytes), path);
}

void save_gcl(const std::string& path, const CompressedClip& clip) {
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(clip.bytes().data()), clip.bytes().size()));
}

}  // namespace gestura
