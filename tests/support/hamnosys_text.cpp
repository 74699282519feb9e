#include "support/hamnosys_text.hpp"

#include "gestura/core/utf8.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"

namespace gestura::test {

std::string hamnosys_text(std::string_view names) {
  std::string out;
  for (const sign::Symbol s : sign::symbols_from_names(names)) utf8::append(out, sign::symbol_info(s).codepoint);
  return out;
}

}  // namespace gestura::test
