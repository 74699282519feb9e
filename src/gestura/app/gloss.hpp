#pragma once
// gloss: English text → ASL glosses, with the reason for every word (text/translator.hpp).
#include <string>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/text/gloss.hpp"

namespace gestura::app {

// The most text one gloss request translates.
inline constexpr std::size_t kMaxGlossBytes = 4u * 1024u * 1024u;

struct GlossRequest {
  std::string text;
  std::string lang = "ase";
  std::string db;     // the user lexicon; default: the user's (GESTURA_LEXICON, XDG data home)
  bool open = false;  // every word taken as signable, no lexicon

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.text, FieldInfo{.name = "text", .help = "English text to translate", .value = "TEXT", .positional = true, .required = true});
    visit(self.lang, FieldInfo{.name = "lang", .help = "sign language of the lexicon lookups (ISO 639-3)", .value = "L"});
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite) to look signs up in besides the built-in one", .value = "PATH"});
    visit(self.open, FieldInfo{.name = "open", .help = "no lexicon: every word is taken as a sign, its gloss the lemma in capitals"});
  }
};

struct GlossResult {
  Translation translation;
  bool have_signs = true;  // false: no lexicon for lang was found, the vocabulary was open
  std::string lang;
};

void validate(const GlossRequest& request);
GlossResult run(const GlossRequest& request, const RunContext& context = {});
// {text, glosses [{gloss, kind, begin, end, reason, letters?}], notes, sentences, markers}
nlohmann::json to_json(const GlossResult& result);

}  // namespace gestura::app
