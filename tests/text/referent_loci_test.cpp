// Spatial grammar, the discourse half (text/referent_loci.hpp): which place each referent gets,
// which place each pronoun points at, and between which places agreement verbs move. Expected
// glosses are worked out by hand from ASL grammar (docs/grammar.md).
#include "gestura/text/referent_loci.hpp"

#include <gtest/gtest.h>

#include <string>

#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace gestura {
namespace {

// The built-in ASL lexicon answers, as in `gestura gloss`.
Translation gloss(std::string_view text) {
  static Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  static LayeredLexicon layers = [] {
    LayeredLexicon l;
    l.push_layer(builtin);
    return l;
  }();
  LexiconInventory inventory(layers, "ase");
  return translate_to_gloss(text, inventory);
}

const GlossToken* find(const Translation& t, std::string_view gloss, std::size_t from = 0) {
  for (std::size_t i = from; i < t.glosses.size(); ++i)
    if (t.glosses[i].gloss == gloss) return &t.glosses[i];
  return nullptr;
}

TEST(ReferentLoci, SheGaveHimTheBookPlacesTwoPeopleAndGiveMovesBetweenThem) {
  const Translation t = gloss("She gave him the book.");
  EXPECT_EQ(t.text(), "IX-3a GIVE:3a→3b IX-3b BOOK");
  const GlossToken* she = find(t, "IX-3a");
  const GlossToken* give = find(t, "GIVE:3a→3b");
  const GlossToken* him = find(t, "IX-3b");
  ASSERT_TRUE(she && give && him);
  EXPECT_EQ(she->sign(), "IX-3");
  EXPECT_EQ(she->at, (Locus{3, 0}));
  EXPECT_EQ(him->at, (Locus{3, 1}));
  EXPECT_NE(she->at, him->at);
  EXPECT_EQ(give->sign(), "GIVE");
  EXPECT_EQ(give->from, she->at);
  EXPECT_EQ(give->to, him->at);
  EXPECT_NE(give->reason.find("agreement verb"), std::string::npos) << give->reason;
}

TEST(ReferentLoci, FirstAndSecondPersonAgreementRunsBothWays) {
  const Translation a = gloss("I give you the book.");
  const Translation b = gloss("You give me the book.");
  const GlossToken* ga = find(a, "GIVE:1→2");
  const GlossToken* gb = find(b, "GIVE:2→1");
  ASSERT_TRUE(ga) << a.text();
  ASSERT_TRUE(gb) << b.text();
  EXPECT_EQ(ga->from, (Locus{1, 0}));
  EXPECT_EQ(gb->to, (Locus{1, 0}));
  // An imperative: the addressee helps.
  EXPECT_NE(gloss("Help me!").text().find("HELP:2→1"), std::string::npos) << gloss("Help me!").text();
}

TEST(ReferentLoci, LaterPronounsReuseTheirAntecedentsPlaces) {
  // John and Mary are placed where they are introduced; he and her point back at them, and each
  // name is followed by the index that sets its place up.
  const Translation t = gloss("John met Mary. He gave her a book.");
  EXPECT_EQ(t.text(), "FS-JOHN IX-3a MEET FS-MARY IX-3b / IX-3a GIVE:3a→3b IX-3b BOOK") << t.text();
  // Gender from the pronoun alone: two women and a man.
  const Translation u = gloss("My mother called my father. She told him a story.");
  const GlossToken* she = find(u, "IX-3a");
  const GlossToken* him = find(u, "IX-3b");
  ASSERT_TRUE(she && him) << u.text();
  EXPECT_NE(find(u, "TELL:3a→3b"), nullptr) << u.text();
}

// Reported speech after a verb of telling: English leaves "he" open, and the grammar takes the
// teller, as readers most often do without more context (docs/grammar.md, "Reported speech").
TEST(ReferentLoci, ReportedSpeechAfterTellTakesTheTeller) {
  const Translation t = gloss("John told Tom he won.");
  EXPECT_EQ(t.text(), "FS-JOHN IX-3a FS-TOM IX-3b TELL:3a→3b IX-3a WIN") << t.text();
  // A pronoun of the other gender has only one antecedent.
  const Translation u = gloss("John told Mary she won.");
  EXPECT_NE(u.text().find("IX-3b WIN"), std::string::npos) << u.text();
}

TEST(ReferentLoci, HerIsTheRecipientOfAThingAndThePossessorOfAPerson) {
  EXPECT_EQ(gloss("I gave her money.").text(), "IX-1 GIVE:1→3a IX-3a MONEY");
  EXPECT_EQ(gloss("She sent her mother a letter.").text(), "IX-3a POSS-3a MOTHER IX-3b SEND:3a→3b LETTER");
  EXPECT_EQ(gloss("I need to tell her something.").text(), "IX-1 MUST TELL:1→3a IX-3a SOMETHING");
}

TEST(ReferentLoci, AnObjectPronounIsNotItsOwnClausesSubject) {
  const Translation t = gloss("He helped him.");
  EXPECT_EQ(t.text(), "IX-3a HELP:3a→3b IX-3b") << t.text();
  // A possessive may be: John's own keys.
  const Translation u = gloss("The boy lost his keys.");
  EXPECT_NE(u.text().find("BOY IX-3a"), std::string::npos) << u.text();
  EXPECT_NE(u.text().find("POSS-3a"), std::string::npos) << u.text();
}

TEST(ReferentLoci, PluralsAreArcsOverTheirPlaces) {
  // A plural noun of people is set up with an arc over its place; "they" reuses it.
  const Translation t = gloss("The children played. They laughed.");
  EXPECT_NE(t.text().find("CHILD IX-3a-PL"), std::string::npos) << t.text();
  const GlossToken* they = find(t, "IX-3a-PL", 2);
  ASSERT_TRUE(they) << t.text();
  EXPECT_EQ(they->sign(), "IX-3-PL");
  // "they" with no plural antecedent sweeps over the people already placed.
  const Translation u = gloss("John met Mary. They went home.");
  const GlossToken* both = find(u, "IX-3-PL:3a+3b");
  ASSERT_TRUE(both) << u.text();
  ASSERT_EQ(both->over.size(), 2u);
  EXPECT_EQ(both->over[0], (Locus{3, 0}));
  EXPECT_EQ(both->over[1], (Locus{3, 1}));
}

TEST(ReferentLoci, QuotedSpeechIsRoleShiftedTowardTheSpeaker) {
  const Translation t = gloss("She said, \"I am hungry.\"");
  ASSERT_EQ(t.role_shifts.size(), 1u) << t.text();
  const RoleShift& r = t.role_shifts[0];
  const GlossToken* she = find(t, "IX-3a");
  ASSERT_TRUE(she) << t.text();
  EXPECT_EQ(r.toward, she->at);
  // Over the quote's glosses only: IX-1 HUNGRY.
  std::string quoted;
  for (std::size_t i = r.first; i < r.last; ++i) quoted += t.glosses[i].gloss + " ";
  EXPECT_EQ(quoted, "IX-1 HUNGRY ") << t.text();
  // Quoted after the speech verb's subject comes later in the sentence too.
  const Translation u = gloss("\"I am hungry,\" he said.");
  ASSERT_EQ(u.role_shifts.size(), 1u) << u.text();
  EXPECT_EQ(u.role_shifts[0].toward, (Locus{3, 0}));
  // The signer quoting themselves needs no shift; no quotes, no shift.
  EXPECT_TRUE(gloss("I said, \"Hello.\"").role_shifts.empty());
  EXPECT_TRUE(gloss("She said she was tired.").role_shifts.empty());
}

TEST(ReferentLoci, PointingWordsThatAreNotAnaphoraKeepTheirSign) {
  // "this" is IX-3 pointing at a thing present, not at a referent's place.
  const Translation t = gloss("I like this.");
  EXPECT_EQ(t.text(), "IX-1 LIKE IX-3") << t.text();
  EXPECT_FALSE(t.glosses.back().at);
}

TEST(ReferentLoci, AgreementIsTheLexiconEntrysField) {
  // The built-in lexicon marks the directional verbs; plain verbs and pronouns have none.
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  LayeredLexicon layers;
  layers.push_layer(builtin);
  LexiconInventory inventory(layers, "ase");
  for (const char* verb : {"GIVE", "HELP", "TELL", "ASK", "SHOW", "SEND", "PAY"})
    EXPECT_EQ(inventory.agreement_of(verb), Agreement::forward) << verb;
  EXPECT_EQ(inventory.agreement_of("BORROW"), Agreement::backward);
  for (const char* plain : {"LOVE", "EAT", "GO", "KNOW", "IX-3", "NO-SUCH-SIGN"})
    EXPECT_EQ(inventory.agreement_of(plain), Agreement::none) << plain;
}

TEST(ReferentLoci, AUserSignMarkedForwardAgrees) {
  // A user lexicon adds a sign the built-in one lacks, marked as an agreement verb: in a sentence
  // it moves from the subject's place to the object's, as GIVE does. Unmarked, it keeps its place.
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  for (const Agreement agreement : {Agreement::forward, Agreement::none}) {
    Lexicon user = Lexicon::in_memory();
    SignEntry e;
    e.gloss = "NUDGE";
    e.language = "ase";
    e.notation = builtin.find("GIVE", "ase")->notation;
    e.keywords = {Keyword{"nudge"}};
    e.agreement = agreement;
    user.add(e);
    LayeredLexicon layers;
    layers.push_layer(builtin);
    layers.push_layer(user);
    LexiconInventory inventory(layers, "ase");
    const Translation t = translate_to_gloss("The boy nudged the girl.", inventory);
    if (agreement == Agreement::forward)
      EXPECT_NE(t.text().find("NUDGE:3a→3b"), std::string::npos) << t.text();
    else
      EXPECT_EQ(t.text().find("NUDGE:"), std::string::npos) << t.text();
    EXPECT_NE(t.text().find("NUDGE"), std::string::npos) << t.text();
  }
}

// A person named after an agreement verb is set up before the verb is directed at their place:
// object, index, then the verb (docs/grammar.md, "Objects named after the verb").
TEST(ReferentLoci, AnObjectNamedAfterTheVerbIsSetUpBeforeTheVerbMovesThere) {
  const Translation t = gloss("The teacher helped the boy.");
  EXPECT_EQ(t.text(), "TEACHER IX-3a BOY IX-3b HELP:3a→3b") << t.text();
  // Its modifiers go with it; the imperative's verb follows the named recipient; a negation still
  // follows the verb phrase.
  EXPECT_EQ(gloss("Give Rose the keys.").text(), "FS-ROSE IX-3a GIVE:2→3a KEY") << gloss("Give Rose the keys.").text();
  EXPECT_EQ(gloss("The teacher did not help the boy.").text(), "TEACHER IX-3a BOY IX-3b HELP:3a→3b NOT");
  // A possessive goes with its noun; "her" before adjectives and a person is the possessive.
  EXPECT_EQ(gloss("The mother helped her little son.").text(), "MOTHER IX-3a POSS-3a SMALL SON IX-3b HELP:3a→3b");
  // A pronoun object already has its place: the order stays.
  EXPECT_EQ(gloss("She gave him the book.").text(), "IX-3a GIVE:3a→3b IX-3b BOOK");
  // Every place the verb uses is set up by a gloss before it.
  for (const char* text : {"The teacher helped the boy.", "John told Tom he won.", "Ask Mark about the meeting."}) {
    const Translation u = gloss(text);
    for (std::size_t i = 0; i < u.glosses.size(); ++i) {
      if (!u.glosses[i].to) continue;
      bool set_up = u.glosses[i].to.person != 3;
      for (std::size_t k = 0; k < i; ++k) set_up = set_up || u.glosses[k].at == u.glosses[i].to;
      EXPECT_TRUE(set_up) << text << " → " << u.text();
    }
  }
}

}  // namespace
}  // namespace gestura
