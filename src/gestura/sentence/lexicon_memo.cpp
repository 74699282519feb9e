#include "gestura/sentence/lexicon_memo.hpp"

#include "gestura/text/translator.hpp"

namespace gestura {

namespace {
// Answers kept per sign language before they are dropped and asked again (a long-lived server
// meets many words; a sentence a few dozen).
constexpr std::size_t kMaxKept = 8192;
}  // namespace

struct LexiconMemo::Language {
  explicit Language(LayeredLexicon& lexicon, const std::string& code) : inventory(lexicon, code) {}
  LexiconInventory inventory;
  std::unordered_map<std::string, std::shared_ptr<const SignEntry>> entries;
  std::unordered_map<std::string, std::shared_ptr<const Translation>> translations;
  std::size_t size() const { return inventory.remembered() + entries.size() + translations.size(); }
};

LexiconMemo::LexiconMemo(LayeredLexicon& lexicon) : lexicon_(&lexicon) {}
LexiconMemo::~LexiconMemo() = default;

LexiconMemo::Utterance LexiconMemo::utterance(std::string_view language) {
  std::lock_guard lock(mutex_);
  std::optional<std::vector<std::int64_t>> now = lexicon_->version();
  if (!now || now != version_) languages_.clear();
  version_ = std::move(now);
  return Utterance(*this, std::string(language), version_.has_value());
}

LexiconMemo::Language& LexiconMemo::language(const std::string& code) {
  std::unique_ptr<Language>& kept = languages_[code];
  if (!kept || kept->size() > kMaxKept)
    kept = std::make_unique<Language>(*lexicon_, code);
  return *kept;
}

LexiconMemo::Utterance::Utterance(LexiconMemo& memo, std::string language, bool kept)
    : memo_(&memo), language_(std::move(language)) {
  if (!kept) own_ = std::make_unique<Language>(*memo.lexicon_, language_);
}

LexiconMemo::Utterance::Utterance(Utterance&&) noexcept = default;
LexiconMemo::Utterance::~Utterance() = default;

std::optional<std::string> LexiconMemo::Utterance::gloss_for(std::string_view word) {
  std::lock_guard lock(memo_->mutex_);
  return (own_ ? *own_ : memo_->language(language_)).inventory.gloss_for(word);
}

Agreement LexiconMemo::Utterance::agreement_of(std::string_view gloss) {
  std::lock_guard lock(memo_->mutex_);
  return (own_ ? *own_ : memo_->language(language_)).inventory.agreement_of(gloss);
}

std::shared_ptr<const Translation> LexiconMemo::Utterance::translation(std::string_view text) {
  const std::string key(text);
  if (!own_) {
    std::lock_guard lock(memo_->mutex_);
    Language& kept = memo_->language(language_);
    if (const auto it = kept.translations.find(key); it != kept.translations.end()) return it->second;
  }
  // Outside the lock: the translator asks gloss_for and agreement_of, which take it.
  auto out = std::make_shared<const Translation>(translate_to_gloss(text, *this));
  if (!own_) {
    std::lock_guard lock(memo_->mutex_);
    memo_->language(language_).translations.emplace(key, out);
  }
  return out;
}

std::shared_ptr<const SignEntry> LexiconMemo::Utterance::find(std::string_view gloss) {
  std::lock_guard lock(memo_->mutex_);
  Language& kept = own_ ? *own_ : memo_->language(language_);
  std::string key(gloss);
  if (const auto it = kept.entries.find(key); it != kept.entries.end()) return it->second;
  std::optional<SignEntry> entry = memo_->lexicon_->find(gloss, language_);
  std::shared_ptr<const SignEntry> out = entry ? std::make_shared<const SignEntry>(std::move(*entry)) : nullptr;
  kept.entries.emplace(std::move(key), out);
  return out;
}

}  // namespace gestura
