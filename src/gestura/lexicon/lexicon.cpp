#include "gestura/lexicon/lexicon.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <pugixml.hpp>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/schema.hpp"
#include "gestura/lexicon/sign_language_codes.hpp"

namespace gestura {

namespace {

constexpr std::string_view kSignColumns =
    "SELECT id, gloss, lang, variant, notation_kind, notation, clip, source, licence, created, updated, agreement FROM signs ";

std::string ascii_lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c + 32 : c); });
  return out;
}

// LIKE pattern that matches `text` literally.
std::string like_escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '%' || c == '_' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out;
}

// Stored SiGML must be one well-formed element, nested no deeper than real signs come near: a
// hostile entry 300,000 elements deep once made `lexicon export` indent its way to 16 GB of memory.
void validate_sigml(const SignEntry& e) {
  pugi::xml_document doc;
  if (!doc.load_buffer(e.notation.data(), e.notation.size()) || !doc.first_child())
    throw Error("gloss '" + e.gloss + "': its SiGML notation is not well-formed XML");
  struct DepthCheck : pugi::xml_tree_walker {
    bool too_deep = false;
    bool for_each(pugi::xml_node&) override {
      too_deep = depth() >= kMaxStoredSigmlDepth;
      return !too_deep;
    }
  } check;
  doc.traverse(check);
  if (check.too_deep)
    throw Error("gloss '" + e.gloss + "': its SiGML elements nest deeper than " +
                std::to_string(kMaxStoredSigmlDepth) + " (kMaxStoredSigmlDepth)");
}

void validate(const SignEntry& e) {
  if (e.gloss.empty()) throw Error("sign entry has an empty gloss");
  if (e.gloss.find_first_of("\n\r\t") != std::string::npos)
    throw Error("gloss '" + e.gloss + "' contains a control character");
  require_known_sign_language(e.language);
  if (e.variant < 0) throw Error("gloss '" + e.gloss + "': variant must be 1 or more");
  if (e.notation_kind == NotationKind::clip ? e.clip.empty() : e.notation.empty())
    throw Error("gloss '" + e.gloss + "' has no " + std::string(to_string(e.notation_kind)) + " notation");
  if (e.notation_kind == NotationKind::sigml) validate_sigml(e);
  for (const Keyword& k : e.keywords) {
    if (k.word.empty()) throw Error("gloss '" + e.gloss + "' has an empty keyword");
    if (!is_spoken_language_code(k.language))
      throw Error("gloss '" + e.gloss + "': keyword '" + k.word + "' has a bad language code '" + k.language +
                  "' (expected ISO 639-1/3 like eng or en)");
  }
}

}  // namespace

Lexicon::Lexicon(sqlite::Database db) : db_(std::move(db)) {
  db_.exec("PRAGMA foreign_keys = ON");
  if (!db_.read_only()) {
    lexicon_schema::migrate(db_);
    return;
  }
  const int version = lexicon_schema::version_of(db_);
  if (version == lexicon_schema::current_version()) return;
  if (version > lexicon_schema::current_version())
    throw Error(SourceLocation{db_.path()}, "lexicon schema version " + std::to_string(version) +
                                                " is newer than this program supports (" +
                                                std::to_string(lexicon_schema::current_version()) + ")");
  throw Error(SourceLocation{db_.path()},
              version == 0 ? "not a gestura lexicon (no schema version)"
                           : "lexicon schema version " + std::to_string(version) +
                                 " is older than this program's; it cannot be upgraded while read-only (open it "
                                 "for writing once, e.g. with lexicon add or import)");
}

void Lexicon::require_writable() const {
  if (db_.read_only())
    throw Error(SourceLocation{db_.path()}, "the lexicon was opened read-only; adding, importing and removing need "
                                            "it opened for writing");
}

namespace {

bool writable(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  return ::access(path.c_str(), W_OK) == 0 && ::access(folder.empty() ? "." : folder.c_str(), W_OK) == 0;
}

}  // namespace

Lexicon Lexicon::open_read_only(const std::string& path, int busy_timeout_ms) {
  {
    // A file from an older version is upgraded once, as opening it for writing always did, when it
    // can be written; a read-only one must already be current (the constructor says so).
    sqlite::Database probe(path, sqlite::Access::read, busy_timeout_ms);
    const int version = lexicon_schema::version_of(probe);
    if (version > 0 && version < lexicon_schema::current_version() && writable(path)) open(path, busy_timeout_ms);
  }
  return Lexicon(sqlite::Database(path, sqlite::Access::read, busy_timeout_ms));
}

Lexicon Lexicon::open(const std::string& path, int busy_timeout_ms) {
  // SQLite would say "unable to open database file" or "attempt to write a readonly database"
  // somewhere later; say what is wrong before anything is tried. (access() also sees read-only
  // mounts and immutable files, which stop root as well.)
  if (path != ":memory:" && std::filesystem::exists(path)) {
    if (!writable(path))
      throw Error(SourceLocation{path}, std::string("the lexicon is read-only (") + std::strerror(errno) +
                                            "): it can be listed, searched and exported, but adding, importing "
                                            "and removing need the file and its folder writable");
  }
  sqlite::Database db(path, true, busy_timeout_ms);
  // Nothing is written into a damaged file: a write could spread the damage over pages that are
  // still good. Reading (open_read_only) still works, so what is left can be exported.
  if (const std::string problems = db.integrity_problems(); !problems.empty())
    throw Error(SourceLocation{path}, "the lexicon database is damaged (quick_check: " + problems +
                                          "); it is left as it is and not written to. Export what can still be "
                                          "read (gestura lexicon export) and import it into a new file");
  // WAL lets readers in other processes keep a consistent snapshot while one writer commits.
  {
    auto mode = db.prepare("PRAGMA journal_mode = WAL");
    mode.step();
  }  // finalized before the schema migration runs DDL
  return Lexicon(std::move(db));
}

Lexicon Lexicon::in_memory() { return Lexicon(sqlite::Database(":memory:", true)); }

std::int64_t Lexicon::add(SignEntry e, OnConflict on_conflict) {
  require_writable();
  validate(e);
  sqlite::Transaction tx(db_);
  if (e.variant == 0) {
    auto next = db_.prepare("SELECT COALESCE(MAX(variant), 0) + 1 FROM signs WHERE gloss = ?1 AND lang = ?2");
    next.bind(1, e.gloss).bind(2, e.language);
    next.step();
    e.variant = static_cast<int>(next.integer(0));
  }
  std::optional<std::int64_t> created;
  {
    auto existing = db_.prepare("SELECT id, created FROM signs WHERE gloss = ?1 AND lang = ?2 AND variant = ?3");
    existing.bind(1, e.gloss).bind(2, e.language).bind(3, std::int64_t{e.variant});
    if (existing.step()) {
      if (on_conflict == OnConflict::fail)
        throw Error("sign '" + e.gloss + "' (" + e.language + ", variant " + std::to_string(e.variant) +
                    ") already exists in " + db_.path());
      created = existing.integer(1);
      auto drop = db_.prepare("DELETE FROM signs WHERE id = ?1");
      drop.bind(1, existing.integer(0)).run();
    }
  }
  auto& insert = db_.cached(
      "INSERT INTO signs (gloss, lang, variant, notation_kind, notation, clip, source, licence, created, updated, "
      "agreement) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, COALESCE(?9, unixepoch()), unixepoch(), ?10)");
  insert.bind(1, e.gloss).bind(2, e.language).bind(3, std::int64_t{e.variant});
  insert.bind(4, to_string(e.notation_kind)).bind(5, e.notation);
  if (e.clip.empty()) insert.bind_null(6); else insert.bind(6, e.clip);
  insert.bind(7, e.source).bind(8, e.licence);
  if (created) insert.bind(9, *created); else insert.bind_null(9);
  insert.bind(10, to_string(e.agreement));
  insert.run();
  const std::int64_t id = db_.last_insert_rowid();
  auto& keyword = db_.cached("INSERT INTO keywords (sign_id, word, lang, meaning) VALUES (?1, ?2, ?3, ?4)");
  for (const Keyword& k : e.keywords) {
    keyword.reset();
    keyword.bind(1, id).bind(2, ascii_lower(k.word)).bind(3, k.language).bind(4, k.meaning).run();
  }
  tx.commit();
  return id;
}

std::size_t Lexicon::remove(std::string_view gloss, std::string_view language, std::optional<int> variant) {
  require_writable();
  sqlite::Transaction tx(db_);
  auto drop = db_.prepare(variant ? "DELETE FROM signs WHERE gloss = ?1 AND lang = ?2 AND variant = ?3"
                                  : "DELETE FROM signs WHERE gloss = ?1 AND lang = ?2");
  drop.bind(1, gloss).bind(2, language);
  if (variant) drop.bind(3, std::int64_t{*variant});
  drop.run();
  const auto removed = static_cast<std::size_t>(db_.changes());
  tx.commit();
  return removed;
}

std::optional<std::array<std::int64_t, 2>> Lexicon::version() {
  if (sqlite3_get_autocommit(db_.handle()) == 0) return std::nullopt;
  auto& data_version = db_.cached("PRAGMA data_version");
  data_version.step();
  const std::int64_t committed = data_version.integer(0);
  data_version.reset();
  return std::array<std::int64_t, 2>{committed, sqlite3_total_changes64(db_.handle())};
}

std::vector<SignEntry> Lexicon::query(std::string_view where_and_order, const std::vector<std::string>& params) {
  // Inside a transaction the answer may hold what a rollback takes back: not kept.
  const auto now = version();
  if (!now) return query_database(where_and_order, params);
  std::string key(where_and_order);
  for (const std::string& p : params) key.append(1, '\x1f').append(p);
  {
    if ((*now)[0] != memo_.data_version || (*now)[1] != memo_.changes) {
      memo_.results.clear();
      memo_.data_version = (*now)[0];
      memo_.changes = (*now)[1];
    }
    if (auto hit = memo_.results.find(key); hit != memo_.results.end()) return hit->second;
  }
  std::vector<SignEntry> out = query_database(where_and_order, params);
  // Bounded: a long-lived server asks many different questions.
  constexpr std::size_t kMemoEntries = 4096;
  if (memo_.results.size() >= kMemoEntries) memo_.results.clear();
  memo_.results.emplace(std::move(key), out);
  return out;
}

std::vector<SignEntry> Lexicon::query_database(std::string_view where_and_order, const std::vector<std::string>& params) {
  auto& stmt = db_.cached(std::string(kSignColumns) + std::string(where_and_order));
  for (std::size_t i = 0; i < params.size(); ++i) stmt.bind(static_cast<int>(i + 1), params[i]);
  std::vector<SignEntry> out;
  while (stmt.step()) {
    SignEntry e;
    e.id = stmt.integer(0);
    e.gloss = stmt.text(1);
    e.language = stmt.text(2);
    e.variant = static_cast<int>(stmt.integer(3));
    e.notation_kind = notation_kind_from_string(stmt.text(4));
    e.notation = stmt.text(5);
    e.clip = stmt.blob(6);
    e.source = stmt.text(7);
    e.licence = stmt.text(8);
    e.created = stmt.integer(9);
    e.updated = stmt.integer(10);
    e.agreement = agreement_from_string(stmt.text(11));
    out.push_back(std::move(e));
  }
  for (SignEntry& e : out) load_keywords(e);
  return out;
}

void Lexicon::load_keywords(SignEntry& entry) {
  auto& stmt = db_.cached("SELECT word, lang, meaning FROM keywords WHERE sign_id = ?1 ORDER BY rowid");
  stmt.bind(1, entry.id);
  while (stmt.step()) entry.keywords.push_back(Keyword{stmt.text(0), stmt.text(1), stmt.text(2)});
}

std::optional<SignEntry> Lexicon::find(std::string_view gloss, std::string_view language, int variant) {
  auto found = query("WHERE gloss = ?1 AND lang = ?2 AND variant = ?3",
                     {std::string(gloss), std::string(language), std::to_string(variant)});
  if (found.empty()) return std::nullopt;
  return std::move(found.front());
}

std::vector<SignEntry> Lexicon::find_all(std::string_view gloss, std::string_view language) {
  return query("WHERE gloss = ?1 AND (?2 = '' OR lang = ?2) ORDER BY lang, variant",
               {std::string(gloss), std::string(language)});
}

std::vector<SignEntry> Lexicon::by_keyword(std::string_view word, std::string_view language,
                                           std::string_view spoken) {
  return query(
      "WHERE id IN (SELECT sign_id FROM keywords WHERE word = ?1 AND lang = ?3) AND (?2 = '' OR lang = ?2) "
      "ORDER BY lang, gloss, variant",
      {ascii_lower(word), std::string(language), std::string(spoken)});
}

std::vector<SignEntry> Lexicon::search(std::string_view text, SearchMode mode, std::string_view language,
                                       std::size_t limit) {
  std::string pattern;
  if (mode == SearchMode::substring) pattern.push_back('%');
  pattern.append(like_escaped(ascii_lower(text)));
  pattern.push_back('%');
  return query(
      "WHERE (gloss LIKE ?1 ESCAPE '\\' OR id IN (SELECT sign_id FROM keywords WHERE word LIKE ?1 ESCAPE '\\')) "
      "AND (?2 = '' OR lang = ?2) ORDER BY gloss <> ?3, gloss, lang, variant LIMIT " +
          std::to_string(limit),
      {pattern, std::string(language), std::string(text)});
}

std::vector<SignEntry> Lexicon::list(std::string_view language) {
  return query("WHERE ?1 = '' OR lang = ?1 ORDER BY gloss, lang, variant", {std::string(language)});
}

std::size_t Lexicon::size() {
  auto stmt = db_.prepare("SELECT COUNT(*) FROM signs");
  stmt.step();
  return static_cast<std::size_t>(stmt.integer(0));
}

void Lexicon::atomically(const std::function<void()>& body) {
  require_writable();
  sqlite::Transaction tx(db_);
  body();
  tx.commit();
}

}  // namespace gestura
