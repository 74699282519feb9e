#pragma once
// A lexicon of signs stored in SQLite. One Lexicon owns one connection; it is not shared between
// threads. Files are opened in WAL mode so readers in other processes see the last committed state
// while a writer works; every write is one transaction.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gestura/lexicon/sign_entry.hpp"
#include "gestura/lexicon/sqlite.hpp"

namespace gestura {

enum class OnConflict { fail, replace };

// The deepest nesting of elements a stored SiGML notation may have (real signs: under 10).
inline constexpr int kMaxStoredSigmlDepth = 64;
enum class SearchMode { prefix, substring };

class Lexicon {
 public:
  // Opens or creates the database file for reading and writing, upgrading its schema. Waits
  // `busy_timeout_ms` for a lock held by another connection, then fails with an Error naming the
  // file. A file that fails SQLite's quick_check is refused (nothing is written into a damaged
  // database); so is a read-only one.
  static Lexicon open(const std::string& path, int busy_timeout_ms = 2000);
  // Opens an existing database for reading only: never writes to the file or its folder, so
  // read-only files, folders and mounts and immutable files can be listed and searched. A file of
  // an older schema is upgraded first when it can be written; a read-only one must be current.
  // add, remove and atomically throw an Error naming the file.
  static Lexicon open_read_only(const std::string& path, int busy_timeout_ms = 2000);
  // A private database in memory (the built-in layer, tests).
  static Lexicon in_memory();

  const std::string& path() const { return db_.path(); }

  // Stores `entry`; returns its id. Validates gloss, sign-language code and notation. A variant of 0
  // takes the next free variant number of that gloss. With OnConflict::fail an existing
  // gloss+language+variant is an error; with replace the old entry (and its keywords) is replaced,
  // keeping its creation time.
  std::int64_t add(SignEntry entry, OnConflict on_conflict = OnConflict::fail);
  // Removes the entries of `gloss` in `language` (one variant, or all when nullopt); returns how many.
  std::size_t remove(std::string_view gloss, std::string_view language, std::optional<int> variant = std::nullopt);

  std::optional<SignEntry> find(std::string_view gloss, std::string_view language, int variant = 1);
  // Every variant of `gloss`, in every sign language when `language` is empty.
  std::vector<SignEntry> find_all(std::string_view gloss, std::string_view language = {});
  // Signs whose keywords contain `word` (case-insensitive) in spoken language `spoken`; restricted to
  // one sign language unless `language` is empty.
  std::vector<SignEntry> by_keyword(std::string_view word, std::string_view language = {},
                                    std::string_view spoken = "eng");
  // Entries whose gloss or a keyword starts with / contains `text` (ASCII case-insensitive), exact
  // gloss matches first, at most `limit`.
  std::vector<SignEntry> search(std::string_view text, SearchMode mode = SearchMode::substring,
                                std::string_view language = {}, std::size_t limit = 100);
  std::vector<SignEntry> list(std::string_view language = {});
  std::size_t size();

  // Runs `body` in one transaction: if it throws, nothing it wrote is kept.
  void atomically(const std::function<void()>& body);

  sqlite::Database& database() { return db_; }

  // A value that changes with every commit to the file, by this connection or another (SQLite's
  // data_version and this connection's change count): answers read while it stays equal are still
  // true. nullopt inside a transaction, whose writes a rollback may take back.
  std::optional<std::array<std::int64_t, 2>> version();

 private:
  explicit Lexicon(sqlite::Database db);
  void require_writable() const;
  std::vector<SignEntry> query(std::string_view where_and_order, const std::vector<std::string>& params);
  std::vector<SignEntry> query_database(std::string_view where_and_order, const std::vector<std::string>& params);
  void load_keywords(SignEntry& entry);

  sqlite::Database db_;
  // The results of recent queries, reused while nothing has been committed to the file since (by
  // this connection or another: SQLite's data_version and this connection's change count), so a
  // sentence's look-ups of a lexicon nobody is editing cost no SQL; an edit in the studio is seen
  // by the next query as before.
  struct Memo {
    std::int64_t data_version = -1, changes = -1;
    std::unordered_map<std::string, std::vector<SignEntry>> results;
  } memo_;
};

}  // namespace gestura
