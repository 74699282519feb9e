#pragma once
// The pose editor's model (ALIAS Motion Editor, ch. 4), without a window: one pose of the avatar's
// skeleton plus face morph weights, edited joint by joint inside the joint limits (bend about the
// joint's flexion axis, pivot about the limb's own axis), hands set from handshape presets, the
// whole pose mirrored left/right; every edit undoable.
#include <cstdint>
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
  // Shows another pose without an undo step (the timeline's pose at the playhead): the history is
  // cleared, as the edits it held were of the pose shown before.
  void assign(const Pose& pose, std::span<const float> morphs);
  // Counts edits, undo and redo (not assign), so a caller can tell whether the user changed the pose.
  std::uint64_t revision() const { return revision_; }
  // Replaces the pose (an IK drag, a key read from the timeline), clamped into the limits.
  void set_pose(const Pose& pose, const std::string& merge_key = {});
  // Replaces pose and face weights together (sizes must match the editor's).
  void set_pose_and_morphs(const Pose& pose, std::span<const float> morphs, const std::string& merge_key = {});

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
  std::uint64_t revision_ = 0;
};

// True for the finger and thumb joints of one hand ("r_index2", "l_thumb1", ...).
bool is_hand_joint(const std::string& name, char side);

}  // namespace gestura::studio
