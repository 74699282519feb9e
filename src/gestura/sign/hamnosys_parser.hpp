#pragma once
// Parses HamNoSys 4 notation into the typed model of hamnosys_model.hpp. Three front doors meet in
// one symbol sequence: Unicode text (private-use code points), comma-separated symbol names, and
// (in sigml.hpp) SiGML elements. Errors are gestura::Error whose SourceLocation.index is the
// 0-based symbol index and whose message names the class of symbol that was expected.
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"

namespace gestura::sign {

struct ParseOptions {
  // Lenient (default) accepts what real lexicons contain although it is not well formed — a group
  // closed by the wrong bracket, a group left open at the end, a sign without a handshape — and
  // records a ParseNote. Strict turns those into errors.
  bool strict = false;
};

// Limits that keep hostile input cheap: longer signs or deeper nesting are errors.
inline constexpr std::size_t kMaxSignSymbols = 2048;
inline constexpr int kMaxGroupDepth = 32;

// Decodes UTF-8 text of HamNoSys code points (ASCII space and punctuation allowed). Throws with the
// index of the offending symbol (bad UTF-8, unknown code point, too long).
std::vector<Symbol> symbols_from_unicode(std::string_view utf8);
// Splits "hamflathand,hamextfingeru,..." (commas and/or white space) into symbols.
std::vector<Symbol> symbols_from_names(std::string_view names);

// The body, arm or hand site a location symbol names (nullopt for other symbols).
std::optional<Site> site_of_symbol(Symbol symbol);

HamSign parse_hamnosys(std::span<const Symbol> symbols, const ParseOptions& options = {});
HamSign parse_hamnosys_unicode(std::string_view utf8, const ParseOptions& options = {});
HamSign parse_hamnosys_names(std::string_view names, const ParseOptions& options = {});

}  // namespace gestura::sign
