// The built-in ASL lexicon (data/lexicon/ase.jsonl): it loads with the real loader, every notation
// parses with the strict HamNoSys parser, the translator finds a sign for every content word of a set of
// everyday sentences, and a few signs carry the phonology we know them to have (checked against the
// parsed notation, not against the file's own text).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"
#include "support/build_paths.hpp"

using namespace gestura;
using namespace gestura::sign;

namespace {

const std::string kAseFile = gestura::test::source_dir() + "/data/lexicon/ase.jsonl";

std::vector<nlohmann::json> raw_lines() {
  std::ifstream in(kAseFile);
  EXPECT_TRUE(in) << kAseFile;
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

class BuiltinAse : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    lexicon_ = new Lexicon(load_builtin_lexicon(kAseFile));
    entries_ = new std::vector<SignEntry>(lexicon_->list("ase"));
  }
  static void TearDownTestSuite() {
    delete entries_;
    delete lexicon_;
  }
  static const SignEntry& entry(const std::string& gloss) {
    const auto it = std::find_if(entries_->begin(), entries_->end(), [&](const SignEntry& e) { return e.gloss == gloss; });
    if (it == entries_->end()) throw std::runtime_error("no entry " + gloss);
    return *it;
  }
  static ManualSign sign(const std::string& gloss) {
    return parse_hamnosys_unicode(entry(gloss).notation, ParseOptions{.strict = true}).main();
  }
  static Lexicon* lexicon_;
  static std::vector<SignEntry>* entries_;
};
Lexicon* BuiltinAse::lexicon_ = nullptr;
std::vector<SignEntry>* BuiltinAse::entries_ = nullptr;

const Motion* first_motion(const std::vector<Element>& actions) {
  for (const Element& e : actions) {
    if (const Motion* m = e.motion()) return m;
    if (const Motion* m = first_motion(e.children)) return m;
  }
  return nullptr;
}

bool has_motion_kind(const std::vector<Element>& actions, MotionKind kind) {
  return std::any_of(actions.begin(), actions.end(), [&](const Element& e) {
    return (e.motion() && e.motion()->kind == kind) || has_motion_kind(e.children, kind);
  });
}

bool has_repetition(const std::vector<Element>& actions) {
  return std::any_of(actions.begin(), actions.end(),
                     [&](const Element& e) { return e.repetition() != nullptr || has_repetition(e.children); });
}

}  // namespace

TEST_F(BuiltinAse, LoadsAtLeast300SignsAllAslWithUniqueGlosses) {
  const std::vector<nlohmann::json> lines = raw_lines();
  EXPECT_GE(entries_->size(), 300u);
  // The loader replaces on a repeated (gloss, lang, variant): equal counts mean no gloss was written twice.
  EXPECT_EQ(entries_->size(), lines.size());
  std::set<std::string> glosses;
  for (const nlohmann::json& line : lines) {
    EXPECT_EQ(line.at("lang"), "ase") << line.dump();
    EXPECT_TRUE(glosses.insert(line.at("gloss").get<std::string>()).second) << "repeated gloss " << line.at("gloss");
  }
  for (const SignEntry& e : *entries_) {
    EXPECT_EQ(e.language, "ase");
    EXPECT_EQ(e.variant, 1) << e.gloss;
    EXPECT_EQ(e.notation_kind, NotationKind::hamnosys) << e.gloss;
    EXPECT_EQ(e.source, "gestura") << e.gloss;
    EXPECT_EQ(e.licence, "CC0-1.0") << e.gloss;
    EXPECT_FALSE(e.keywords.empty()) << e.gloss;
  }
}

TEST_F(BuiltinAse, EveryLineHasADescriptionACategoryAndNamesMatchingTheUnicode) {
  for (const nlohmann::json& line : raw_lines()) {
    const std::string gloss = line.at("gloss");
    EXPECT_GE(line.at("description").get<std::string>().size(), 20u) << gloss;
    EXPECT_FALSE(line.at("category").get<std::string>().empty()) << gloss;
    EXPECT_EQ(symbols_from_names(line.at("names").get<std::string>()),
              symbols_from_unicode(line.at("hamnosys").get<std::string>()))
        << gloss;
  }
}

TEST_F(BuiltinAse, EveryNotationParsesStrictly) {
  for (const SignEntry& e : *entries_) {
    try {
      const HamSign parsed = parse_hamnosys_unicode(e.notation, ParseOptions{.strict = true});
      EXPECT_TRUE(parsed.notes.empty()) << e.gloss;
      EXPECT_EQ(parsed.segments.size(), 1u) << e.gloss << ": compounds are written as sequences, not top-level hamplus";
      EXPECT_TRUE(parsed.main().posture.handshape.dominant.has_value()) << e.gloss;
      EXPECT_TRUE(parsed.main().posture.orientation.dominant.has_value()) << e.gloss;
    } catch (const gestura::Error& error) {
      ADD_FAILURE() << e.gloss << ": " << error.what();
    }
  }
}

TEST_F(BuiltinAse, EachEnglishKeywordLeadsToItsOwnSign) {
  LayeredLexicon layers;
  layers.push_layer(*lexicon_);
  LexiconInventory inventory(layers, "ase");
  std::map<std::string, std::string> owner;
  for (const SignEntry& e : *entries_)
    for (const Keyword& k : e.keywords) {
      const auto [it, fresh] = owner.emplace(k.word, e.gloss);
      EXPECT_TRUE(fresh) << "'" << k.word << "' is a keyword of " << it->second << " and " << e.gloss;
      if (k.word.find(' ') == std::string::npos) {
        EXPECT_EQ(inventory.gloss_for(k.word), e.gloss) << k.word;
      }
    }
}

// A number the translator emits is signed from the lexicon: directly (0–20, the tens, 100, 1000) or,
// by the composition rule of docs/asl-lexicon.md, digit by digit (47 = 4 then 7).
bool number_is_signable(Lexicon& lexicon, const std::string& number) {
  if (lexicon.find(number, "ase")) return true;
  if (number.empty() || !std::all_of(number.begin(), number.end(), [](unsigned char c) { return std::isdigit(c); }))
    return false;
  return std::all_of(number.begin(), number.end(),
                     [&](char digit) { return lexicon.find(std::string(1, digit), "ase").has_value(); });
}

TEST_F(BuiltinAse, TheTranslatorFindsASignForEveryWordOfEverydaySentences) {
  const std::vector<std::string> sentences{
      "Hello, my name is John.",
      "Nice to meet you.",
      "Thank you very much.",
      "How are you?",
      "I am fine, thank you.",
      "Where do you live?",
      "I live in New York.",
      "What is your name?",
      "I don't understand.",
      "Can you help me?",
      "I want to eat pizza.",
      "My mother is a teacher.",
      "My father works at the hospital.",
      "I went to the store yesterday.",
      "We will go to school tomorrow.",
      "Do you have a brother or a sister?",
      "I love you.",
      "I don't know.",
      "Why didn't you come yesterday?",
      "How many children do you have?",
      "I have two dogs and a cat.",
      "I am deaf and my friend is hearing.",
      "She is learning sign language.",
      "I like coffee but I don't like tea.",
      "The weather is cold today.",
      "I am very tired tonight.",
      "Please give me the book.",
      "What time is it?",
      "I have finished my work.",
      "See you later!",
      "The red car is new.",
      "When is your birthday?",
      "Goodbye, have a good day.",
      "Who is your teacher?",
      "I need 25 dollars.",
  };
  LayeredLexicon layers;
  layers.push_layer(*lexicon_);
  LexiconInventory inventory(layers, "ase");
  std::set<std::string> fingerspelled;
  std::size_t signs = 0;
  for (const std::string& text : sentences) {
    const Translation t = translate_to_gloss(text, inventory);
    for (const GlossToken& g : t.glosses) {
      switch (g.kind) {
        case GlossKind::sign:
          ++signs;
          EXPECT_TRUE(lexicon_->find(g.sign(), "ase").has_value()) << text << ": " << g.gloss << " (sign " << g.sign() << ")";
          break;
        case GlossKind::number:
          EXPECT_TRUE(number_is_signable(*lexicon_, g.gloss)) << text << ": " << g.gloss;
          break;
        case GlossKind::fingerspell: fingerspelled.insert(g.gloss); break;
        case GlossKind::pause: break;
      }
    }
  }
  // Only the name is spelled; every other word has a sign.
  EXPECT_EQ(fingerspelled, (std::set<std::string>{"FS-JOHN"}));
  EXPECT_GE(signs, 100u);
  // Spot checks of words whose sign depends on keyword choices.
  EXPECT_EQ(translate_to_gloss("I am deaf and my friend is hearing.", inventory).text(),
            "IX-1 DEAF AND POSS-1 FRIEND HEARING");
  EXPECT_EQ(translate_to_gloss("My mom and dad.", inventory).text(), "POSS-1 MOTHER AND FATHER");
}

TEST_F(BuiltinAse, MotherIsAnOpenFiveWithTheThumbOnTheChin_FatherOnTheForehead) {
  for (const auto& [gloss, site] : {std::pair{"MOTHER", Site::chin}, std::pair{"FATHER", Site::forehead}}) {
    const ManualSign s = sign(gloss);
    ASSERT_TRUE(s.posture.handshape.dominant) << gloss;
    EXPECT_EQ(s.posture.handshape.dominant->form.basic, BasicHandshape::Finger2345) << gloss;
    EXPECT_EQ(s.posture.handshape.dominant->form.thumb, ThumbModifier::Out) << gloss;
    ASSERT_TRUE(s.posture.location.dominant) << gloss;
    EXPECT_EQ(s.posture.location.dominant->site, site) << gloss;
    EXPECT_EQ(s.posture.location.dominant->proximity, Proximity::touch) << gloss;
    EXPECT_EQ(s.posture.orientation.dominant->extended_finger, Direction::U) << gloss;
    EXPECT_EQ(s.symmetry.kind, SymmetryKind::none) << gloss;  // one-handed
    EXPECT_TRUE(has_repetition(s.actions)) << gloss << ": the thumb taps twice";
  }
}

TEST_F(BuiltinAse, ThankYouLeavesTheChinForwardAndDown) {
  const ManualSign s = sign("THANK-YOU");
  EXPECT_EQ(s.posture.handshape.dominant->form.basic, BasicHandshape::Flat);
  EXPECT_EQ(s.posture.location.dominant->site, Site::chin);
  const Motion* m = first_motion(s.actions);
  ASSERT_NE(m, nullptr);
  ASSERT_TRUE(m->direction);
  const DirectionComponents c = components(*m->direction);
  EXPECT_EQ(c.vertical, -1);
  EXPECT_EQ(c.sagittal, 1);
}

TEST_F(BuiltinAse, HelloIsASaluteFromTheForehead) {
  const ManualSign s = sign("HELLO");
  EXPECT_EQ(s.posture.handshape.dominant->form.basic, BasicHandshape::Flat);
  EXPECT_EQ(s.posture.location.dominant->site, Site::forehead);
  EXPECT_EQ(s.posture.location.dominant->side, Side::dominant_side);
  // Fingers up (tilted toward the forehead, as in a salute) with palm "d": the palm faces away from the signer.
  EXPECT_EQ(components(*s.posture.orientation.dominant->extended_finger).vertical, 1);
  EXPECT_EQ(s.posture.orientation.dominant->palm, Direction::D);
  const Motion* m = first_motion(s.actions);
  ASSERT_TRUE(m && m->direction);
  EXPECT_EQ(components(*m->direction).sagittal, 1);  // out, away from the head
}

TEST_F(BuiltinAse, YesNodsAFist_NoSnapsTwoFingersOntoTheThumb) {
  const ManualSign yes = sign("YES");
  EXPECT_EQ(yes.posture.handshape.dominant->form.basic, BasicHandshape::Fist);
  EXPECT_TRUE(has_motion_kind(yes.actions, MotionKind::nodding));
  const ManualSign no = sign("NO");
  EXPECT_EQ(no.posture.handshape.dominant->form.basic, BasicHandshape::Finger23);
  EXPECT_EQ(no.posture.handshape.dominant->form.thumb, ThumbModifier::Out);
  const Motion* m = first_motion(no.actions);
  ASSERT_TRUE(m && m->kind == MotionKind::replacement && m->new_handshape);
  EXPECT_EQ(m->new_handshape->form.basic, BasicHandshape::Pinch12);
}

TEST_F(BuiltinAse, PointingSignsAndTwoHandedSigns) {
  const ManualSign me = sign("IX-1");
  EXPECT_EQ(me.posture.handshape.dominant->form.basic, BasicHandshape::Finger2);
  EXPECT_EQ(me.posture.orientation.dominant->extended_finger, Direction::I);  // at the signer
  EXPECT_EQ(me.posture.location.dominant->site, Site::chest);
  EXPECT_EQ(sign("IX-2").posture.orientation.dominant->extended_finger, Direction::O);
  EXPECT_EQ(sign("GO").symmetry.kind, SymmetryKind::parallel);
  EXPECT_EQ(sign("WANT").symmetry.kind, SymmetryKind::mirrored_lr);
  // SCHOOL: the dominant hand claps onto a different (palm-up) non-dominant hand.
  const ManualSign school = sign("SCHOOL");
  ASSERT_TRUE(school.posture.orientation.nondominant);
  EXPECT_EQ(school.posture.orientation.nondominant->palm, Direction::U);
  EXPECT_EQ(school.posture.orientation.dominant->palm, Direction::D);
}

TEST_F(BuiltinAse, CardinalNumbersOneToFiveFaceTheSignerSixToNineFaceOut) {
  for (int n = 1; n <= 9; ++n) {
    const ManualSign s = sign(std::to_string(n));
    EXPECT_EQ(s.posture.orientation.dominant->extended_finger, Direction::U) << n;
    // Fingers up: palm "u" faces the signer, palm "d" the addressee.
    EXPECT_EQ(s.posture.orientation.dominant->palm, n <= 5 ? Direction::U : Direction::D) << n;
  }
  EXPECT_EQ(sign("1").posture.handshape.dominant->form.basic, BasicHandshape::Finger2);
  EXPECT_EQ(sign("2").posture.handshape.dominant->form.basic, BasicHandshape::Finger23Spread);
  EXPECT_EQ(sign("5").posture.handshape.dominant->form.basic, BasicHandshape::Finger2345);
  EXPECT_EQ(sign("5").posture.handshape.dominant->form.thumb, ThumbModifier::Out);
  EXPECT_NE(sign("4").posture.handshape.dominant->form.thumb, ThumbModifier::Out);
  for (int n = 0; n <= 20; ++n) EXPECT_TRUE(lexicon_->find(std::to_string(n), "ase")) << n;
  for (int n = 30; n <= 100; n += 10) EXPECT_TRUE(lexicon_->find(std::to_string(n), "ase")) << n;
  // A ten ends in the O of zero.
  const ManualSign forty = sign("40");
  const Motion* m = first_motion(forty.actions);
  ASSERT_TRUE(m && m->new_handshape);
  EXPECT_EQ(m->new_handshape->form.basic, BasicHandshape::PinchAll);
}
