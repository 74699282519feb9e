#include "gestura/render/subject.hpp"

#include "gestura/core/error.hpp"

namespace gestura {

Animator::Animator(const RenderSubject& subject) : subject_(&subject) {
  const Skeleton& skeleton = subject.skeleton;
  skeleton.validate();
  for (std::size_t v = 0; v < subject.mesh.joints.size(); ++v) {
    const JointIndices j = subject.mesh.joints[v];
    if (std::max(std::max(j.x, j.y), std::max(j.z, j.w)) >= skeleton.size())
      throw Error("render subject: vertex " + std::to_string(v) + " refers to a joint beyond the skeleton's " +
                  std::to_string(skeleton.size()));
  }
  rest_ = rest_pose(skeleton);
  pose_ = rest_;
  model_.resize(skeleton.size());
  skinning_.resize(skeleton.size());
  inverse_bind_.resize(skeleton.size());
  local_to_model(skeleton, rest_, model_);
  for (std::size_t j = 0; j < model_.size(); ++j) inverse_bind_[j] = glm::inverse(model_[j]);
  morph_weights_.assign(subject.mesh.morphs.size(), 0.0f);
  if (subject.clip) {
    if (subject.clip->joint_count() != skeleton.size())
      throw Error("render subject: the clip animates " + std::to_string(subject.clip->joint_count()) +
                  " joints, the skeleton has " + std::to_string(skeleton.size()));
    validate(*subject.clip, skeleton);
    sampler_.emplace(*subject.clip);
    channels_.resize(subject.clip->channels.size());
    for (const std::string& name : subject.clip->channel_names) channel_morph_.push_back(subject.mesh.find_morph(name));
  }
  pose_at(0.0f);
}

float Animator::duration() const { return subject_->clip ? subject_->clip->duration : 0.0f; }

void Animator::pose_at(float t) {
  if (sampler_) {
    sampler_->sample(t, WrapMode::Clamp, rest_, pose_, channels_);
    for (std::size_t c = 0; c < channel_morph_.size(); ++c)
      if (channel_morph_[c] >= 0) morph_weights_[static_cast<std::size_t>(channel_morph_[c])] = channels_[c];
  }
  local_to_model(subject_->skeleton, pose_, model_);
  for (std::size_t j = 0; j < model_.size(); ++j) skinning_[j] = model_[j] * inverse_bind_[j];
}

}  // namespace gestura
