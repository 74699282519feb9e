#include "gestura/lexicon/layered_lexicon.hpp"

#include <algorithm>
#include <strings.h>

namespace gestura {

void LayeredLexicon::push_layer(Lexicon& layer) { layers_.push_back(&layer); }

std::optional<std::vector<std::int64_t>> LayeredLexicon::version() {
  std::vector<std::int64_t> out{static_cast<std::int64_t>(layers_.size())};
  for (Lexicon* layer : layers_) {
    const auto v = layer->version();
    if (!v) return std::nullopt;
    out.insert(out.end(), v->begin(), v->end());
  }
  return out;
}

bool LayeredLexicon::hidden_above(std::size_t layer, const SignEntry& entry) {
  for (std::size_t above = layer + 1; above < layers_.size(); ++above)
    if (!layers_[above]->find_all(entry.gloss, entry.language).empty()) return true;
  return false;
}

template <class Query>
std::vector<SignEntry> LayeredLexicon::merged(Query&& per_layer, bool by_gloss) {
  std::vector<SignEntry> out;
  for (std::size_t i = layers_.size(); i-- > 0;)
    for (SignEntry& e : per_layer(*layers_[i]))
      if (!hidden_above(i, e)) out.push_back(std::move(e));
  if (!by_gloss) return out;
  std::stable_sort(out.begin(), out.end(), [](const SignEntry& a, const SignEntry& b) {
    const int by_gloss = strcasecmp(a.gloss.c_str(), b.gloss.c_str());
    if (by_gloss != 0) return by_gloss < 0;
    if (a.language != b.language) return a.language < b.language;
    return a.variant < b.variant;
  });
  return out;
}

std::optional<SignEntry> LayeredLexicon::find(std::string_view gloss, std::string_view language, int variant) {
  for (std::size_t i = layers_.size(); i-- > 0;) {
    // The topmost layer that knows the gloss decides, even if it lacks this variant.
    if (layers_[i]->find_all(gloss, language).empty()) continue;
    return layers_[i]->find(gloss, language, variant);
  }
  return std::nullopt;
}

std::vector<SignEntry> LayeredLexicon::find_all(std::string_view gloss, std::string_view language) {
  return merged([&](Lexicon& l) { return l.find_all(gloss, language); });
}

std::vector<SignEntry> LayeredLexicon::by_keyword(std::string_view word, std::string_view language,
                                                  std::string_view spoken) {
  // Top layer first: a user's sign for a word is preferred to a built-in one.
  return merged([&](Lexicon& l) { return l.by_keyword(word, language, spoken); }, false);
}

std::vector<SignEntry> LayeredLexicon::search(std::string_view text, SearchMode mode, std::string_view language,
                                              std::size_t limit) {
  auto out = merged([&](Lexicon& l) { return l.search(text, mode, language, limit); });
  if (out.size() > limit) out.resize(limit);
  return out;
}

std::vector<SignEntry> LayeredLexicon::list(std::string_view language) {
  return merged([&](Lexicon& l) { return l.list(language); });
}

}  // namespace gestura
