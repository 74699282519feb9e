#pragma once
// The pose editor's model (ALIAS Motion Editor, ch. 4), without a window: one pose of the avatar's
// skeleton plus face morph weights, edited joint by joint inside the joint limits (bend about the
// joint's flexion axis, pivot about the limb's own axis), hands set from handshape presets, the
// whole pose mirrored left/right; every edit undoable.
#include <span>
#include <string>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::studio {

class PoseEditor {
 public:
  // Contract: `skeleton` outlives the editor.
  PoseEditor(const Skeleton& skeleton, std::vector<std::string> morph_names);

  const Skeleton& skeleton() const { return *skeleton_; }
  const Pose& pose() const { return pose_; }
  const std::vector<std::string>& morph_names() const { return morph_names_; }
  std::span<const float> morph_weights() const { return morphs_; }

  // Euler angles (degrees) of a joint relative to its rest orientation, in its rotation order.
  vec3 angles_degrees(int joint) const;
  // Sets them, each free axis clamped into its limits and locked axes kept at 0. Returns false (and
  // changes nothing) for a joint without free axes or out of range.
  bool set_angles_degrees(int joint, const vec3& degrees, const std::string& merge_key = {});
  // The axis a joint bends about (its first free axis that is not the limb's own axis) and the
  // limb's own axis (the free axis closest to the direction of its child bone); -1 when none.
  int bend_axis(int joint) const;
  int pivot_axis(int joint) const;

  bool set_morph(std::size_t index, float weight, const std::string& merge_key = {});
  // Copies the finger and thumb joints of one hand ('r' or 'l') from `source` (a pose on the same
  // skeleton, e.g. a performed handshape).
  void set_hand(char side, const Pose& source);
  // Left and right exchanged and reflected in the body's mid-plane (x = 0).
  void mirror();
  void reset();

  bool undo();
  bool redo();
  void seal() { last_key_.clear(); }

  // Joint model matrices of the pose.
  void model(std::span<mat4> out) const;

 private:
  struct Snapshot {
    Pose pose;
    std::vector<float> morphs;
  };
  void record(const std::string& merge_key);

  const Skeleton* skeleton_;
  std::vector<std::string> morph_names_;
  Pose pose_;
  std::vector<float> morphs_;
  std::vector<Snapshot> undo_, redo_;
  std::string last_key_;
};

// True for the finger and thumb joints of one hand ("r_index2", "l_thumb1", ...).
bool is_hand_joint(const std::string& name, char side);

}  // namespace gestura::studio
