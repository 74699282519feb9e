#pragma once
// The lexicon's answers a signer needs, kept from one utterance to the next while the lexicon is
// unchanged: which sign an English word has and whether it is an agreement verb (the translator's
// sign inventory), the entry of each gloss signed, and the translation of each text (a line said
// again, as subtitles and dialogue repeat lines, like the parse cache of text/english_parse.cpp).
// Whether the lexicon changed is asked once per utterance (LayeredLexicon::version: a commit by any
// process, a layer added), so a warm sentence asks SQLite nothing for the words it has met before,
// and an edit (the studio, another process) is seen by the next utterance, as when every utterance
// asked afresh.
//
//   LexiconMemo memo(lexicon);                      // one per Signer
//   LexiconMemo::Utterance u = memo.utterance("ase");  // at the start of each utterance
//   u.translation(text)                             // translate_to_gloss(text, u.inventory()), kept
//   u.find("MOTHER")                                // the entry, or nullptr
//
// Thread-safe: utterances on several threads share what is kept; each look-up holds the memo's
// lock while it asks the lexicon, which is therefore asked by one thread at a time.
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/text/gloss.hpp"
#include "gestura/text/lexicon_inventory.hpp"

namespace gestura {

class LexiconMemo {
  struct Language;

 public:
  // Contract: `lexicon` outlives the memo.
  explicit LexiconMemo(LayeredLexicon& lexicon);
  ~LexiconMemo();

  // The look-ups of one utterance in `language`.
  class Utterance final : public SignInventory {
   public:
    Utterance(Utterance&&) noexcept;
    ~Utterance() override;
    std::optional<std::string> gloss_for(std::string_view word) override;
    Agreement agreement_of(std::string_view gloss) override;
    SignInventory& inventory() { return *this; }
    // translate_to_gloss(text, inventory()), kept by text. Throws what it throws (nothing is kept).
    std::shared_ptr<const Translation> translation(std::string_view text);
    // The entry of `gloss` (its first variant, the top layer's), or nullptr when it has none.
    std::shared_ptr<const SignEntry> find(std::string_view gloss);

   private:
    friend class LexiconMemo;
    Utterance(LexiconMemo& memo, std::string language, bool kept);
    LexiconMemo* memo_;
    std::string language_;
    // While a layer is inside a transaction nothing is kept: the answers of this utterance only.
    std::unique_ptr<Language> own_;
  };

  // Forgets what was kept when the lexicon has changed since the last utterance.
  Utterance utterance(std::string_view language);

 private:
  Language& language(const std::string& code);  // under mutex_

  LayeredLexicon* lexicon_;
  std::mutex mutex_;
  std::optional<std::vector<std::int64_t>> version_;
  std::unordered_map<std::string, std::unique_ptr<Language>> languages_;
};

}  // namespace gestura
