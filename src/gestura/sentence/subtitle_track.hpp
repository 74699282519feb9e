#pragma once
// A signer track for a subtitled programme: each cue signed, fitted into its time window and
// placed at its start on one long clip (the TV interpreter of sign-language-interpreter.txt §1).
//
//   SubtitleTrack t = fit_subtitles(subs.cues, [&](std::string_view text, float speed) {
//     return signer.say(text, {.speed = speed}); }, skeleton, {});
//   t.clip  // the whole programme; t.cues  // what happened to each cue
//
// Fitting one cue (window = from when signing can start to the cue's end + slack):
//   1. signed at speed 1; if it fits, done;
//   2. re-signed faster, speed ≈ duration / window, up to max_speed;
//   3. still too long: may spill into the gap before the next cue's start, at the lowest speed
//      (≤ max_speed) that fits there;
//   4. still too long: NOT fitted — it is signed at max_speed in full and overruns, and the next
//      cues start late (shifted), catching up by speeding up or using gaps. Truncating instead
//      would cut signs in half, which is meaningless to a viewer; a late but whole sentence is not.
// Between cues the signer is at rest (see anim/clip_timeline.hpp), unless the gap from one cue's last
// sign to the next cue's first sign is under kCoarticulationGap (cue_bridge.hpp): then the hands go
// straight from one to the other. Cues without text are skipped.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/io/subtitles.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Signs `text` at `speed` (1 = normal tempo). Its clip must be on the skeleton given to fit_subtitles.
using SignFunction = std::function<SentencePerformance(std::string_view text, float speed)>;

struct SubtitleFitOptions {
  float max_speed = 1.5f;   // in [1, 2] (the Signer's tempo limit is 2)
  float slack = 0.25f;      // seconds past a cue's end that still count as in time, >= 0
  int max_attempts = 4;     // signings per window while searching the speed, >= 1
};

enum class CueFit : std::uint8_t {
  InTime,    // within [start, end + slack] (possibly sped up)
  Spilled,   // ran past end + slack but finished before the next cue
  Overran,   // did not fit even at max_speed: next cues shifted
  Skipped,   // no text
};
const char* to_string(CueFit fit);

struct FittedCue {
  int index = 0;                 // the cue's number
  double cue_start = 0.0, cue_end = 0.0;
  double start = 0.0;            // when its signing starts on the programme clip (>= cue_start)
  double duration = 0.0;         // of the placed performance, including its return to rest
  float speed = 1.0f;            // the tempo it was signed at
  double needed = 0.0;           // = duration; seconds the signing takes at that speed
  double available = 0.0;        // seconds it was allowed (to end + slack, or to the next cue when spilling)
  CueFit fit = CueFit::Skipped;
  bool coarticulated = false;    // joined to the previous cue's last sign without resting between
  std::vector<std::string> glosses;
  std::vector<std::string> notes;  // the performance's notes (unknown words fingerspelled …)

  bool fitted() const { return fit == CueFit::InTime || fit == CueFit::Spilled; }
};

struct SubtitleTrack {
  Clip clip;                     // on `skeleton`; duration = max(last cue end, end of the last signing)
  std::vector<FittedCue> cues;   // one per input cue, in order
};

// Contract: cues sorted by start (parse_* return them so). Throws gestura::Error for options out of
// range, a performance whose clip does not fit `skeleton`, or an Error from `sign` — then prefixed
// with "line L: cue N:" so the user can find the cue in the file.
SubtitleTrack fit_subtitles(const std::vector<SubtitleCue>& cues, const SignFunction& sign,
                            const Skeleton& skeleton, const SubtitleFitOptions& options);

}  // namespace gestura
