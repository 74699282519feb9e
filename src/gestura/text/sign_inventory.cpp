#include "gestura/text/sign_inventory.hpp"

#include "gestura/core/utf8.hpp"

namespace gestura {

std::optional<std::string> OpenVocabulary::gloss_for(std::string_view word) { return utf8::upper(word); }

std::optional<std::string> WordListInventory::gloss_for(std::string_view word) {
  const auto it = words_.find(std::string(word));
  if (it == words_.end()) return std::nullopt;
  return it->second;
}

Agreement WordListInventory::agreement_of(std::string_view gloss) {
  const auto it = agreement_.find(std::string(gloss));
  return it == agreement_.end() ? Agreement::none : it->second;
}

}  // namespace gestura
