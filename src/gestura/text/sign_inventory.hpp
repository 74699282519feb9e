#pragma once
// The translator's question to the lexicon: "is there a sign for this English word, and what is its
// gloss?". The lexicon's keyword lookup is the authority (see lexicon_inventory.hpp); a word list
// serves tests and small setups, and an open vocabulary stands in when there is no lexicon at all.
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "gestura/lexicon/sign_entry.hpp"

namespace gestura {

class SignInventory {
 public:
  virtual ~SignInventory() = default;
  // The gloss of a sign for `word` (a lowercase English word, lemma or phrase), if there is one.
  virtual std::optional<std::string> gloss_for(std::string_view word) = 0;
  // True when every word is taken as signable (no lexicon): the translator then recognises names only
  // by their capital letter and cannot check lemma guesses.
  virtual bool open_vocabulary() const { return false; }
  // Whether the sign `gloss` is an agreement verb (the lexicon entry's `agreement` field): the grammar
  // pass moves it from its subject's place to its object's. Without a lexicon, none is.
  virtual Agreement agreement_of(std::string_view /*gloss*/) { return Agreement::none; }
};

// Every word is a sign whose gloss is the word in capitals.
class OpenVocabulary final : public SignInventory {
 public:
  std::optional<std::string> gloss_for(std::string_view word) override;
  bool open_vocabulary() const override { return true; }
};

// A fixed word → gloss table.
class WordListInventory final : public SignInventory {
 public:
  WordListInventory() = default;
  WordListInventory(std::initializer_list<std::pair<const std::string, std::string>> words) : words_(words) {}
  void add(std::string word, std::string gloss) { words_.insert_or_assign(std::move(word), std::move(gloss)); }
  void set_agreement(std::string gloss, Agreement agreement) { agreement_.insert_or_assign(std::move(gloss), agreement); }
  std::optional<std::string> gloss_for(std::string_view word) override;
  Agreement agreement_of(std::string_view gloss) override;

 private:
  std::unordered_map<std::string, std::string> words_;
  std::unordered_map<std::string, Agreement> agreement_;
};

}  // namespace gestura
