#pragma once
// What the render and view commands show: a skeleton, a mesh skinned to it (bind pose = the
// skeleton's rest pose), and optionally a clip for the same skeleton. An Animator turns a time
// into the renderer's per-frame input (skinning matrices, morph weights).
#include <optional>
#include <span>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct RenderSubject {
  Skeleton skeleton;
  Mesh mesh;
  std::optional<Clip> clip;  // none = the rest pose
};

class Animator {
 public:
  // Contract: `subject` outlives the animator. Throws gestura::Error when the clip does not fit the
  // skeleton or the mesh refers to joints the skeleton lacks.
  explicit Animator(const RenderSubject& subject);

  float duration() const;  // 0 without a clip
  // Poses the skeleton at time t (clamped into the clip) and fills skinning() and morph_weights():
  // clip channels whose name matches a morph target drive that target.
  void pose_at(float t);
  std::span<const mat4> skinning() const { return skinning_; }
  std::span<const float> morph_weights() const { return morph_weights_; }
  std::span<const mat4> model() const { return model_; }  // joint model matrices of the last pose

 private:
  const RenderSubject* subject_;
  std::optional<Sampler> sampler_;
  Pose rest_, pose_;
  std::vector<mat4> inverse_bind_, model_, skinning_;
  std::vector<float> channels_, morph_weights_;
  std::vector<int> channel_morph_;  // per clip channel: morph index or -1
};

}  // namespace gestura
