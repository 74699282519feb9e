#pragma once
// The studio's undo/redo history. Every edit is one Edit: the draft before and after, and, for edits
// that write the user lexicon (save, delete), the rows removed and the row written, so that undoing a
// save puts the database back as it was and redoing writes it again. Plain data: the model applies
// edits, the stack only orders them.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "gestura/lexicon/sign_entry.hpp"
#include "gestura/studio/sign_draft.hpp"

namespace gestura::studio {

// A change of the user lexicon, applied as one transaction.
struct StoreChange {
  std::vector<SignEntry> removed;   // rows taken out (restored on undo)
  std::optional<SignEntry> written; // the row put in (taken out on undo)
};

struct Edit {
  std::string label;  // "edit notation", "save HOUSE", shown in the Edit menu and the status bar
  SignDraft before, after;
  std::optional<StoreChange> store;
  // Consecutive edits with the same non-empty key merge into one (typing in one field is one edit
  // until the field loses focus: see UndoStack::seal).
  std::string merge_key;
};

class UndoStack {
 public:
  // Records an edit that was just applied; drops whatever could have been redone.
  void push(Edit edit);
  // Ends merging: the next edit starts a new entry even with the same merge key.
  void seal() { sealed_ = true; }

  bool can_undo() const { return done_ > 0; }
  bool can_redo() const { return done_ < edits_.size(); }
  // The edit to revert / re-apply, moving the cursor; contract: can_undo() / can_redo().
  const Edit& undo();
  const Edit& redo();
  // The labels of the edits undo / redo would act on (empty when none).
  std::string undo_label() const { return can_undo() ? edits_[done_ - 1].label : std::string(); }
  std::string redo_label() const { return can_redo() ? edits_[done_].label : std::string(); }
  std::size_t size() const { return edits_.size(); }
  void clear() { edits_.clear(), done_ = 0, sealed_ = true; }

  // History beyond this many edits is forgotten, oldest first.
  static constexpr std::size_t kMaxEdits = 1000;

 private:
  std::vector<Edit> edits_;
  std::size_t done_ = 0;  // edits_[0, done_) are applied
  bool sealed_ = true;
};

}  // namespace gestura::studio
