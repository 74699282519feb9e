#include "gestura/text/tokenizer.hpp"

#include <gtest/gtest.h>

#include "gestura/text/lemmatizer.hpp"

using namespace gestura;

namespace {

std::vector<std::string> texts(const std::vector<Token>& tokens) {
  std::vector<std::string> out;
  for (const Token& t : tokens) out.push_back(t.text);
  return out;
}

}  // namespace

TEST(Tokenizer, FoldsTypography) {
  const auto tokens = tokenize("\u201cDon\u2019t\u201d \u2014 it\u2019s 3:30 p.m. on 3/14, $5.");
  EXPECT_EQ(texts(tokens), (std::vector<std::string>{"Don't", "\u2014", "it's", "3:30", "p.m.", "on", "3/14", ",", "$",
                                                     "5", "."}));
  EXPECT_EQ(tokens[1].kind, TokenKind::pause);
  EXPECT_EQ(tokens[3].kind, TokenKind::number);
  EXPECT_EQ(tokens[8].kind, TokenKind::symbol);
  EXPECT_EQ(tokens.back().kind, TokenKind::sentence_end);
  // Byte spans: "Don’t" starts after the 3-byte opening quote and is 7 bytes long (’ is 3 bytes).
  EXPECT_EQ(tokens[0].begin, 3u);
  EXPECT_EQ(tokens[0].end, 10u);
}

TEST(Tokenizer, WordsNumbersOrdinals) {
  EXPECT_EQ(texts(tokenize("well-known 1,000 21st U.S. I.")),
            (std::vector<std::string>{"well-known", "1,000", "21st", "U.S.", "I", "."}));
  EXPECT_EQ(texts(tokenize("caf\u00e9 na\u00efve")), (std::vector<std::string>{"caf\u00e9", "na\u00efve"}));
}

TEST(Tokenizer, WordsAreInNfcWithSpansIntoTheInput) {
  const std::string decomposed = "Jose\u0301 came";  // e + combining acute accent
  const auto tokens = tokenize(decomposed);
  ASSERT_EQ(tokens.size(), 2u);
  EXPECT_EQ(tokens[0].text, "Jos\u00e9") << "the precomposed letter";
  EXPECT_EQ(tokens[0].begin, 0u);
  EXPECT_EQ(tokens[0].end, 6u) << "the span still covers the bytes typed";
  EXPECT_EQ(texts(tokenize("Jos\u00e9 came")), texts(tokens));
}

TEST(Lemmatizer, CandidatesBestFirst) {
  auto first = [](std::string_view w) { return lemma_candidates(w).front().lemma; };
  EXPECT_EQ(first("went"), "go");
  EXPECT_EQ(first("children"), "child");
  EXPECT_EQ(first("babies"), "baby");
  EXPECT_EQ(first("boxes"), "box");
  EXPECT_EQ(first("cats"), "cat");
  EXPECT_EQ(first("stopped"), "stop");
  EXPECT_EQ(first("liked"), "like");
  EXPECT_EQ(first("walked"), "walk");
  EXPECT_EQ(first("visited"), "visit");
  EXPECT_EQ(first("making"), "make");
  EXPECT_EQ(first("running"), "run");
  EXPECT_EQ(first("eating"), "eat");
  EXPECT_EQ(first("studied"), "study");
  EXPECT_EQ(first("bus"), "bus");
  EXPECT_EQ(first("morning"), "morning");
  EXPECT_EQ(first("class"), "class");
  EXPECT_EQ(lemma_candidates("thing").size(), 1u);  // "th" has no vowel: no -ing stem
  EXPECT_EQ(lemma_candidates("hoped")[0].rule, "past -ed");
}
