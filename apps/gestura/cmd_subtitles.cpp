// gestura subtitles: a signer track for a subtitled programme (.srt/.vtt → MP4/WebM).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/subtitles.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sentence/subtitle_track.hpp"

namespace gestura::cli {
namespace {

constexpr const char* kUsage = R"(usage: gestura subtitles IN.srt|IN.vtt -o OUT.mp4|OUT.webm [options]

Signs every subtitle cue (English → ASL, as gestura say does) and renders one video in which each
cue's signing starts at the cue's start time, the signer resting between cues. A cue that is too
long for its time is signed faster (up to --max-speed), then allowed to run into the silence
before the next cue; if it still does not fit it is signed in full and the following cues start
late. Every cue is listed with its times, glosses, speed and whether it fitted. Exits 0 even when
some cues did not fit, 1 on malformed subtitles or bad options.

  -o, --output PATH   output video (.mp4 or .webm)
  --max-speed X       fastest tempo used to fit a cue, 1..2          [1.5]
  --slack S           seconds past a cue's end still counted in time  [0.25]
  --size WxH          image size (even sides for video)              [1280x720]
  --fps N             frames per second, 1..120                      [30]
  --camera LIST       front, side, three-quarter, top, side-section   [front]
  --avatar SPEC       default (the generated avatar) or makehuman:DIR [default])";

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

float parse_max_speed(const std::string& text) {
  char* end = nullptr;
  const float v = std::strtof(text.c_str(), &end);
  if (end == text.c_str() || *end || !(v >= 1.0f && v <= 2.0f))
    throw Error("bad --max-speed '" + text + "' (expected a number from 1 to 2)");
  return v;
}

std::string clock(double seconds) {
  char buf[32];
  const int whole = static_cast<int>(seconds);
  std::snprintf(buf, sizeof buf, "%02d:%02d:%06.3f", whole / 3600, whole / 60 % 60, seconds - whole / 60 * 60);
  return buf;
}

void print_table(const SubtitleTrack& track) {
  std::printf("%5s  %-12s %-12s %-12s %6s  %-11s %s\n", "cue", "start", "end", "signed at", "speed", "fit",
              "glosses");
  int unfit = 0;
  for (const FittedCue& c : track.cues) {
    std::string glosses;
    for (const std::string& g : c.glosses) glosses += (glosses.empty() ? "" : " ") + g;
    if (c.coarticulated) glosses = "(joined) " + glosses;
    std::printf("%5d  %-12s %-12s %-12s %5.2fx  %-11s %s\n", c.index, clock(c.cue_start).c_str(),
                clock(c.cue_end).c_str(), c.fit == CueFit::Skipped ? "-" : clock(c.start).c_str(), c.speed,
                to_string(c.fit), glosses.c_str());
    if (c.fit == CueFit::Overran) {
      ++unfit;
      std::printf("       needs %.2f s at %.2fx, %.2f s available: the following cues start late\n", c.needed,
                  c.speed, c.available);
    }
    for (const std::string& note : c.notes) std::printf("       note: %s\n", note.c_str());
  }
  std::printf("%zu cues, %d not fitted; programme %.2f s\n", track.cues.size(), unfit, track.clip.duration);
}

int run(const std::vector<std::string>& args) {
  std::optional<std::string> input;
  RenderJob job;
  SubtitleFitOptions fit;
  std::string avatar_spec = "default";
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") job.output = flag_value(args, i);
    else if (a == "--max-speed") fit.max_speed = parse_max_speed(flag_value(args, i));
    else if (a == "--slack") fit.slack = parse_seconds(flag_value(args, i), "--slack");
    else if (a == "--size") job.size = parse_image_size(flag_value(args, i));
    else if (a == "--fps") job.fps = parse_fps(flag_value(args, i));
    else if (a == "--camera") job.cameras = parse_camera_list(flag_value(args, i));
    else if (a == "--avatar") avatar_spec = flag_value(args, i);
    else if (a.size() > 1 && a[0] == '-') throw Error("unknown flag '" + a + "' (see gestura subtitles --help)");
    else if (input) throw Error("give one subtitle file");
    else input = a;
  }
  if (!input) throw Error("missing IN.srt or IN.vtt (see gestura subtitles --help)");
  if (job.output.empty()) throw Error("missing -o OUT.mp4 or OUT.webm");
  if (!ends_with(job.output, ".mp4") && !ends_with(job.output, ".webm"))
    throw Error("-o " + job.output + ": the output must be a .mp4 or .webm video");
  validate(job);  // before the slow parts
  const Subtitles subs = read_subtitles(*input);
  for (const std::string& note : subs.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
  if (subs.cues.empty()) throw Error(*input + ": no subtitle cues");

  DefaultLexicon lexicon;
  const Avatar avatar = load_avatar(avatar_spec);
  const Signer signer(avatar, lexicon.layers());
  SayOptions say;
  say.fps = static_cast<float>(job.fps);
  const SignFunction sign = [&](std::string_view text, float speed) {
    SayOptions options = say;
    options.speed = speed;
    return signer.say(text, options);
  };
  const SubtitleTrack track = [&] {
    try {
      return fit_subtitles(subs.cues, sign, avatar.skeleton, fit);
    } catch (const Error& e) {  // a cue the signer refused: name the file too
      if (e.where().line > 0 && e.where().file.empty()) throw Error({*input, e.where().line, 0, -1}, e.message());
      throw;
    }
  }();
  const RenderReport report = render_to_file(RenderSubject{avatar.skeleton, avatar.mesh, track.clip}, job);
  print_table(track);
  std::printf("wrote %s (%d frames)\n", std::filesystem::absolute(job.output).c_str(), report.frames);
  return 0;
}

Registration reg{{"subtitles", "sign a subtitle file (.srt/.vtt) in time with its cues, rendered to MP4/WebM",
                  kUsage, run}};

}  // namespace
}  // namespace gestura::cli
