#pragma once
// The lexicon as the translator's sign inventory: a word has a sign when some entry of the chosen
// sign language lists it as an English keyword (or, failing that, has it as its gloss). Answers are
// cached, as one sentence asks for the same few words repeatedly.
#include <string>
#include <unordered_map>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/text/sign_inventory.hpp"

namespace gestura {

class LexiconInventory final : public SignInventory {
 public:
  LexiconInventory(LayeredLexicon& lexicon, std::string sign_language) : lexicon_(lexicon), language_(std::move(sign_language)) {}
  std::optional<std::string> gloss_for(std::string_view word) override;
  // The agreement field of the gloss's first variant in the chosen language (the top layer's).
  Agreement agreement_of(std::string_view gloss) override;
  // How many answers are kept.
  std::size_t remembered() const { return cache_.size() + agreement_cache_.size(); }

 private:
  LayeredLexicon& lexicon_;
  std::string language_;
  std::unordered_map<std::string, std::optional<std::string>> cache_;
  std::unordered_map<std::string, Agreement> agreement_cache_;
};

}  // namespace gestura
