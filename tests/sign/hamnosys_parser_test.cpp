// Hand-checked HamNoSys signs parsed into the typed model, the symbol table against the published
// code point list, and malformed input that must give gestura::Error with a symbol index.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura::sign;

// Encodes symbols as the UTF-8 Unicode form (our own encoder, independent of the decoder's table).
std::string utf8(char32_t cp) {
  std::string out;
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
  return out;
}

int error_index(const std::string& names, const ParseOptions& options = {}) {
  try {
    parse_hamnosys_names(names, options);
  } catch (const gestura::Error& e) {
    return e.where().index;
  }
  return -100;  // parsed
}

TEST(HamnosysSymbols, TableMatchesPublishedCodepoints) {
  std::ifstream in(gestura::test::shared_data() + "/hamnosys/codepoints.tsv");
  ASSERT_TRUE(in);
  std::string line;
  std::getline(in, line);  // header
  int rows = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name, tex, code;
    std::getline(fields, name, '\t');
    std::getline(fields, tex, '\t');
    std::getline(fields, code, '\t');
    const char32_t cp = static_cast<char32_t>(std::stoul(code.substr(2), nullptr, 16));
    const auto by_name = symbol_from_name(name);
    ASSERT_TRUE(by_name) << name;
    EXPECT_EQ(symbol_info(*by_name).codepoint, cp) << name;
    const auto by_cp = symbol_from_codepoint(cp);
    ASSERT_TRUE(by_cp) << code;
    EXPECT_EQ(symbol_name(*by_cp), name);
    ++rows;
  }
  EXPECT_EQ(rows, 209);
  EXPECT_EQ(symbol_table().size(), 209u);
}

TEST(HamnosysDirections, ComponentsVectorsAndMerging) {
  EXPECT_EQ(to_string(Direction::UOL), "uol");
  EXPECT_EQ(gestura::parse_direction("dir"), Direction::DIR);
  // Avatar frame: +X is the avatar's left, +Y up, +Z forward.
  EXPECT_EQ(direction_vector(Direction::L), glm::vec3(1, 0, 0));
  EXPECT_EQ(direction_vector(Direction::O), glm::vec3(0, 0, 1));
  EXPECT_EQ(direction_vector(Direction::D), glm::vec3(0, -1, 0));
  EXPECT_EQ(merge_directions(Direction::UO, Direction::OL), Direction::UOL);
  EXPECT_EQ(merge_directions(Direction::DI, Direction::IR), Direction::DIR);
  EXPECT_EQ(merge_directions(Direction::U, Direction::D), std::nullopt);
  EXPECT_EQ(merge_directions(Direction::DO, Direction::IR), std::nullopt);
  for (int d = 0; d < 26; ++d) {
    const auto dir = static_cast<Direction>(d);
    EXPECT_EQ(gestura::parse_direction(to_string(dir)), dir);
    const DirectionComponents c = components(dir);  // the model's components are the vector's axes
    EXPECT_EQ(direction_vector(dir), glm::normalize(glm::vec3(c.lateral, c.vertical, c.sagittal)));
  }
}

// DGS PILL1^: pinch hand pointing up-left, palm left, at the lips; moves in a little while
// opening to a C-shape; ends close; repeated.
TEST(HamnosysParser, PillHandshapeLocationAndReplacement) {
  const HamSign sign = parse_hamnosys_names(
      "hampinch12,hamextfingerul,hampalml,hamlips,hamparbegin,hammovei,hamsmallmod,hamreplace,hamcee12,"
      "hamfingerstraightmod,hamthumbopenmod,hamparend,hamclose,hamrepeatfromstart");
  ASSERT_EQ(sign.segments.size(), 1u);
  const ManualSign& m = sign.main();
  EXPECT_EQ(m.symmetry.kind, SymmetryKind::none);
  ASSERT_TRUE(m.posture.handshape.dominant);
  EXPECT_EQ(m.posture.handshape.dominant->form.basic, BasicHandshape::Pinch12);
  EXPECT_EQ(m.posture.orientation.dominant->extended_finger, Direction::UL);
  EXPECT_EQ(m.posture.orientation.dominant->palm, Direction::L);
  EXPECT_EQ(m.posture.location.dominant->site, Site::lips);
  ASSERT_EQ(m.actions.size(), 3u);
  const Element& par = m.actions[0];
  EXPECT_EQ(par.kind, ElementKind::parallel);
  ASSERT_EQ(par.children.size(), 2u);
  EXPECT_EQ(par.children[0].motion()->kind, MotionKind::straight);
  EXPECT_EQ(par.children[0].motion()->direction, Direction::I);
  EXPECT_EQ(par.children[0].motion()->size, Size::small);
  const Motion& replace = *par.children[1].motion();
  EXPECT_EQ(replace.kind, MotionKind::replacement);
  ASSERT_TRUE(replace.new_handshape);
  EXPECT_EQ(replace.new_handshape->form.basic, BasicHandshape::Cee12);
  EXPECT_EQ(replace.new_handshape->form.bending, FingerBending::Bent);
  EXPECT_EQ(replace.new_handshape->form.thumb, ThumbModifier::Opposed);
  EXPECT_EQ(m.actions[1].contact()->proximity, Proximity::close);
  EXPECT_EQ(m.actions[2].repetition()->kind, RepetitionKind::from_start);
  EXPECT_TRUE(sign.notes.empty());
}

TEST(HamnosysParser, ThreeAxisDirectionFromTwoSymbols) {
  const HamSign sign = parse_hamnosys_names("hamfinger2,hamextfingeruo,hamextfingerol,hampalmd");
  EXPECT_EQ(sign.main().posture.orientation.dominant->extended_finger, Direction::UOL);
  EXPECT_EQ(sign.main().posture.orientation.dominant->palm, Direction::D);
}

// DGS ARM2^-like: hands given separately, the other hand's shape left open, constellation at the
// wrist, then a downward movement ending in touch.
TEST(HamnosysParser, HandPairPostureAndTargetContact) {
  const HamSign sign = parse_hamnosys_names(
      "hamparbegin,hamfinger2,hamextfingerol,hampalmd,hamplus,hamnondominant,hametc,hamextfingeror,hampalmd,"
      "hamparend,hamwristback,hamclose,hammoved,hamtouch");
  const Posture& p = sign.main().posture;
  EXPECT_EQ(p.handshape.dominant->form.basic, BasicHandshape::Finger2);
  EXPECT_FALSE(p.handshape.nondominant);
  EXPECT_TRUE(p.nondominant_unspecified);
  EXPECT_EQ(p.orientation.dominant->extended_finger, Direction::OL);
  EXPECT_EQ(p.orientation.nondominant->extended_finger, Direction::OR);
  EXPECT_EQ(p.location.dominant->site, Site::wrist_back);
  EXPECT_EQ(p.location.dominant->proximity, Proximity::close);
  ASSERT_EQ(sign.main().actions.size(), 1u);
  const Motion& move = *sign.main().actions[0].motion();
  EXPECT_EQ(move.direction, Direction::D);
  EXPECT_EQ(move.target_contact, Proximity::touch);
}

TEST(HamnosysParser, SymmetryCircleSideAndModifiers) {
  const HamSign sign = parse_hamnosys_names(
      "hamsymmlr,hamflathand,hamthumboutmod,hamindexfinger,hamfingerbendmod,hamextfingero,hampalml,hamchest,hamlrat,"
      "hamcirclei,hamlargemod,hamfast,hamrepeatcontinueseveral");
  const ManualSign& m = sign.main();
  EXPECT_EQ(m.symmetry.kind, SymmetryKind::mirrored_lr);
  const HandshapeForm& hs = m.posture.handshape.dominant->form;
  EXPECT_EQ(hs.thumb, ThumbModifier::Out);
  ASSERT_EQ(hs.finger_modifiers.size(), 1u);
  EXPECT_TRUE(hs.finger_modifiers[0].fingers.contains(Finger::Index));
  EXPECT_FALSE(hs.finger_modifiers[0].fingers.contains(Finger::Middle));
  EXPECT_EQ(hs.finger_modifiers[0].bending, FingerBending::Round);
  EXPECT_EQ(m.posture.location.dominant->site, Site::chest);
  EXPECT_EQ(m.posture.location.dominant->side, Side::dominant_side);
  ASSERT_EQ(m.actions.size(), 2u);
  const Motion& circle = *m.actions[0].motion();
  EXPECT_EQ(circle.kind, MotionKind::circle);
  EXPECT_EQ(circle.direction, Direction::I);
  EXPECT_EQ(circle.size, Size::large);
  EXPECT_TRUE(circle.manner.fast);
  EXPECT_EQ(m.actions[1].repetition()->kind, RepetitionKind::continued_several);
}

TEST(HamnosysParser, FingerLocationBetweenHandshapeAndTargetedMotion) {
  const HamSign sign = parse_hamnosys_names(
      "hamfinger2,hambetween,hamfinger2,hamfingerstraightmod,hamextfingerul,hampalml,hamchest,hamclose,"
      "hamseqbegin,hammover,hamwavy,hamindexfinger,hamfingertip,hamtouch,hamseqend");
  const ManualSign& m = sign.main();
  ASSERT_TRUE(m.posture.handshape.dominant->between);
  EXPECT_EQ(m.posture.handshape.dominant->between->bending, FingerBending::Bent);
  ASSERT_EQ(m.actions.size(), 1u);
  EXPECT_EQ(m.actions[0].kind, ElementKind::sequence);
  const Motion& move = *m.actions[0].children.at(0).motion();
  EXPECT_EQ(move.path, PathShape::wavy);
  ASSERT_TRUE(move.target);
  EXPECT_EQ(move.target->site, Site::fingers);
  EXPECT_TRUE(move.target->fingers.contains(Finger::Index));
  EXPECT_EQ(move.target->finger_part, FingerPart::tip);
  EXPECT_EQ(move.target_contact, Proximity::touch);
}

// DGS-style location between two points: between the shoulders' centre and the dominant shoulder.
TEST(HamnosysParser, LocationBetweenTwoPointsAndAlternatingMotion) {
  const HamSign sign = parse_hamnosys_names(
      "hamsymmpar,hamflathand,hamextfingerul,hampalmd,hamshoulders,hambetween,hamlrat,hamshoulders,hamtouch,"
      "hammoved,hamalternatingmotion");
  const Location& loc = *sign.main().posture.location.dominant;
  EXPECT_EQ(loc.site, Site::shoulders);
  EXPECT_EQ(loc.side, Side::centre);
  ASSERT_TRUE(loc.between);
  EXPECT_EQ(loc.between->site, Site::shoulders);
  EXPECT_EQ(loc.between->side, Side::dominant_side);
  EXPECT_EQ(loc.proximity, Proximity::touch);
  EXPECT_TRUE(sign.main().actions.at(0).motion()->alternating);
  EXPECT_TRUE(sign.notes.empty());
}

// One finger direction for both hands, then a palm per hand.
TEST(HamnosysParser, SharedFingerDirectionWithPalmPerHand) {
  const HamSign sign = parse_hamnosys_names(
      "hamsymmlr,hamflathand,hamextfingerdo,hamparbegin,hampalml,hamplus,hampalmr,hamparend,hammoveo");
  const Posture& p = sign.main().posture;
  EXPECT_EQ(p.orientation.dominant->extended_finger, Direction::DO);
  EXPECT_EQ(p.orientation.dominant->palm, Direction::L);
  EXPECT_EQ(p.orientation.nondominant->extended_finger, Direction::DO);
  EXPECT_EQ(p.orientation.nondominant->palm, Direction::R);
  EXPECT_TRUE(sign.notes.empty());
}

// The fingertips touch the chin, then the hand moves out.
TEST(HamnosysParser, HandPartAtLocation) {
  const HamSign sign = parse_hamnosys_names(
      "hamflathand,hamextfingeru,hampalml,hamchin,hamseqbegin,hamtouch,hamfingertip,hamseqend,hammoveo");
  const Location& loc = *sign.main().posture.location.dominant;
  EXPECT_EQ(loc.site, Site::chin);
  ASSERT_TRUE(loc.hand_part);
  EXPECT_EQ(loc.hand_part->site, Site::fingers);
  EXPECT_EQ(loc.hand_part->finger_part, FingerPart::tip);
  EXPECT_EQ(loc.proximity, Proximity::touch);
  ASSERT_EQ(sign.main().actions.size(), 1u);
  EXPECT_EQ(sign.main().actions[0].motion()->direction, Direction::O);
}

// DGS PROFESSION1A: after the arc, "…chin, (touch, thumb tip)" again names the part of the moving
// hand that reaches the chin, as in the posture (read alone it was a place on the other hand).
TEST(HamnosysParser, HandPartAfterAMovementsPlace) {
  const HamSign sign = parse_hamnosys_names(
      "hamfist,hamthumboutmod,hamextfingerul,hampalmdl,hamchin,hamlrat,hamseqbegin,hamtouch,hamthumb,hamfingertip,"
      "hamseqend,hammovel,hamarcr,hamlrat,hamchin,hamseqbegin,hamtouch,hamthumb,hamfingertip,hamseqend");
  const auto& actions = sign.main().actions;
  ASSERT_EQ(actions.size(), 1u);  // no separate sequence left over
  const Motion& m = *actions[0].motion();
  ASSERT_TRUE(m.target);
  EXPECT_EQ(m.target->site, Site::chin);
  ASSERT_TRUE(m.target->hand_part);
  EXPECT_EQ(m.target->hand_part->site, Site::fingers);
  EXPECT_EQ(m.target->hand_part->finger_part, FingerPart::tip);
  EXPECT_EQ(m.target_contact, Proximity::touch);
}

TEST(HamnosysParser, UnicodeAndNamesGiveTheSameSymbols) {
  const std::string names = "hamsymmpar,hamfist,hamextfingero,hampalmd,hamparbegin,hammoveo,hamplus,hamnomotion,hamparend";
  std::string text;
  for (Symbol s : symbols_from_names(names)) text += utf8(symbol_info(s).codepoint);
  EXPECT_EQ(symbols_from_unicode(text), symbols_from_names(names));
  const HamSign sign = parse_hamnosys_unicode(text);
  EXPECT_EQ(sign.main().symmetry.kind, SymmetryKind::parallel);
  EXPECT_EQ(sign.main().actions.at(0).kind, ElementKind::hand_pair);
}

TEST(HamnosysParser, CompoundSegmentsAndLenientNotes) {
  const HamSign sign = parse_hamnosys_names("hamflathand,hamextfingeru,hampalml,hammoved,hamplus,hamfist,hamextfingero,hampalmd");
  ASSERT_EQ(sign.segments.size(), 2u);
  EXPECT_EQ(sign.segments[1].posture.handshape.dominant->form.basic, BasicHandshape::Fist);
  EXPECT_EQ(sign.segments[1].first_symbol, 5);
  // A group left open at the end: lenient notes it, strict rejects it at the opening bracket.
  const std::string open = "hamflathand,hamextfingeru,hampalml,hamparbegin,hammoved,hamreplace,hamfist";
  EXPECT_FALSE(parse_hamnosys_names(open).notes.empty());
  EXPECT_EQ(error_index(open, ParseOptions{.strict = true}), 3);
}

TEST(HamnosysErrors, NameTheSymbolIndexAndExpectedClass) {
  EXPECT_EQ(error_index(""), 0);
  EXPECT_EQ(error_index("hamspace,hamspace"), 0);
  EXPECT_EQ(error_index("hamflathand,hamextfingeru,hamfoo"), 2);
  EXPECT_EQ(error_index("hamflathand,hamextfingeru,hampalml,hamparend"), 3);   // stray closer
  EXPECT_EQ(error_index("hamflathand,hamextfingeru,hamreplace"), 3);           // replace with nothing
  EXPECT_EQ(error_index("hamflathand,hamextfingeru,hammetaalt"), 2);
  EXPECT_EQ(error_index("hamtouch,hammoveu"), 0);                               // no handshape
  EXPECT_EQ(error_index("hamsymmlr,hamtouch,hammoveu"), 1);
  EXPECT_EQ(error_index("hamflathand,hamextfingeru,hampalml,hamplus"), 4);     // plus then nothing
  try {
    parse_hamnosys_names("hamflathand,hamextfingeru,hamreplace,hamrepeatfromstart");
    FAIL();
  } catch (const gestura::Error& e) {
    EXPECT_EQ(e.where().index, 3);
    EXPECT_NE(std::string(e.what()).find("expected a handshape, orientation or location"), std::string::npos);
  }
}

TEST(HamnosysErrors, BadUnicodeBinaryJunkAndHugeInput) {
  try {
    parse_hamnosys_unicode(utf8(0xE001) + utf8(0xE020) + utf8(0xE0FF));
    FAIL();
  } catch (const gestura::Error& e) {
    EXPECT_EQ(e.where().index, 2);
    EXPECT_NE(std::string(e.what()).find("U+E0FF"), std::string::npos);
  }
  EXPECT_THROW(parse_hamnosys_unicode(utf8(0xE001) + "\xC3"), gestura::Error);  // truncated UTF-8
  // The shared strict decoder: an overlong encoding of hamflathand (U+E001) is not hamflathand.
  try {
    parse_hamnosys_unicode(utf8(0xE020) + std::string("\xF0\x8E\x80\x81"));
    FAIL() << "overlong UTF-8 accepted";
  } catch (const gestura::Error& e) {
    EXPECT_EQ(e.where().index, 1);
    EXPECT_NE(std::string(e.what()).find("invalid UTF-8 at byte 3"), std::string::npos) << e.what();
  }
  std::mt19937 rng(7);
  std::string junk(4096, '\0');
  for (char& c : junk) c = static_cast<char>(rng());
  EXPECT_THROW(parse_hamnosys_unicode(junk), gestura::Error);
  // 1 MB of valid symbols: rejected at the length limit, not parsed.
  std::string huge;
  while (huge.size() < (1u << 20)) huge += utf8(0xE001);
  try {
    parse_hamnosys_unicode(huge);
    FAIL();
  } catch (const gestura::Error& e) {
    EXPECT_EQ(e.where().index, static_cast<int>(kMaxSignSymbols));
  }
  std::string deep = "hamflathand,hamextfingeru";
  for (int i = 0; i < 100; ++i) deep += ",hamseqbegin";
  EXPECT_EQ(error_index(deep), 2 + kMaxGroupDepth);
}

// Seeded fuzz: random symbol soup, and mutations of a real sign. Every input either parses or
// throws gestura::Error whose index lies inside the input; nothing else escapes.
TEST(HamnosysErrors, FuzzedSymbolSoupNeverCrashes) {
  std::mt19937 rng(20261121);
  const auto table = symbol_table();
  const std::vector<Symbol> base = symbols_from_names(
      "hamsymmlr,hamparbegin,hamfinger2,hamextfingerol,hampalmdl,hamplus,hamflathand,hamextfingeror,hampalmdr,"
      "hamparend,hamchest,hamclose,hamseqbegin,hammoveu,hamarcl,hamreplace,hamfist,hamseqend,hamrepeatfromstart");
  int errors = 0, runs = 0;
  for (int i = 0; i < 4000; ++i) {
    std::vector<Symbol> soup;
    if (i % 2 == 0) {
      const std::size_t n = rng() % 40;
      for (std::size_t k = 0; k < n; ++k) soup.push_back(table[rng() % table.size()].symbol);
    } else {
      soup = base;
      for (int k = 0; k < 3; ++k) soup[rng() % soup.size()] = table[rng() % table.size()].symbol;
    }
    for (bool strict : {false, true}) {
      ++runs;
      try {
        parse_hamnosys(soup, ParseOptions{.strict = strict});
      } catch (const gestura::Error& e) {
        ++errors;
        EXPECT_GE(e.where().index, 0);
        EXPECT_LE(e.where().index, static_cast<int>(soup.size()));
      }
    }
  }
  std::printf("fuzz: %d of %d random inputs rejected\n", errors, runs);
  EXPECT_GT(errors, runs / 2);
}

}  // namespace
