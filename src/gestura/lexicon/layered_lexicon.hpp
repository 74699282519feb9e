#pragma once
// A read view over several lexicons stacked on each other: the first layer is the bottom (normally the
// built-in lexicon), later layers are user lexicons. A layer that has a gloss in a sign language
// hides every variant of that gloss+language below it, so a user can both add signs and replace
// built-in ones without editing the built-in data. The view does not own the layers.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "gestura/lexicon/lexicon.hpp"

namespace gestura {

class LayeredLexicon {
 public:
  // Adds `layer` on top of the layers added before.
  void push_layer(Lexicon& layer);
  std::size_t layer_count() const { return layers_.size(); }
  // The layers' versions (Lexicon::version) after their number: equal while no layer has changed and
  // none was added, so answers read under one value may be kept; nullopt while a layer is inside a
  // transaction.
  std::optional<std::vector<std::int64_t>> version();

  std::optional<SignEntry> find(std::string_view gloss, std::string_view language, int variant = 1);
  std::vector<SignEntry> find_all(std::string_view gloss, std::string_view language = {});
  // Signs for an English word, the topmost layer's first (so a translator picking the first
  // prefers user signs); glosses hidden by a higher layer are left out.
  std::vector<SignEntry> by_keyword(std::string_view word, std::string_view language = {},
                                    std::string_view spoken = "eng");
  std::vector<SignEntry> search(std::string_view text, SearchMode mode = SearchMode::substring,
                                std::string_view language = {}, std::size_t limit = 100);
  std::vector<SignEntry> list(std::string_view language = {});

 private:
  // True when a layer above `layer` has `gloss` in `language`.
  bool hidden_above(std::size_t layer, const SignEntry& entry);
  // Merges per-layer results top-down, dropping entries hidden by a higher layer; sorted by gloss,
  // language and variant unless `by_gloss` is false (then top layer first).
  template <class Query>
  std::vector<SignEntry> merged(Query&& per_layer, bool by_gloss = true);

  std::vector<Lexicon*> layers_;
};

}  // namespace gestura
