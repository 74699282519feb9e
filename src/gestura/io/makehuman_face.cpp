#include "gestura/io/makehuman_face.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "gestura/io/makehuman_files.hpp"

namespace gestura {

using nlohmann::json;
using namespace makehuman_detail;

int FacePoseUnits::find_unit(std::string_view name) const {
  for (std::size_t i = 0; i < units.size(); ++i)
    if (units[i] == name) return static_cast<int>(i);
  return -1;
}

int FacePoseUnits::find_bone(std::string_view name) const {
  for (std::size_t i = 0; i < bones.size(); ++i)
    if (bones[i] == name) return static_cast<int>(i);
  return -1;
}

namespace {

// Just enough BVH for the pose-unit file: joint names and channel lists from HIERARCHY, then the
// frames. Tokens are whitespace separated; errors name file:line.
class BvhTokens {
 public:
  BvhTokens(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  std::string_view next() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= text_.size()) fail("unexpected end of file");
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  void expect(std::string_view word) {
    const std::string_view got = next();
    if (got != word) fail("expected '" + std::string(word) + "', found '" + std::string(got) + "'");
  }
  float number() {
    const std::string_view t = next();
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(value))
      fail("expected a number, found '" + std::string(t) + "'");
    return value;
  }
  int integer() {
    const float value = number();
    if (value < 0.0f || value > 1e6f || value != std::floor(value)) fail("expected a count");
    return static_cast<int>(value);
  }
  [[noreturn]] void fail(const std::string& message) const { throw Error(SourceLocation{name_, line_}, message); }

 private:
  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

struct BvhChannels {
  std::vector<std::string> joints;
  std::vector<std::vector<char>> channels;  // per joint: 'x','y','z' rotations, 'p' a position channel
};

void read_joint(BvhTokens& in, BvhChannels& out, int depth) {
  if (depth > 256) in.fail("hierarchy nested too deeply");
  out.joints.emplace_back(in.next());
  const std::size_t me = out.joints.size() - 1;
  out.channels.emplace_back();
  in.expect("{");
  for (;;) {
    const std::string_view t = in.next();
    if (t == "}") return;
    if (t == "OFFSET") {
      in.number();
      in.number();
      in.number();
    } else if (t == "CHANNELS") {
      const int n = in.integer();
      if (n > 6) in.fail("more than 6 channels");
      for (int c = 0; c < n; ++c) {
        const std::string_view ch = in.next();
        if (ch == "Xrotation") out.channels[me].push_back('x');
        else if (ch == "Yrotation") out.channels[me].push_back('y');
        else if (ch == "Zrotation") out.channels[me].push_back('z');
        else if (ch == "Xposition" || ch == "Yposition" || ch == "Zposition") out.channels[me].push_back('p');
        else in.fail("unknown channel '" + std::string(ch) + "'");
      }
    } else if (t == "JOINT") {
      read_joint(in, out, depth + 1);
    } else if (t == "End") {
      in.expect("Site");
      in.expect("{");
      in.expect("OFFSET");
      in.number();
      in.number();
      in.number();
      in.expect("}");
    } else {
      in.fail("unexpected '" + std::string(t) + "' in joint " + out.joints[me]);
    }
  }
}

}  // namespace

FacePoseUnits parse_makehuman_face_units(std::string_view json_text, const std::string& json_name,
                                         std::string_view bvh_text, const std::string& bvh_name) {
  FacePoseUnits out;
  const json doc = parse_json(json_text, json_name);
  const json& mapping = member(doc, "framemapping", json::value_t::array, json_name, "");
  for (std::size_t i = 0; i < mapping.size(); ++i) {
    if (!mapping[i].is_string()) field_error(json_name, "framemapping[" + std::to_string(i) + "]", "expected a name");
    out.units.push_back(mapping[i].get<std::string>());
  }

  BvhTokens in(bvh_text, bvh_name);
  in.expect("HIERARCHY");
  in.expect("ROOT");
  BvhChannels channels;
  read_joint(in, channels, 0);
  in.expect("MOTION");
  in.expect("Frames:");
  const int frames = in.integer();
  in.expect("Frame");
  in.expect("Time:");
  in.number();
  if (static_cast<std::size_t>(frames) != out.units.size())
    in.fail(std::to_string(frames) + " frames but " + json_name + " names " + std::to_string(out.units.size()));

  out.bones = channels.joints;
  out.rotations.reserve(out.units.size() * out.bones.size());
  // BVH (Z up, facing −Y) → ours (Y up, facing +Z): (x, y, z) → (x, z, −y), a −90° turn about X.
  const quat to_ours = glm::angleAxis(-kPi / 2.0f, vec3(1, 0, 0));
  const quat to_bvh = glm::inverse(to_ours);
  for (int f = 0; f < frames; ++f) {
    for (std::size_t j = 0; j < channels.joints.size(); ++j) {
      quat q(1.0f, 0.0f, 0.0f, 0.0f);
      for (char c : channels.channels[j]) {
        const float value = in.number();
        if (c == 'p') continue;
        const vec3 axis(c == 'x' ? 1.0f : 0.0f, c == 'y' ? 1.0f : 0.0f, c == 'z' ? 1.0f : 0.0f);
        q = q * glm::angleAxis(deg(value), axis);  // BVH: channels compose left to right
      }
      out.rotations.push_back(glm::normalize(to_ours * q * to_bvh));
    }
  }
  return out;
}

FacePoseUnits read_makehuman_face_units(const std::string& json_path, const std::string& bvh_path) {
  return parse_makehuman_face_units(read_file(json_path), json_path, read_file(bvh_path), bvh_path);
}

FaceExpression parse_makehuman_expression(std::string_view json_text, const std::string& name) {
  const json doc = parse_json(json_text, name);
  FaceExpression out;
  out.name = member(doc, "name", json::value_t::string, name, "").get<std::string>();
  const json& units = member(doc, "unit_poses", json::value_t::object, name, "");
  for (const auto& [unit, weight] : units.items()) {
    if (!weight.is_number() || !std::isfinite(weight.get<float>()))
      field_error(name, "unit_poses." + unit, "expected a number");
    out.units.push_back(unit);
    out.weights.push_back(weight.get<float>());
  }
  return out;
}

FaceExpression read_makehuman_expression(const std::string& path) {
  return parse_makehuman_expression(read_file(path), path);
}

std::vector<FaceExpression> read_makehuman_expressions(const std::string& directory) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".mhpose") paths.push_back(entry.path().string());
  if (ec) throw Error(SourceLocation{directory}, "cannot list directory: " + ec.message());
  std::sort(paths.begin(), paths.end());
  std::vector<FaceExpression> out;
  for (const std::string& path : paths) out.push_back(read_makehuman_expression(path));
  return out;
}

void expression_rotations(const FacePoseUnits& units, const FaceExpression& expression, std::span<quat> out) {
  if (out.size() != units.bones.size())
    throw Error("expression_rotations: " + std::to_string(out.size()) + " outputs for " +
                std::to_string(units.bones.size()) + " bones");
  std::fill(out.begin(), out.end(), quat(1.0f, 0.0f, 0.0f, 0.0f));
  const quat identity(1.0f, 0.0f, 0.0f, 0.0f);
  for (std::size_t i = 0; i < expression.units.size(); ++i) {
    const int u = units.find_unit(expression.units[i]);
    if (u < 0)
      throw Error("expression '" + expression.name + "': unknown pose unit '" + expression.units[i] + "'");
    const std::span<const quat> unit = units.unit(static_cast<std::size_t>(u));
    for (std::size_t b = 0; b < out.size(); ++b)
      out[b] = glm::normalize(glm::slerp(identity, unit[b], expression.weights[i]) * out[b]);
  }
}

}  // namespace gestura
