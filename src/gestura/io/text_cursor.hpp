#pragma once
// A streaming tokenizer over text held in memory, for the line-oriented text formats (BVH first).
// It knows where it is (1-based line and byte column) so that every parse error can name the place.
//
// Tokens are runs of bytes that are not blanks; '{' and '}' are tokens on their own even when glued
// to a word. Tokens are views into the text: nothing is copied or allocated while scanning, so a
// file of any size is read in one pass with memory proportional to what the caller keeps.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "gestura/core/error.hpp"

namespace gestura {

struct Token {
  std::string_view text;  // empty at end of text (or end of line for next_on_line)
  int line = 0;
  int column = 0;

  bool empty() const { return text.empty(); }
  bool is(std::string_view word) const { return text == word; }
};

class TextCursor {
 public:
  // `source` names the text in error messages (usually the file path). A UTF-8 byte order mark at
  // the start is skipped.
  TextCursor(std::string_view text, std::string source);

  Token next();          // skips blanks and line ends; an empty token at the end of the text
  Token peek();          // next() without consuming
  Token next_on_line();  // skips blanks but not line ends; an empty token at the end of a line
  bool at_line_end();    // only blanks remain before the next line end (or the end of text)
  void skip_line_end();  // consumes blanks and one line end, if at a line end
  bool at_end();         // only blanks and line ends remain
  bool eof() const { return pos_ >= text_.size(); }  // nothing at all remains

  int line() const { return line_; }
  int column() const { return static_cast<int>(pos_ - line_start_) + 1; }
  const std::string& source() const { return source_; }

  SourceLocation where(const Token& token) const { return {source_, token.line, token.column, -1}; }
  SourceLocation here() const { return {source_, line_, column(), -1}; }
  [[noreturn]] void fail(const Token& at, const std::string& message) const;

 private:
  void skip_blanks();
  Token scan();

  std::string_view text_;
  std::string source_;
  std::size_t pos_ = 0;
  std::size_t line_start_ = 0;
  int line_ = 1;
};

// A token for an error message: quoted, non-printable bytes escaped, long tokens shortened;
// "end of file" / "end of line" for an empty token.
std::string describe(const Token& token, bool at_line_end = false);

// Parses a whole token as a decimal number ("12", "-0.5", "+3e2"); nullopt if it is not one.
// Out-of-range values ("1e999") and the words inf / nan give nullopt too.
std::optional<double> parse_number(std::string_view text);
std::optional<long long> parse_integer(std::string_view text);

}  // namespace gestura
