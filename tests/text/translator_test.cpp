// Expected glosses are worked out by hand from ASL grammar and the conventions in
// docs/text-to-gloss.md (IX-1/IX-2 pointing, third persons at their places IX-3a, IX-3b… as
// docs/grammar.md says, time first, NOT and CAN'T after the verb phrase, wh-word last, numbers as digits, names and unknown words fingerspelled as FS-WORD).
#include "gestura/text/translator.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

// A small ASL vocabulary: English keyword → gloss, as a lexicon would answer.
WordListInventory vocabulary() {
  WordListInventory v;
  for (const char* word :
       {"go", "store", "live", "like", "coffee", "name", "have", "book", "eat", "meat", "swim", "come", "child",
        "play", "nice", "dollar", "cent", "help", "want", "drink", "water", "mother", "father", "work", "school",
        "deaf", "understand", "sign", "language", "happy", "cat", "dog", "car", "buy", "new", "see", "movie",
        "study", "stop", "watch", "box", "baby", "will", "can", "with", "and", "old", "year", "for", "win", "class",
        "start", "birthday", "born", "home", "cold", "meet", "wake", "up", "teacher", "percent"})
    v.add(word, [&] {
      std::string g(word);
      for (char& c : g) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return g;
    }());
  v.set_agreement("HELP", Agreement::forward);  // as the built-in lexicon's entry says
  return v;
}

Translation gloss(std::string_view text) {
  WordListInventory v = vocabulary();
  return translate_to_gloss(text, v);
}

struct Example {
  const char* english;
  const char* asl;
};

class TranslatorExamples : public ::testing::TestWithParam<Example> {};

}  // namespace

TEST_P(TranslatorExamples, GivesTheHandGlossedSequence) {
  EXPECT_EQ(gloss(GetParam().english).text(), GetParam().asl) << GetParam().english;
}

INSTANTIATE_TEST_SUITE_P(
    Sentences, TranslatorExamples,
    ::testing::Values(
        // time first, article and preposition dropped, irregular past
        Example{"I went to the store yesterday.", "YESTERDAY IX-1 GO STORE"},
        // wh-word last, do-support dropped
        Example{"Where do you live?", "IX-2 LIVE WHERE"},
        Example{"What is your name?", "POSS-2 NAME WHAT"},
        Example{"Why didn't you come yesterday?", "YESTERDAY IX-2 COME NOT WHY"},
        Example{"How many dogs do you have?", "DOG IX-2 HAVE HOW-MANY"},
        Example{"How are you?", "HOW IX-2"},
        // negation after the verb phrase
        Example{"I don't like coffee.", "IX-1 LIKE COFFEE NOT"},
        Example{"She can't swim.", "IX-3a SWIM CAN'T"},
        Example{"He doesn't understand sign language.", "IX-3a UNDERSTAND SIGN LANGUAGE NOT"},
        Example{"I never eat meat.", "IX-1 NEVER EAT MEAT"},
        Example{"I don't know.", "IX-1 DON'T-KNOW"},
        // yes/no questions keep their order
        Example{"Do you like coffee?", "IX-2 LIKE COFFEE"},
        Example{"Can you help me?", "CAN IX-2 HELP:2→1 IX-1"},
        Example{"I am deaf. Are you deaf?", "IX-1 DEAF / IX-2 DEAF"},
        // names and unknown words
        Example{"My name is John.", "POSS-1 NAME FS-JOHN"},
        Example{"I like zxqv.", "IX-1 LIKE FS-ZXQV"},
        Example{"Mary and I watched a movie last night.", "LAST-NIGHT FS-MARY AND IX-1 WATCH MOVIE"},
        // numbers, money, dates, times
        Example{"I have $5.50.", "IX-1 HAVE 5 DOLLAR 50 CENT"},
        Example{"I have three cats.", "IX-1 HAVE 3 CAT"},
        Example{"We won 25 dollars.", "WE WIN 25 DOLLAR"},
        Example{"She is twenty-five years old.", "IX-3a 25 YEAR OLD"},
        Example{"Class starts at 3:30.", "TIME 3 30 CLASS START"},
        Example{"I wake up at 7am.", "TIME 7 MORNING IX-1 WAKE UP"},
        Example{"My birthday is March 14.", "FS-MARCH 14 POSS-1 BIRTHDAY"},
        Example{"I was born on 3/14/1990.", "FS-MARCH 14 1990 IX-1 BORN"},
        Example{"I bought a new car for $20,000.", "IX-1 BUY NEW CAR FOR 20000 DOLLAR"},
        // contractions, lemmas, synonyms, pronouns
        Example{"I'm happy!", "IX-1 HAPPY"},
        Example{"The children are playing.", "CHILD IX-3a-PL PLAY"},
        Example{"The babies studied.", "BABY IX-3a-PL STUDY"},
        Example{"My mom stopped working.", "POSS-1 MOTHER STOP WORK"},
        Example{"I saw her yesterday.", "YESTERDAY IX-1 SEE IX-3a"},
        Example{"Her dog is old.", "POSS-3a DOG OLD"},
        Example{"I will see you tomorrow.", "TOMORROW IX-1 WILL SEE IX-2"},
        // perfect aspect: have + participle → FINISH; possession stays HAVE
        Example{"We have eaten.", "WE FINISH EAT"},
        Example{"She has two cats.", "IX-3a HAVE 2 CAT"},
        Example{"Thank you!", "THANK-YOU"},
        Example{"Nice to meet you!", "NICE MEET IX-2"},
        Example{"Yesterday, I went home.", "YESTERDAY / IX-1 GO HOME"},
        // typography: curly apostrophes and quotes, em dash, accented names
        Example{"I don\u2019t like coffee \u2014 it\u2019s cold.", "IX-1 LIKE COFFEE NOT / IX-3a COLD"},
        Example{"\u201cI met Jos\u00e9 in Z\u00fcrich.\u201d", "IX-1 MEET FS-JOSE FS-ZURICH"}));

TEST(Translator, ReasonsExplainEachWord) {
  const Translation t = gloss("I went to the store yesterday.");
  ASSERT_EQ(t.glosses.size(), 4u);
  // The parse makes 'went' a verb and WordNet gives its lemma (the rule table's "irregular past"
  // answers only when the sentence does not parse).
  EXPECT_EQ(t.glosses[2].reason, "'went' → GO: verb, WordNet lemma 'go'");
  EXPECT_EQ(t.glosses[0].reason, "'yesterday' → YESTERDAY: time expression, moved to the front");
  ASSERT_EQ(t.notes.size(), 6u);  // every source word, in text order
  EXPECT_EQ(t.notes[2].word, "to");
  EXPECT_EQ(t.notes[3].reason, "'the' dropped: article");
  // Spans point back into the text.
  const std::string text = "I went to the store yesterday.";
  EXPECT_EQ(text.substr(t.glosses[3].begin, t.glosses[3].end - t.glosses[3].begin), "store");
  EXPECT_EQ(t.glosses[3].kind, GlossKind::sign);
}

TEST(Translator, FingerspellingCarriesLetters) {
  const Translation t = gloss("My name is Zoë.");
  ASSERT_EQ(t.glosses.size(), 3u);
  EXPECT_EQ(t.glosses[2].gloss, "FS-ZOE");
  EXPECT_EQ(t.glosses[2].kind, GlossKind::fingerspell);
  EXPECT_EQ(t.glosses[2].letters, (std::vector<std::string>{"Z", "O", "E"}));
  EXPECT_NE(t.glosses[2].reason.find("name"), std::string::npos);

  // However the accent was typed: as é, or as e and a combining accent.
  const Translation precomposed = gloss("My name is Jos\u00e9."), combining = gloss("My name is Jose\u0301.");
  EXPECT_EQ(precomposed.text(), combining.text());
  EXPECT_EQ(combining.glosses[2].gloss, "FS-JOSE");
  EXPECT_EQ(combining.glosses[2].letters, (std::vector<std::string>{"J", "O", "S", "E"}));

  const Translation cyrillic = gloss("I met \u0418\u0432\u0430\u043d.");  // Иван
  ASSERT_EQ(cyrillic.glosses.size(), 3u);
  EXPECT_EQ(cyrillic.glosses[2].kind, GlossKind::fingerspell);
  EXPECT_EQ(cyrillic.glosses[2].letters.size(), 4u);
  EXPECT_NE(cyrillic.glosses[2].reason.find("outside the ASL manual alphabet"), std::string::npos);
}

TEST(Translator, NumbersAreNumberKind) {
  const Translation t = gloss("I have $5.50.");
  ASSERT_EQ(t.glosses.size(), 6u);
  EXPECT_EQ(t.glosses[2].kind, GlossKind::number);
  EXPECT_EQ(t.glosses[3].kind, GlossKind::sign);  // DOLLAR
  EXPECT_EQ(t.glosses[4].kind, GlossKind::number);
}

TEST(Translator, SentenceTypesAndMarkerSpans) {
  const Translation t = gloss("I am deaf. Are you deaf? Where do you live? I don't like coffee. Wow!");
  // IX-1 DEAF / IX-2 DEAF / IX-2 LIVE WHERE / IX-1 LIKE COFFEE NOT / WOW
  ASSERT_EQ(t.sentences.size(), 5u);
  EXPECT_EQ(t.sentences[0].type, SentenceType::statement);
  EXPECT_EQ(t.sentences[1].type, SentenceType::yes_no_question);
  EXPECT_EQ(t.sentences[2].type, SentenceType::wh_question);
  EXPECT_EQ(t.sentences[3].type, SentenceType::statement);
  EXPECT_TRUE(t.sentences[3].negated);
  EXPECT_EQ(t.sentences[4].type, SentenceType::exclamation);
  EXPECT_EQ(t.text(), "IX-1 DEAF / IX-2 DEAF / IX-2 LIVE WHERE / IX-1 LIKE COFFEE NOT / FS-WOW");

  auto marker = [&](MarkerKind kind) {
    for (const Marker& m : t.markers)
      if (m.kind == kind) return std::pair{m.first, m.last};
    return std::pair<std::size_t, std::size_t>{0, 0};
  };
  EXPECT_EQ(marker(MarkerKind::yes_no_question), (std::pair<std::size_t, std::size_t>{3, 5}));
  EXPECT_EQ(marker(MarkerKind::wh_question), (std::pair<std::size_t, std::size_t>{6, 9}));
  EXPECT_EQ(marker(MarkerKind::negation), (std::pair<std::size_t, std::size_t>{11, 14}));  // LIKE COFFEE NOT
  EXPECT_EQ(marker(MarkerKind::exclamation), (std::pair<std::size_t, std::size_t>{15, 16}));
}

TEST(Translator, NegatedWhQuestionMarksBoth) {
  const Translation t = gloss("Why don't you like coffee?");
  EXPECT_EQ(t.text(), "IX-2 LIKE COFFEE NOT WHY");
  ASSERT_EQ(t.markers.size(), 2u);
  EXPECT_EQ(t.markers[0].kind, MarkerKind::negation);
  EXPECT_EQ(t.markers[0].first, 1u);
  EXPECT_EQ(t.markers[0].last, 4u);
  EXPECT_EQ(t.markers[1].kind, MarkerKind::wh_question);
  EXPECT_EQ(t.markers[1].last, 5u);
}

TEST(Translator, OpenVocabularyUsesLemmasAndCapitalsForNames) {
  OpenVocabulary open;
  EXPECT_EQ(translate_to_gloss("Yesterday Sarah bought three books.", open).text(), "YESTERDAY FS-SARAH BUY 3 BOOK");
  EXPECT_EQ(translate_to_gloss("The kids liked running.", open).text(), "KID IX-3a-PL LIKE RUN");
}

// A keyword of several words (as a lexicon lists "train station" or "wake up") is one sign, found
// with its first or last word inflected; a form the lexicon lists as written keeps its own sign
// before lemmas are tried; a capitalised word with a sign is signed, not spelled as a name.
TEST(Translator, LexiconPhrasesListedFormsAndCapitalisedWordsWithSigns) {
  WordListInventory v{{"train station", "STATION"}, {"train", "TRAIN"}, {"wake up", "WAKE-UP"},
                      {"glasses", "GLASSES"},       {"glass", "GLASS"},   {"sunday", "SUNDAY"},
                      {"credit card", "CREDIT-CARD"}, {"pay", "PAY"},     {"lose", "LOSE"}};
  EXPECT_EQ(translate_to_gloss("Where is the train station?", v).text(), "STATION WHERE");
  EXPECT_EQ(translate_to_gloss("The train is late.", v).text(), "TRAIN FS-LATE");
  EXPECT_EQ(translate_to_gloss("She woke up.", v).text(), "IX-3a WAKE-UP");
  EXPECT_EQ(translate_to_gloss("I paid with credit cards.", v).text(), "IX-1 PAY FS-WITH CREDIT-CARD");
  EXPECT_EQ(translate_to_gloss("I lost my glasses.", v).text(), "IX-1 LOSE POSS-1 GLASSES");
  EXPECT_EQ(translate_to_gloss("I drank a glass.", v).text(), "IX-1 FS-DRANK GLASS");
  EXPECT_EQ(translate_to_gloss("We rest on Sundays.", v).text(), "WE FS-REST SUNDAY");
  // The open vocabulary would take any run of words as one sign, so it does not look phrases up.
  OpenVocabulary open;
  EXPECT_EQ(translate_to_gloss("The train station.", open).text(), "TRAIN STATION");
}

TEST(TranslatorInput, EmptyAndPunctuationOnly) {
  EXPECT_TRUE(gloss("").glosses.empty());
  EXPECT_TRUE(gloss("").sentences.empty());
  const Translation t = gloss("  ?! ... ,, \u2014 \u201c\u201d ");
  EXPECT_TRUE(t.glosses.empty());
  EXPECT_TRUE(t.markers.empty());
}

TEST(TranslatorInput, InvalidUtf8IsAClearError) {
  auto message = [](std::string_view text) -> std::string {
    try {
      gloss(text);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_EQ(message("caf\xC3"), "invalid UTF-8 at byte 3 (the text must be UTF-8)");  // truncated
  EXPECT_EQ(message("ab \xC0\xAF"), "invalid UTF-8 at byte 3 (the text must be UTF-8)");  // overlong '/'
  EXPECT_EQ(message("\xED\xA0\x80"), "invalid UTF-8 at byte 0 (the text must be UTF-8)");  // surrogate
  EXPECT_EQ(message("ok \xFF"), "invalid UTF-8 at byte 3 (the text must be UTF-8)");
}

TEST(TranslatorInput, BinaryJunkNeverCrashes) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk.push_back(static_cast<char>((i * 7919 + 13) % 256));
  EXPECT_THROW(gloss(junk), Error);  // not UTF-8
  // Valid UTF-8 that is no language: controls, NULs, emoji, symbols.
  const std::string valid_junk("\x01\x02\0\x7f \xF0\x9F\x98\x80 \xC2\xA7\xC2\xB6 ### @@ 12abc", 27);
  const Translation t = gloss(valid_junk);
  for (const GlossToken& g : t.glosses) EXPECT_FALSE(g.gloss.empty());
}

TEST(TranslatorInput, OneMegabyteOfText) {
  std::string text;
  const std::string sentence = "I went to the store yesterday. ";
  while (text.size() < (1u << 20)) text += sentence;
  const std::size_t sentences = text.size() / sentence.size();
  const Translation t = gloss(text);
  // 4 glosses per sentence plus a pause between sentences.
  EXPECT_EQ(t.glosses.size(), sentences * 5 - 1);
  EXPECT_EQ(t.sentences.size(), sentences);
  // One megabyte without any sentence end is one long sentence; still handled.
  std::string run_on(1u << 20, 'a');
  for (std::size_t i = 5; i < run_on.size(); i += 6) run_on[i] = ' ';
  const Translation long_one = gloss(run_on);
  EXPECT_EQ(long_one.glosses.size(), (1u << 20) / 6 + 1);
}

// Random sentences built from the tricky pieces (contractions, money, clock times, dates, wh-words,
// negation, dashes, curly quotes, accented names) must keep the output's invariants.
TEST(TranslatorInput, RandomMixesKeepInvariants) {
  const std::vector<std::string> pieces{
      "I",     "you",   "her",  "don't", "can't", "not",    "never",   "who",  "how many", "where", "do",
      "the",   "$",     "$5",   "5.50",  "3:30",  "7am",    "p.m.",    "o'clock", "March", "May",  "14",
      "2024",  "3/14",  "1st",  "%",     "50%",   "twenty-five", "and", "one",   ",",     "\u2014", "\u2019s",
      "\u201c", "Jos\u00e9", "\u0418\u0432\u0430\u043d", "?",  "!",   ".",      "...",     "thank", "you",
      "last",  "night", "Yesterday", "dogs", "went", "store", "-",    ":",      "\u2026", "a.m",  "is"};
  std::uint32_t seed = 12345;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  for (int round = 0; round < 2000; ++round) {
    std::string text;
    const int length = static_cast<int>(next() % 14);
    for (int k = 0; k < length; ++k) {
      if (next() % 3) text.push_back(' ');
      text += pieces[next() % pieces.size()];
    }
    const Translation t = gloss(text);
    for (const GlossToken& g : t.glosses) {
      EXPECT_FALSE(g.gloss.empty()) << text;
      EXPECT_LE(g.begin, g.end) << text;
      EXPECT_LE(g.end, text.size()) << text;
      if (g.kind == GlossKind::fingerspell) {
        EXPECT_FALSE(g.letters.empty()) << text;
      }
    }
    for (const Marker& m : t.markers) {
      EXPECT_LT(m.first, m.last) << text;
      EXPECT_LE(m.last, t.glosses.size()) << text;
    }
    for (const Sentence& s : t.sentences) EXPECT_LE(s.last, t.glosses.size()) << text;
    if (!t.glosses.empty()) {
      EXPECT_NE(t.glosses.front().kind, GlossKind::pause) << text;
      EXPECT_NE(t.glosses.back().kind, GlossKind::pause) << text;
    }
  }
}

// The examples of issue 15 that the rule tables got wrong, now read through the parse.
TEST(TranslatorParse, IssueExamplesReadThroughTheParse) {
  WordListInventory v = vocabulary();
  for (const auto& [word, gloss] : std::vector<std::pair<const char*, const char*>>{
           {"head", "HEAD"}, {"hurt", "HURT"}, {"station", "STATION"}, {"homework", "HOMEWORK"}, {"this", "THIS"},
           {"cost", "COST"}, {"room", "ROOM"}, {"leave", "LEAVE"}, {"left", "LEFT"}, {"turn", "TURN"},
           {"give", "GIVE"}, {"do", "DO"}})
    v.add(word, gloss);
  v.add("train station", "STATION");
  const auto text = [&](std::string_view english) { return translate_to_gloss(english, v).text(); };
  // "hurts" is a verb: its lemma, not a fingerspelled form; "head" the noun, never a verb's synonym.
  EXPECT_EQ(text("my head hurts"), "POSS-1 HEAD HURT");
  EXPECT_EQ(text("I went to the train station."), "IX-1 GO STATION");
  // "does" as the main verb is DO; as do-support it is dropped, and HOW-MUCH is signed once, last.
  EXPECT_EQ(text("She does her homework."), "IX-3a DO POSS-3a HOMEWORK");
  const Translation coffee = translate_to_gloss("How much does this coffee cost?", v);
  EXPECT_EQ(coffee.text(), "THIS COFFEE COST HOW-MUCH");
  // The same word by its part of speech: "left" the verb is LEAVE, the direction LEFT.
  EXPECT_EQ(text("He left the room."), "IX-3a LEAVE ROOM");
  EXPECT_EQ(text("Turn left."), "TURN LEFT");
}

// A participle in an adjective phrase keeps the sign listed for its form; as its clause's verb it
// takes its lemma's.
TEST(TranslatorParse, AParticipleUsedAsAnAdjectiveKeepsItsOwnSign) {
  WordListInventory v = vocabulary();
  v.add("tired", "TIRED");
  v.add("tire", "WHEEL");
  v.add("very", "VERY");
  v.add("yesterday", "YESTERDAY");
  v.add("leave", "LEAVE");
  v.add("left", "LEFT");
  const auto text = [&](std::string_view english) { return translate_to_gloss(english, v).text(); };
  EXPECT_EQ(text("I am tired."), "IX-1 TIRED");
  EXPECT_EQ(text("I am very tired."), "IX-1 VERY TIRED");
  EXPECT_EQ(text("He left yesterday."), "YESTERDAY IX-3a LEAVE");
  // After "was", where the parse joins "tired and left" as two verbs, WordNet's adjective 'tired'
  // (a form the lexicon signs) is the state; "left" after "and" is still the verb.
  EXPECT_EQ(text("She was tired and left."), "IX-3a TIRED AND LEAVE");
  // A passive participle that is no adjective in WordNet keeps its verb: "was given" → GIVE.
  v.add("give", "GIVE");
  EXPECT_EQ(text("The book was given to me.").find("GIVE") != std::string::npos, true) << text("The book was given to me.");
}

// ASL has no passive: the agent of a by-phrase is signed before the verb (DOOR LOCK TEACHER would read
// as the door locking the teacher); a state the lexicon signs as an adjective keeps its order.
TEST(TranslatorParse, APassivesAgentIsSignedBeforeItsVerb) {
  WordListInventory v = vocabulary();
  for (const char* word : {"door", "lock", "surprised", "gift"})
    v.add(word, [&] {
      std::string g(word);
      for (char& c : g) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return g;
    }());
  EXPECT_EQ(translate_to_gloss("The door was locked by the teacher.", v).text(), "DOOR TEACHER LOCK");
  EXPECT_EQ(translate_to_gloss("The door was locked by my father.", v).text(), "DOOR POSS-1 FATHER LOCK");
  EXPECT_EQ(translate_to_gloss("I was surprised by the gift.", v).text(), "IX-1 SURPRISED GIFT");
  // "by" that is no passive's stays a place word (dropped as a preposition), in order.
  EXPECT_EQ(translate_to_gloss("I live by the school.", v).text(), "IX-1 LIVE SCHOOL");
}

// A capitalised word that link-grammar reads as a given name is a name, even when the noun has a
// sign: "Bill" in "John told Bill he won" is a person, fingerspelled and placed, not BILL (money).
TEST(TranslatorParse, AGivenNameIsANameNotTheNoun) {
  WordListInventory v = vocabulary();
  v.add("bill", "BILL");
  v.add("tell", "TELL");
  v.add("pay", "PAY");
  v.set_agreement("TELL", Agreement::forward);
  const Translation t = translate_to_gloss("John told Bill he won.", v);
  EXPECT_EQ((" " + t.text() + " ").find(" BILL "), std::string::npos) << t.text();
  EXPECT_NE(t.text().find("FS-BILL"), std::string::npos) << t.text();
  EXPECT_NE(t.text().find("TELL:3a→3b"), std::string::npos) << t.text();
  // The noun keeps its sign.
  EXPECT_EQ(translate_to_gloss("I paid the bill.", v).text(), "IX-1 PAY BILL");
}

// At the start of a sentence every word has a capital, and link-grammar reads any word of its name
// lists as a name there (Hope.f, Summer.f). A name is what the common word cannot be: a singular
// count noun standing bare as the subject of an action ("Bill paid.", "Rose bought flowers."); a
// mass or abstract noun, or a thing that only *is* something, stays the noun.
TEST(TranslatorParse, ASentenceOpeningGivenNameIsANameWhenTheNounCannotStandThere) {
  WordListInventory v = vocabulary();
  for (const char* word : {"bill", "pay", "rose", "flower", "hope", "important", "summer", "hot", "art", "fun",
                           "due", "today", "ask", "about", "mark", "meeting", "easter", "park", "love"})
    v.add(word, [&] {
      std::string g(word);
      for (char& c : g) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return g;
    }());
  v.set_agreement("ASK", Agreement::forward);
  EXPECT_EQ(translate_to_gloss("Bill paid.", v).text(), "FS-BILL PAY");
  EXPECT_EQ(translate_to_gloss("Rose bought flowers.", v).text().rfind("FS-ROSE ", 0), 0u)
      << translate_to_gloss("Rose bought flowers.", v).text();
  EXPECT_EQ(translate_to_gloss("Hope is important.", v).text(), "HOPE IMPORTANT");
  EXPECT_EQ(translate_to_gloss("Summer is hot.", v).text(), "SUMMER HOT");
  EXPECT_EQ(translate_to_gloss("Love is important.", v).text(), "LOVE IMPORTANT");
  // A word that is a noun for a person (Mom) is signed as that noun, wherever it stands.
  v.add("mom", "MOTHER");
  EXPECT_EQ(translate_to_gloss("Mom went home.", v).text(), "MOTHER GO HOME");
  EXPECT_EQ(translate_to_gloss("I called Mom.", v).text().find("FS-"), std::string::npos)
      << translate_to_gloss("I called Mom.", v).text();
  EXPECT_EQ(translate_to_gloss("Bill is due today.", v).text().find("FS-"), std::string::npos)
      << translate_to_gloss("Bill is due today.", v).text();
  // Inside a sentence: a name from link-grammar's lists even where the parse read another word
  // (Mark.c, the currency), set up before the verb that is directed at it.
  EXPECT_EQ(translate_to_gloss("Ask Mark about the meeting.", v).text(), "FS-MARK IX-3a ASK:2→3a ABOUT MEETING");
  // A capitalised word whose first WordNet sense is itself capitalised is that thing; after an
  // article it is no name.
  EXPECT_EQ(translate_to_gloss("We love Easter.", v).text(), "WE LOVE EASTER");
  EXPECT_EQ(translate_to_gloss("I like the Park.", v).text(), "IX-1 LIKE PARK");
}

TEST(TranslatorParse, TheExplanationNamesTheParse) {
  WordListInventory v = vocabulary();
  v.add("give", "GIVE");
  v.set_agreement("GIVE", Agreement::forward);  // as the lexicon entry says
  const Translation t = translate_to_gloss("She gave him the book. Do you like coffee?", v);
  ASSERT_EQ(t.sentences.size(), 2u);
  EXPECT_EQ(t.sentences[0].parse.rfind("(S (NP she) (VP gave", 0), 0u) << t.sentences[0].parse;
  EXPECT_NE(t.sentences[0].parse.find("subject 'She' → verb 'gave'"), std::string::npos) << t.sentences[0].parse;
  EXPECT_NE(t.sentences[0].parse.find("verb 'gave' → object 'book'"), std::string::npos) << t.sentences[0].parse;
  bool do_dropped = false;
  for (const WordNote& n : t.notes)
    if (n.word == "Do") do_dropped = n.reason.find("do-support (parse: I link to the verb") != std::string::npos;
  EXPECT_TRUE(do_dropped);
  EXPECT_EQ(t.text(), "IX-3a GIVE:3a→3b IX-3b BOOK / IX-2 LIKE COFFEE");
}

TEST(TranslatorParse, AuxiliariesDroppedAndPerfectHaveSigned) {
  WordListInventory v = vocabulary();
  v.add("dinner", "DINNER");
  const auto text = [&](std::string_view english) { return translate_to_gloss(english, v).text(); };
  EXPECT_EQ(text("I have eaten dinner."), "IX-1 FINISH EAT DINNER");
  EXPECT_EQ(text("Have you eaten?"), "FINISH IX-2 EAT");
  EXPECT_EQ(text("She is going to school."), "IX-3a GO SCHOOL");
  EXPECT_EQ(text("Did you see the movie?"), "IX-2 SEE MOVIE");
  EXPECT_EQ(text("I do not like meat."), "IX-1 LIKE MEAT NOT");
}
