#include "gestura/io/text_cursor.hpp"

#include <charconv>
#include <cmath>

namespace gestura {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool is_brace(char c) { return c == '{' || c == '}'; }

}  // namespace

TextCursor::TextCursor(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {
  if (text_.starts_with("\xEF\xBB\xBF")) pos_ = line_start_ = 3;
}

void TextCursor::skip_blanks() {
  while (pos_ < text_.size() && is_blank(text_[pos_])) ++pos_;
}

Token TextCursor::scan() {
  Token token{{}, line_, column()};
  if (pos_ >= text_.size() || text_[pos_] == '\n') return token;
  const std::size_t start = pos_;
  if (is_brace(text_[pos_])) {
    ++pos_;
  } else {
    while (pos_ < text_.size() && text_[pos_] != '\n' && !is_blank(text_[pos_]) && !is_brace(text_[pos_])) ++pos_;
  }
  token.text = text_.substr(start, pos_ - start);
  return token;
}

Token TextCursor::next() {
  for (;;) {
    skip_blanks();
    if (pos_ >= text_.size() || text_[pos_] != '\n') break;
    ++pos_;
    ++line_;
    line_start_ = pos_;
  }
  return scan();
}

Token TextCursor::peek() {
  const std::size_t pos = pos_, line_start = line_start_;
  const int line = line_;
  const Token token = next();
  pos_ = pos, line_start_ = line_start, line_ = line;
  return token;
}

Token TextCursor::next_on_line() {
  skip_blanks();
  return scan();
}

bool TextCursor::at_line_end() {
  skip_blanks();
  return pos_ >= text_.size() || text_[pos_] == '\n';
}

void TextCursor::skip_line_end() {
  skip_blanks();
  if (pos_ < text_.size() && text_[pos_] == '\n') {
    ++pos_;
    ++line_;
    line_start_ = pos_;
  }
}

bool TextCursor::at_end() { return peek().empty(); }

void TextCursor::fail(const Token& at, const std::string& message) const { throw Error(where(at), message); }

std::string describe(const Token& token, bool at_line_end) {
  if (token.empty()) return at_line_end ? "end of line" : "end of file";
  constexpr std::size_t kShown = 32;
  std::string out = "'";
  for (std::size_t i = 0; i < token.text.size() && i < kShown; ++i) {
    const auto c = static_cast<unsigned char>(token.text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out.push_back(static_cast<char>(c));
    } else {
      static constexpr char hex[] = "0123456789abcdef";
      out += "\\x";
      out.push_back(hex[c >> 4]);
      out.push_back(hex[c & 15]);
    }
  }
  if (token.text.size() > kShown) out += "...";
  return out + "'";
}

std::optional<double> parse_number(std::string_view text) {
  if (text.starts_with('+')) text.remove_prefix(1);
  if (text.empty() || text.starts_with('+')) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_integer(std::string_view text) {
  if (text.starts_with('+')) text.remove_prefix(1);
  if (text.empty() || text.starts_with('+')) return std::nullopt;
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace gestura
