#pragma once
// Thin RAII ownership of the SQLite C API: a connection, a prepared statement and a transaction guard.
// Every failure becomes a gestura::Error whose location names the database file, so a caller never
// sees a bare SQLite result code.
#include <sqlite3.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace gestura::sqlite {

class Statement;

// How a file is opened. `read` never writes, not even the shared-memory index of a WAL database:
// when the file or its folder cannot be written (read-only media, a read-only mount, no
// permission), it falls back to SQLite's immutable mode, which reads the main file as it is,
// without locks (a WAL log left by a crashed writer is then not seen).
enum class Access { create, write, read };

class Database {
 public:
  // Opens (and creates when `create` is true) the file at `path`; ":memory:" gives a private in-memory
  // database. Waits up to `busy_timeout_ms` for another connection's lock before failing.
  Database(const std::string& path, bool create, int busy_timeout_ms = 2000);
  Database(const std::string& path, Access access, int busy_timeout_ms = 2000);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  Database(Database&& other) noexcept;
  Database& operator=(Database&& other) noexcept;

  // Runs one or more statements without results.
  void exec(std::string_view sql);
  Statement prepare(std::string_view sql);
  // A statement prepared once per connection and reused (reset, bindings cleared) on every call;
  // for the hot lookups. Not re-entrant: finish with one before asking for the same SQL again.
  Statement& cached(const std::string& sql);
  std::int64_t last_insert_rowid() const;
  int changes() const;

  const std::string& path() const { return path_; }
  sqlite3* handle() const { return db_; }
  bool read_only() const { return read_only_; }
  bool immutable() const { return immutable_; }

  // PRAGMA quick_check: empty when the file is sound, else SQLite's first findings (a few lines).
  std::string integrity_problems();

  // Throws gestura::Error naming the file; `what` says which operation failed.
  [[noreturn]] void fail(const std::string& what) const;

 private:
  void open_with(const std::string& name, int flags, int busy_timeout_ms);

  sqlite3* db_ = nullptr;
  std::string path_;
  bool read_only_ = false, immutable_ = false;
  std::unordered_map<std::string, std::unique_ptr<Statement>> cache_;
};

class Statement {
 public:
  Statement(Database& db, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&&) = delete;

  // Bind parameters are 1-based like sqlite3_bind_*.
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, const std::vector<std::uint8_t>& blob);
  Statement& bind_null(int index);

  // Advances to the next row; false when done. Throws on error.
  bool step();
  // Runs a statement that returns no rows.
  void run();
  void reset();

  std::string text(int column) const;
  std::int64_t integer(int column) const;
  std::vector<std::uint8_t> blob(int column) const;
  bool is_null(int column) const;

 private:
  [[noreturn]] void fail(const std::string& what) const;

  // The connection and its file name, not the Database object, which may move.
  sqlite3* db_;
  std::string path_;
  sqlite3_stmt* stmt_ = nullptr;
};

// Begins a transaction (IMMEDIATE, so a writer takes its lock up front and waits on the busy timeout
// rather than failing half-way); rolls back on destruction unless commit() was called. Inside an open
// transaction it becomes a savepoint, so an operation that is atomic on its own (adding one entry) is
// also a part of a larger atomic one (an import).
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
  bool nested_;
  bool open_ = true;
};

}  // namespace gestura::sqlite
