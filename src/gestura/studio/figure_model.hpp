#pragma once
// The figure editor's model (ALIAS Tree Editor, ch. 3), without a window: a skeleton edited as a
// tree — rename, add and remove joints, copy a branch or mirror it onto the other side, change rest
// offsets, degrees of freedom, rotation order, limits and the Denavit–Hartenberg description
// (ch. 4.1) — every edit checked by Skeleton::validate() and undoable.
//
// The skeleton file is BVH (what `gestura retarget --to` and `gestura render` read): the hierarchy
// with each joint's rest offset, its rotation channels in the joint's rotation order, and one frame
// holding the rest orientations (BVH has no rest rotations of its own). What BVH cannot say (which
// axes are free, the limits, DH parameters) goes beside it in FILE.figure.json, read back when
// present; a BVH from elsewhere loads with every axis free.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/skeleton/skeleton.hpp"

namespace gestura::studio {

class FigureEditor {
 public:
  explicit FigureEditor(Skeleton skeleton);

  const Skeleton& skeleton() const { return skeleton_; }
  const std::string& file() const { return file_; }  // the file last saved or loaded
  std::uint64_t revision() const { return revision_; }

  // Each returns false (changing nothing) and sets error() when the edit is not possible.
  bool rename(int joint, const std::string& name);
  // A new leaf joint under `parent` (rest rotation identity, no free axis). Returns its index or -1.
  int add_joint(int parent, const std::string& name, const vec3& rest_offset);
  // Removes a joint; its children hang from its parent, keeping their rest positions. Not the root.
  bool remove_joint(int joint);
  // A copy of the joint's branch under the same parent, names given `suffix` ("l_index" → "l_index_copy").
  // Returns the index of the copy's first joint or -1.
  int copy_branch(int joint, const std::string& suffix = "_copy");
  // The branch reflected in the body's mid-plane (x = 0) onto the other side: l_ ↔ r_ names,
  // offsets (−x, y, z), rotations and limits about y and z negated. Joints of the other side that
  // exist are overwritten (indices kept, so a skinned body stays bound); missing ones are added.
  // Returns the number of joints written, -1 on error (a joint without an l_/r_ side).
  int mirror_branch(int joint);
  bool set_rest_offset(int joint, const vec3& offset, const std::string& merge_key = {});
  bool set_dofs(int joint, const JointDofs& dofs, const std::string& merge_key = {});
  bool set_dh(int joint, const std::optional<DenavitHartenberg>& dh, const std::string& merge_key = {});
  // The DH parameters that give the joint's rest offset: theta = atan2(y, x), a = √(x² + y²), d = z,
  // alpha = 0 (Rz(θ)·Tz(d)·Tx(a) moves the origin to the offset).
  DenavitHartenberg dh_from_rest(int joint) const;

  // The joints under `joint` (itself first), in skeleton order.
  std::vector<int> branch(int joint) const;

  // Writes FILE (BVH) and its .figure.json (each atomically). Throws gestura::Error.
  void save(const std::string& path);
  // Reads FILE (and its .figure.json when present). On any problem the figure is unchanged, the
  // message (naming the file, line and what is wrong) is in error(), and false is returned.
  bool load(const std::string& path);

  bool undo();
  bool redo();
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  void seal() { last_key_.clear(); }
  const std::string& error() const { return error_; }

 private:
  bool apply(Skeleton next, const std::string& merge_key);
  bool fail(std::string message);

  Skeleton skeleton_;
  std::string file_;
  std::vector<Skeleton> undo_, redo_;
  std::string last_key_;
  std::string error_;
  std::uint64_t revision_ = 0;
};

// The sidecar of a skeleton file: "arm.bvh" → "arm.figure.json".
std::string figure_sidecar_path(const std::string& bvh_path);

// Reads a skeleton file as FigureEditor::load does. Throws gestura::Error.
Skeleton load_figure(const std::string& path);
void save_figure(const std::string& path, const Skeleton& skeleton);

// The same from and to text (what the two functions above read and write; also what the fuzz
// target drives). `bvh_source` and `sidecar_source` name the texts in errors; without a sidecar
// every axis with a rotation channel is free, in the file's rotation order.
Skeleton read_figure(std::string_view bvh_text, const std::string& bvh_source,
                     std::optional<std::string_view> sidecar_text, const std::string& sidecar_source);
struct FigureTexts {
  std::string bvh;      // the skeleton file
  std::string sidecar;  // its .figure.json
};
// `bvh_file_name` is recorded in the sidecar ("skeleton"). Throws gestura::Error on an invalid skeleton.
FigureTexts write_figure(const Skeleton& skeleton, const std::string& bvh_file_name);

}  // namespace gestura::studio
