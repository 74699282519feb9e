#include "gestura/world/json_locate.hpp"

#include <vector>

namespace gestura {
namespace {

// A minimal scanner over JSON text: it only needs to skip values and find members and elements.
struct Scanner {
  std::string_view text;
  std::size_t pos = 0;

  void skip_space() {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\n' || text[pos] == '\r')) ++pos;
  }
  bool at(char c) {
    skip_space();
    return pos < text.size() && text[pos] == c;
  }
  // Reads a string token (the cursor on its opening quote) and returns its raw content.
  std::string string_token() {
    std::string out;
    if (pos >= text.size() || text[pos] != '"') return out;
    ++pos;
    while (pos < text.size() && text[pos] != '"') {
      if (text[pos] == '\\' && pos + 1 < text.size()) {
        const char e = text[pos + 1];
        out.push_back(e == 'n' ? '\n' : e == 't' ? '\t' : e);  // enough to compare member names
        pos += 2;
        continue;
      }
      out.push_back(text[pos++]);
    }
    if (pos < text.size()) ++pos;
    return out;
  }
  // Skips one value of any kind. Returns false on malformed text.
  bool skip_value(int depth = 0) {
    skip_space();
    if (pos >= text.size() || depth > 512) return false;
    const char c = text[pos];
    if (c == '"') {
      string_token();
      return true;
    }
    if (c == '{' || c == '[') {
      const char close = c == '{' ? '}' : ']';
      ++pos;
      if (at(close)) return ++pos, true;
      while (pos < text.size()) {
        if (c == '{') {
          skip_space();
          string_token();
          if (!at(':')) return false;
          ++pos;
        }
        if (!skip_value(depth + 1)) return false;
        if (at(',')) {
          ++pos;
          continue;
        }
        if (at(close)) return ++pos, true;
        return false;
      }
      return false;
    }
    while (pos < text.size() && text[pos] != ',' && text[pos] != '}' && text[pos] != ']' && text[pos] != ' ' &&
           text[pos] != '\n' && text[pos] != '\r' && text[pos] != '\t')
      ++pos;
    return true;
  }
  // With the cursor at an object, moves it to the value of member `name`. False when absent.
  bool enter_member(const std::string& name) {
    if (!at('{')) return false;
    ++pos;
    if (at('}')) return false;
    while (pos < text.size()) {
      skip_space();
      const std::string key = string_token();
      if (!at(':')) return false;
      ++pos;
      skip_space();
      if (key == name) return true;
      if (!skip_value()) return false;
      if (!at(',')) return false;
      ++pos;
    }
    return false;
  }
  bool enter_element(std::size_t index) {
    if (!at('[')) return false;
    ++pos;
    if (at(']')) return false;
    for (std::size_t i = 0; pos < text.size(); ++i) {
      skip_space();
      if (i == index) return true;
      if (!skip_value()) return false;
      if (!at(',')) return false;
      ++pos;
    }
    return false;
  }
};

SourceLocation location_of(std::string_view text, const std::string& file, std::size_t byte) {
  SourceLocation where{file, 1, 1};
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++where.line, where.column = 1;
    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++where.column;  // count UTF-8 characters
  }
  return where;
}

// "/a/b~1c/0" → {"a", "b/c", "0"}.
std::vector<std::string> pointer_tokens(std::string_view pointer) {
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (i < pointer.size()) {
    if (pointer[i] == '/') ++i;
    std::string token;
    while (i < pointer.size() && pointer[i] != '/') {
      if (pointer[i] == '~' && i + 1 < pointer.size()) {
        token.push_back(pointer[i + 1] == '1' ? '/' : '~');
        i += 2;
        continue;
      }
      token.push_back(pointer[i++]);
    }
    tokens.push_back(token);
  }
  return tokens;
}

}  // namespace

SourceLocation JsonLocator::locate(std::string_view pointer) const {
  if (text_.empty()) return SourceLocation{file_, 0, 0};
  Scanner s{text_};
  s.skip_space();
  std::size_t found = s.pos;
  for (const std::string& token : pointer_tokens(pointer)) {
    const std::size_t before = s.pos;
    bool ok = false;
    if (s.at('{')) {
      ok = s.enter_member(token);
    } else if (s.at('[')) {
      std::size_t index = 0;
      bool digits = !token.empty();
      for (char c : token) digits = digits && c >= '0' && c <= '9', index = index * 10 + static_cast<std::size_t>(c - '0');
      ok = digits && s.enter_element(index);
    }
    if (!ok) {
      s.pos = before;
      break;
    }
    s.skip_space();
    found = s.pos;
  }
  return location_of(text_, file_, found);
}

void JsonLocator::fail(std::string_view pointer, const std::string& message) const {
  const std::string where = pointer.empty() ? std::string("/") : std::string(pointer);
  throw Error(locate(pointer), where + ": " + message);
}

void throw_json_syntax_error(std::string_view text, const std::string& file, std::size_t byte, const std::string& what) {
  // nlohmann reports the byte after the offending token; step back onto it.
  throw Error(location_of(text, file, byte > 0 ? byte - 1 : 0), "JSON syntax: " + what);
}

}  // namespace gestura
