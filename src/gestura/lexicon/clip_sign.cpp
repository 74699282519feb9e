#include "gestura/lexicon/clip_sign.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "gestura/compress/compress.hpp"
#include "gestura/compress/decompress_clip.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

namespace {

constexpr char kMagic[4] = {'G', 'C', 'S', '\0'};
constexpr std::uint32_t kVersion = 1;
// More than any face has: a blob claiming more is not one of ours.
constexpr std::uint32_t kMaxChannels = 4096;

template <class T>
void put(std::vector<std::uint8_t>& out, T v) {
  const std::size_t at = out.size();
  out.resize(at + sizeof v);
  std::memcpy(out.data() + at, &v, sizeof v);
}

// Reads the framed layout; every read names what was cut short.
class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, const std::string& what) : bytes_(bytes), what_(what) {}
  template <class T>
  T get(const char* field) {
    T v;
    need(sizeof v, field);
    std::memcpy(&v, bytes_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::vector<std::uint8_t> take(std::size_t n, const char* field) {
    need(n, field);
    std::vector<std::uint8_t> out(bytes_.begin() + static_cast<std::ptrdiff_t>(at_),
                                  bytes_.begin() + static_cast<std::ptrdiff_t>(at_ + n));
    at_ += n;
    return out;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void need(std::size_t n, const char* field) const {
    if (bytes_.size() - at_ < n)
      throw Error(what_ + ": cut short in " + field + " at byte " + std::to_string(at_) + " of " + std::to_string(bytes_.size()));
  }
  const std::vector<std::uint8_t>& bytes_;
  std::string what_;
  std::size_t at_ = 0;
};

bool moves(const FloatTrack& track) {
  for (float v : track.values)
    if (v != 0.0f) return true;
  return false;
}

}  // namespace

std::vector<std::uint8_t> encode_clip_sign(const Clip& clip, const Skeleton& skeleton) {
  std::vector<std::uint8_t> gcl = compress(clip, skeleton).bytes();
  std::vector<std::size_t> face;
  for (std::size_t c = 0; c < clip.channels.size() && c < clip.channel_names.size(); ++c)
    if (moves(clip.channels[c])) face.push_back(c);
  if (face.empty()) return gcl;
  std::vector<std::uint8_t> out;
  out.reserve(16 + gcl.size());
  for (char c : kMagic) out.push_back(static_cast<std::uint8_t>(c));
  put(out, kVersion);
  put(out, static_cast<std::uint32_t>(gcl.size()));
  out.insert(out.end(), gcl.begin(), gcl.end());
  put(out, static_cast<std::uint32_t>(face.size()));
  for (std::size_t c : face) {
    const std::string& name = clip.channel_names[c];
    if (name.empty() || name.size() > 0xffff) throw Error("a clip sign's face channel needs a name of 1–65535 bytes");
    put(out, static_cast<std::uint16_t>(name.size()));
    for (char ch : name) out.push_back(static_cast<std::uint8_t>(ch));
    const FloatTrack& track = clip.channels[c];
    put(out, static_cast<std::uint32_t>(track.times.size()));
    for (std::size_t k = 0; k < track.times.size(); ++k) put(out, track.times[k]), put(out, track.values[k]);
  }
  return out;
}

Clip decode_clip_sign(const SignEntry& entry) {
  if (entry.notation_kind != NotationKind::clip) throw Error("sign '" + entry.gloss + "' is not a clip sign");
  const std::string what = "clip sign '" + entry.gloss + "'";
  const std::vector<std::uint8_t>& blob = entry.clip;
  if (blob.size() < 4 || std::memcmp(blob.data(), kMagic, 4) != 0)
    return decompress_clip(CompressedClip::from_bytes(blob, what), entry.gloss);
  Reader in(blob, what);
  (void)in.take(4, "the magic");
  if (const auto version = in.get<std::uint32_t>("the version"); version != kVersion)
    throw Error(what + ": version " + std::to_string(version) + " is not known (this build reads " + std::to_string(kVersion) + ")");
  const auto gcl_size = in.get<std::uint32_t>("the motion's size");
  Clip clip = decompress_clip(CompressedClip::from_bytes(in.take(gcl_size, "the motion"), what), entry.gloss);
  const auto channels = in.get<std::uint32_t>("the channel count");
  if (channels > kMaxChannels) throw Error(what + ": " + std::to_string(channels) + " face channels is not a face");
  for (std::uint32_t c = 0; c < channels; ++c) {
    const auto name_size = in.get<std::uint16_t>("a channel name's size");
    const std::vector<std::uint8_t> name = in.take(name_size, "a channel name");
    const std::string channel(name.begin(), name.end());
    if (channel.empty() || clip.find_channel(channel) >= 0) throw Error(what + ": face channel " + std::to_string(c) + " has no name or one used before");
    FloatTrack& track = clip.channel(channel);
    const auto keys = in.get<std::uint32_t>("a channel's key count");
    for (std::uint32_t k = 0; k < keys; ++k) {
      const float t = in.get<float>("a channel key");
      const float v = in.get<float>("a channel key");
      if (!std::isfinite(t) || !std::isfinite(v) || (!track.times.empty() && t < track.times.back()))
        throw Error(what + ": face channel '" + channel + "' key " + std::to_string(k) + " is not a finite time in order");
      track.add(t, v);
    }
  }
  if (!in.done()) throw Error(what + ": bytes after the face channels");
  return clip;
}

}  // namespace gestura
