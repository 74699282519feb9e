#include "gestura/studio/pose_editor.hpp"

#include <algorithm>
#include <cmath>

namespace gestura::studio {
namespace {

// The joint of the other side ("l_elbow" ↔ "r_elbow"); the joint itself when it has none.
int counterpart(const Skeleton& s, int joint) {
  const std::string& name = s.names[joint];
  if (name.size() > 2 && name[1] == '_' && (name[0] == 'l' || name[0] == 'r')) {
    const int other = s.find(std::string(1, name[0] == 'l' ? 'r' : 'l') + name.substr(1));
    if (other >= 0) return other;
  }
  return joint;
}

}  // namespace

bool is_hand_joint(const std::string& name, char side) {
  if (name.size() < 3 || name[0] != side || name[1] != '_') return false;
  for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"})
    if (name.compare(2, std::char_traits<char>::length(finger), finger) == 0) return true;
  return false;
}

PoseEditor::PoseEditor(const Skeleton& skeleton, std::vector<std::string> morph_names)
    : skeleton_(&skeleton), morph_names_(std::move(morph_names)), pose_(rest_pose(skeleton)), morphs_(morph_names_.size(), 0.0f) {}

vec3 PoseEditor::angles_degrees(int joint) const {
  if (joint < 0 || joint >= static_cast<int>(skeleton_->size())) return vec3(0.0f);
  return glm::degrees(joint_angles(*skeleton_, joint, pose_.rotations[joint]));
}

void PoseEditor::record(const std::string& merge_key) {
  if (merge_key.empty() || merge_key != last_key_ || undo_.empty()) undo_.push_back({pose_, morphs_});
  if (undo_.size() > 500) undo_.erase(undo_.begin());
  redo_.clear();
  last_key_ = merge_key;
  ++revision_;
}

void PoseEditor::assign(const Pose& pose, std::span<const float> morphs) {
  if (pose.size() != pose_.size() || morphs.size() != morphs_.size()) return;
  pose_ = pose;
  std::copy(morphs.begin(), morphs.end(), morphs_.begin());
  undo_.clear(), redo_.clear(), last_key_.clear();
}

bool PoseEditor::set_angles_degrees(int joint, const vec3& degrees, const std::string& merge_key) {
  if (joint < 0 || joint >= static_cast<int>(skeleton_->size())) return false;
  const JointDofs& dofs = skeleton_->dofs[joint];
  if (dofs.count() == 0) return false;
  vec3 radians = glm::radians(degrees);
  for (int axis = 0; axis < 3; ++axis)
    radians[axis] = dofs.free(axis) ? std::clamp(radians[axis], dofs.min_angle[axis], dofs.max_angle[axis]) : 0.0f;
  record(merge_key);
  pose_.rotations[joint] = joint_rotation(*skeleton_, joint, radians);
  return true;
}

int PoseEditor::pivot_axis(int joint) const {
  if (joint < 0 || joint >= static_cast<int>(skeleton_->size())) return -1;
  // The limb's direction: towards its first child.
  vec3 along(0.0f);
  for (std::size_t c = 0; c < skeleton_->size(); ++c)
    if (skeleton_->parents[c] == joint) {
      along = skeleton_->rest_translations[c];
      break;
    }
  if (glm::length(along) < 1e-6f) return -1;
  along = glm::normalize(along);
  int best = -1;
  float best_dot = 0.7f;  // only an axis really along the bone
  for (int axis = 0; axis < 3; ++axis)
    if (skeleton_->dofs[joint].free(axis) && std::abs(along[axis]) > best_dot) best = axis, best_dot = std::abs(along[axis]);
  return best;
}

int PoseEditor::bend_axis(int joint) const {
  if (joint < 0 || joint >= static_cast<int>(skeleton_->size())) return -1;
  const int pivot = pivot_axis(joint);
  for (int axis = 0; axis < 3; ++axis)
    if (skeleton_->dofs[joint].free(axis) && axis != pivot) return axis;
  return -1;
}

bool PoseEditor::set_morph(std::size_t index, float weight, const std::string& merge_key) {
  if (index >= morphs_.size()) return false;
  record(merge_key);
  morphs_[index] = std::clamp(weight, 0.0f, 1.0f);
  return true;
}

void PoseEditor::set_hand(char side, const Pose& source) {
  record({});
  for (std::size_t j = 0; j < skeleton_->size() && j < source.size(); ++j)
    if (is_hand_joint(skeleton_->names[j], side)) pose_.rotations[j] = source.rotations[j];
}

void PoseEditor::mirror() {
  record({});
  const Pose before = pose_;
  for (std::size_t j = 0; j < skeleton_->size(); ++j) {
    const int other = counterpart(*skeleton_, static_cast<int>(j));
    // Reflection in the x = 0 plane: a rotation (w, x, y, z) becomes (w, x, -y, -z).
    const quat q = before.rotations[other];
    pose_.rotations[j] = quat(q.w, q.x, -q.y, -q.z);
    const vec3 t = before.translations[other];
    if (skeleton_->parents[j] < 0) pose_.translations[j] = vec3(-t.x, t.y, t.z);
  }
  // Face morphs named with a side swap too ("smile_l" ↔ "smile_r").
  const std::vector<float> morphs = morphs_;
  for (std::size_t i = 0; i < morph_names_.size(); ++i) {
    std::string other = morph_names_[i];
    if (other.ends_with("_l")) other.back() = 'r';
    else if (other.ends_with("_r")) other.back() = 'l';
    const auto it = std::find(morph_names_.begin(), morph_names_.end(), other);
    if (it != morph_names_.end()) morphs_[i] = morphs[static_cast<std::size_t>(it - morph_names_.begin())];
  }
}

void PoseEditor::set_pose(const Pose& pose, const std::string& merge_key) {
  if (pose.size() != pose_.size()) return;
  record(merge_key);
  pose_ = pose;
  clamp_to_limits(*skeleton_, pose_);
}

void PoseEditor::set_pose_and_morphs(const Pose& pose, std::span<const float> morphs, const std::string& merge_key) {
  if (pose.size() != pose_.size() || morphs.size() != morphs_.size()) return;
  record(merge_key);
  pose_ = pose;
  clamp_to_limits(*skeleton_, pose_);
  std::copy(morphs.begin(), morphs.end(), morphs_.begin());
}

void PoseEditor::reset() {
  record({});
  pose_ = rest_pose(*skeleton_);
  std::fill(morphs_.begin(), morphs_.end(), 0.0f);
}

bool PoseEditor::undo() {
  if (undo_.empty()) return false;
  redo_.push_back({pose_, morphs_});
  pose_ = undo_.back().pose;
  morphs_ = undo_.back().morphs;
  undo_.pop_back();
  last_key_.clear();
  ++revision_;
  return true;
}

bool PoseEditor::redo() {
  if (redo_.empty()) return false;
  undo_.push_back({pose_, morphs_});
  pose_ = redo_.back().pose;
  morphs_ = redo_.back().morphs;
  redo_.pop_back();
  last_key_.clear();
  ++revision_;
  return true;
}

void PoseEditor::model(std::span<mat4> out) const { local_to_model(*skeleton_, pose_, out); }

}  // namespace gestura::studio
