#pragma once
// Lexicon database schema, versioned with PRAGMA user_version. Each migration step takes the schema
// from version N to N+1; opening a database applies the missing steps in one transaction, so an
// interrupted upgrade leaves the old version intact.
#include <span>
#include <string_view>

#include "gestura/lexicon/sqlite.hpp"

namespace gestura::lexicon_schema {

struct Migration {
  int to_version;
  std::string_view sql;
};

std::span<const Migration> migrations();
int current_version();

int version_of(sqlite::Database& db);
// Applies the steps from the database's version up to `target` (default: current). Throws
// gestura::Error naming the file when the database is newer than this program knows.
void migrate(sqlite::Database& db, int target = current_version());

}  // namespace gestura::lexicon_schema
