#pragma once
// The sign database editor without a window: the lexicons (the built-in one, read-only, under the
// user's writable SQLite file), the draft being edited, and the undo history. Every change of the
// draft or the database goes through here as an Edit, so the UI, the --script replay and the tests
// drive the same code. Failures never throw out of an action: they end up in status() and leave the
// draft and the database as they were.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/studio/sign_draft.hpp"
#include "gestura/studio/undo_stack.hpp"

namespace gestura::studio {

struct BrowseFilter {
  std::string text;       // in the gloss or a keyword (empty: all)
  std::string language;   // ISO 639-3, empty: all
  std::string handshape;  // a symbol name the notation must contain (e.g. hamfist), empty: any
  std::string location;   // likewise for a location symbol (hamchest)
};

struct BrowseRow {
  SignEntry entry;
  bool builtin = false;  // from the read-only built-in lexicon
};

class StudioModel {
 public:
  // `builtin_files`: the built-in lexicon's .jsonl files (empty: none). `user_db`: the user's SQLite
  // lexicon, created when missing. A user lexicon that cannot be opened (corrupt, locked) leaves the
  // model read-only with the reason in status() and user_error().
  StudioModel(const std::vector<std::string>& builtin_files, std::string user_db);
  ~StudioModel();
  StudioModel(const StudioModel&) = delete;
  StudioModel& operator=(const StudioModel&) = delete;

  const SignDraft& draft() const { return draft_; }
  const std::string& status() const { return status_; }
  const std::string& user_db() const { return user_db_; }
  const std::string& user_error() const { return user_error_; }
  bool writable() const { return user_ != nullptr; }
  // The draft differs from what was last opened or saved.
  bool dirty() const { return draft_ != clean_; }
  // Increases with every change of the draft (the preview re-synthesizes when it moves).
  std::uint64_t revision() const { return revision_; }
  UndoStack& history() { return history_; }

  std::vector<BrowseRow> browse(const BrowseFilter& filter, std::size_t limit = 2000);
  // The signs of the user's lexicon (empty when it could not be opened).
  std::vector<SignEntry> user_signs();
  // The built-in and user lexicons as one (what `gestura say` signs from).
  LayeredLexicon& lexicon() { return layers_; }
  std::optional<BrowseRow> find(const EntryKey& key);

  // ---- edits (each one undoable) ----
  void new_sign();
  bool open(const EntryKey& key);  // false (status says why) when absent or not HamNoSys
  void duplicate();                // the draft as a new sign: next free variant of its gloss
  // Replaces the draft; consecutive edits with the same merge key are one undo step until seal().
  void edit(const std::string& label, SignDraft after, const std::string& merge_key = {});
  void seal() { history_.seal(); }
  // Symbol edits on the notation (indices into name_tokens(draft().names)); an index out of range
  // or an unknown name changes nothing and says so in status().
  bool replace_symbol(int index, const std::string& name);
  bool insert_symbol(int index, const std::string& name);  // index == count: append
  bool remove_symbol(int index);
  // Sets one non-manual tier to one value (empty: removes the tier). A value SiGML cannot hold
  // changes nothing and says why in status(). With a merge key (typing in a field), consecutive
  // changes are one undo step until seal().
  bool set_nonmanual(sign::NonManualTier tier, const std::string& value, const std::string& merge_key = {});
  // Writes the draft into the user lexicon in one transaction (replacing the row it came from, also
  // when its gloss or variant changed). Notation that does not parse is never saved: false, status
  // names the symbol, the database is untouched.
  bool save();
  // Removes the draft's row from the user lexicon (built-in rows cannot be removed).
  bool remove();
  bool undo();
  bool redo();

  // Replaces the draft without an undo step (recovery of an autosaved draft marks it dirty).
  void restore_draft(const SignDraft& draft);

 private:
  void apply_store(const StoreChange& change, bool forward);
  void set_draft(const SignDraft& draft);
  std::optional<SignEntry> user_row(const EntryKey& key);

  std::vector<std::string> builtin_files_;
  std::string user_db_, user_error_;
  std::unique_ptr<Lexicon> builtin_, user_;
  LayeredLexicon layers_;
  SignDraft draft_, clean_;
  UndoStack history_;
  std::string status_;
  std::uint64_t revision_ = 0;
};

}  // namespace gestura::studio
