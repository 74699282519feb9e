#include "gestura/world/tracks.hpp"

#include <algorithm>

#include "gestura/anim/blend.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

TrackStack::TrackStack(const Skeleton& skeleton) : skeleton_(&skeleton), rest_(rest_pose(skeleton)) {}

void TrackStack::add(TrackLayer layer) {
  if (!layer.clip) throw Error("track layer '" + layer.name + "' has no clip");
  if (layer.clip->joint_count() != skeleton_->size())
    throw Error("track layer '" + layer.name + "': the clip has " + std::to_string(layer.clip->joint_count()) +
                " joints, the skeleton " + std::to_string(skeleton_->size()));
  if (!layer.mask.empty() && layer.mask.size() != skeleton_->size())
    throw Error("track layer '" + layer.name + "': the mask does not match the skeleton");
  std::vector<int> map;
  for (const std::string& name : layer.clip->channel_names) {
    auto it = std::find(channel_names_.begin(), channel_names_.end(), name);
    if (it == channel_names_.end()) it = channel_names_.insert(channel_names_.end(), name);
    map.push_back(static_cast<int>(it - channel_names_.begin()));
  }
  channel_map_.push_back(std::move(map));
  samplers_.push_back(std::make_unique<Sampler>(*layer.clip));
  layers_.push_back(std::move(layer));
  poses_.resize(layers_.size());
}

float TrackStack::duration() const {
  float end = 0.0f;
  for (const TrackLayer& l : layers_) end = std::max(end, l.start + l.clip->duration);
  return end;
}

float TrackStack::envelope(const TrackLayer& l, float t) {
  const float local = t - l.start, length = l.clip->duration;
  if (local < 0.0f) return 0.0f;
  if (local > length) return l.hold ? l.weight : 0.0f;
  float w = l.weight;
  if (l.fade_in > 0.0f) w *= crossfade_weight(local, l.fade_in);
  if (l.fade_out > 0.0f && !l.hold) w *= crossfade_weight(length - local, l.fade_out);
  return w;
}

void TrackStack::evaluate(float t, Pose& out, std::vector<float>* channels) {
  std::vector<BlendLayer> active;
  active.reserve(layers_.size());
  if (channels) channels->assign(channel_names_.size(), 0.0f);
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    const TrackLayer& l = layers_[i];
    const float w = envelope(l, t);
    if (w <= 0.0f) continue;
    scratch_.assign(l.clip->channels.size(), 0.0f);
    const float local = std::clamp(t - l.start, 0.0f, l.clip->duration);
    samplers_[i]->sample(local, WrapMode::Clamp, rest_, poses_[i], scratch_);
    if (channels)
      for (std::size_t c = 0; c < scratch_.size(); ++c) (*channels)[static_cast<std::size_t>(channel_map_[i][c])] += w * scratch_[c];
    active.push_back(BlendLayer{&poses_[i], w, l.mask, l.priority});
  }
  if (active.empty()) {
    out = rest_;
    return;
  }
  blend_layers(active, rest_, out);
}

std::vector<float> mask_of_clip(const Clip& clip, std::size_t joints) {
  std::vector<float> mask(joints, 0.0f);
  for (std::size_t j = 0; j < joints && j < clip.joint_count(); ++j)
    if (!clip.rotations[j].empty() || !clip.translations[j].empty()) mask[j] = 1.0f;
  return mask;
}

std::vector<float> mask_below(const Skeleton& skeleton, std::span<const std::string> roots) {
  std::vector<float> mask(skeleton.size(), 0.0f);
  for (const std::string& r : roots) {
    const int j = skeleton.find(r);
    if (j >= 0) mask[static_cast<std::size_t>(j)] = 1.0f;
  }
  for (std::size_t j = 0; j < skeleton.size(); ++j)
    if (skeleton.parents[j] >= 0 && mask[static_cast<std::size_t>(skeleton.parents[j])] > 0.0f) mask[j] = 1.0f;
  return mask;
}

Clip bake(TrackStack& stack, float duration, float fps) {
  const std::size_t n = stack.layers().empty() ? 0 : stack.layers().front().clip->joint_count();
  Clip out;
  out.name = "performance";
  out.resize_joints(n);
  out.duration = duration;
  std::vector<bool> rotated(n, false), moved(n, false);
  for (const TrackLayer& l : stack.layers())
    for (std::size_t j = 0; j < n; ++j) {
      rotated[j] = rotated[j] || !l.clip->rotations[j].empty();
      moved[j] = moved[j] || !l.clip->translations[j].empty();
    }
  for (const std::string& c : stack.channel_names()) out.channel(c).interpolation = Interpolation::Linear;
  const int frames = std::max(1, static_cast<int>(std::ceil(duration * fps - 1e-4f))) + 1;
  Pose pose;
  std::vector<float> channels;
  for (int i = 0; i < frames; ++i) {
    const float t = std::min(duration, static_cast<float>(i) / fps);
    stack.evaluate(t, pose, &channels);
    for (std::size_t j = 0; j < n; ++j) {
      if (rotated[j]) out.rotations[j].add(t, pose.rotations[j]);
      if (moved[j]) out.translations[j].add(t, pose.translations[j]);
    }
    for (std::size_t c = 0; c < channels.size(); ++c) out.channels[c].add(t, channels[c]);
    if (t >= duration) break;
  }
  for (std::size_t j = 0; j < n; ++j) {
    out.rotations[j].interpolation = Interpolation::Linear;
    make_continuous(out.rotations[j]);
    out.translations[j].interpolation = Interpolation::Linear;
  }
  return out;
}

}  // namespace gestura
