// The lexicon answers a signer keeps between utterances (sentence/lexicon_memo.hpp): kept while the
// lexicon is unchanged, forgotten after a commit, never kept from inside a transaction.
#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sentence/lexicon_memo.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "support/signing_avatar.hpp"

namespace gestura {
namespace {

// The avatar is the one the sign tests share and one signer serves every test (building them is the
// slow part); a user layer above the built-in lexicon, empty between tests.
struct World {
  const Avatar& avatar = test::signing_avatar().avatar;
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  Lexicon user = Lexicon::in_memory();
  LayeredLexicon layers;
  std::optional<Signer> signer;
  World() {
    layers.push_layer(builtin);
    layers.push_layer(user);
    signer.emplace(avatar, layers);
  }
};

World& world() {
  static World w;
  return w;
}

// A user sign for "zebra" made like BOOK (any notation the synthesizer performs).
SignEntry zebra() {
  const std::optional<SignEntry> book = world().builtin.find("BOOK", "ase");
  EXPECT_TRUE(book.has_value());
  SignEntry e;
  e.gloss = "ZEBRA";
  e.language = "ase";
  e.notation = book ? book->notation : "";
  e.keywords = {Keyword{"zebra", "eng", ""}};
  return e;
}

bool signs(const SentencePerformance& p, const std::string& gloss) {
  for (const PerformedGloss& g : p.glosses)
    if (g.gloss == gloss) return true;
  return false;
}

TEST(SignerLexiconMemo, AnswersAsTheLexiconDoes) {
  LayeredLexicon layers;
  layers.push_layer(world().builtin);
  LexiconMemo memo(layers);
  LexiconInventory direct(layers, "ase");
  for (int round = 0; round < 2; ++round) {  // the second round is answered from what was kept
    LexiconMemo::Utterance u = memo.utterance("ase");
    for (const char* word : {"book", "store", "buy", "sister", "zebra", "mother", "give"}) {
      EXPECT_EQ(u.gloss_for(word), direct.gloss_for(word)) << word;
      EXPECT_EQ(u.agreement_of(word), direct.agreement_of(word)) << word;
    }
    ASSERT_NE(u.find("BOOK"), nullptr);
    EXPECT_EQ(u.find("BOOK")->notation, world().builtin.find("BOOK", "ase")->notation);
    EXPECT_EQ(u.find("NO-SUCH-GLOSS"), nullptr);
  }
}

TEST(SignerLexiconMemo, ASignAddedBetweenUtterancesIsSignedInTheNextOne) {
  Lexicon& user = world().user;
  const Signer& signer = *world().signer;
  SayOptions quick;
  quick.mouthing = false;

  const SentencePerformance before = signer.say("A zebra.", quick);
  EXPECT_FALSE(signs(before, "ZEBRA"));  // fingerspelled
  user.add(zebra());
  const SentencePerformance added = signer.say("A zebra.", quick);
  EXPECT_TRUE(signs(added, "ZEBRA"));
  user.remove("ZEBRA", "ase");
  const SentencePerformance removed = signer.say("A zebra.", quick);
  EXPECT_FALSE(signs(removed, "ZEBRA"));
  ASSERT_EQ(removed.glosses.size(), before.glosses.size());
  for (std::size_t i = 0; i < before.glosses.size(); ++i) EXPECT_EQ(removed.glosses[i].gloss, before.glosses[i].gloss);
}

TEST(SignerLexiconMemo, WhatATransactionSawIsNotKeptAfterItsRollback) {
  Lexicon& user = world().user;
  const Signer& signer = *world().signer;
  SayOptions quick;
  quick.mouthing = false;
  signer.say("A zebra.", quick);  // the memo holds the answers without ZEBRA
  EXPECT_THROW(user.atomically([&] {
    user.add(zebra());
    // Inside the transaction the new sign is seen, and nothing of it may outlive the rollback.
    EXPECT_TRUE(signs(signer.say("A zebra.", quick), "ZEBRA"));
    throw std::runtime_error("rolled back");
  }),
               std::runtime_error);
  EXPECT_FALSE(signs(signer.say("A zebra.", quick), "ZEBRA"));
}

TEST(SignerLexiconMemo, AWarmUtteranceIsTheSameAsTheFirst) {
  const Signer& signer = *world().signer;
  SayOptions quick;
  quick.mouthing = false;
  const char* text = "My sister bought a book.";
  const SentencePerformance first = signer.say(text, quick);
  const SentencePerformance again = signer.say(text, quick);
  ASSERT_EQ(first.glosses.size(), again.glosses.size());
  for (std::size_t i = 0; i < first.glosses.size(); ++i) {
    EXPECT_EQ(first.glosses[i].gloss, again.glosses[i].gloss);
    EXPECT_EQ(first.glosses[i].start, again.glosses[i].start);
  }
  ASSERT_EQ(first.clip.rotations.size(), again.clip.rotations.size());
  for (std::size_t j = 0; j < first.clip.rotations.size(); ++j) {
    ASSERT_EQ(first.clip.rotations[j].values.size(), again.clip.rotations[j].values.size());
    for (std::size_t k = 0; k < first.clip.rotations[j].values.size(); ++k)
      ASSERT_EQ(first.clip.rotations[j].values[k], again.clip.rotations[j].values[k]) << "joint " << j << " key " << k;
  }
}

}  // namespace
}  // namespace gestura
