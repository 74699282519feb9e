#pragma once
// The timeline editor's model (ALIAS ch. 8; the key frames of the sign-language interpreter),
// without a window. A timeline is
//   - an optional source motion (a sign or an utterance from `say`) cut into bars: one per sign,
//     the transitions between them and the pauses. A bar's duration can be changed; the source is
//     then played faster or slower inside it (a piecewise-linear time warp) and everything after it
//     moves with it;
//   - scalar channels with keys: a joint's Euler angle about one axis (degrees from the rest
//     orientation, in the joint's rotation order) or a face morph weight. A keyed channel replaces
//     that angle or weight of the source. Each key says how the segment after it is interpolated:
//     step, linear, Catmull-Rom or Kochanek–Bartels with its own tension, continuity and bias.
// Every edit is undoable. The whole is baked into a Clip (sampled frames) for export.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/anim/interpolation.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::studio {

enum class KeyInterpolation : std::uint8_t { Step, Linear, CatmullRom, KochanekBartels };
const char* to_string(KeyInterpolation interpolation);
// "step", "linear", "catmull-rom", "kb" (or "kochanek-bartels"); false when unknown.
bool parse_key_interpolation(const std::string& text, KeyInterpolation& out);

struct TimelineKey {
  float time = 0.0f;   // seconds on the timeline
  float value = 0.0f;  // degrees (joint channel) or weight (morph channel)
  KeyInterpolation interpolation = KeyInterpolation::CatmullRom;  // of the segment after this key
  Tcb tcb;             // Kochanek–Bartels tension, continuity, bias at this key
};

struct TimelineChannel {
  std::string name;  // "r_elbow.x" for a joint angle, the morph's name for a face channel
  int joint = -1;    // joint channel: the joint and its axis (0 x, 1 y, 2 z)
  int axis = -1;
  int morph = -1;    // face channel: the morph index
  std::vector<TimelineKey> keys;  // strictly increasing times
};

// The channel's value at time t: the first key's value before it, the last one's after it; in
// between the segment's interpolation. Hermite segments take Kochanek–Bartels tangents (the core's
// kb_tangents, adjusted for uneven key spacing); Catmull-Rom is tension = continuity = bias = 0.
// At the first and last key the missing neighbour is the key itself (the one-sided difference).
// Contract: at least one key.
float evaluate(std::span<const TimelineKey> keys, float t);

enum class BarKind : std::uint8_t { Sign, Transition, Pause };
const char* to_string(BarKind kind);

struct TimelineBar {
  std::string label;          // the gloss, "transition" or "pause"
  BarKind kind = BarKind::Sign;
  float source_start = 0.0f;  // the part of the source motion it plays
  float source_end = 0.0f;
  float duration = 0.0f;      // how long it lasts on the timeline
};

// A sign of the source (gloss and the seconds from its first posture to the end of its last hold).
struct SourceSign {
  std::string gloss;
  float start = 0.0f, end = 0.0f;
};

// The bars of a source motion of `duration` seconds: its signs in time order, the gaps between
// them (a transition, or a pause when longer than `pause_seconds`), the way in and out.
std::vector<TimelineBar> bars_from_signs(std::span<const SourceSign> signs, float duration, float pause_seconds = 0.45f);

class Timeline {
 public:
  // Contract: `skeleton` outlives the timeline.
  Timeline(const Skeleton& skeleton, std::vector<std::string> morph_names);

  const Skeleton& skeleton() const { return *skeleton_; }
  const std::vector<std::string>& morph_names() const { return morph_names_; }

  // ---- the source motion ----
  // Replaces the source (and its bars); keys stay. An empty clip removes the source.
  void set_source(Clip clip, std::span<const SourceSign> signs, std::string title);
  bool has_source() const { return source_ && source_->duration > 0.0f; }
  const std::string& title() const { return title_; }
  const std::vector<TimelineBar>& bars() const { return bars_; }
  float bar_start(int bar) const;  // where it begins on the timeline
  // Retimes a bar (at least 0.04 s, at most 60 s): the source plays faster or slower inside it and
  // keys inside or after it move with the motion. False (and nothing changes) for a bad index.
  bool set_bar_duration(int bar, float seconds);
  // The source time shown at timeline time t.
  float source_time(float t) const;

  // Timeline length: the bars' total, else 2 s, extended to the last key.
  float duration() const;

  // ---- channels and keys ----
  const std::vector<TimelineChannel>& channels() const { return channels_; }
  int find_channel(const std::string& name) const;  // -1 when absent
  // The channel of a joint axis ("r_elbow.x") or a morph, added when missing; -1 when the name is
  // not a free axis of a joint or a morph of the avatar.
  int channel_for(const std::string& name);

  // Adds a key at `time` (replacing the value of a key within 1 ms of it). Returns its index.
  int set_key(int channel, float time, float value, const std::string& merge_key = {});
  // Drags a key to a new time, kept between its neighbours (1 ms apart) and at 0 or later.
  bool move_key(int channel, int key, float time, const std::string& merge_key = {});
  // Every key at `from` (within 1 ms) moves to `to` on every channel (a film-strip column).
  int move_keys_at(float from, float to);
  bool set_key_value(int channel, int key, float value, const std::string& merge_key = {});
  bool set_interpolation(int channel, int key, KeyInterpolation interpolation, const Tcb& tcb, const std::string& merge_key = {});
  bool remove_key(int channel, int key);
  // Keys a pose at `time`: every free joint axis that differs from what the timeline shows there
  // by more than 0.05 degrees, or is already keyed; every morph likewise. Returns the keys set.
  int key_pose(const Pose& pose, std::span<const float> morph_weights, float time);
  // The distinct key times, increasing.
  std::vector<float> key_times() const;

  // ---- what it shows ----
  // Local pose and morph weights at time t. Contract: pose sized for the skeleton, morphs for the names.
  void sample(float t, Pose& pose, std::span<float> morph_weights) const;
  // Frames at `fps` over [0, duration()] (at least two), as a clip on the skeleton with face channels.
  Clip bake(float fps) const;

  // ---- undo ----
  bool undo();
  bool redo();
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  void seal() { last_key_.clear(); }  // the next edit starts a new undo step
  std::uint64_t revision() const { return revision_; }

 private:
  // An undo step holds the source too (shared, so a step costs no copy of the motion).
  struct Snapshot {
    std::vector<TimelineChannel> channels;
    std::vector<TimelineBar> bars;
    std::shared_ptr<const Clip> source;
    std::string title;
  };
  Snapshot snapshot() const { return {channels_, bars_, source_, title_}; }
  void restore(Snapshot snapshot);
  void record(const std::string& merge_key);
  void sample_source(float t, Pose& pose, std::span<float> morph_weights) const;

  const Skeleton* skeleton_;
  std::vector<std::string> morph_names_;
  std::shared_ptr<const Clip> source_;
  std::vector<int> source_morph_channel_;  // per morph: the source clip's channel, or -1
  std::string title_;
  std::vector<TimelineBar> bars_;
  std::vector<TimelineChannel> channels_;
  std::vector<Snapshot> undo_, redo_;
  std::string last_key_;
  std::uint64_t revision_ = 0;
};

}  // namespace gestura::studio
