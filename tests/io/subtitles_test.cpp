// Subtitle parsing: valid SRT/WebVTT variants give the cue times and plain text; malformed input
// names file:line:col and what was expected; random bytes and mutations never crash.
#include "gestura/io/subtitles.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

// The message of the Error thrown by parsing `text`, or "" when it parses.
std::string srt_error(std::string_view text) {
  try {
    parse_srt(text, "t.srt");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string vtt_error(std::string_view text) {
  try {
    parse_webvtt(text, "t.vtt");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Subtitles, SrtBasicTwoCues) {
  const auto s = parse_srt(
      "1\n00:00:01,000 --> 00:00:03,500\nHello there.\n\n"
      "2\n00:00:04,250 --> 00:01:02,005\nHow are\nyou?\n",
      "t.srt");
  ASSERT_EQ(s.cues.size(), 2u);
  EXPECT_EQ(s.cues[0].index, 1);
  EXPECT_DOUBLE_EQ(s.cues[0].start, 1.0);
  EXPECT_DOUBLE_EQ(s.cues[0].end, 3.5);
  EXPECT_EQ(s.cues[0].text, "Hello there.");
  EXPECT_EQ(s.cues[0].line, 2);
  EXPECT_DOUBLE_EQ(s.cues[1].start, 4.25);
  EXPECT_DOUBLE_EQ(s.cues[1].end, 62.005);
  EXPECT_EQ(s.cues[1].text, "How are you?");
  EXPECT_TRUE(s.notes.empty());
}

TEST(Subtitles, SrtBomCrlfNoTrailingBlankDotMillis) {
  const auto s = parse_srt("\xEF\xBB\xBF" "7\r\n01:00:00.100 --> 01:00:02.000\r\n<i>Hi</i> {\\an8}there\r\n\r\n"
                           "8\r\n01:00:03,000 --> 01:00:04,000 X1:100 X2:200 Y1:10 Y2:20\r\n<font color=\"red\">Bye</font>",
                           "t.srt");
  ASSERT_EQ(s.cues.size(), 2u);
  EXPECT_EQ(s.cues[0].index, 7);
  EXPECT_DOUBLE_EQ(s.cues[0].start, 3600.1);
  EXPECT_EQ(s.cues[0].text, "Hi there");
  EXPECT_EQ(s.cues[1].index, 8);
  EXPECT_EQ(s.cues[1].text, "Bye");
}

TEST(Subtitles, SrtLoneCrAndMissingSeparatorAndUnnumbered) {
  const auto a = parse_srt("1\r00:00:01,000 --> 00:00:02,000\rA\r", "t.srt");
  ASSERT_EQ(a.cues.size(), 1u);
  EXPECT_EQ(a.cues[0].text, "A");
  // The blank line between cues was lost: the number + timing pair still starts cue 2.
  const auto b = parse_srt("1\n00:00:01,000 --> 00:00:02,000\nOne\n2\n00:00:03,000 --> 00:00:04,000\nTwo\n", "t.srt");
  ASSERT_EQ(b.cues.size(), 2u);
  EXPECT_EQ(b.cues[0].text, "One");
  EXPECT_EQ(b.cues[1].text, "Two");
  // A cue without its number gets its position.
  const auto c = parse_srt("00:00:01,000 --> 00:00:02,000\nX\n\n\n\n00:00:05,000 --> 00:00:06,000\nY\n", "t.srt");
  ASSERT_EQ(c.cues.size(), 2u);
  EXPECT_EQ(c.cues[1].index, 2);
  EXPECT_EQ(c.cues[1].text, "Y");
}

TEST(Subtitles, EmptyAndBlankFilesHaveNoCues) {
  EXPECT_TRUE(parse_srt("", "t.srt").cues.empty());
  EXPECT_TRUE(parse_srt("\n\n  \r\n", "t.srt").cues.empty());
  EXPECT_TRUE(parse_webvtt("WEBVTT\n", "t.vtt").cues.empty());
}

TEST(Subtitles, TimestampForms) {
  double t = -1;
  EXPECT_TRUE(parse_subtitle_time("00:00:01,000", t));
  EXPECT_DOUBLE_EQ(t, 1.0);
  EXPECT_TRUE(parse_subtitle_time("01:02.5", t));  // no hours, one fraction digit = 0.5 s
  EXPECT_DOUBLE_EQ(t, 62.5);
  EXPECT_TRUE(parse_subtitle_time("100:00:00.000", t));
  EXPECT_DOUBLE_EQ(t, 360000.0);
  EXPECT_TRUE(parse_subtitle_time("0:0:7.07", t));
  EXPECT_DOUBLE_EQ(t, 7.07);
  for (const char* bad : {"", "1", "00:60:00,000", "00:00:60,000", "00:00:01", "00:00:01,0000", "a0:00:01,000",
                          "00:00:01,", "-0:00:01,000", "1:2:3:4.000", "00:00 01,000", "00:00:01,00x"})
    EXPECT_FALSE(parse_subtitle_time(bad, t)) << bad;
}

TEST(Subtitles, MarkupStripped) {
  EXPECT_EQ(strip_subtitle_markup("<v Roger Bingham>We are <c.loud>in</c> <00:00:05.000>New York"),
            "We are in New York");
  EXPECT_EQ(strip_subtitle_markup("  Fish &amp; chips &lt;3&nbsp;today  \n  ok "), "Fish & chips <3 today ok");
  EXPECT_EQ(strip_subtitle_markup("{\\an8}{\\pos(10,20)}Top"), "Top");
  EXPECT_EQ(strip_subtitle_markup("a < b {not a tag} & c"), "a < b {not a tag} & c");  // unclosed '<' kept
  EXPECT_EQ(strip_subtitle_markup("<b>"), "");
}

TEST(Subtitles, VttHeaderNotesStyleRegionSettingsIdentifiers) {
  const auto s = parse_webvtt(
      "\xEF\xBB\xBFWEBVTT - Some title\nKind: captions\nLanguage: en\n\n"
      "REGION\nid:fred\nwidth:40%\n\n"
      "STYLE\n::cue { color: red }\n\n"
      "NOTE this is\na comment\n\n"
      "intro\n00:01.000 --> 00:04.000 align:start line:0 position:10%\n<v Mary>Good <b>morning</b>!\n\n"
      "NOTE\nanother\n\n"
      "00:00:05.000 --> 00:00:06.500\nSecond\nline\n",
      "t.vtt");
  ASSERT_EQ(s.cues.size(), 2u);
  EXPECT_DOUBLE_EQ(s.cues[0].start, 1.0);
  EXPECT_DOUBLE_EQ(s.cues[0].end, 4.0);
  EXPECT_EQ(s.cues[0].text, "Good morning!");
  EXPECT_EQ(s.cues[0].index, 1);
  EXPECT_EQ(s.cues[0].line, 16);
  EXPECT_EQ(s.cues[1].index, 2);
  EXPECT_DOUBLE_EQ(s.cues[1].end, 6.5);
  EXPECT_EQ(s.cues[1].text, "Second line");
}

TEST(Subtitles, VttCrlfNoFinalNewlineAndCommaMillis) {
  const auto s = parse_webvtt("WEBVTT\r\n\r\n1\r\n00:00:01,000 --> 00:00:02,000\r\nX", "t.vtt");
  ASSERT_EQ(s.cues.size(), 1u);
  EXPECT_EQ(s.cues[0].text, "X");
}

TEST(Subtitles, OverlapsAndDisorderAreReportedNotRefused) {
  const auto s = parse_srt(
      "1\n00:00:05,000 --> 00:00:08,000\nB\n\n"
      "2\n00:00:01,000 --> 00:00:03,000\nA\n\n"
      "3\n00:00:07,000 --> 00:00:09,000\nC\n\n"
      "4\n00:00:10,000 --> 00:00:11,000\n<i></i>\n",
      "t.srt");
  ASSERT_EQ(s.cues.size(), 4u);
  EXPECT_EQ(s.cues[0].text, "A");
  EXPECT_EQ(s.cues[1].text, "B");
  ASSERT_EQ(s.notes.size(), 3u);
  EXPECT_NE(s.notes[0].find("cue 4 has no text"), std::string::npos) << s.notes[0];
  EXPECT_NE(s.notes[1].find("not in time order"), std::string::npos) << s.notes[1];
  EXPECT_NE(s.notes[2].find("t.srt:10: cue 3 starts at 7.000 s, before cue 1 ends at 8.000 s"), std::string::npos)
      << s.notes[2];
}

TEST(Subtitles, SrtMalformedNamesThePlace) {
  EXPECT_EQ(srt_error("1\n00:00:01,000 00:00:02,000\nx\n"),
            "t.srt:2:1: expected a timing line 'hh:mm:ss,mmm --> hh:mm:ss,mmm', got '00:00:01,000 00:00:02,000'");
  EXPECT_EQ(srt_error("1\n00:00:01,000 --> 00:00:0x,000\nx\n"),
            "t.srt:2:18: bad end time '00:00:0x,000': expected [hh:]mm:ss,mmm");
  EXPECT_EQ(srt_error("1\n00:61:01,000 --> 00:00:02,000\n"),
            "t.srt:2:1: bad start time '00:61:01,000': expected [hh:]mm:ss,mmm");
  EXPECT_EQ(srt_error("1\n00:00:03,000 --> 00:00:02,000\nx\n"),
            "t.srt:2:18: cue ends at 2.000 s, not after its start at 3.000 s");
  EXPECT_EQ(srt_error("1\n00:00:03,000 --> 00:00:03,000\nx\n"),
            "t.srt:2:18: cue ends at 3.000 s, not after its start at 3.000 s");
  EXPECT_EQ(srt_error("Hello world\n"), "t.srt:1:1: expected a cue number or a timing line, got 'Hello world'");
  EXPECT_EQ(srt_error("1\n00:00:01,000 --> 00:00:02,000\nx\n\n2\n"),
            "t.srt:6:1: expected a timing line 'hh:mm:ss,mmm --> hh:mm:ss,mmm' after cue number 2");
  EXPECT_EQ(srt_error("1\n00:00:01,000 --> \nx\n"), "t.srt:2:18: bad end time '': expected [hh:]mm:ss,mmm");
  EXPECT_EQ(srt_error(" --> 00:00:01,000\n"), "t.srt:1:1: bad start time '': expected [hh:]mm:ss,mmm");
}

TEST(Subtitles, VttMalformedNamesThePlace) {
  EXPECT_EQ(vtt_error("1\n00:00:01.000 --> 00:00:02.000\nx\n"), "t.vtt:1:1: expected the 'WEBVTT' header, got '1'");
  EXPECT_EQ(vtt_error(""), "t.vtt:1:1: expected the 'WEBVTT' header, got ''");
  EXPECT_EQ(vtt_error("WEBVTTX\n"), "t.vtt:1:1: expected the 'WEBVTT' header, got 'WEBVTTX'");
  EXPECT_EQ(vtt_error("WEBVTT\n\nid\n\n"),
            "t.vtt:4:1: expected a timing line 'mm:ss.mmm --> mm:ss.mmm' after cue identifier 'id'");
  EXPECT_EQ(vtt_error("WEBVTT\n\nid\nnot timing\n"),
            "t.vtt:4:1: expected a timing line 'hh:mm:ss,mmm --> hh:mm:ss,mmm', got 'not timing'");
  EXPECT_EQ(vtt_error("WEBVTT\n\n00:02.000 --> 00:01.000\nx\n"),
            "t.vtt:3:15: cue ends at 1.000 s, not after its start at 2.000 s");
}

TEST(Subtitles, BinaryAndBadUtf8Refused) {
  EXPECT_EQ(srt_error(std::string_view("1\n00:00:01,000 --> 00:00:02,000\nab\0c\n", 36)),
            "t.srt:3:3: binary data (byte 0): expected subtitle text");
  EXPECT_EQ(srt_error("1\n00:00:01,000 --> 00:00:02,000\ncaf\xC3\n"),
            "t.srt:3:4: invalid UTF-8: expected subtitle text in UTF-8");
  EXPECT_EQ(srt_error("\x89PNG\r\n\x1a\n"), "t.srt:1:1: invalid UTF-8: expected subtitle text in UTF-8");
  EXPECT_EQ(srt_error("PNG\r\n\x1a\n"), "t.srt:2:1: binary data (byte 26): expected subtitle text");
  // Accented text is fine.
  EXPECT_EQ(parse_srt("1\n00:00:01,000 --> 00:00:02,000\ncafé\n", "t.srt").cues.at(0).text, "café");
}

TEST(Subtitles, OversizedRefused) {
  const std::string big(kMaxSubtitleBytes + 1, '\n');
  EXPECT_NE(srt_error(big).find("bytes; the limit is 20971520"), std::string::npos);
  const auto path = std::filesystem::temp_directory_path() / "gestura_subtitles_big.srt";
  std::ofstream(path, std::ios::binary) << big;
  try {
    read_subtitles(path.string());
    ADD_FAILURE() << "oversized file accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the limit is 20971520"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Subtitles, ReadByExtension) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto vtt = dir / "gestura_subtitles_case.VTT";
  std::ofstream(vtt, std::ios::binary) << "WEBVTT\n\n00:01.000 --> 00:02.000\nHi\n";
  EXPECT_EQ(read_subtitles(vtt.string()).cues.at(0).text, "Hi");
  std::filesystem::remove(vtt);
  EXPECT_THROW(read_subtitles((dir / "x.txt").string()), Error);
  EXPECT_THROW(read_subtitles((dir / "gestura_no_such_file.srt").string()), Error);
}

// Random bytes and random mutations of a valid file: parsing either succeeds with sane cues or
// throws gestura::Error — never anything else.
TEST(Subtitles, FuzzNeverCrashes) {
  const std::string seed_srt = "1\r\n00:00:01,000 --> 00:00:02,500\r\n<i>Hello</i> &amp; {\\an8}bye\r\n\r\n"
                               "2\n00:00:03.000 --> 00:00:04,000 X1:1\nTwo\nlines\n";
  const std::string seed_vtt = "WEBVTT\n\nNOTE x\n\nid\n00:01.000 --> 00:02.000 align:start\n<v A>Hi</v>\n";
  std::mt19937 rng(20261121);
  const std::string alphabet = "0123456789:,.-> \n\r<>{}\\&;WEBVTTNOTE\xC3\xA9\xFF";
  int parsed = 0, refused = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    std::string text = iter % 2 ? seed_srt : seed_vtt;
    const int edits = 1 + static_cast<int>(rng() % 6);
    for (int e = 0; e < edits; ++e) {
      const std::size_t pos = text.empty() ? 0 : rng() % text.size();
      switch (rng() % 4) {
        case 0: if (!text.empty()) text.erase(pos, 1 + rng() % 4); break;
        case 1: text.insert(pos, 1, alphabet[rng() % alphabet.size()]); break;
        case 2: if (!text.empty()) text[pos] = static_cast<char>(rng() % 256); break;
        default: text.insert(pos, text.substr(rng() % (text.size() + 1), rng() % 12)); break;
      }
    }
    if (iter % 10 == 0) {  // pure noise
      text.resize(rng() % 200);
      for (char& c : text) c = static_cast<char>(rng() % 256);
    }
    for (const SubtitleFormat format : {SubtitleFormat::Srt, SubtitleFormat::WebVtt}) {
      try {
        const Subtitles s = parse_subtitles(text, format, "fuzz");
        for (const SubtitleCue& c : s.cues) {
          ASSERT_GE(c.start, 0.0);
          ASSERT_GT(c.end, c.start);
        }
        ++parsed;
      } catch (const Error& e) {
        ASSERT_NE(std::string(e.what()).find("fuzz"), std::string::npos) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GT(parsed, 100);   // the mutations are mild enough that many still parse
  EXPECT_GT(refused, 100);  // and harsh enough that many do not
}
