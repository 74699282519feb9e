#include "gestura/studio/undo_stack.hpp"

namespace gestura::studio {

void UndoStack::push(Edit edit) {
  edits_.resize(done_);
  const bool merge = !sealed_ && !edit.merge_key.empty() && !edits_.empty() && !edit.store && !edits_.back().store &&
                     edits_.back().merge_key == edit.merge_key;
  if (merge) {
    edits_.back().after = std::move(edit.after);
  } else {
    edits_.push_back(std::move(edit));
    if (edits_.size() > kMaxEdits) edits_.erase(edits_.begin());
  }
  done_ = edits_.size();
  sealed_ = edits_.back().merge_key.empty();
}

const Edit& UndoStack::undo() {
  sealed_ = true;
  return edits_[--done_];
}

const Edit& UndoStack::redo() {
  sealed_ = true;
  return edits_[done_++];
}

}  // namespace gestura::studio
