#include "gestura/io/bap.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <fstream>
#include <sstream>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {
namespace {

struct Field {
  std::string_view text;
  int column;  // 1-based
};

// Line-by-line reader that skips blank lines and remembers where each field was.
class Lines {
 public:
  Lines(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  // The next non-blank line split into fields; false at the end of the text.
  bool next(std::vector<Field>& fields) {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      const std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      fields.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) fields.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
      }
      if (!fields.empty()) return true;
    }
    return false;
  }
  [[noreturn]] void fail(int column, const std::string& message) const {
    throw Error(SourceLocation{source_, line_, column}, message);
  }
  int line() const { return line_; }

 private:
  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

template <class T>
bool parse_number(std::string_view text, T& out) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

BapFile read_bap(std::string_view text, const std::string& source) {
  Lines lines(text, source);
  std::vector<Field> f;
  BapFile file;
  if (!lines.next(f)) throw Error(SourceLocation{source, 1, 1}, "empty BAP file: expected a header 'version name fps frame_count'");
  if (f.size() != 4) lines.fail(1, "header needs 4 fields 'version name fps frame_count', found " + std::to_string(f.size()));
  file.version = std::string(f[0].text);
  file.name = std::string(f[1].text);
  if (!parse_number(f[2].text, file.fps) || !(file.fps > 0.0f && file.fps <= 10000.0f))
    lines.fail(f[2].column, "frame rate must be a number in (0, 10000], got '" + std::string(f[2].text) + "'");
  int frames = 0;
  if (!parse_number(f[3].text, frames) || frames < 0 || frames > kBapMaxFrames)
    lines.fail(f[3].column, "frame count must be a whole number in 0.." + std::to_string(kBapMaxFrames) + ", got '" + std::string(f[3].text) + "'");

  std::vector<std::int32_t> previous;
  for (int frame = 0; frame < frames; ++frame) {
    if (!lines.next(f))
      throw Error(SourceLocation{source, lines.line(), 0},
                  "file ends after " + std::to_string(frame) + " of the header's " + std::to_string(frames) + " frames");
    if (frame == 0) {
      if (f.size() != kBapBodyCount && f.size() != kBapExtendedCount)
        lines.fail(1, "mask has " + std::to_string(f.size()) + " flags; expected " + std::to_string(kBapBodyCount) + " or " +
                          std::to_string(kBapExtendedCount));
      file.parameter_count = static_cast<int>(f.size());
      previous.assign(f.size(), 0);
      file.values.reserve(static_cast<std::size_t>(std::min(frames, 10000)) * f.size());
    } else if (static_cast<int>(f.size()) != file.parameter_count) {
      lines.fail(1, "mask has " + std::to_string(f.size()) + " flags; the first frame had " + std::to_string(file.parameter_count));
    }
    int sent = 0;
    for (const Field& flag : f) {
      if (flag.text != "0" && flag.text != "1") lines.fail(flag.column, "mask flag must be 0 or 1, got '" + std::string(flag.text) + "'");
      file.mask.push_back(flag.text == "1");
      sent += flag.text == "1";
    }
    if (!lines.next(f))
      throw Error(SourceLocation{source, lines.line(), 0}, "file ends before the values of frame " + std::to_string(frame));
    int number = 0;
    if (!parse_number(f[0].text, number) || number != frame)
      lines.fail(f[0].column, "expected frame number " + std::to_string(frame) + ", got '" + std::string(f[0].text) + "'");
    if (static_cast<int>(f.size()) - 1 != sent)
      lines.fail(f.back().column, "frame " + std::to_string(frame) + ": mask sends " + std::to_string(sent) + " values, line has " +
                                      std::to_string(f.size() - 1));
    const std::size_t mask_at = file.mask.size() - static_cast<std::size_t>(file.parameter_count);
    std::size_t k = 1;
    for (int p = 0; p < file.parameter_count; ++p) {
      if (!file.mask[mask_at + static_cast<std::size_t>(p)]) continue;
      std::int32_t v = 0;
      if (!parse_number(f[k].text, v))
        lines.fail(f[k].column, "BAP " + std::to_string(p + 1) + ": expected a 32-bit integer, got '" + std::string(f[k].text) + "'");
      previous[static_cast<std::size_t>(p)] = v;
      ++k;
    }
    file.values.insert(file.values.end(), previous.begin(), previous.end());
  }
  if (lines.next(f)) lines.fail(f[0].column, "more lines than the header's " + std::to_string(frames) + " frames");
  return file;
}

BapFile load_bap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  return read_bap(text.str(), path);
}

std::string write_bap(const BapFile& file) {
  const int n = file.parameter_count, frames = file.frame_count();
  if (n != kBapBodyCount && n != kBapExtendedCount) throw Error("write_bap: parameter count must be 186 or 296");
  std::vector<std::uint8_t> used(static_cast<std::size_t>(n), 0);
  for (std::size_t i = 0; i < file.values.size(); ++i)
    if (file.values[i] != 0) used[i % static_cast<std::size_t>(n)] = 1;
  std::string mask;
  for (int p = 0; p < n; ++p) mask += (p ? " " : ""), mask += used[static_cast<std::size_t>(p)] ? '1' : '0';
  std::ostringstream out;
  out << file.version << ' ' << file.name << ' ' << file.fps << ' ' << frames << '\n';
  for (int f = 0; f < frames; ++f) {
    out << mask << '\n' << f;
    for (int p = 0; p < n; ++p)
      if (used[static_cast<std::size_t>(p)]) out << ' ' << file.values[static_cast<std::size_t>(f) * static_cast<std::size_t>(n) + static_cast<std::size_t>(p)];
    out << '\n';
  }
  return out.str();
}

void save_bap(const std::string& path, const BapFile& file) {
  write_file_atomically(path, write_bap(file));
}

namespace {

// For each BAP 1..186, the skeleton joint it turns (-1 when the skeleton lacks it).
std::vector<int> bap_joints(const Skeleton& skeleton) {
  std::vector<int> joints;
  for (const BapInfo& info : bap_table()) joints.push_back(skeleton.find(info.joint));
  return joints;
}

}  // namespace

Clip bap_to_clip(const BapFile& file, const Skeleton& skeleton) {
  const std::vector<int> joints = bap_joints(skeleton);
  const int frames = file.frame_count();
  const std::size_t n = static_cast<std::size_t>(file.parameter_count);
  Clip clip;
  clip.name = file.name;
  clip.duration = frames > 1 ? static_cast<float>(frames - 1) / file.fps : 0.0f;
  clip.resize_joints(skeleton.size());
  std::vector<vec3> angles(skeleton.size()), offsets(skeleton.size());
  std::vector<std::uint8_t> turned(skeleton.size(), 0), moved(skeleton.size(), 0);
  for (int f = 0; f < frames; ++f) {
    std::fill(angles.begin(), angles.end(), vec3(0.0f));
    std::fill(offsets.begin(), offsets.end(), vec3(0.0f));
    for (std::size_t b = 0; b < joints.size(); ++b) {
      const int j = joints[b];
      if (j < 0) continue;
      const BapInfo& info = bap_table()[b];
      const double v = static_cast<double>(file.values[static_cast<std::size_t>(f) * n + b]);
      if (info.translation) offsets[static_cast<std::size_t>(j)][info.axis] = static_cast<float>(v * kBapLengthUnit), moved[static_cast<std::size_t>(j)] = 1;
      else angles[static_cast<std::size_t>(j)][info.axis] = static_cast<float>(v * kBapAngleUnit), turned[static_cast<std::size_t>(j)] = 1;
    }
    const float t = static_cast<float>(f) / file.fps;
    for (std::size_t j = 0; j < skeleton.size(); ++j) {
      if (turned[j]) clip.rotations[j].add(t, joint_rotation(skeleton, static_cast<int>(j), angles[j]));
      if (moved[j]) clip.translations[j].add(t, skeleton.rest_translations[j] + offsets[j]);
    }
  }
  for (QuatTrack& track : clip.rotations) make_continuous(track);
  return clip;
}

BapFile clip_to_bap(const Clip& clip, const Skeleton& skeleton, float fps, const std::string& name) {
  if (!(fps > 0.0f && fps <= 10000.0f)) throw Error("clip_to_bap: frame rate must be in (0, 10000]");
  check_output_length(clip.duration, fps, "BAP clip '" + name + "'");
  const double count = std::floor(static_cast<double>(clip.duration) * fps + 0.5) + 1.0;
  if (count > kBapMaxFrames) throw Error("clip_to_bap: more than " + std::to_string(kBapMaxFrames) + " frames");
  const int frames = static_cast<int>(count);
  const std::vector<int> joints = bap_joints(skeleton);
  BapFile file;
  file.name = name.empty() ? "gestura" : name;
  file.fps = fps;
  file.parameter_count = kBapBodyCount;
  file.values.assign(static_cast<std::size_t>(frames) * kBapBodyCount, 0);
  file.mask.assign(file.values.size(), 1);
  const Pose rest = rest_pose(skeleton);
  Pose pose = rest;
  std::vector<vec3> angles(skeleton.size());
  auto to_units = [](double value, double unit) {
    return static_cast<std::int32_t>(std::clamp(std::llround(value / unit), static_cast<long long>(INT32_MIN), static_cast<long long>(INT32_MAX)));
  };
  for (int f = 0; f < frames; ++f) {
    sample_clip(clip, std::min(static_cast<float>(f) / fps, clip.duration), WrapMode::Clamp, rest, pose);
    for (std::size_t j = 0; j < skeleton.size(); ++j) angles[j] = joint_angles(skeleton, static_cast<int>(j), pose.rotations[j]);
    for (std::size_t b = 0; b < joints.size(); ++b) {
      const int j = joints[b];
      if (j < 0) continue;
      const BapInfo& info = bap_table()[b];
      const std::size_t ju = static_cast<std::size_t>(j);
      file.values[static_cast<std::size_t>(f) * kBapBodyCount + b] =
          info.translation ? to_units(pose.translations[ju][info.axis] - skeleton.rest_translations[ju][info.axis], kBapLengthUnit)
                           : to_units(angles[ju][info.axis], kBapAngleUnit);
    }
  }
  return file;
}

}  // namespace gestura
