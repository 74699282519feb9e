#include "gestura/io/subtitles.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <cctype>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"

namespace gestura {
namespace {

struct Line {
  std::string_view text;
  int number = 0;  // 1-based
};

bool is_blank(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t'; });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string quoted(std::string_view s) {
  std::string out = "'";
  for (char c : s.substr(0, 40)) {
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  if (s.size() > 40) out += "…";
  return out + "'";
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}

// Splits into lines (LF, CRLF or lone CR), after refusing oversized text, binary bytes and bad
// UTF-8 with the place they occur. A leading BOM is dropped.
std::vector<Line> split_lines(std::string_view text, const std::string& source) {
  if (text.size() > kMaxSubtitleBytes)
    throw Error({source, 0, 0, -1}, "subtitle file is " + std::to_string(text.size()) +
                                        " bytes; the limit is " + std::to_string(kMaxSubtitleBytes));
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  std::vector<Line> lines;
  std::size_t begin = 0;
  int number = 1;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const bool end = i == text.size();
    const char c = end ? '\n' : text[i];
    if (c != '\n' && c != '\r') continue;
    const std::string_view line = text.substr(begin, i - begin);
    for (std::size_t p = 0; p < line.size();) {
      const auto byte = static_cast<unsigned char>(line[p]);
      const SourceLocation at{source, number, static_cast<int>(p) + 1, -1};
      if ((byte < 0x20 && byte != '\t') || byte == 0x7f)
        throw Error(at, "binary data (byte " + std::to_string(byte) + "): expected subtitle text");
      try {
        utf8::next(line, p);
      } catch (const Error&) {
        throw Error(at, "invalid UTF-8: expected subtitle text in UTF-8");
      }
    }
    if (!end || !line.empty()) lines.push_back({line, number});
    ++number;
    if (!end && c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    begin = i + 1;
  }
  return lines;
}

bool parse_digits(std::string_view s, std::size_t min_len, std::size_t max_len, long long& value) {
  if (s.size() < min_len || s.size() > max_len) return false;
  value = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    value = value * 10 + (c - '0');
  }
  return true;
}

std::optional<int> parse_cue_number(std::string_view s) {
  long long v = 0;
  if (!parse_digits(trim(s), 1, 9, v)) return std::nullopt;
  return static_cast<int>(v);
}

struct Timing {
  double start = 0.0, end = 0.0;
};

// "start --> end [settings]"; throws naming the column of the bad part.
Timing parse_timing(const Line& line, const std::string& source) {
  const std::string_view s = line.text;
  const std::size_t arrow = s.find("-->");
  if (arrow == std::string_view::npos)
    throw Error({source, line.number, 1, -1},
                "expected a timing line 'hh:mm:ss,mmm --> hh:mm:ss,mmm', got " + quoted(s));
  const std::string_view left = trim(s.substr(0, arrow));
  std::size_t end_begin = arrow + 3;
  while (end_begin < s.size() && (s[end_begin] == ' ' || s[end_begin] == '\t')) ++end_begin;
  std::size_t end_stop = end_begin;
  while (end_stop < s.size() && s[end_stop] != ' ' && s[end_stop] != '\t') ++end_stop;
  const std::string_view right = s.substr(end_begin, end_stop - end_begin);
  Timing t;
  const int start_col = static_cast<int>(left.empty() ? 1 : left.data() - s.data() + 1);
  if (!parse_subtitle_time(left, t.start))
    throw Error({source, line.number, start_col, -1},
                "bad start time " + quoted(left) + ": expected [hh:]mm:ss,mmm");
  if (!parse_subtitle_time(right, t.end))
    throw Error({source, line.number, static_cast<int>(end_begin) + 1, -1},
                "bad end time " + quoted(right) + ": expected [hh:]mm:ss,mmm");
  if (!(t.end > t.start))
    throw Error({source, line.number, static_cast<int>(end_begin) + 1, -1},
                "cue ends at " + seconds_text(t.end) + ", not after its start at " + seconds_text(t.start));
  return t;
}

bool is_timing_line(std::string_view s) {
  const std::size_t arrow = s.find("-->");
  if (arrow == std::string_view::npos) return false;
  double t = 0.0;
  return parse_subtitle_time(trim(s.substr(0, arrow)), t);
}

std::string join_text(const std::vector<Line>& lines, std::size_t first, std::size_t last) {
  std::string joined;
  for (std::size_t i = first; i < last; ++i) {
    if (i > first) joined += '\n';
    joined += lines[i].text;
  }
  return strip_subtitle_markup(joined);
}

Subtitles finish(std::vector<SubtitleCue> cues, const std::string& source) {
  Subtitles out;
  for (const SubtitleCue& c : cues)
    if (c.text.empty())
      out.notes.push_back(source + ":" + std::to_string(c.line) + ": cue " + std::to_string(c.index) +
                          " has no text");
  const bool ordered = std::is_sorted(cues.begin(), cues.end(), [](const auto& a, const auto& b) {
    return a.start < b.start;
  });
  if (!ordered) {
    out.notes.push_back(source + ": cues are not in time order; sorted by start time");
    std::stable_sort(cues.begin(), cues.end(), [](const auto& a, const auto& b) { return a.start < b.start; });
  }
  for (std::size_t i = 1; i < cues.size(); ++i)
    if (cues[i].start < cues[i - 1].end)
      out.notes.push_back(source + ":" + std::to_string(cues[i].line) + ": cue " + std::to_string(cues[i].index) +
                          " starts at " + seconds_text(cues[i].start) + ", before cue " +
                          std::to_string(cues[i - 1].index) + " ends at " + seconds_text(cues[i - 1].end) +
                          " (overlap)");
  out.cues = std::move(cues);
  return out;
}

bool starts_with_word(std::string_view s, std::string_view word) {
  return s.starts_with(word) && (s.size() == word.size() || s[word.size()] == ' ' || s[word.size()] == '\t');
}

}  // namespace

bool parse_subtitle_time(std::string_view text, double& seconds) {
  std::vector<std::string_view> fields;
  std::size_t begin = 0;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == ':') fields.push_back(text.substr(begin, i - begin)), begin = i + 1;
  if (fields.size() != 2 && fields.size() != 3) return false;
  long long hours = 0, minutes = 0, secs = 0, frac = 0;
  if (fields.size() == 3 && !parse_digits(fields[0], 1, 5, hours)) return false;
  if (!parse_digits(fields[fields.size() - 2], 1, 2, minutes) || minutes >= 60) return false;
  const std::string_view last = fields.back();
  const std::size_t sep = last.find_first_of(",.");
  if (sep == std::string_view::npos) return false;
  const std::string_view frac_text = last.substr(sep + 1);
  if (!parse_digits(last.substr(0, sep), 1, 2, secs) || secs >= 60) return false;
  if (!parse_digits(frac_text, 1, 3, frac)) return false;
  double fraction = static_cast<double>(frac);
  for (std::size_t i = 0; i < frac_text.size(); ++i) fraction /= 10.0;
  seconds = static_cast<double>(hours * 3600 + minutes * 60 + secs) + fraction;
  return true;
}

std::string strip_subtitle_markup(std::string_view text) {
  static constexpr std::pair<std::string_view, std::string_view> kEntities[] = {
      {"&amp;", "&"}, {"&lt;", "<"},       {"&gt;", ">"},       {"&nbsp;", " "},
      {"&quot;", "\""}, {"&apos;", "'"}, {"&lrm;", ""},       {"&rlm;", ""}};
  std::string out;
  bool pending_space = false;
  auto put = [&](std::string_view piece) {
    for (char c : piece) {
      if (c == ' ' || c == '\t' || c == '\n') {
        pending_space = !out.empty();
        continue;
      }
      if (pending_space) out += ' ', pending_space = false;
      out += c;
    }
  };
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '<') {
      const std::size_t close = text.find('>', i);
      if (close != std::string_view::npos) {
        i = close + 1;
        continue;
      }
    } else if (c == '{' && i + 1 < text.size() && text[i + 1] == '\\') {
      const std::size_t close = text.find('}', i);
      if (close != std::string_view::npos) {
        i = close + 1;
        continue;
      }
    } else if (c == '&') {
      bool decoded = false;
      for (const auto& [name, value] : kEntities)
        if (text.substr(i).starts_with(name)) {
          put(value.empty() ? std::string_view{} : value);
          if (value == " ") pending_space = !out.empty();
          i += name.size();
          decoded = true;
          break;
        }
      if (decoded) continue;
    }
    put(text.substr(i, 1));
    ++i;
  }
  return out;
}

Subtitles parse_srt(std::string_view text, const std::string& source) {
  const std::vector<Line> lines = split_lines(text, source);
  std::vector<SubtitleCue> cues;
  std::size_t i = 0;
  while (i < lines.size()) {
    if (is_blank(lines[i].text)) {
      ++i;
      continue;
    }
    SubtitleCue cue;
    cue.index = static_cast<int>(cues.size()) + 1;
    if (const auto number = parse_cue_number(lines[i].text)) {
      cue.index = *number;
      ++i;
      if (i == lines.size() || is_blank(lines[i].text))
        throw Error({source, i < lines.size() ? lines[i].number : lines[i - 1].number + 1, 1, -1},
                    "expected a timing line 'hh:mm:ss,mmm --> hh:mm:ss,mmm' after cue number " +
                        std::to_string(cue.index));
    } else if (lines[i].text.find("-->") == std::string_view::npos) {
      throw Error({source, lines[i].number, 1, -1},
                  "expected a cue number or a timing line, got " + quoted(lines[i].text));
    }
    const Timing timing = parse_timing(lines[i], source);
    cue.start = timing.start, cue.end = timing.end, cue.line = lines[i].number;
    const std::size_t first = ++i;
    // Text runs to a blank line; a "number, timing line" pair also starts the next cue, for files
    // that lost their blank separators.
    while (i < lines.size() && !is_blank(lines[i].text) &&
           !(i + 1 < lines.size() && parse_cue_number(lines[i].text) && is_timing_line(lines[i + 1].text)))
      ++i;
    cue.text = join_text(lines, first, i);
    cues.push_back(std::move(cue));
  }
  return finish(std::move(cues), source);
}

Subtitles parse_webvtt(std::string_view text, const std::string& source) {
  const std::vector<Line> lines = split_lines(text, source);
  if (lines.empty() || !starts_with_word(lines[0].text, "WEBVTT"))
    throw Error({source, 1, 1, -1}, "expected the 'WEBVTT' header, got " +
                                        quoted(lines.empty() ? std::string_view{} : lines[0].text));
  std::size_t i = 0;
  while (i < lines.size() && !is_blank(lines[i].text)) ++i;  // header and its metadata lines
  std::vector<SubtitleCue> cues;
  while (i < lines.size()) {
    if (is_blank(lines[i].text)) {
      ++i;
      continue;
    }
    const std::string_view head = lines[i].text;
    if (head.find("-->") == std::string_view::npos &&
        (starts_with_word(head, "NOTE") || starts_with_word(trim(head), "STYLE") ||
         starts_with_word(trim(head), "REGION"))) {
      while (i < lines.size() && !is_blank(lines[i].text)) ++i;
      continue;
    }
    if (head.find("-->") == std::string_view::npos) {  // a cue identifier
      ++i;
      if (i == lines.size() || is_blank(lines[i].text))
        throw Error({source, i < lines.size() ? lines[i].number : lines[i - 1].number + 1, 1, -1},
                    "expected a timing line 'mm:ss.mmm --> mm:ss.mmm' after cue identifier " + quoted(head));
    }
    SubtitleCue cue;
    cue.index = static_cast<int>(cues.size()) + 1;
    const Timing timing = parse_timing(lines[i], source);
    cue.start = timing.start, cue.end = timing.end, cue.line = lines[i].number;
    const std::size_t first = ++i;
    while (i < lines.size() && !is_blank(lines[i].text)) ++i;
    cue.text = join_text(lines, first, i);
    cues.push_back(std::move(cue));
  }
  return finish(std::move(cues), source);
}

Subtitles parse_subtitles(std::string_view text, SubtitleFormat format, const std::string& source) {
  return format == SubtitleFormat::Srt ? parse_srt(text, source) : parse_webvtt(text, source);
}

Subtitles read_subtitles(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  SubtitleFormat format;
  if (ext == ".srt") format = SubtitleFormat::Srt;
  else if (ext == ".vtt") format = SubtitleFormat::WebVtt;
  else throw Error({path, 0, 0, -1}, "unknown subtitle extension '" + ext + "': expected .srt or .vtt");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw Error({path, 0, 0, -1}, "cannot read subtitle file: " + ec.message());
  if (size > kMaxSubtitleBytes)
    throw Error({path, 0, 0, -1}, "subtitle file is " + std::to_string(size) + " bytes; the limit is " +
                                      std::to_string(kMaxSubtitleBytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error({path, 0, 0, -1}, "cannot open subtitle file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_subtitles(buffer.str(), format, path);
}

}  // namespace gestura
