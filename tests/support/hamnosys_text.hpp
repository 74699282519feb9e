// HamNoSys written as symbol names ("hamflathand,hamchest") → the Unicode text the lexicon stores.
#pragma once

#include <string>
#include <string_view>

namespace gestura::test {

// Throws like sign::symbols_from_names on an unknown name.
std::string hamnosys_text(std::string_view names);

}  // namespace gestura::test
