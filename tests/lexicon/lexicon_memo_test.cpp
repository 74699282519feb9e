// The lexicon reuses the answers of recent queries (a sentence asks the same few questions every
// time): never an answer older than the file. Edits by another connection, by this one, and
// writes a rollback takes back are all seen by the next query.
#include <gtest/gtest.h>

#include <stdexcept>

#include "gestura/lexicon/lexicon.hpp"
#include "temp_dir.hpp"

namespace {

using namespace gestura;
using gestura::testing::TempDir;

// hamfinger2 hamextfingeri hampalml hamchest hamtouch: the index finger touches the chest.
constexpr const char* kIndexAtChest = "\xee\x80\x82\xee\x80\xac\xee\x80\xbe\xee\x81\x92\xee\x83\x91";

SignEntry sign(const std::string& gloss, const std::string& word) {
  SignEntry e;
  e.gloss = gloss;
  e.language = "ase";
  e.notation = kIndexAtChest;
  e.keywords.push_back(Keyword{word});
  return e;
}

TEST(LexiconMemo, AnswersFollowEveryCommittedChange) {
  TempDir dir;
  const std::string path = dir.file("user.sqlite");
  Lexicon reader = Lexicon::open(path);
  Lexicon writer = Lexicon::open(path);  // another process, as far as the file knows
  writer.add(sign("HOUSE", "house"));

  ASSERT_EQ(reader.by_keyword("house", "ase").size(), 1u);
  ASSERT_EQ(reader.by_keyword("house", "ase").size(), 1u);  // asked twice: the same answer
  EXPECT_FALSE(reader.find("HOME", "ase"));

  // Another connection commits: the next answers include it.
  writer.add(sign("HOME", "house"));
  EXPECT_EQ(reader.by_keyword("house", "ase").size(), 2u);
  EXPECT_TRUE(reader.find("HOME", "ase"));

  // This connection writes: seen at once too.
  reader.remove("HOME", "ase");
  EXPECT_EQ(reader.by_keyword("house", "ase").size(), 1u);
  EXPECT_FALSE(reader.find("HOME", "ase"));

  // A transaction that fails after writing and reading: what it read is not kept.
  EXPECT_THROW(reader.atomically([&] {
    reader.add(sign("HUT", "house"));
    EXPECT_EQ(reader.by_keyword("house", "ase").size(), 2u);
    throw std::runtime_error("stop");
  }),
               std::runtime_error);
  EXPECT_EQ(reader.by_keyword("house", "ase").size(), 1u);
  EXPECT_FALSE(reader.find("HUT", "ase"));
  EXPECT_EQ(writer.by_keyword("house", "ase").size(), 1u);
}

}  // namespace
