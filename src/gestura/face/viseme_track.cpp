#include "gestura/face/viseme_track.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/face/face_channels.hpp"

namespace gestura::face {
namespace {

constexpr float kMaxOverlap = 0.06f;       // seconds each side
constexpr float kMaxAnticipation = 0.2f;   // seconds of lip rounding ahead of a rounded vowel

float strength(const Phoneme& p, const Articulation& a) {
  if (a.cls == PhonemeClass::vowel) {
    if (p.symbol.front() == '@') return 0.5f;  // reduced vowels barely shape the lips
    return p.stress == Stress::none ? 0.7f : 1.0f;
  }
  if (a.viseme == kPP) return 1.0f;  // a lip closure must be seen fully
  if (a.viseme == kFF) return 0.9f;
  return 0.7f;
}

}  // namespace

void append_viseme_actions(std::span<const Phoneme> phonemes, float start, float end, float amplitude,
                           std::vector<FaceAction>& out) {
  if (phonemes.empty() || !(end > start) || !(amplitude > 0.0f)) return;
  float total = 0.0f;
  for (const Phoneme& p : phonemes) total += std::max(p.duration, 0.0f);
  if (!(total > 0.0f)) return;

  const std::size_t n = phonemes.size();
  std::vector<float> bounds(n + 1);
  bounds[0] = start;
  float acc = 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    acc += std::max(phonemes[i].duration, 0.0f);
    bounds[i + 1] = start + (end - start) * acc / total;
  }
  bounds[n] = end;
  auto length = [&](std::size_t i) { return bounds[i + 1] - bounds[i]; };
  auto overlap = [&](std::size_t a, std::size_t b) {
    return std::min({0.4f * length(a), 0.4f * length(b), kMaxOverlap});
  };

  for (std::size_t i = 0; i < n; ++i) {
    const Phoneme& p = phonemes[i];
    Articulation a = articulation(p.symbol);
    if (p.cls == PhonemeClass::pause || length(i) <= 0.0f) continue;
    float weight = strength(p, a) * amplitude;
    if (a.transparent) {
      if (i + 1 >= n) continue;
      const float jaw = a.jaw;
      a = articulation(phonemes[i + 1].symbol);
      a.jaw = jaw;
      weight *= 0.5f;
    }
    // Edges of the whole interval: the bump starts (ends) exactly there and rises within the phoneme.
    const float o_in = i > 0 ? overlap(i - 1, i) : 0.0f;
    const float o_out = i + 1 < n ? overlap(i, i + 1) : 0.0f;
    const float edge = std::min(0.4f * length(i), kMaxOverlap);
    const float a_start = bounds[i] - o_in, a_end = bounds[i + 1] + o_out;
    const float ramp_in = i > 0 ? 2.0f * o_in : edge, ramp_out = i + 1 < n ? 2.0f * o_out : edge;
    if (a.viseme != kSil) out.push_back(FaceAction{a.viseme, a_start, a_end, weight, ramp_in, ramp_out});
    if (a.jaw > 0.0f)
      out.push_back(FaceAction{kJawOpen, a_start, a_end, a.jaw * amplitude, ramp_in, ramp_out});

    if (a.cls == PhonemeClass::vowel && a.rounding >= 0.5f) {
      // Walk back over the consonants before the vowel (the anticipation window).
      std::size_t first = i;
      while (first > 0 && phonemes[first - 1].cls != PhonemeClass::vowel &&
             phonemes[first - 1].cls != PhonemeClass::pause && bounds[i] - bounds[first - 1] <= kMaxAnticipation)
        --first;
      const float r_start = std::max(bounds[first] - o_in, start);
      const float rise = std::max(bounds[i] + o_in - r_start, 1e-3f);
      const float fall = std::min(ramp_out, a_end - r_start - rise);
      out.push_back(FaceAction{kMouthPucker, r_start, a_end, a.rounding * 0.6f * amplitude, rise,
                               std::max(fall, 0.0f)});
    }
  }
}

}  // namespace gestura::face
