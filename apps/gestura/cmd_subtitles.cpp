// gestura subtitles: a signer track for a subtitled programme (.srt/.vtt → MP4/WebM),
// app/subtitles.hpp.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "command.hpp"
#include "gestura/app/subtitles.hpp"

namespace gestura::cli {
namespace {

std::string clock(double seconds) {
  char buf[32];
  const int whole = static_cast<int>(seconds);
  std::snprintf(buf, sizeof buf, "%02d:%02d:%06.3f", whole / 3600, whole / 60 % 60, seconds - whole / 60 * 60);
  return buf;
}

void print_table(const SubtitleTrack& track) {
  std::printf("%5s  %-12s %-12s %-12s %6s  %-11s %s\n", "cue", "start", "end", "signed at", "speed", "fit", "glosses");
  int unfit = 0;
  for (const FittedCue& c : track.cues) {
    std::string glosses;
    for (const std::string& g : c.glosses) glosses += (glosses.empty() ? "" : " ") + g;
    if (c.coarticulated) glosses = "(joined) " + glosses;
    std::printf("%5d  %-12s %-12s %-12s %5.2fx  %-11s %s\n", c.index, clock(c.cue_start).c_str(), clock(c.cue_end).c_str(),
                c.fit == CueFit::Skipped ? "-" : clock(c.start).c_str(), c.speed, to_string(c.fit), glosses.c_str());
    if (c.fit == CueFit::Overran) {
      ++unfit;
      std::printf("       needs %.2f s at %.2fx, %.2f s available: the following cues start late\n", c.needed, c.speed,
                  c.available);
    }
    for (const std::string& note : c.notes) std::printf("       note: %s\n", note.c_str());
  }
  std::printf("%zu cues, %d not fitted; programme %.2f s\n", track.cues.size(), unfit, track.clip.duration);
}

Invocation prepare() {
  auto request = std::make_shared<app::SubtitlesRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::SubtitlesResult r = app::run(*request, context);
    for (const app::Notice& n : r.notices) std::fprintf(stderr, "%s\n", n.text().c_str());
    print_table(r.track);
    std::printf("wrote %s (%d frames)\n", std::filesystem::absolute(r.written).c_str(), r.report.frames);
    return 0;
  };
  return invocation;
}

const Registration reg{{"subtitles", "sign a subtitle file (.srt/.vtt) in time with its cues, rendered to MP4/WebM",
                        "Signs every subtitle cue (English → ASL, as gestura say does) and renders one video in which\n"
                        "each cue's signing starts at the cue's start time, the signer resting between cues. A cue that\n"
                        "is too long for its time is signed faster (up to --max-speed), then allowed to run into the\n"
                        "silence before the next cue; if it still does not fit it is signed in full and the following\n"
                        "cues start late. Every cue is listed with its times, glosses, speed and whether it fitted.\n"
                        "IN '-' reads the subtitles from standard input. Exits 0 even when some cues did not fit, 1 on\n"
                        "malformed subtitles, 2 on bad options.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
