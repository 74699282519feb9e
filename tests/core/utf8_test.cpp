// The one UTF-8 path: strict decoding (bytes other decoders let through are refused), and Unicode
// case, letters and normalisation from ICU.
#include <gtest/gtest.h>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"

namespace {

using namespace gestura;

TEST(Utf8, DecodesStrictly) {
  std::size_t pos = 0;
  char32_t cp = 0;
  const std::string e_acute = "\xC3\xA9";
  ASSERT_TRUE(utf8::decode(e_acute, pos, cp));
  EXPECT_EQ(cp, 0xE9u);
  EXPECT_EQ(pos, 2u);
  // Overlong forms, surrogates, code points past U+10FFFF, stray continuation bytes and truncation.
  for (const std::string& bad : {std::string("\xC0\x80", 2), std::string("\xE0\x80\x80"), std::string("\xED\xA0\x80"),
                                std::string("\xF4\x90\x80\x80"), std::string("\x80"), std::string("\xC3"),
                                std::string("\xE2\x82")}) {
    pos = 0;
    EXPECT_FALSE(utf8::decode(bad, pos, cp)) << testing::PrintToString(bad);
    EXPECT_EQ(pos, 0u) << "a refused sequence does not move the cursor";
    EXPECT_THROW(utf8::validate(bad), Error);
  }
  try {
    utf8::validate("ok\xFF");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("byte 2"), std::string::npos) << e.what();
  }
}

TEST(Utf8, CaseAndLettersOfEveryScript) {
  EXPECT_EQ(utf8::upper("straße"), "STRASSE") << "full case mapping";
  EXPECT_EQ(utf8::lower("ΣΟΦΙΑ Ивана"), "σοφια ивана");
  EXPECT_EQ(utf8::to_upper(U'ł'), U'Ł');
  EXPECT_EQ(utf8::to_lower(U'Ő'), U'ő');
  EXPECT_TRUE(utf8::is_letter(U'ß'));
  EXPECT_TRUE(utf8::is_letter(U'名'));
  EXPECT_TRUE(utf8::is_letter(0x0301)) << "a combining accent belongs to its word";
  EXPECT_TRUE(utf8::is_mark(0x0301));
  EXPECT_FALSE(utf8::is_letter(U'€'));
  EXPECT_FALSE(utf8::is_letter(0x1F600)) << "emoji";
  EXPECT_FALSE(utf8::is_letter(U'×'));
  EXPECT_TRUE(utf8::is_space(0x00A0));
  EXPECT_TRUE(utf8::is_space(0x3000));
  EXPECT_TRUE(utf8::is_space(0xFEFF));
  EXPECT_FALSE(utf8::is_space(U'a'));
}

TEST(Utf8, BaseLettersAndComposition) {
  EXPECT_EQ(utf8::base_letter(U'é'), U'e');
  EXPECT_EQ(utf8::base_letter(U'Ŝ'), U'S');
  EXPECT_EQ(utf8::base_letter(U'ḗ'), U'e') << "two accents";
  EXPECT_EQ(utf8::base_letter(U'ñ'), U'n');
  EXPECT_EQ(utf8::base_letter(U'ß'), U'ß') << "no decomposition";
  EXPECT_EQ(utf8::base_letter(U'ø'), U'ø');
  EXPECT_EQ(utf8::base_letter(U'a'), U'a');
  EXPECT_EQ(utf8::nfc("Jose\xCC\x81"), "Jos\xC3\xA9");
  EXPECT_EQ(utf8::nfc("plain ASCII"), "plain ASCII");
  EXPECT_THROW(utf8::nfc("bad\xFF"), Error);
}

}  // namespace
