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

}  // namespace gestura
