// Fuzz target: subtitles, every input read both as SubRip (.srt) and as WebVTT (.vtt), each cue's
// text stripped of markup.
#include "fuzz_target.hpp"
#include "gestura/io/subtitles.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = gestura::fuzz::text_of(data, size);
  for (const gestura::SubtitleFormat format : {gestura::SubtitleFormat::Srt, gestura::SubtitleFormat::WebVtt})
    gestura::fuzz::expect_result_or_error([&] {
      const gestura::Subtitles subtitles = gestura::parse_subtitles(text, format, "fuzz");
      for (const gestura::SubtitleCue& cue : subtitles.cues) (void)gestura::strip_subtitle_markup(cue.text);
    });
  return 0;
}
