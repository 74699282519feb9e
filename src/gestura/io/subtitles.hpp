#pragma once
// Subtitle files (SubRip .srt and WebVTT .vtt) read into timed cues of plain text, for signing a
// programme in step with its subtitles (the TV interpreter of sign-language-interpreter.txt §1).
//
//   Subtitles subs = read_subtitles("episode.srt");
//   for (const SubtitleCue& c : subs.cues) signer.say(c.text, …)   // c.start, c.end in seconds
//
// Lenient where real files vary: UTF-8 BOM, CRLF/CR line ends, no blank line at the end, hours
// optional, ',' or '.' before the milliseconds, SRT cues without a number, VTT cue settings and
// NOTE/STYLE/REGION blocks. Strict where a mistake would mis-time the signing: a malformed
// timestamp, a missing "-->", an end not after its start, non-UTF-8 or binary bytes and files over
// kMaxSubtitleBytes throw gestura::Error naming file:line:col and what was expected.
// Overlapping or out-of-order cues are allowed (broadcast files have them) but reported in notes;
// cues are returned sorted by start time.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gestura {

inline constexpr std::size_t kMaxSubtitleBytes = 20u * 1024u * 1024u;

struct SubtitleCue {
  int index = 0;        // the SRT cue number, or the 1-based position for VTT / unnumbered cues
  double start = 0.0;   // seconds
  double end = 0.0;     // seconds, > start
  std::string text;     // tags stripped, entities decoded, lines joined by one space
  int line = 0;         // line of the timing line in the file, for messages
};

struct Subtitles {
  std::vector<SubtitleCue> cues;    // sorted by start (stable)
  std::vector<std::string> notes;   // overlaps, reordering, empty cues — "file:line: …"
};

enum class SubtitleFormat { Srt, WebVtt };

Subtitles parse_srt(std::string_view text, const std::string& source);
Subtitles parse_webvtt(std::string_view text, const std::string& source);
Subtitles parse_subtitles(std::string_view text, SubtitleFormat format, const std::string& source);

// By extension (.srt / .vtt, any case); refuses other extensions, unreadable and oversized files.
Subtitles read_subtitles(const std::string& path);

// One timestamp: "[hh:]mm:ss[,.]mmm" (1–3 fraction digits, minutes and seconds < 60).
// Returns false for anything else. Exposed for tests and for the CLI's messages.
bool parse_subtitle_time(std::string_view text, double& seconds);

// Cue text to plain text: <i>, <b>, <v Name>, <c.cls>, <00:01.000> and {\an8}-style tags removed,
// &amp; &lt; &gt; &nbsp; &quot; &apos; &lrm; &rlm; decoded, whitespace runs collapsed, trimmed.
std::string strip_subtitle_markup(std::string_view text);

}  // namespace gestura
