#include "gestura/text/lexicon_inventory.hpp"

namespace gestura {

std::optional<std::string> LexiconInventory::gloss_for(std::string_view word) {
  std::string key(word);
  if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
  std::optional<std::string> gloss;
  if (const auto by_keyword = lexicon_.by_keyword(word, language_); !by_keyword.empty())
    gloss = by_keyword.front().gloss;
  else if (const auto by_gloss = lexicon_.find(word, language_))
    gloss = by_gloss->gloss;
  cache_.emplace(std::move(key), gloss);
  return gloss;
}

Agreement LexiconInventory::agreement_of(std::string_view gloss) {
  std::string key(gloss);
  if (const auto it = agreement_cache_.find(key); it != agreement_cache_.end()) return it->second;
  const auto entry = lexicon_.find(gloss, language_);
  const Agreement agreement = entry ? entry->agreement : Agreement::none;
  agreement_cache_.emplace(std::move(key), agreement);
  return agreement;
}

}  // namespace gestura
