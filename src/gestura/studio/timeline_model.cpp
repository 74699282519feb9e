#include "gestura/studio/timeline_model.hpp"

#include <algorithm>
#include <cmath>

namespace gestura::studio {
namespace {

constexpr float kSameTime = 1e-3f;  // keys closer than this are the same key
constexpr float kMinBar = 0.04f, kMaxBar = 60.0f;

const char* const kAxisSuffix[] = {".x", ".y", ".z"};

}  // namespace

const char* to_string(KeyInterpolation interpolation) {
  switch (interpolation) {
    case KeyInterpolation::Step: return "step";
    case KeyInterpolation::Linear: return "linear";
    case KeyInterpolation::CatmullRom: return "catmull-rom";
    case KeyInterpolation::KochanekBartels: return "kb";
  }
  return "?";
}

bool parse_key_interpolation(const std::string& text, KeyInterpolation& out) {
  if (text == "step") out = KeyInterpolation::Step;
  else if (text == "linear") out = KeyInterpolation::Linear;
  else if (text == "catmull-rom") out = KeyInterpolation::CatmullRom;
  else if (text == "kb" || text == "kochanek-bartels" || text == "tcb") out = KeyInterpolation::KochanekBartels;
  else return false;
  return true;
}

const char* to_string(BarKind kind) {
  switch (kind) {
    case BarKind::Sign: return "sign";
    case BarKind::Transition: return "transition";
    case BarKind::Pause: return "pause";
  }
  return "?";
}

float evaluate(std::span<const TimelineKey> keys, float t) {
  const std::size_t n = keys.size();
  if (n == 1 || t <= keys[0].time) return keys[0].value;
  if (t >= keys[n - 1].time) return keys[n - 1].value;
  std::size_t k = 0;
  while (k + 2 < n && keys[k + 1].time <= t) ++k;
  const TimelineKey &a = keys[k], &b = keys[k + 1];
  const float u = (t - a.time) / (b.time - a.time);
  switch (a.interpolation) {
    case KeyInterpolation::Step: return a.value;
    case KeyInterpolation::Linear: return a.value + (b.value - a.value) * u;
    case KeyInterpolation::CatmullRom:
    case KeyInterpolation::KochanekBartels: break;
  }
  // Tangents leaving a and arriving at b. A Catmull-Rom segment uses zero TCB at both ends; a
  // Kochanek–Bartels one each key's own (the key before b says how the segment is shaped, the
  // TCB of b how it arrives there).
  const bool kb = a.interpolation == KeyInterpolation::KochanekBartels;
  const Tcb tcb_a = kb ? a.tcb : Tcb{}, tcb_b = kb ? b.tcb : Tcb{};
  const TimelineKey& before = k > 0 ? keys[k - 1] : a;
  const TimelineKey& after = k + 2 < n ? keys[k + 2] : b;
  float in_a = 0, out_a = 0, in_b = 0, out_b = 0;
  kb_tangents(before.value, a.value, b.value, a.time - before.time, b.time - a.time, tcb_a, in_a, out_a);
  kb_tangents(a.value, b.value, after.value, b.time - a.time, after.time - b.time, tcb_b, in_b, out_b);
  return hermite(a.value, out_a, b.value, in_b, u);
}

std::vector<TimelineBar> bars_from_signs(std::span<const SourceSign> signs, float duration, float pause_seconds) {
  std::vector<SourceSign> sorted(signs.begin(), signs.end());
  std::sort(sorted.begin(), sorted.end(), [](const SourceSign& a, const SourceSign& b) { return a.start < b.start; });
  std::vector<TimelineBar> bars;
  const auto gap = [&](float from, float to, bool inside) {
    if (to - from < kMinBar * 0.5f) return;
    const bool pause = inside && to - from > pause_seconds;
    bars.push_back({pause ? "pause" : "transition", pause ? BarKind::Pause : BarKind::Transition, from, to, to - from});
  };
  float at = 0.0f;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const float start = std::clamp(sorted[i].start, at, duration), end = std::clamp(sorted[i].end, start, duration);
    gap(at, start, i > 0);
    if (end - start > 0.0f) bars.push_back({sorted[i].gloss, BarKind::Sign, start, end, end - start});
    at = std::max(at, end);
  }
  gap(at, duration, false);
  if (bars.empty() && duration > 0.0f) bars.push_back({"motion", BarKind::Sign, 0.0f, duration, duration});
  return bars;
}

Timeline::Timeline(const Skeleton& skeleton, std::vector<std::string> morph_names)
    : skeleton_(&skeleton), morph_names_(std::move(morph_names)), source_morph_channel_(morph_names_.size(), -1) {}

void Timeline::record(const std::string& merge_key) {
  if (merge_key.empty() || merge_key != last_key_ || undo_.empty()) undo_.push_back(snapshot());
  if (undo_.size() > 500) undo_.erase(undo_.begin());
  redo_.clear();
  last_key_ = merge_key;
  ++revision_;
}

void Timeline::restore(Snapshot snapshot) {
  channels_ = std::move(snapshot.channels);
  bars_ = std::move(snapshot.bars);
  source_ = std::move(snapshot.source);
  title_ = std::move(snapshot.title);
  for (std::size_t m = 0; m < morph_names_.size(); ++m) source_morph_channel_[m] = source_ ? source_->find_channel(morph_names_[m]) : -1;
  last_key_.clear();
  ++revision_;
}

bool Timeline::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(snapshot());
  restore(std::move(undo_.back()));
  undo_.pop_back();
  return true;
}

bool Timeline::redo() {
  if (redo_.empty()) return false;
  undo_.push_back(snapshot());
  restore(std::move(redo_.back()));
  redo_.pop_back();
  return true;
}

void Timeline::set_source(Clip clip, std::span<const SourceSign> signs, std::string title) {
  record({});
  clip.resize_joints(skeleton_->size());
  source_ = std::make_shared<const Clip>(std::move(clip));
  title_ = std::move(title);
  bars_ = has_source() ? bars_from_signs(signs, source_->duration) : std::vector<TimelineBar>{};
  for (std::size_t m = 0; m < morph_names_.size(); ++m) source_morph_channel_[m] = source_->find_channel(morph_names_[m]);
}

float Timeline::bar_start(int bar) const {
  float at = 0.0f;
  for (int i = 0; i < bar && i < static_cast<int>(bars_.size()); ++i) at += bars_[static_cast<std::size_t>(i)].duration;
  return at;
}

bool Timeline::set_bar_duration(int bar, float seconds) {
  if (bar < 0 || bar >= static_cast<int>(bars_.size()) || !std::isfinite(seconds)) return false;
  seconds = std::clamp(seconds, kMinBar, kMaxBar);
  const float start = bar_start(bar), old = bars_[static_cast<std::size_t>(bar)].duration, end = start + old;
  record("bar:" + std::to_string(bar));
  // Keys go with the motion: inside the bar they keep their fraction of it, after it they shift.
  for (TimelineChannel& c : channels_)
    for (TimelineKey& k : c.keys) {
      if (k.time >= end) k.time += seconds - old;
      else if (k.time > start) k.time = start + (k.time - start) / old * seconds;
    }
  bars_[static_cast<std::size_t>(bar)].duration = seconds;
  return true;
}

float Timeline::source_time(float t) const {
  if (bars_.empty()) return t;
  float at = 0.0f;
  for (const TimelineBar& b : bars_) {
    if (t < at + b.duration) return b.source_start + std::max(0.0f, t - at) / b.duration * (b.source_end - b.source_start);
    at += b.duration;
  }
  return bars_.back().source_end;
}

float Timeline::duration() const {
  float d = bars_.empty() ? 2.0f : bar_start(static_cast<int>(bars_.size()));
  for (const TimelineChannel& c : channels_)
    if (!c.keys.empty()) d = std::max(d, c.keys.back().time);
  return d;
}

int Timeline::find_channel(const std::string& name) const {
  for (std::size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].name == name) return static_cast<int>(i);
  return -1;
}

int Timeline::channel_for(const std::string& name) {
  if (const int found = find_channel(name); found >= 0) return found;
  TimelineChannel c;
  c.name = name;
  if (name.size() > 2 && name[name.size() - 2] == '.') {
    const int axis = name.back() - 'x';
    const int joint = skeleton_->find(name.substr(0, name.size() - 2));
    if (joint < 0 || axis < 0 || axis > 2 || !skeleton_->dofs[static_cast<std::size_t>(joint)].free(axis)) return -1;
    c.joint = joint, c.axis = axis;
  } else {
    const auto it = std::find(morph_names_.begin(), morph_names_.end(), name);
    if (it == morph_names_.end()) return -1;
    c.morph = static_cast<int>(it - morph_names_.begin());
  }
  // Channels are kept in skeleton order (joints, then axes), morphs after them.
  const auto order = [&](const TimelineChannel& x) { return x.joint >= 0 ? x.joint * 3 + x.axis : 1000000 + x.morph; };
  const std::ptrdiff_t at =
      std::find_if(channels_.begin(), channels_.end(), [&](const TimelineChannel& x) { return order(x) > order(c); }) - channels_.begin();
  channels_.insert(channels_.begin() + at, std::move(c));
  return static_cast<int>(at);
}

int Timeline::set_key(int channel, float time, float value, const std::string& merge_key) {
  if (channel < 0 || channel >= static_cast<int>(channels_.size()) || !std::isfinite(time) || !std::isfinite(value)) return -1;
  record(merge_key);
  auto& keys = channels_[static_cast<std::size_t>(channel)].keys;
  time = std::max(0.0f, time);
  auto it = std::lower_bound(keys.begin(), keys.end(), time - kSameTime, [](const TimelineKey& k, float t) { return k.time < t; });
  if (it != keys.end() && std::abs(it->time - time) < kSameTime) {
    it->value = value;
    return static_cast<int>(it - keys.begin());
  }
  TimelineKey key{time, value};
  // A new key takes the interpolation of the key before it (what the segment it splits used).
  if (it != keys.begin()) key.interpolation = std::prev(it)->interpolation;
  return static_cast<int>(keys.insert(it, key) - keys.begin());
}

bool Timeline::move_key(int channel, int key, float time, const std::string& merge_key) {
  if (channel < 0 || channel >= static_cast<int>(channels_.size()) || !std::isfinite(time)) return false;
  auto& keys = channels_[static_cast<std::size_t>(channel)].keys;
  if (key < 0 || key >= static_cast<int>(keys.size())) return false;
  const std::size_t k = static_cast<std::size_t>(key);
  const float lo = k > 0 ? keys[k - 1].time + kSameTime : 0.0f;
  const float hi = k + 1 < keys.size() ? keys[k + 1].time - kSameTime : 3600.0f;
  if (lo > hi) return false;
  record(merge_key);
  keys[k].time = std::clamp(time, lo, hi);
  return true;
}

int Timeline::move_keys_at(float from, float to) {
  if (!std::isfinite(to)) return 0;
  record({});
  int moved = 0;
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    auto& keys = channels_[c].keys;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (std::abs(keys[k].time - from) >= kSameTime) continue;
      const float lo = k > 0 ? keys[k - 1].time + kSameTime : 0.0f;
      const float hi = k + 1 < keys.size() ? keys[k + 1].time - kSameTime : 3600.0f;
      if (lo <= hi) keys[k].time = std::clamp(to, lo, hi), ++moved;
    }
  }
  return moved;
}

bool Timeline::set_key_value(int channel, int key, float value, const std::string& merge_key) {
  if (channel < 0 || channel >= static_cast<int>(channels_.size()) || !std::isfinite(value)) return false;
  auto& keys = channels_[static_cast<std::size_t>(channel)].keys;
  if (key < 0 || key >= static_cast<int>(keys.size())) return false;
  record(merge_key);
  keys[static_cast<std::size_t>(key)].value = value;
  return true;
}

bool Timeline::set_interpolation(int channel, int key, KeyInterpolation interpolation, const Tcb& tcb, const std::string& merge_key) {
  if (channel < 0 || channel >= static_cast<int>(channels_.size())) return false;
  auto& keys = channels_[static_cast<std::size_t>(channel)].keys;
  if (key < 0 || key >= static_cast<int>(keys.size())) return false;
  if (!std::isfinite(tcb.tension) || !std::isfinite(tcb.continuity) || !std::isfinite(tcb.bias)) return false;
  record(merge_key);
  TimelineKey& k = keys[static_cast<std::size_t>(key)];
  k.interpolation = interpolation;
  k.tcb = {std::clamp(tcb.tension, -1.0f, 1.0f), std::clamp(tcb.continuity, -1.0f, 1.0f), std::clamp(tcb.bias, -1.0f, 1.0f)};
  return true;
}

bool Timeline::remove_key(int channel, int key) {
  if (channel < 0 || channel >= static_cast<int>(channels_.size())) return false;
  auto& keys = channels_[static_cast<std::size_t>(channel)].keys;
  if (key < 0 || key >= static_cast<int>(keys.size())) return false;
  record({});
  keys.erase(keys.begin() + key);
  if (keys.empty()) channels_.erase(channels_.begin() + channel);
  return true;
}

int Timeline::key_pose(const Pose& pose, std::span<const float> morph_weights, float time) {
  Pose shown;
  shown.resize(skeleton_->size());
  std::vector<float> shown_morphs(morph_names_.size(), 0.0f);
  sample(time, shown, shown_morphs);
  record({});
  // The whole pose is one undo step: record() was called once above, put() records nothing.
  const auto put = [&](const std::string& name, float value) {
    const int c = channel_for(name);
    if (c < 0) return 0;
    auto& keys = channels_[static_cast<std::size_t>(c)].keys;
    auto it = std::lower_bound(keys.begin(), keys.end(), time - kSameTime, [](const TimelineKey& k, float t) { return k.time < t; });
    if (it != keys.end() && std::abs(it->time - time) < kSameTime) {
      it->value = value;
    } else {
      TimelineKey key{std::max(0.0f, time), value};
      if (it != keys.begin()) key.interpolation = std::prev(it)->interpolation;
      keys.insert(it, key);
    }
    return 1;
  };
  int count = 0;
  for (std::size_t j = 0; j < skeleton_->size() && j < pose.size(); ++j) {
    const JointDofs& dofs = skeleton_->dofs[j];
    if (dofs.count() == 0) continue;
    const vec3 want = glm::degrees(joint_angles(*skeleton_, static_cast<int>(j), pose.rotations[j]));
    const vec3 have = glm::degrees(joint_angles(*skeleton_, static_cast<int>(j), shown.rotations[j]));
    for (int axis = 0; axis < 3; ++axis) {
      if (!dofs.free(axis)) continue;
      const std::string name = skeleton_->names[j] + kAxisSuffix[axis];
      if (std::abs(want[axis] - have[axis]) > 0.05f || find_channel(name) >= 0) count += put(name, want[axis]);
    }
  }
  for (std::size_t m = 0; m < morph_names_.size() && m < morph_weights.size(); ++m)
    if (std::abs(morph_weights[m] - shown_morphs[m]) > 1e-3f || find_channel(morph_names_[m]) >= 0) count += put(morph_names_[m], morph_weights[m]);
  return count;
}

std::vector<float> Timeline::key_times() const {
  std::vector<float> times;
  for (const TimelineChannel& c : channels_)
    for (const TimelineKey& k : c.keys) times.push_back(k.time);
  std::sort(times.begin(), times.end());
  std::vector<float> distinct;
  for (const float t : times)
    if (distinct.empty() || t - distinct.back() >= kSameTime) distinct.push_back(t);
  return distinct;
}

void Timeline::sample_source(float t, Pose& pose, std::span<float> morph_weights) const {
  const Pose rest = rest_pose(*skeleton_);
  pose = rest;
  std::fill(morph_weights.begin(), morph_weights.end(), 0.0f);
  if (!has_source()) return;
  const Clip& source = *source_;
  const float s = std::clamp(source_time(t), 0.0f, source.duration);
  for (std::size_t j = 0; j < skeleton_->size(); ++j) {
    if (!source.rotations[j].empty()) pose.rotations[j] = sample_track(source.rotations[j], s);
    if (!source.translations[j].empty()) pose.translations[j] = sample_track(source.translations[j], s);
    if (!source.scales[j].empty()) pose.scales[j] = sample_track(source.scales[j], s);
  }
  for (std::size_t m = 0; m < morph_weights.size() && m < source_morph_channel_.size(); ++m)
    if (const int c = source_morph_channel_[m]; c >= 0 && !source.channels[static_cast<std::size_t>(c)].empty())
      morph_weights[m] = sample_track(source.channels[static_cast<std::size_t>(c)], s);
}

void Timeline::sample(float t, Pose& pose, std::span<float> morph_weights) const {
  sample_source(t, pose, morph_weights);
  // Keyed angles replace the source's, joint by joint (all keyed axes of a joint at once).
  for (std::size_t i = 0; i < channels_.size();) {
    const TimelineChannel& c = channels_[i];
    if (c.joint < 0) {
      if (c.morph >= 0 && static_cast<std::size_t>(c.morph) < morph_weights.size() && !c.keys.empty())
        morph_weights[static_cast<std::size_t>(c.morph)] = std::clamp(evaluate(c.keys, t), 0.0f, 1.0f);
      ++i;
      continue;
    }
    const int joint = c.joint;
    vec3 angles = joint_angles(*skeleton_, joint, pose.rotations[static_cast<std::size_t>(joint)]);
    // Keyed angles stay inside the joint's limits (a typed or overshooting spline value stops there).
    const JointDofs& dofs = skeleton_->dofs[static_cast<std::size_t>(joint)];
    for (; i < channels_.size() && channels_[i].joint == joint; ++i)
      if (const int axis = channels_[i].axis; !channels_[i].keys.empty())
        angles[axis] = std::clamp(glm::radians(evaluate(channels_[i].keys, t)), dofs.min_angle[axis], dofs.max_angle[axis]);
    pose.rotations[static_cast<std::size_t>(joint)] = joint_rotation(*skeleton_, joint, angles);
  }
}

Clip Timeline::bake(float fps) const {
  const float step = 1.0f / std::clamp(fps, 1.0f, 240.0f);
  const float length = duration();
  const int frames = std::max(2, static_cast<int>(std::ceil(length / step - 1e-4f)) + 1);
  Clip clip;
  clip.name = title_.empty() ? "timeline" : title_;
  clip.resize_joints(skeleton_->size());
  clip.duration = static_cast<float>(frames - 1) * step;
  std::vector<bool> moves_translation(skeleton_->size(), false);
  for (std::size_t j = 0; j < skeleton_->size(); ++j)
    moves_translation[j] = skeleton_->parents[j] < 0 || (has_source() && !source_->translations[j].empty());
  for (std::size_t m = 0; m < morph_names_.size(); ++m) clip.channel(morph_names_[m]);
  Pose pose;
  pose.resize(skeleton_->size());
  std::vector<float> morphs(morph_names_.size(), 0.0f);
  for (int f = 0; f < frames; ++f) {
    const float t = static_cast<float>(f) * step;
    sample(std::min(t, length), pose, morphs);
    for (std::size_t j = 0; j < skeleton_->size(); ++j) {
      clip.rotations[j].add(t, pose.rotations[j]);
      if (moves_translation[j]) clip.translations[j].add(t, pose.translations[j]);
    }
    for (std::size_t m = 0; m < morphs.size(); ++m) clip.channels[m].add(t, morphs[m]);
  }
  for (QuatTrack& track : clip.rotations) make_continuous(track);
  return clip;
}

}  // namespace gestura::studio
