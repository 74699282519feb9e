#pragma once
// lexicon: the signs gestura knows. Queries read the built-in lexicon with the user's SQLite
// lexicon on top; changes write the user's lexicon. The user lexicon is `db`, else
// $GESTURA_LEXICON, else $XDG_DATA_HOME/gestura/lexicon.sqlite, else
// ~/.local/share/gestura/lexicon.sqlite (created on first write).
#include <optional>
#include <string>
#include <vector>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/app/notice.hpp"
#include "gestura/lexicon/sign_entry.hpp"

namespace gestura::app {

enum class LexiconQueryKind { list, show, search };

template <>
struct TextCodec<LexiconQueryKind> {
  static LexiconQueryKind parse(std::string_view text);
  static std::string format(LexiconQueryKind kind);
};

struct LexiconQuery {
  LexiconQueryKind kind = LexiconQueryKind::list;
  std::string text;  // show: the gloss; search: what glosses or keywords contain
  bool prefix = false;  // search: start with text instead of containing it
  std::string lang;     // one sign language (ISO 639-3), or all
  std::string db;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.kind, FieldInfo{.name = "kind", .help = "list, show or search", .value = "KIND"});
    visit(self.text, FieldInfo{.name = "text", .help = "show: the gloss; search: the text glosses or keywords contain", .value = "TEXT", .positional = true});
    visit(self.prefix, FieldInfo{.name = "prefix", .help = "search: glosses and keywords starting with TEXT"});
    visit(self.lang, FieldInfo{.name = "lang", .help = "only this sign language (ISO 639-3: ase, bfi, gsg, pso, ins, ...)", .value = "L"});
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite file)", .value = "PATH"});
  }
};

struct LexiconQueryResult {
  std::vector<SignEntry> entries;
};

void validate(const LexiconQuery& query);
LexiconQueryResult run(const LexiconQuery& query, const RunContext& context = {});
nlohmann::json to_json(const LexiconQueryResult& result);

// What a change did.
struct LexiconChangeResult {
  std::size_t count = 0;    // signs added, imported, exported or removed
  std::size_t skipped = 0;  // export to SiGML: entries without SiGML notation
  std::string path;         // the lexicon written, or the file exported
  std::string gloss, lang;  // add: the entry
  std::vector<Notice> bad_lines;  // import --skip-bad: each line skipped, with its file, line and why
};
nlohmann::json to_json(const LexiconChangeResult& result);

struct LexiconAddRequest {
  std::string gloss, lang, hamnosys, sigml, keywords, source, licence, agreement;
  std::optional<int> variant;
  bool replace = false;
  std::string db;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.gloss, FieldInfo{.name = "gloss", .help = "the sign's gloss", .value = "G", .required = true});
    visit(self.lang, FieldInfo{.name = "lang", .help = "its sign language (ISO 639-3)", .value = "L", .required = true});
    visit(self.hamnosys, FieldInfo{.name = "hamnosys", .help = "its notation in HamNoSys Unicode", .value = "S"});
    visit(self.sigml, FieldInfo{.name = "sigml", .help = "or a SiGML file holding its <hns_sign gloss=G>", .value = "FILE"});
    visit(self.keywords, FieldInfo{.name = "keywords", .help = "English words it translates, comma-separated", .value = "a,b"});
    visit(self.variant, FieldInfo{.name = "variant", .help = "the variant number", .value = "N", .min = 1, .max = 1000000, .unset = "1"});
    visit(self.source, FieldInfo{.name = "source", .help = "where the sign comes from", .value = "S"});
    visit(self.licence, FieldInfo{.name = "licence", .help = "its licence", .value = "L"});
    visit(self.agreement, FieldInfo{.name = "agreement", .help = "none (the default), or an agreement verb: forward (subject to object) or backward", .value = "A"});
    visit(self.replace, FieldInfo{.name = "replace", .help = "replace an entry with the same gloss, language and variant"});
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite file)", .value = "PATH"});
  }
};
void validate(const LexiconAddRequest& request);
LexiconChangeResult run(const LexiconAddRequest& request, const RunContext& context = {});

struct LexiconImportRequest {
  std::string file, lang, licence, source, db;
  bool skip_bad = false;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.file, FieldInfo{.name = "file", .help = ".jsonl (one entry per line) or .sigml (needs --lang)", .value = "FILE", .positional = true, .required = true});
    visit(self.lang, FieldInfo{.name = "lang", .help = "sign language of entries that name none (ISO 639-3)", .value = "L"});
    visit(self.licence, FieldInfo{.name = "licence", .help = "licence of entries that name none", .value = "L"});
    visit(self.source, FieldInfo{.name = "source", .help = "source of entries that name none (default: the file name)", .value = "S"});
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite file)", .value = "PATH"});
    visit(self.skip_bad, FieldInfo{.name = "skip_bad", .help = "skip lines that are bad (bad JSON, missing fields, notation that does not parse), reporting each; import the rest"});
  }
};
// Entries whose notation does not parse are refused (by add and import), naming the symbol where
// the parse stops; import names the file and line too.
void validate(const LexiconImportRequest& request);
LexiconChangeResult run(const LexiconImportRequest& request, const RunContext& context = {});

struct LexiconExportRequest {
  std::string file, lang, db;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.file, FieldInfo{.name = "file", .help = ".jsonl (everything) or .sigml (SiGML entries only)", .value = "FILE", .positional = true, .required = true});
    visit(self.lang, FieldInfo{.name = "lang", .help = "only this sign language", .value = "L"});
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite file)", .value = "PATH"});
  }
};
void validate(const LexiconExportRequest& request);
LexiconChangeResult run(const LexiconExportRequest& request, const RunContext& context = {});

struct LexiconRemoveRequest {
  std::string gloss, lang;
  std::optional<int> variant;
  std::string db;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.gloss, FieldInfo{.name = "gloss", .help = "the gloss to remove", .value = "GLOSS", .positional = true, .required = true});
    visit(self.lang, FieldInfo{.name = "lang", .help = "its sign language", .value = "L", .required = true});
    visit(self.variant, FieldInfo{.name = "variant", .help = "only this variant", .value = "N", .min = 1, .max = 1000000, .unset = "all"});
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite file)", .value = "PATH"});
  }
};
void validate(const LexiconRemoveRequest& request);
LexiconChangeResult run(const LexiconRemoveRequest& request, const RunContext& context = {});

}  // namespace gestura::app
