#include "gestura/core/utf8.hpp"

#include <unicode/bytestream.h>
#include <unicode/locid.h>
#include <unicode/normalizer2.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>

#include "gestura/core/error.hpp"

namespace gestura::utf8 {

namespace {

[[noreturn]] void invalid(std::size_t pos) {
  throw Error("invalid UTF-8 at byte " + std::to_string(pos) + " (the text must be UTF-8)");
}

const icu::Normalizer2& normalizer(bool compose) {
  UErrorCode status = U_ZERO_ERROR;
  const icu::Normalizer2* n = compose ? icu::Normalizer2::getNFCInstance(status) : icu::Normalizer2::getNFDInstance(status);
  if (U_FAILURE(status) || n == nullptr) throw Error(std::string("ICU normaliser unavailable: ") + u_errorName(status));
  return *n;
}

icu::UnicodeString unicode(std::string_view text) {
  validate(text);  // ICU would replace bad bytes silently
  return icu::UnicodeString::fromUTF8(icu::StringPiece(text.data(), static_cast<std::int32_t>(text.size())));
}

std::string to_utf8(const icu::UnicodeString& text) {
  std::string out;
  text.toUTF8String(out);
  return out;
}

}  // namespace

bool decode(std::string_view text, std::size_t& pos, char32_t& out) {
  const auto lead = static_cast<unsigned char>(text[pos]);
  if (lead < 0x80) {
    out = lead;
    ++pos;
    return true;
  }
  int extra = 0;
  char32_t cp = 0;
  if ((lead & 0xE0) == 0xC0) {
    extra = 1;
    cp = lead & 0x1F;
  } else if ((lead & 0xF0) == 0xE0) {
    extra = 2;
    cp = lead & 0x0F;
  } else if ((lead & 0xF8) == 0xF0) {
    extra = 3;
    cp = lead & 0x07;
  } else {
    return false;
  }
  if (pos + static_cast<std::size_t>(extra) >= text.size()) return false;  // truncated at the end
  for (int i = 1; i <= extra; ++i) {
    const auto byte = static_cast<unsigned char>(text[pos + static_cast<std::size_t>(i)]);
    if ((byte & 0xC0) != 0x80) return false;
    cp = (cp << 6) | (byte & 0x3F);
  }
  static constexpr char32_t kMinimum[] = {0, 0x80, 0x800, 0x10000};
  if (cp < kMinimum[extra] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
  pos += static_cast<std::size_t>(extra) + 1;
  out = cp;
  return true;
}

char32_t next(std::string_view text, std::size_t& pos) {
  char32_t cp = 0;
  if (!decode(text, pos, cp)) invalid(pos);
  return cp;
}

void validate(std::string_view text) {
  for (std::size_t pos = 0; pos < text.size();) next(text, pos);
}

void append(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    out.push_back(static_cast<char>(cp));
  } else if (cp < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else if (cp < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

char32_t to_lower(char32_t cp) { return static_cast<char32_t>(u_tolower(static_cast<UChar32>(cp))); }
char32_t to_upper(char32_t cp) { return static_cast<char32_t>(u_toupper(static_cast<UChar32>(cp))); }

char32_t base_letter(char32_t cp) {
  if (cp < 0xC0) return cp;  // ASCII and Latin-1 symbols: nothing to take off
  icu::UnicodeString decomposed;
  if (!normalizer(false).getDecomposition(static_cast<UChar32>(cp), decomposed)) return cp;
  // getDecomposition gives the full canonical decomposition (for NFD).
  const UChar32 base = decomposed.char32At(0);
  for (std::int32_t i = U16_LENGTH(base); i < decomposed.length();) {
    const UChar32 c = decomposed.char32At(i);
    if (!is_mark(static_cast<char32_t>(c))) return cp;
    i += U16_LENGTH(c);
  }
  return static_cast<char32_t>(base);
}

bool is_mark(char32_t cp) { return (U_GET_GC_MASK(static_cast<UChar32>(cp)) & U_GC_M_MASK) != 0; }

bool is_letter(char32_t cp) {
  if (cp < 0x80) return (cp >= 'a' && cp <= 'z') || (cp >= 'A' && cp <= 'Z');
  return u_hasBinaryProperty(static_cast<UChar32>(cp), UCHAR_ALPHABETIC) || is_mark(cp);
}

bool is_digit(char32_t cp) { return cp >= '0' && cp <= '9'; }

bool is_space(char32_t cp) {
  if (cp <= 0x20 || (cp >= 0x7F && cp <= 0x9F)) return true;
  return u_isUWhiteSpace(static_cast<UChar32>(cp)) || cp == 0x200B || cp == 0xFEFF;
}

std::string lower(std::string_view text) { return to_utf8(unicode(text).toLower(icu::Locale::getRoot())); }
std::string upper(std::string_view text) { return to_utf8(unicode(text).toUpper(icu::Locale::getRoot())); }

std::string nfc(std::string_view text) {
  validate(text);
  const icu::Normalizer2& n = normalizer(true);
  UErrorCode status = U_ZERO_ERROR;
  // Most text is already NFC (every ASCII text is): then it is returned as it is.
  const icu::StringPiece piece(text.data(), static_cast<std::int32_t>(text.size()));
  if (n.isNormalizedUTF8(piece, status) && U_SUCCESS(status)) return std::string(text);
  std::string out;
  icu::StringByteSink<std::string> sink(&out);
  status = U_ZERO_ERROR;
  n.normalizeUTF8(0, piece, sink, nullptr, status);
  if (U_FAILURE(status)) throw Error(std::string("cannot normalise the text: ") + u_errorName(status));
  return out;
}

}  // namespace gestura::utf8
