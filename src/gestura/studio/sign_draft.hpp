#pragma once
// The sign the studio is editing, as plain data: the lexicon entry's fields, with the notation held
// as HamNoSys symbol names ("hamflathand,hamextfingeru,...") because that is what a person can read
// and type without a HamNoSys font. A draft may hold notation that does not parse; only a draft
// that parses becomes a lexicon row (to_entry). Its non-manual tiers (brows, head, gaze, mouth
// picture, ...) are kept as SiGML holds them: a sign with any becomes a SiGML row (<hns_sign> with
// <hamnosys_nonmanual> and <hamnosys_manual>), one without stays a HamNoSys row.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "gestura/lexicon/sign_entry.hpp"
#include "gestura/studio/nonmanual_tiers.hpp"

namespace gestura::studio {

// Which lexicon row a draft came from (gloss, sign language, variant), to replace it on save.
struct EntryKey {
  std::string gloss, language;
  int variant = 1;
  bool operator==(const EntryKey&) const = default;
};
EntryKey key_of(const SignEntry& entry);

struct SignDraft {
  std::string gloss, language = "ase";
  int variant = 1;
  std::string names;       // the notation as comma-separated HamNoSys symbol names
  std::vector<DraftNonManual> nonmanuals;  // non-manual tier values, in the tiers' order
  std::string keywords;    // English words, comma-separated
  std::string meaning;     // a plain description of what the sign means / looks like (first keyword's meaning)
  std::string source, licence;
  Agreement agreement = Agreement::none;  // an agreement verb's direction (docs/grammar.md)
  std::optional<EntryKey> origin;  // the row it was opened from; none for a new sign
  bool from_builtin = false;       // opened from the read-only built-in lexicon

  bool operator==(const SignDraft&) const = default;
};

// A lexicon entry as a draft. HamNoSys Unicode becomes symbol names; a SiGML <hns_sign> its symbol
// names and non-manual tiers. A clip, a gestural SiGML sign or SiGML that does not read cannot be
// edited as symbols and throws gestura::Error saying so.
SignDraft draft_from_entry(const SignEntry& entry, bool builtin);

// The names split at commas and white space, empty tokens dropped: one token per symbol.
std::vector<std::string> name_tokens(std::string_view names);
std::string join_names(const std::vector<std::string>& tokens);

// Where the notation fails to parse: the symbol index (into name_tokens) and the parser's message.
struct NotationError {
  int symbol = -1;  // -1: not at one symbol
  std::string message;
};
// nullopt when the draft's notation parses (strictly enough to perform: the lenient parser).
std::optional<NotationError> notation_error(const SignDraft& draft);

// The draft as a lexicon row: HamNoSys Unicode notation, or a SiGML <hns_sign> when it has non-manual
// tiers. Throws gestura::Error with the symbol index when the notation does not parse, and for an
// empty gloss or language or a tier value SiGML cannot hold.
SignEntry to_entry(const SignDraft& draft);

// The <hns_sign> element of a draft (the notation of the SiGML row to_entry writes).
std::string hns_sign_xml(const SignDraft& draft);

nlohmann::json to_json(const SignDraft& draft);
// Throws gestura::Error for a value of the wrong type.
SignDraft draft_from_json(const nlohmann::json& json);

}  // namespace gestura::studio
