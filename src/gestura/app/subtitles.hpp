#pragma once
// subtitles: a signer track for a subtitled programme. Every cue of an .srt/.vtt is signed
// (English → ASL, as say does) starting at its cue time, fitted by tempo into its time, and the
// whole programme rendered as one MP4/WebM (sentence/subtitle_track.hpp).
#include <string>
#include <vector>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"
#include "gestura/app/notice.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/sentence/subtitle_track.hpp"

namespace gestura::app {

struct SubtitlesRequest {
  std::string input;       // .srt or .vtt; "-": standard input (SRT, or WebVTT when it starts so)
  std::string output;      // .mp4 or .webm
  float max_speed = 1.5f;
  float slack = 0.25f;
  PictureOptions picture;
  AvatarChoice avatar;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.input, FieldInfo{.name = "input", .help = "the subtitles (.srt or .vtt; '-' reads standard input)", .value = "IN", .positional = true, .required = true});
    visit(self.output, FieldInfo{.name = "output", .help = "the video to write (.mp4 or .webm)", .value = "OUT", .short_flag = 'o', .required = true, .group = "Output"});
    visit(self.max_speed, FieldInfo{.name = "max_speed", .help = "fastest tempo used to fit a cue", .value = "X", .min = 1, .max = 2});
    visit(self.slack, FieldInfo{.name = "slack", .help = "seconds past a cue's end still counted in time", .value = "S", .min = 0, .max = 60});
    PictureOptions::fields(self.picture, visit);
    AvatarChoice::fields(self.avatar, visit);
  }
};

struct SubtitlesResult {
  SubtitleTrack track;  // the programme clip and every cue's fit
  RenderReport report;
  std::vector<Notice> notices;  // from the subtitle file (overlaps, reordering, empty cues)
  std::string written;
};

void validate(const SubtitlesRequest& request);
SubtitlesResult run(const SubtitlesRequest& request, const RunContext& context = {});
nlohmann::json to_json(const SubtitlesResult& result);

}  // namespace gestura::app
