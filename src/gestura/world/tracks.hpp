#pragma once
// A character's motion as tracks (realtime-virtual-humans.txt §3, the TRACK system: "a sequence ...
// can integrate different motion generators such as walking, grasping, inverse kinematics ... and key
// framing within a unified framework"): clips placed in time, each with a weight envelope, a mask of
// the body parts it drives and a priority, blended every frame with anim/blend (a higher priority
// claims its joints first, alias-movement-through-environments.txt §5.4's reserve lists). The walk
// drives the whole body at priority 0; signing drives arms, hands, head and face above it, fading in
// and out, so a character walks while signing.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct TrackLayer {
  std::string name;
  std::shared_ptr<const Clip> clip;
  float start = 0.0f;          // timeline time of the clip's time 0
  float fade_in = 0.25f;       // seconds from 0 to full weight after start
  float fade_out = 0.25f;      // seconds from full weight to 0 before the clip ends
  float weight = 1.0f;
  std::vector<float> mask;     // per joint 0..1; empty = every joint
  int priority = 0;
  bool hold = false;           // keep the last frame (at full weight) after the clip ends
};

class TrackStack {
 public:
  explicit TrackStack(const Skeleton& skeleton);  // contract: the skeleton outlives the stack

  void add(TrackLayer layer);
  const std::vector<TrackLayer>& layers() const { return layers_; }
  float duration() const;  // the end of the last layer

  // The blended pose at t; `channels` receives every layer's named channels (face weights),
  // weighted by the layers' envelopes and summed, in the order of channel_names().
  void evaluate(float t, Pose& out, std::vector<float>* channels = nullptr);
  const std::vector<std::string>& channel_names() const { return channel_names_; }

  // A layer's envelope weight at t (0 outside it).
  static float envelope(const TrackLayer& layer, float t);

 private:
  const Skeleton* skeleton_;
  std::vector<TrackLayer> layers_;
  std::vector<std::unique_ptr<Sampler>> samplers_;
  std::vector<std::vector<int>> channel_map_;  // per layer: its channels' indices in channel_names_
  std::vector<std::string> channel_names_;
  std::vector<Pose> poses_;
  std::vector<float> scratch_;
  Pose rest_;
};

// A mask of the joints a clip animates (1 where it has a rotation or translation track).
std::vector<float> mask_of_clip(const Clip& clip, std::size_t joints);
// A mask of the named joints and everything below them.
std::vector<float> mask_below(const Skeleton& skeleton, std::span<const std::string> roots);

// Bakes the stack into one clip with a key every 1/fps from 0 to `duration` on every joint some
// layer drives, and every channel.
Clip bake(TrackStack& stack, float duration, float fps);

}  // namespace gestura
