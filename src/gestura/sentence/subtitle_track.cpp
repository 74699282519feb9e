#include "gestura/sentence/subtitle_track.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "gestura/anim/clip_timeline.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sentence/cue_bridge.hpp"

namespace gestura {
namespace {

struct Attempt {
  SentencePerformance performance;
  float speed = 1.0f;
  bool fits = false;
};

// Re-signs faster until the performance fits `window` seconds or max_speed is reached. Speed is
// re-estimated from each attempt (duration is roughly inversely proportional to tempo, but holds
// and the return to rest do not all scale, so one estimate is not always enough).
Attempt sign_within(std::string_view text, double window, Attempt best, const SignFunction& sign,
                    const SubtitleFitOptions& options) {
  for (int attempt = 1; attempt < options.max_attempts && !best.fits && best.speed < options.max_speed; ++attempt) {
    const double ratio = window > 0.0 ? best.performance.duration / window : 1e9;
    const float speed = std::min(options.max_speed, static_cast<float>(best.speed * ratio * 1.02));
    if (speed <= best.speed) break;
    Attempt next{sign(text, speed), speed, false};
    next.fits = next.performance.duration <= window;
    best = std::move(next);
  }
  return best;
}

// When the performance's first sign starts and its last sign ends (seconds on its own clock);
// nullopt when it has no sign.
std::optional<std::array<float, 2>> signing_interval(const SentencePerformance& p) {
  std::optional<std::array<float, 2>> out;
  for (const PerformedGloss& g : p.glosses) {
    if (g.gloss == "PAUSE") continue;
    if (!out) out = std::array<float, 2>{g.start, g.end};
    (*out)[1] = g.end;
  }
  return out;
}

}  // namespace

const char* to_string(CueFit fit) {
  switch (fit) {
    case CueFit::InTime: return "in time";
    case CueFit::Spilled: return "spilled";
    case CueFit::Overran: return "NOT FITTED";
    case CueFit::Skipped: return "skipped";
  }
  return "?";
}

SubtitleTrack fit_subtitles(const std::vector<SubtitleCue>& cues, const SignFunction& sign,
                            const Skeleton& skeleton, const SubtitleFitOptions& options) {
  if (!(options.max_speed >= 1.0f && options.max_speed <= 2.0f))
    throw Error("max speed " + std::to_string(options.max_speed) + " out of range: expected 1 to 2");
  if (!(options.slack >= 0.0f) || !std::isfinite(options.slack))
    throw Error("subtitle slack must be a finite number of seconds >= 0");
  if (options.max_attempts < 1) throw Error("subtitle fitting needs at least one attempt per cue");
  SubtitleTrack track;
  track.clip = empty_timeline(skeleton);
  track.clip.name = "subtitles";
  double free_at = 0.0;  // when the signer has finished the previous cue
  std::optional<double> last_sign_end;  // programme time the previous cue's last sign ended
  double programme_end = 0.0;
  for (std::size_t i = 0; i < cues.size(); ++i) {
    const SubtitleCue& cue = cues[i];
    FittedCue fitted;
    fitted.index = cue.index, fitted.cue_start = cue.start, fitted.cue_end = cue.end;
    programme_end = std::max(programme_end, cue.end);
    if (cue.text.empty()) {
      track.cues.push_back(std::move(fitted));
      continue;
    }
    const double start = std::max(cue.start, free_at);
    const double in_time = cue.end + options.slack - start;
    double next_start = std::numeric_limits<double>::infinity();
    for (std::size_t k = i + 1; k < cues.size(); ++k)
      if (!cues[k].text.empty()) {
        next_start = cues[k].start;
        break;
      }
    // A cue the signer refuses (too long, bad text) is named, so the user can find it in the file.
    const SignFunction sign_cue = [&](std::string_view text, float speed) {
      try {
        return sign(text, speed);
      } catch (const Error& e) {
        throw Error(SourceLocation{"", cue.line, 0, -1}, "cue " + std::to_string(cue.index) + ": " + e.what());
      }
    };
    const Attempt normal{sign_cue(cue.text, 1.0f), 1.0f, false};
    Attempt best = normal;
    best.fits = best.performance.duration <= in_time;
    best = sign_within(cue.text, in_time, std::move(best), sign_cue, options);
    fitted.available = in_time;
    fitted.fit = CueFit::InTime;
    if (!best.fits) {
      const double spill = next_start - start;
      fitted.available = std::max(in_time, spill);
      if (spill > in_time) {
        // The lowest speed that fits the longer window: search again from normal tempo.
        Attempt relaxed = normal;
        relaxed.fits = relaxed.performance.duration <= spill;
        relaxed = sign_within(cue.text, spill, std::move(relaxed), sign_cue, options);
        if (relaxed.fits || relaxed.performance.duration < best.performance.duration) best = std::move(relaxed);
      }
      fitted.fit = best.performance.duration <= fitted.available ? CueFit::Spilled : CueFit::Overran;
    }
    fitted.start = start;
    fitted.speed = best.speed;
    fitted.duration = fitted.needed = best.performance.duration;
    for (const PerformedGloss& g : best.performance.glosses) fitted.glosses.push_back(g.gloss);
    fitted.notes = best.performance.notes;
    const std::optional<std::array<float, 2>> signing = signing_interval(best.performance);
    Clip clip = std::move(best.performance.clip);
    clip.duration = static_cast<float>(best.performance.duration);
    try {
      place_clip(track.clip, clip, start, skeleton);
    } catch (const Error& e) {  // a programme past the longest timeline: name the cue
      throw Error(SourceLocation{"", cue.line, 0, -1}, "cue " + std::to_string(cue.index) + ": " + e.what());
    }
    if (signing) {
      // Close cues are coarticulated: the hands go from the previous cue's last sign straight to
      // this cue's first sign instead of resting in between.
      const double first_sign = start + (*signing)[0];
      if (last_sign_end && first_sign - *last_sign_end < kCoarticulationGap) {
        bridge_arms(track.clip, skeleton, static_cast<float>(*last_sign_end), static_cast<float>(first_sign));
        fitted.coarticulated = true;
      }
      last_sign_end = start + (*signing)[1];
    }
    free_at = start + fitted.duration;
    programme_end = std::max(programme_end, free_at);
    track.cues.push_back(std::move(fitted));
  }
  track.clip.duration = static_cast<float>(programme_end);
  return track;
}

}  // namespace gestura
