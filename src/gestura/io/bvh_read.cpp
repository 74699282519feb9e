// BVH reader: one pass over the text with an explicit joint stack (no recursion, so nesting depth
// cannot overflow the call stack), then the raw channel values are turned into clip tracks.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "gestura/anim/change_basis.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/text_cursor.hpp"

namespace gestura {

namespace {

class BvhReader {
 public:
  BvhReader(std::string_view text, const std::string& source, const BvhReadOptions& options)
      : in_(text, source), scale_(options.scale), z_up_(options.z_up) {}

  BvhFile read() {
    // Within 1e-6..1e6 every scaled value (at most 1e7 in the file) stays a finite float.
    if (!(scale_ >= 1e-6f && scale_ <= 1e6f)) throw Error(in_.source() + ": scale must lie in 1e-6..1e6");
    read_hierarchy();
    read_motion();
    build_clip();
    if (z_up_) change_basis(out_.skeleton, out_.clip, z_up_to_y_up());
    return std::move(out_);
  }

 private:
  Token expect(std::string_view word, std::string_view context) {
    const Token t = in_.next();
    if (!t.is(word))
      in_.fail(t, "expected '" + std::string(word) + "' " + std::string(context) + ", found " + found(t));
    return t;
  }

  // A token for messages; an empty one is the end of the line or of the file, whichever it is.
  std::string found(const Token& t) const { return describe(t, !in_.eof()); }

  double number(const Token& t, std::string_view what) {
    const auto v = parse_number(t.text);
    if (!v || std::abs(*v) > kBvhMaxMagnitude) bad_number(t, what);
    return *v;
  }

  [[noreturn]] void bad_number(const Token& t, std::string_view what) {
    if (parse_number(t.text))
      in_.fail(t, std::string(what) + " " + std::string(t.text) + " is out of range (limit ±1e7)");
    in_.fail(t, "expected a number for " + std::string(what) + ", found " + found(t));
  }

  // The joint name is the rest of the line up to a brace; names with blanks are kept (single spaced).
  std::string read_name(const Token& keyword) {
    std::string name;
    while (!in_.at_line_end() && !in_.peek().is("{")) {
      const Token part = in_.next_on_line();
      const auto is_control = [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7F; };
      if (std::any_of(part.text.begin(), part.text.end(), is_control))
        in_.fail(part, "joint name " + found(part) + " contains control characters");
      if (!name.empty()) name += ' ';
      name.append(part.text);
    }
    if (name.empty()) in_.fail(keyword, "expected a joint name after " + std::string(keyword.text));
    return name;
  }

  vec3 read_offset(std::string_view joint) {
    expect("OFFSET", "in joint '" + std::string(joint) + "'");
    vec3 offset;
    for (int a = 0; a < 3; ++a)
      offset[a] = static_cast<float>(number(in_.next(), "an OFFSET coordinate") * scale_);
    return offset;
  }

  BvhChannels read_channels(std::string_view joint) {
    expect("CHANNELS", "in joint '" + std::string(joint) + "' after its OFFSET");
    const Token count_token = in_.next();
    const auto count = parse_integer(count_token.text);
    if (!count || *count < 0 || *count > 6)
      in_.fail(count_token, "expected a channel count from 0 to 6, found " + found(count_token));
    BvhChannels channels;
    for (long long i = 0; i < *count; ++i) {
      const Token t = in_.next();
      int index = -1;
      for (int c = 0; c < 6; ++c)
        if (t.text == to_string(static_cast<BvhChannel>(c))) index = c;
      if (index < 0)
        in_.fail(t, "CHANNELS declares " + std::to_string(*count) + " channels; expected a channel name (" +
                        "Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation), found " + found(t));
      const auto channel = static_cast<BvhChannel>(index);
      if (std::find(channels.order.begin(), channels.order.begin() + channels.count, channel) !=
          channels.order.begin() + channels.count)
        in_.fail(t, "channel " + std::string(t.text) + " appears twice in joint '" + std::string(joint) + "'");
      channels.push(channel);
    }
    return channels;
  }

  int add_joint(const Token& at, std::string name, int parent, const vec3& offset, bool end_site) {
    if (out_.skeleton.size() >= static_cast<std::size_t>(kBvhMaxJoints))
      in_.fail(at, "too many joints (limit " + std::to_string(kBvhMaxJoints) + ")");
    if (!end_site) {
      const auto [it, fresh] = first_line_.emplace(name, at.line);
      if (!fresh)
        in_.fail(at, "duplicate joint name '" + name + "' (first at line " + std::to_string(it->second) + ")");
    }
    const int j = out_.skeleton.add_joint(std::move(name), parent, offset);
    out_.end_site.push_back(end_site ? 1 : 0);
    out_.channels.emplace_back();
    return j;
  }

  // ROOT/JOINT name { OFFSET x y z CHANNELS n ... — leaves the joint open on the stack.
  void open_joint(const Token& keyword, int parent) {
    std::string name = read_name(keyword);
    expect("{", "after " + std::string(keyword.text) + " " + name);
    const vec3 offset = read_offset(name);
    const BvhChannels channels = read_channels(name);
    const int j = add_joint(keyword, std::move(name), parent, offset, false);
    out_.channels[static_cast<std::size_t>(j)] = channels;
    JointDofs& dofs = out_.skeleton.dofs[static_cast<std::size_t>(j)];
    dofs.order = channels.rotation_order();
    for (int i = 0; i < channels.count; ++i)
      if (!is_position(channels[i])) dofs.axes |= static_cast<std::uint8_t>(1u << axis_of(channels[i]));
    // BVH carries no limits: the free axes may take any angle.
    dofs.min_angle = vec3(-kPi);
    dofs.max_angle = vec3(kPi);
    open_.push_back({j, keyword.line});
  }

  void read_end_site(const Token& end) {
    const Token site = in_.next();
    if (!site.is("Site")) in_.fail(site, "expected 'Site' after 'End', found " + found(site));
    expect("{", "after End Site");
    const int parent = open_.back().joint;
    const vec3 offset = read_offset(out_.skeleton.names[static_cast<std::size_t>(parent)] + " End Site");
    expect("}", "to close the End Site");
    add_joint(end, {}, parent, offset, true);  // named after the hierarchy is complete
  }

  void read_hierarchy() {
    expect("HIERARCHY", "at the start of a BVH file");
    root_ = expect("ROOT", "after HIERARCHY");
    open_joint(root_, -1);
    while (!open_.empty()) {
      const Token t = in_.next();
      if (t.is("JOINT")) {
        open_joint(t, open_.back().joint);
      } else if (t.is("End")) {
        read_end_site(t);
      } else if (t.is("}")) {
        open_.pop_back();
      } else {
        const OpenJoint& inner = open_.back();
        in_.fail(t, "expected JOINT, End Site or '}' in joint '" +
                        out_.skeleton.names[static_cast<std::size_t>(inner.joint)] + "' (opened at line " +
                        std::to_string(inner.line) + "), found " + found(t));
      }
    }
    name_end_sites();
  }

  // End sites are named "<parent>_end" once all joint names are known, so they never take a name
  // that a later joint uses.
  void name_end_sites() {
    auto& names = out_.skeleton.names;
    for (std::size_t j = 0; j < names.size(); ++j) {
      if (!out_.end_site[j]) continue;
      const std::string base = names[static_cast<std::size_t>(out_.skeleton.parents[j])] + "_end";
      std::string name = base;
      for (int k = 2; first_line_.count(name); ++k) name = base + "_" + std::to_string(k);
      first_line_.emplace(name, 0);
      names[j] = std::move(name);
    }
  }

  void read_motion() {
    const Token motion = in_.next();
    if (motion.is("ROOT"))
      in_.fail(motion, "a second ROOT; only BVH files with a single ROOT are supported (first ROOT at line " +
                           std::to_string(root_.line) + ")");
    if (!motion.is("MOTION")) in_.fail(motion, "expected MOTION after the hierarchy, found " + found(motion));

    const Token frames_label = expect("Frames:", "after MOTION");
    const Token frames_token = in_.next_on_line();
    const auto frames = parse_integer(frames_token.text);
    if (!frames || *frames < 0)
      in_.fail(frames_token, "expected a frame count (a whole number ≥ 0), found " + found(frames_token));
    if (*frames > kBvhMaxFrames)
      in_.fail(frames_token, "frame count " + std::to_string(*frames) + " is over the limit of " +
                                 std::to_string(kBvhMaxFrames));
    out_.frame_count = static_cast<int>(*frames);

    expect("Frame", "(Frame Time:) after the frame count");
    const Token time_label = in_.next_on_line();
    if (!time_label.is("Time:")) in_.fail(time_label, "expected 'Time:' after 'Frame', found " + found(time_label));
    const Token time_token = in_.next_on_line();
    const double frame_time = number(time_token, "the frame time");
    // At least a microsecond keeps every frame time of the longest allowed clip distinct as a float.
    if (!(frame_time >= 1e-6))
      in_.fail(time_token, "the frame time must be positive (at least 1e-6 s), found " + std::string(time_token.text));
    out_.frame_time = static_cast<float>(frame_time);
    if (!in_.at_line_end()) {
      const Token extra = in_.next_on_line();
      in_.fail(extra, "unexpected " + found(extra) + " after the frame time");
    }
    in_.skip_line_end();
    read_frames(frames_label.line);

    if (!in_.at_end()) {
      const Token extra = in_.next();
      in_.fail(extra, "unexpected " + found(extra) + " after the " + std::to_string(out_.frame_count) +
                          " frames declared at line " + std::to_string(frames_label.line) +
                          " (more frames than declared?)");
    }
  }

  // One frame per line, exactly one value per channel; blank lines are skipped.
  void read_frames(int frames_line) {
    const int per_frame = out_.channel_count();
    if (per_frame == 0) return;
    std::vector<float> column_scale;  // scale for position columns, 1 for angles
    for (const BvhChannels& c : out_.channels)
      for (int i = 0; i < c.count; ++i) column_scale.push_back(is_position(c[i]) ? scale_ : 1.0f);
    const auto n = static_cast<std::size_t>(per_frame);
    values_.reserve(std::min<std::size_t>(static_cast<std::size_t>(out_.frame_count), 1u << 16) * n);
    for (int f = 0; f < out_.frame_count; ++f) {
      while (in_.at_line_end() && !in_.eof()) in_.skip_line_end();
      if (in_.eof())
        in_.fail(in_.next(), "the file ends after " + std::to_string(f) + " frames but line " +
                                 std::to_string(frames_line) + " declares " + std::to_string(out_.frame_count));
      std::size_t count = 0;
      for (Token t = in_.next_on_line(); !t.empty(); t = in_.next_on_line()) {
        if (count == n)
          in_.fail(t, "frame " + std::to_string(f + 1) + " has more than " + std::to_string(n) +
                          " values (one per channel)");
        const auto v = parse_number(t.text);
        if (!v || std::abs(*v) > kBvhMaxMagnitude) [[unlikely]]
          bad_number(t, "channel " + column_name(count));
        values_.push_back(static_cast<float>(*v * column_scale[count]));
        ++count;
      }
      if (count < n)
        in_.fail(in_.next_on_line(), "frame " + std::to_string(f + 1) + " has " + std::to_string(count) +
                                         " values, expected " + std::to_string(n) + " (one per channel)");
      in_.skip_line_end();
    }
  }

  std::string column_name(std::size_t column) const {
    for (std::size_t j = 0; j < out_.channels.size(); ++j) {
      const BvhChannels& c = out_.channels[j];
      if (column < c.count) return out_.skeleton.names[j] + "." + std::string(to_string(c[static_cast<int>(column)]));
      column -= c.count;
    }
    return "?";
  }

  void build_clip() {
    const auto frames = static_cast<std::size_t>(out_.frame_count);
    const auto per_frame = static_cast<std::size_t>(out_.channel_count());
    auto time_of = [&](std::size_t f) { return static_cast<float>(static_cast<double>(f) * out_.frame_time); };
    Clip& clip = out_.clip;
    clip.name = in_.source();
    if (const auto slash = clip.name.find_last_of('/'); slash != std::string::npos) clip.name.erase(0, slash + 1);
    if (const auto dot = clip.name.rfind('.'); dot != std::string::npos && dot > 0) clip.name.erase(dot);
    clip.duration = frames > 1 ? time_of(frames - 1) : 0.0f;
    clip.resize_joints(out_.skeleton.size());
    if (per_frame == 0) return;  // no tracks (and no key times for a declared-but-empty motion)

    std::vector<float> times(frames);
    for (std::size_t f = 0; f < frames; ++f) times[f] = time_of(f);

    std::vector<vec3> angles(frames), positions(frames);
    std::size_t column = 0;
    for (std::size_t j = 0; j < out_.channels.size(); ++j) {
      const BvhChannels& c = out_.channels[j];
      if (c.count == 0) continue;
      std::fill(angles.begin(), angles.end(), vec3(0.0f));
      std::fill(positions.begin(), positions.end(), out_.skeleton.rest_translations[j]);
      for (int i = 0; i < c.count; ++i, ++column) {
        const int axis = axis_of(c[i]);
        for (std::size_t f = 0; f < frames; ++f) {
          const float v = values_[f * per_frame + column];
          if (is_position(c[i])) positions[f][axis] += v;
          else angles[f][axis] = deg(v);
        }
      }
      if (c.has_rotation())
        clip.rotations[j] = rotation_track_from_euler(times, angles, c.rotation_order(), Interpolation::Slerp);
      if (c.has_position()) {
        Vec3Track& track = clip.translations[j];
        track.interpolation = Interpolation::Linear;
        track.times = times;
        track.values = positions;
      }
    }
  }

  struct OpenJoint {
    int joint;
    int line;
  };

  TextCursor in_;
  float scale_;
  bool z_up_;
  BvhFile out_;
  Token root_;
  std::vector<OpenJoint> open_;
  std::unordered_map<std::string, int> first_line_;  // joint name → line it was declared on
  std::vector<float> values_;                        // frame-major channel values, positions scaled
};

}  // namespace

BvhFile read_bvh(std::string_view text, const std::string& source, const BvhReadOptions& options) {
  return BvhReader(text, source, options).read();
}

BvhFile load_bvh(const std::string& path, const BvhReadOptions& options) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(path + ": cannot open the file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw Error(path + ": cannot read the file");
  return read_bvh(text.view(), path, options);
}

}  // namespace gestura
