#include "gestura/text/tokenizer.hpp"

#include "gestura/core/utf8.hpp"

namespace gestura {

namespace {

bool is_apostrophe(char32_t cp) { return cp == '\'' || cp == 0x2019 || cp == 0x2018 || cp == 0x02BC; }
bool is_hyphen(char32_t cp) { return cp == '-' || cp == 0x2010 || cp == 0x2011; }
bool is_quote(char32_t cp) {
  return cp == '"' || cp == 0x201C || cp == 0x201D || cp == 0x201E || cp == 0xAB || cp == 0xBB || cp == '`';
}
bool is_symbol(char32_t cp) {
  return cp == '$' || cp == 0x20AC || cp == 0xA3 || cp == '%' || cp == '&' || cp == '+' || cp == '@' || cp == '#';
}
bool is_pause(char32_t cp) {
  return cp == ',' || cp == ';' || cp == ':' || cp == 0x2014 || cp == 0x2013 || cp == 0x2026 || cp == '(' ||
         cp == ')' || cp == '-';
}

// Decoded text with byte offsets, so the scanner can look ahead by code points.
struct Decoded {
  std::vector<char32_t> cps;
  std::vector<std::size_t> offsets;  // byte offset of each code point, plus the total size at the end
};

Decoded decode(std::string_view text) {
  Decoded d;
  d.cps.reserve(text.size());
  d.offsets.reserve(text.size() + 1);
  for (std::size_t pos = 0; pos < text.size();) {
    d.offsets.push_back(pos);
    d.cps.push_back(utf8::next(text, pos));
  }
  d.offsets.push_back(text.size());
  return d;
}

}  // namespace

std::vector<Token> tokenize(std::string_view text) {
  const Decoded d = decode(text);
  const std::size_t n = d.cps.size();
  auto at = [&](std::size_t i) -> char32_t { return i < n ? d.cps[i] : 0; };
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < n) {
    const char32_t c = d.cps[i];
    const std::size_t start = i;
    std::string spelled;
    if (utf8::is_space(c) || is_quote(c) || (is_apostrophe(c) && !utf8::is_letter(at(i + 1)))) {
      ++i;
      continue;
    }
    if (utf8::is_letter(c)) {
      std::size_t segment = 0;  // letters since the last inner period, to recognise "p.m." and "U.S."
      std::size_t periods = 0;
      while (i < n) {
        const char32_t x = d.cps[i];
        if (utf8::is_letter(x)) {
          utf8::append(spelled, x);
          ++segment;
        } else if ((is_apostrophe(x) || is_hyphen(x)) && utf8::is_letter(at(i + 1))) {
          spelled.push_back(is_apostrophe(x) ? '\'' : '-');
          segment = 0;
        } else if (x == '.' && segment == 1 &&
                   ((utf8::is_letter(at(i + 1)) && !utf8::is_letter(at(i + 2))) || periods > 0)) {
          // An abbreviation of single letters ("p.m.", "U.S."): its periods, the last one included,
          // belong to the word; a lone "I." still ends a sentence.
          spelled.push_back('.');
          ++periods;
          segment = 0;
          if (!utf8::is_letter(at(i + 1))) {
            ++i;
            break;
          }
        } else {
          break;
        }
        ++i;
      }
      // One spelling however the word was typed: "José" with a combining accent is "José".
      out.push_back({TokenKind::word, utf8::nfc(spelled), d.offsets[start], d.offsets[i]});
      continue;
    }
    if (utf8::is_digit(c)) {
      while (i < n) {
        const char32_t x = d.cps[i];
        if (utf8::is_digit(x)) {
          spelled.push_back(static_cast<char>(x));
        } else if ((x == ',' || x == '.' || x == ':' || x == '/' || x == '-') && utf8::is_digit(at(i + 1))) {
          spelled.push_back(static_cast<char>(x));
        } else {
          break;
        }
        ++i;
      }
      // Ordinal suffixes stay with their number: 1st, 22nd, 3rd, 4th.
      const auto lower2 = std::u32string{utf8::to_lower(at(i)), utf8::to_lower(at(i + 1))};
      if ((lower2 == U"st" || lower2 == U"nd" || lower2 == U"rd" || lower2 == U"th") && !utf8::is_letter(at(i + 2))) {
        spelled.push_back(static_cast<char>(lower2[0]));
        spelled.push_back(static_cast<char>(lower2[1]));
        i += 2;
      }
      out.push_back({TokenKind::number, std::move(spelled), d.offsets[start], d.offsets[i]});
      continue;
    }
    ++i;
    utf8::append(spelled, c);
    if (c == '.' || c == '!' || c == '?') {
      while (i < n && (d.cps[i] == '.' || d.cps[i] == '!' || d.cps[i] == '?')) utf8::append(spelled, d.cps[i++]);
      out.push_back({TokenKind::sentence_end, std::move(spelled), d.offsets[start], d.offsets[i]});
    } else if (is_symbol(c)) {
      out.push_back({TokenKind::symbol, std::move(spelled), d.offsets[start], d.offsets[i]});
    } else if (is_pause(c) || is_hyphen(c)) {
      out.push_back({TokenKind::pause, std::move(spelled), d.offsets[start], d.offsets[i]});
    }
    // Anything else (emoji, stray symbols, ¿ ¡) carries no sign and is skipped.
  }
  return out;
}

}  // namespace gestura
