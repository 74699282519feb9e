#include "gestura/app/lexicon.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gestura/app/input_file.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/lexicon/sign_language_codes.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::app {
namespace {

std::string user_db_path(const std::string& db) { return db.empty() ? default_user_lexicon_path() : db; }

Lexicon open_for_writing(const std::string& db) {
  const std::filesystem::path path = user_db_path(db);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  return Lexicon::open(path.string());
}

// The layers queries look through: built-in files (if any), then the user file (if it exists).
struct ReadView {
  std::optional<Lexicon> builtin, user;
  LayeredLexicon view;

  explicit ReadView(const std::string& db) {
    if (const auto files = builtin_lexicon_files(); !files.empty()) {
      builtin.emplace(load_builtin_lexicon(files));
      view.push_layer(*builtin);
    }
    const std::string path = user_db_path(db);
    if (!db.empty() && !std::filesystem::exists(path)) throw AppError(ErrorCategory::not_found, Place{"db", {path}}, "no such lexicon");
    if (std::filesystem::exists(path)) {
      user.emplace(Lexicon::open_read_only(path));
      view.push_layer(*user);
    }
  }
};

// "symbol 3 (hamextfingeru, U+E020)": the symbol of a HamNoSys text at a parser's symbol index.
std::string symbol_at(std::string_view hamnosys, int index) {
  std::string out = "symbol " + std::to_string(index);
  try {
    const std::vector<sign::Symbol> symbols = sign::symbols_from_unicode(hamnosys);
    if (index >= 0 && static_cast<std::size_t>(index) < symbols.size()) {
      const sign::Symbol s = symbols[static_cast<std::size_t>(index)];
      char hex[16];
      std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(sign::symbol_info(s).codepoint));
      out += " (" + std::string(sign::symbol_name(s)) + ", " + hex + ")";
    } else if (index >= 0) {
      out += " (the end of the notation)";
    }
  } catch (const Error&) {  // the text itself does not decode; the parser's message names the code point
  }
  return out;
}

// Refuses an entry whose notation does not parse, naming where it stops. Lenient parsing, as
// `gestura check` does by default: what real lexicons contain is accepted.
void check_notation(const SignEntry& e) {
  switch (e.notation_kind) {
    case NotationKind::clip: return;
    case NotationKind::sigml:
      try {
        if (sign::read_sigml(e.notation).empty()) throw Error("no <hns_sign> element");
      } catch (const Error& err) {
        throw Error("sign '" + e.gloss + "': SiGML does not parse: " + err.what());
      }
      return;
    case NotationKind::hamnosys:
      try {
        (void)sign::parse_hamnosys_unicode(e.notation);
      } catch (const Error& err) {
        throw Error("sign '" + e.gloss + "': HamNoSys does not parse at " + symbol_at(e.notation, err.where().index) +
                    ": " + err.message());
      }
      return;
  }
}

nlohmann::json entry_json(const SignEntry& e) {
  nlohmann::json keywords = nlohmann::json::array();
  for (const Keyword& k : e.keywords) keywords.push_back({{"word", k.word}, {"language", k.language}, {"meaning", k.meaning}});
  return {{"gloss", e.gloss},
          {"language", e.language},
          {"variant", e.variant},
          {"notation_kind", to_string(e.notation_kind)},
          {"notation", e.notation_kind == NotationKind::clip ? std::string() : e.notation},
          {"keywords", keywords},
          {"source", e.source},
          {"licence", e.licence},
          {"agreement", to_string(e.agreement)}};
}

}  // namespace

LexiconQueryKind TextCodec<LexiconQueryKind>::parse(std::string_view text) {
  if (text == "list") return LexiconQueryKind::list;
  if (text == "show") return LexiconQueryKind::show;
  if (text == "search") return LexiconQueryKind::search;
  throw Error("'" + std::string(text.substr(0, 40)) + "' is not list, show or search");
}

std::string TextCodec<LexiconQueryKind>::format(LexiconQueryKind kind) {
  return kind == LexiconQueryKind::list ? "list" : kind == LexiconQueryKind::show ? "show" : "search";
}

void validate(const LexiconQuery& query) {
  check_fields(query);
  if (query.kind == LexiconQueryKind::list && !query.text.empty()) usage_error("text", "list takes no text");
  if (query.kind != LexiconQueryKind::list && query.text.empty())
    usage_error("text", query.kind == LexiconQueryKind::show ? "missing: the gloss to show" : "missing: the text to search for");
  if (query.prefix && query.kind != LexiconQueryKind::search) usage_error("prefix", "applies to search");
}

LexiconQueryResult run(const LexiconQuery& query, const RunContext&) {
  validate(query);
  ReadView r(query.db);
  LexiconQueryResult result;
  switch (query.kind) {
    case LexiconQueryKind::list: result.entries = r.view.list(query.lang); break;
    case LexiconQueryKind::show:
      result.entries = r.view.find_all(query.text, query.lang);
      if (result.entries.empty())
        not_found("text", "no sign '" + query.text + "'" + (query.lang.empty() ? "" : " in " + query.lang));
      break;
    case LexiconQueryKind::search:
      result.entries = r.view.search(query.text, query.prefix ? SearchMode::prefix : SearchMode::substring, query.lang);
      break;
  }
  return result;
}

nlohmann::json to_json(const LexiconQueryResult& result) {
  nlohmann::json entries = nlohmann::json::array();
  for (const SignEntry& e : result.entries) entries.push_back(entry_json(e));
  return {{"entries", entries}};
}

nlohmann::json to_json(const LexiconChangeResult& result) {
  nlohmann::json bad = nlohmann::json::array();
  for (const Notice& n : result.bad_lines)
    bad.push_back({{"file", n.where.file}, {"line", n.where.line}, {"message", n.message}});
  return {{"count", result.count}, {"skipped", result.skipped}, {"path", result.path}, {"bad_lines", bad}};
}

void validate(const LexiconAddRequest& request) {
  check_fields(request);
  if (request.hamnosys.empty() == request.sigml.empty()) usage_error("hamnosys", "give exactly one of --hamnosys and --sigml");
}

LexiconChangeResult run(const LexiconAddRequest& request, const RunContext&) {
  validate(request);
  SignEntry e;
  e.gloss = request.gloss;
  e.language = request.lang;
  e.variant = request.variant.value_or(1);
  if (!request.hamnosys.empty()) {
    e.notation = request.hamnosys;
  } else {
    require_file("sigml", request.sigml);
    e.notation_kind = NotationKind::sigml;
    e.notation = read_sigml_sign(request.sigml, request.gloss);
  }
  std::stringstream list(request.keywords);
  for (std::string word; std::getline(list, word, ',');)
    if (!word.empty()) e.keywords.push_back(Keyword{word});
  e.source = request.source.empty() ? "gestura lexicon add" : request.source;
  e.licence = request.licence;
  as_field_error(ErrorCategory::input, "agreement", [&] { e.agreement = agreement_from_string(request.agreement); });
  as_field_error(ErrorCategory::input, "lang", [&] { require_known_sign_language(e.language); });
  as_field_error(ErrorCategory::input, request.hamnosys.empty() ? "sigml" : "hamnosys", [&] { check_notation(e); });
  Lexicon lex = open_for_writing(request.db);
  if (!request.replace && lex.find(e.gloss, e.language, e.variant))
    throw AppError(ErrorCategory::conflict, Place{"gloss", {}},
                   "sign '" + e.gloss + "' (" + e.language + ", variant " + std::to_string(e.variant) +
                       ") already exists in " + lex.path() + " (--replace replaces it)");
  lex.add(e, request.replace ? OnConflict::replace : OnConflict::fail);
  return {1, 0, lex.path(), e.gloss, e.language};
}

void validate(const LexiconImportRequest& request) { check_fields(request); }

LexiconChangeResult run(const LexiconImportRequest& request, const RunContext&) {
  validate(request);
  require_file("file", request.file);
  Lexicon lex = open_for_writing(request.db);
  ImportOptions options;
  options.language = request.lang;
  options.licence = request.licence;
  options.source = request.source;
  options.check = check_notation;
  LexiconChangeResult result;
  if (request.skip_bad) {
    options.skip_bad = [&](const Error& bad) {
      SourceLocation where = bad.where();
      where.index = -1;
      result.bad_lines.push_back(warning("skipped: " + bad.message(), where));
    };
  }
  result.count = import_file(lex, request.file, options);
  result.skipped = result.bad_lines.size();
  result.path = lex.path();
  return result;
}

void validate(const LexiconExportRequest& request) { check_fields(request); }

LexiconChangeResult run(const LexiconExportRequest& request, const RunContext&) {
  validate(request);
  const std::string path = user_db_path(request.db);
  if (!std::filesystem::exists(path)) throw AppError(ErrorCategory::not_found, Place{"db", {path}}, "no such lexicon");
  Lexicon lex = Lexicon::open_read_only(path);
  const auto entries = lex.list(request.lang);
  LexiconChangeResult result;
  // All or nothing: written to a temporary, checked, synced and renamed (a full disk leaves no file).
  as_field_error(ErrorCategory::output, "file", [&] { result.count = export_file(entries, request.file); });
  result.skipped = entries.size() - result.count;
  result.path = request.file;
  return result;
}

void validate(const LexiconRemoveRequest& request) { check_fields(request); }

LexiconChangeResult run(const LexiconRemoveRequest& request, const RunContext&) {
  validate(request);
  Lexicon lex = open_for_writing(request.db);
  LexiconChangeResult result;
  result.count = lex.remove(request.gloss, request.lang, request.variant);
  result.path = lex.path();
  if (result.count == 0) not_found("gloss", "no sign '" + request.gloss + "' in " + request.lang + " in " + lex.path());
  return result;
}

}  // namespace gestura::app
