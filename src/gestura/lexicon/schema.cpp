#include "gestura/lexicon/schema.hpp"

#include <array>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura::lexicon_schema {

namespace {

// Version 1: the first layout — one notation per gloss, keywords without meanings.
constexpr std::string_view kV1 = R"sql(
CREATE TABLE signs (
  id INTEGER PRIMARY KEY,
  gloss TEXT NOT NULL COLLATE NOCASE,
  lang TEXT NOT NULL,
  notation_kind TEXT NOT NULL CHECK (notation_kind IN ('hamnosys', 'sigml', 'clip')),
  notation TEXT NOT NULL DEFAULT '',
  source TEXT NOT NULL DEFAULT '',
  created INTEGER NOT NULL DEFAULT (unixepoch())
);
CREATE UNIQUE INDEX signs_by_gloss ON signs (gloss, lang);
CREATE TABLE keywords (
  sign_id INTEGER NOT NULL REFERENCES signs (id) ON DELETE CASCADE,
  word TEXT NOT NULL,
  lang TEXT NOT NULL DEFAULT 'eng'
);
CREATE INDEX keywords_by_word ON keywords (word);
)sql";

// Version 2: variants per gloss, licence, update time, clip blobs, keyword meanings.
constexpr std::string_view kV2 = R"sql(
ALTER TABLE signs ADD COLUMN variant INTEGER NOT NULL DEFAULT 1 CHECK (variant >= 1);
ALTER TABLE signs ADD COLUMN licence TEXT NOT NULL DEFAULT '';
ALTER TABLE signs ADD COLUMN clip BLOB;
ALTER TABLE signs ADD COLUMN updated INTEGER NOT NULL DEFAULT 0;
UPDATE signs SET updated = created;
DROP INDEX signs_by_gloss;
CREATE UNIQUE INDEX signs_by_gloss ON signs (gloss, lang, variant);
ALTER TABLE keywords ADD COLUMN meaning TEXT NOT NULL DEFAULT '';
CREATE INDEX keywords_by_sign ON keywords (sign_id);
)sql";

// Version 3: agreement verbs are a property of the entry (docs/grammar.md). Rows stored before keep
// their data and gain 'none', except the ASL verbs the grammar pass used to know by name, which
// stay agreement verbs as they were.
constexpr std::string_view kV3 = R"sql(
ALTER TABLE signs ADD COLUMN agreement TEXT NOT NULL DEFAULT 'none'
  CHECK (agreement IN ('none', 'forward', 'backward'));
UPDATE signs SET agreement = 'forward' WHERE lang = 'ase' AND gloss IN
  ('GIVE', 'HELP', 'TELL', 'ASK', 'SHOW', 'SEND', 'PAY', 'INFORM', 'BOTHER', 'ANSWER', 'BLAME', 'EMAIL',
   'WARN', 'ADVISE', 'LEND', 'CHALLENGE', 'TEASE', 'PHONE', 'TEXT', 'FORGIVE');
UPDATE signs SET agreement = 'backward' WHERE lang = 'ase' AND gloss IN ('BORROW');
)sql";

constexpr std::array kMigrations{Migration{1, kV1}, Migration{2, kV2}, Migration{3, kV3}};

}  // namespace

std::span<const Migration> migrations() { return kMigrations; }

int current_version() { return kMigrations.back().to_version; }

int version_of(sqlite::Database& db) {
  auto stmt = db.prepare("PRAGMA user_version");
  return stmt.step() ? static_cast<int>(stmt.integer(0)) : 0;
}

namespace {

void require_supported(sqlite::Database& db, int version) {
  if (version > current_version())
    throw Error(SourceLocation{db.path()}, "lexicon schema version " + std::to_string(version) +
                                               " is newer than this program supports (" +
                                               std::to_string(current_version()) + ")");
}

}  // namespace

void migrate(sqlite::Database& db, int target) {
  // Check first without a write lock: opening an up-to-date lexicon must not wait for a writer.
  const int seen = version_of(db);
  require_supported(db, seen);
  if (seen >= target) return;
  sqlite::Transaction tx(db);
  const int from = version_of(db);  // another process may have upgraded meanwhile
  require_supported(db, from);
  if (from >= target) return;
  for (const Migration& step : kMigrations) {
    if (step.to_version <= from || step.to_version > target) continue;
    db.exec(step.sql);
    db.exec("PRAGMA user_version = " + std::to_string(step.to_version));
  }
  tx.commit();
}

}  // namespace gestura::lexicon_schema
