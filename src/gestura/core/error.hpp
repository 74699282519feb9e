#pragma once
// One error type for the whole library: a message plus where in the input it happened.
// Parsers fill the location (file, line, column, or symbol index); the CLI prints what() as one line.
#include <stdexcept>
#include <string>

namespace gestura {

struct SourceLocation {
  std::string file;   // file or stream name; empty when not from a file
  int line = 0;       // 1-based; 0 = unknown
  int column = 0;     // 1-based; 0 = unknown
  int index = -1;     // symbol / element index for notations; -1 = unknown

  std::string to_string() const;  // "file:line:col" / "symbol 12" / "" — whatever is known
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message);
  Error(const SourceLocation& where, const std::string& message);

  const SourceLocation& where() const noexcept { return where_; }
  const std::string& message() const noexcept { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

// A long job (a video render, a batch) stopped because its caller asked it to, not because
// anything was wrong. Whatever the job was writing has been removed.
class Cancelled : public Error {
 public:
  explicit Cancelled(const std::string& what) : Error(what) {}
};

}  // namespace gestura
