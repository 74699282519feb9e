#include "gestura/studio/studio_model.hpp"

#include <algorithm>
#include <filesystem>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::studio {
namespace {

std::string key_text(const EntryKey& k) { return k.gloss + " (" + k.language + ", variant " + std::to_string(k.variant) + ")"; }

// Does the entry's notation contain the symbol named `name`? Undecodable notation contains nothing.
bool contains_symbol(const SignEntry& e, const std::string& name) {
  if (name.empty()) return true;
  const auto wanted = sign::symbol_from_name(name);
  if (!wanted || e.notation_kind == NotationKind::clip) return false;
  try {
    std::vector<sign::Symbol> symbols;
    if (e.notation_kind == NotationKind::hamnosys) {
      symbols = sign::symbols_from_unicode(e.notation);
    } else {
      for (const sign::SigmlEntry& s : sign::read_sigml_entries(e.notation))
        if (s.sign) symbols.insert(symbols.end(), s.sign->symbols.begin(), s.sign->symbols.end());
    }
    return std::find(symbols.begin(), symbols.end(), *wanted) != symbols.end();
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

StudioModel::StudioModel(const std::vector<std::string>& builtin_files, std::string user_db)
    : builtin_files_(builtin_files), user_db_(std::move(user_db)) {
  if (!builtin_files_.empty()) {
    builtin_ = std::make_unique<Lexicon>(load_builtin_lexicon(builtin_files_));
    layers_.push_layer(*builtin_);
  }
  try {
    const std::filesystem::path path(user_db_);
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    user_ = std::make_unique<Lexicon>(Lexicon::open(user_db_, 500));
    user_->size();  // a file that is not a database fails here, not at the first save
    layers_.push_layer(*user_);
  } catch (const std::exception& e) {
    user_.reset();
    user_error_ = e.what();
    status_ = "the user lexicon " + user_db_ + " cannot be opened (" + user_error_ + "): read-only, nothing will be saved";
  }
  draft_.source = "gestura studio";
  clean_ = draft_;
}

StudioModel::~StudioModel() = default;

std::vector<BrowseRow> StudioModel::browse(const BrowseFilter& filter, std::size_t limit) {
  std::vector<SignEntry> entries;
  try {
    entries = filter.text.empty() ? layers_.list(filter.language)
                                  : layers_.search(filter.text, SearchMode::substring, filter.language, limit);
  } catch (const std::exception& e) {
    status_ = std::string("cannot read the lexicon: ") + e.what();
    return {};
  }
  std::vector<BrowseRow> rows;
  for (SignEntry& e : entries) {
    if (!contains_symbol(e, filter.handshape) || !contains_symbol(e, filter.location)) continue;
    bool builtin = true;
    if (user_) {
      try {
        builtin = !user_->find(e.gloss, e.language, e.variant).has_value();
      } catch (const std::exception&) {
      }
    }
    rows.push_back({std::move(e), builtin});
    if (rows.size() >= limit) break;
  }
  return rows;
}

std::vector<SignEntry> StudioModel::user_signs() {
  if (!user_) return {};
  try {
    return user_->list();
  } catch (const std::exception& e) {
    status_ = std::string("cannot read the lexicon: ") + e.what();
    return {};
  }
}

std::optional<BrowseRow> StudioModel::find(const EntryKey& key) {
  try {
    if (user_)
      if (auto e = user_->find(key.gloss, key.language, key.variant)) return BrowseRow{std::move(*e), false};
    if (builtin_)
      if (auto e = builtin_->find(key.gloss, key.language, key.variant)) return BrowseRow{std::move(*e), true};
  } catch (const std::exception& e) {
    status_ = std::string("cannot read the lexicon: ") + e.what();
  }
  return std::nullopt;
}

std::optional<SignEntry> StudioModel::user_row(const EntryKey& key) {
  if (!user_) return std::nullopt;
  return user_->find(key.gloss, key.language, key.variant);
}

void StudioModel::set_draft(const SignDraft& draft) {
  if (draft == draft_) return;
  draft_ = draft;
  ++revision_;
}

void StudioModel::restore_draft(const SignDraft& draft) {
  set_draft(draft);
  history_.seal();
}

void StudioModel::edit(const std::string& label, SignDraft after, const std::string& merge_key) {
  if (after == draft_) return;
  history_.push(Edit{label, draft_, after, std::nullopt, merge_key});
  set_draft(after);
  status_ = label;
}

void StudioModel::new_sign() {
  SignDraft d;
  d.language = draft_.language.empty() ? "ase" : draft_.language;
  d.source = "gestura studio";
  history_.seal();
  edit("new sign", d);
  clean_ = draft_;
  history_.seal();
}

bool StudioModel::open(const EntryKey& key) {
  const auto row = find(key);
  if (!row) {
    status_ = "no sign " + key_text(key);
    return false;
  }
  try {
    SignDraft d = draft_from_entry(row->entry, row->builtin);
    history_.seal();
    edit("open " + key_text(key), d);
    history_.seal();
    clean_ = draft_;
    status_ = "opened " + key_text(key) + (row->builtin ? " from the built-in lexicon (saving writes a copy into yours)" : "");
    return true;
  } catch (const std::exception& e) {
    status_ = e.what();
    return false;
  }
}

void StudioModel::duplicate() {
  SignDraft d = draft_;
  d.origin.reset();
  d.from_builtin = false;
  int variant = 1;
  try {
    for (const SignEntry& e : layers_.find_all(d.gloss, d.language)) variant = std::max(variant, e.variant + 1);
  } catch (const std::exception&) {
  }
  d.variant = variant;
  history_.seal();
  edit("duplicate as variant " + std::to_string(variant), d);
  history_.seal();
}

bool StudioModel::replace_symbol(int index, const std::string& name) {
  auto tokens = name_tokens(draft_.names);
  if (index < 0 || index >= static_cast<int>(tokens.size())) {
    status_ = "no symbol " + std::to_string(index) + " (the notation has " + std::to_string(tokens.size()) + ")";
    return false;
  }
  if (!sign::symbol_from_name(name)) {
    status_ = "unknown symbol name '" + name + "'";
    return false;
  }
  const std::string old = tokens[index];
  tokens[index] = name;
  SignDraft d = draft_;
  d.names = join_names(tokens);
  history_.seal();
  edit("replace symbol " + std::to_string(index) + " " + old + " by " + name, d);
  history_.seal();
  return true;
}

bool StudioModel::insert_symbol(int index, const std::string& name) {
  auto tokens = name_tokens(draft_.names);
  if (index < 0 || index > static_cast<int>(tokens.size())) {
    status_ = "cannot insert at " + std::to_string(index) + " (the notation has " + std::to_string(tokens.size()) + " symbols)";
    return false;
  }
  if (!sign::symbol_from_name(name)) {
    status_ = "unknown symbol name '" + name + "'";
    return false;
  }
  tokens.insert(tokens.begin() + index, name);
  SignDraft d = draft_;
  d.names = join_names(tokens);
  history_.seal();
  edit("insert " + name + " at " + std::to_string(index), d);
  history_.seal();
  return true;
}

bool StudioModel::remove_symbol(int index) {
  auto tokens = name_tokens(draft_.names);
  if (index < 0 || index >= static_cast<int>(tokens.size())) {
    status_ = "no symbol " + std::to_string(index) + " to remove";
    return false;
  }
  const std::string old = tokens[index];
  tokens.erase(tokens.begin() + index);
  SignDraft d = draft_;
  d.names = join_names(tokens);
  history_.seal();
  edit("remove symbol " + std::to_string(index) + " " + old, d);
  history_.seal();
  return true;
}

bool StudioModel::set_nonmanual(sign::NonManualTier tier, const std::string& value, const std::string& merge_key) {
  const NonManualTierInfo& info = tier_info(tier);
  if (!value.empty())
    if (const auto problem = nonmanual_value_problem(tier, value)) {
      status_ = "not changed: " + *problem;
      return false;
    }
  SignDraft d = draft_;
  d.nonmanuals = with_tier_value(draft_.nonmanuals, tier, value);
  if (d == draft_) {
    status_ = std::string(info.label) + " is already " + (value.empty() ? std::string("empty") : value);
    return false;
  }
  std::string label = std::string(info.label) + " ";
  if (value.empty()) {
    label += "cleared";
  } else {
    label += value;
    if (const auto meaning = code_meaning(tier, value); !meaning.empty()) label += " (" + std::string(meaning) + ")";
  }
  if (!merge_key.empty()) {
    edit(std::string(info.label) + " edited", d, merge_key);
    return true;
  }
  history_.seal();
  edit(label, d);
  history_.seal();
  return true;
}

void StudioModel::apply_store(const StoreChange& change, bool forward) {
  user_->atomically([&] {
    if (forward) {
      for (const SignEntry& r : change.removed) user_->remove(r.gloss, r.language, r.variant);
      if (change.written) user_->add(*change.written, OnConflict::replace);
    } else {
      if (change.written) user_->remove(change.written->gloss, change.written->language, change.written->variant);
      for (const SignEntry& r : change.removed) user_->add(r, OnConflict::replace);
    }
  });
}

bool StudioModel::save() {
  history_.seal();
  if (!user_) {
    status_ = "not saved: the user lexicon is not writable (" + user_error_ + "); the draft is kept";
    return false;
  }
  SignEntry entry;
  try {
    entry = to_entry(draft_);
  } catch (const Error& e) {
    status_ = "not saved: " + (e.where().index >= 0 ? "symbol " + std::to_string(e.where().index) + ": " : std::string()) +
              e.message() + " (the draft is kept)";
    return false;
  }
  try {
    StoreChange change;
    const EntryKey target = key_of(entry);
    if (draft_.origin && *draft_.origin != target && !draft_.from_builtin)
      if (auto old = user_row(*draft_.origin)) change.removed.push_back(std::move(*old));
    if (auto existing = user_row(target)) change.removed.push_back(std::move(*existing));
    change.written = entry;
    apply_store(change, true);
    SignDraft after = draft_;
    after.origin = target;
    after.from_builtin = false;
    history_.push(Edit{"save " + key_text(target), draft_, after, change, {}});
    history_.seal();
    set_draft(after);
    clean_ = draft_;
    status_ = "saved " + key_text(target) + " in " + user_db_;
    return true;
  } catch (const std::exception& e) {
    status_ = std::string("not saved: ") + e.what() + " (the database is unchanged, the draft is kept)";
    return false;
  }
}

bool StudioModel::remove() {
  history_.seal();
  if (!user_) {
    status_ = "nothing removed: the user lexicon is not writable";
    return false;
  }
  if (!draft_.origin || draft_.from_builtin) {
    status_ = draft_.from_builtin ? "built-in signs cannot be deleted (save a copy into your lexicon to change one)"
                                  : "the draft is not stored: nothing to delete";
    return false;
  }
  try {
    auto row = user_row(*draft_.origin);
    if (!row) {
      status_ = "no sign " + key_text(*draft_.origin) + " in " + user_db_;
      return false;
    }
    StoreChange change;
    change.removed.push_back(std::move(*row));
    apply_store(change, true);
    SignDraft after = draft_;
    after.origin.reset();
    history_.push(Edit{"delete " + key_text(*draft_.origin), draft_, after, change, {}});
    history_.seal();
    status_ = "deleted " + key_text(*draft_.origin) + " (the draft stays open; undo brings the row back)";
    set_draft(after);
    return true;
  } catch (const std::exception& e) {
    status_ = std::string("not deleted: ") + e.what();
    return false;
  }
}

bool StudioModel::undo() {
  if (!history_.can_undo()) {
    status_ = "nothing to undo";
    return false;
  }
  const Edit& e = history_.undo();
  try {
    if (e.store) apply_store(*e.store, false);
  } catch (const std::exception& ex) {
    history_.redo();
    status_ = std::string("cannot undo ") + e.label + ": " + ex.what();
    return false;
  }
  set_draft(e.before);
  status_ = "undid " + e.label;
  return true;
}

bool StudioModel::redo() {
  if (!history_.can_redo()) {
    status_ = "nothing to redo";
    return false;
  }
  const Edit& e = history_.redo();
  try {
    if (e.store) apply_store(*e.store, true);
  } catch (const std::exception& ex) {
    history_.undo();
    status_ = std::string("cannot redo ") + e.label + ": " + ex.what();
    return false;
  }
  set_draft(e.after);
  status_ = "redid " + e.label;
  return true;
}

}  // namespace gestura::studio
