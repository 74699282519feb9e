#include "gestura/lexicon/lexicon.hpp"

#include <gtest/gtest.h>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/schema.hpp"
#include "temp_dir.hpp"

using namespace gestura;
using gestura::testing::TempDir;

namespace {

SignEntry sign(std::string gloss, std::string lang, std::string hamnosys, std::vector<std::string> words = {}) {
  SignEntry e;
  e.gloss = std::move(gloss);
  e.language = std::move(lang);
  e.notation = std::move(hamnosys);
  for (auto& w : words) e.keywords.push_back(Keyword{w});
  return e;
}

std::vector<std::string> glosses(const std::vector<SignEntry>& entries) {
  std::vector<std::string> out;
  for (const auto& e : entries) out.push_back(e.gloss);
  return out;
}

// Expects `body` to throw a gestura::Error whose text contains every one of `parts`.
template <class Body>
void expect_error_mentioning(Body&& body, std::initializer_list<std::string> parts) {
  try {
    body();
    ADD_FAILURE() << "expected a gestura::Error";
  } catch (const Error& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(LexiconStore, AddFindRemoveRoundTrip) {
  TempDir dir;
  auto lex = Lexicon::open(dir.file("lex.sqlite"));
  SignEntry house = sign("HOUSE", "ase", "\xee\x80\x81\xee\x80\x82", {"house", "Home"});
  house.keywords.push_back(Keyword{"Haus", "deu", "building"});
  house.source = "test";
  house.licence = "CC0-1.0";
  const auto id = lex.add(house);
  EXPECT_GT(id, 0);

  const auto found = lex.find("house", "ase");  // gloss lookup ignores case
  ASSERT_TRUE(found);
  EXPECT_EQ(found->gloss, "HOUSE");
  EXPECT_EQ(found->notation, house.notation);
  EXPECT_EQ(found->notation_kind, NotationKind::hamnosys);
  ASSERT_EQ(found->keywords.size(), 3u);
  EXPECT_EQ(found->keywords[1].word, "home");  // keywords stored lowercase
  EXPECT_EQ(found->keywords[2], (Keyword{"haus", "deu", "building"}));
  EXPECT_EQ(found->licence, "CC0-1.0");
  EXPECT_GT(found->created, 1700000000);
  EXPECT_EQ(found->created, found->updated);

  EXPECT_FALSE(lex.find("HOUSE", "bfi"));
  EXPECT_EQ(lex.remove("HOUSE", "ase"), 1u);
  EXPECT_FALSE(lex.find("HOUSE", "ase"));
  EXPECT_EQ(lex.size(), 0u);
}

TEST(LexiconStore, VariantsPerGloss) {
  auto lex = Lexicon::in_memory();
  lex.add(sign("BANK", "ase", "a"));
  SignEntry second = sign("BANK", "ase", "b");
  second.variant = 0;  // next free variant
  lex.add(second);
  EXPECT_EQ(lex.find("BANK", "ase", 2)->notation, "b");
  EXPECT_EQ(lex.find_all("BANK").size(), 2u);
  EXPECT_EQ(lex.remove("BANK", "ase", 1), 1u);
  EXPECT_EQ(glosses(lex.find_all("BANK")), std::vector<std::string>{"BANK"});
  EXPECT_EQ(lex.find_all("BANK")[0].variant, 2);
}

TEST(LexiconStore, DuplicateFailsOrReplacesKeepingCreationTime) {
  auto lex = Lexicon::in_memory();
  lex.add(sign("CAT", "ase", "old", {"cat"}));
  expect_error_mentioning([&] { lex.add(sign("CAT", "ase", "new")); }, {"CAT", "already exists"});
  lex.database().exec("UPDATE signs SET created = 1000, updated = 1000");
  lex.add(sign("CAT", "ase", "new", {"kitty"}), OnConflict::replace);
  const auto cat = lex.find("CAT", "ase");
  EXPECT_EQ(cat->notation, "new");
  EXPECT_EQ(cat->created, 1000);
  EXPECT_GT(cat->updated, 1000);
  ASSERT_EQ(cat->keywords.size(), 1u);
  EXPECT_EQ(cat->keywords[0].word, "kitty");
  EXPECT_TRUE(lex.by_keyword("cat").empty());
}

TEST(LexiconStore, RejectsUnknownLanguageCodeWithHint) {
  auto lex = Lexicon::in_memory();
  expect_error_mentioning([&] { lex.add(sign("HOUSE", "asl", "x")); }, {"unknown sign-language code 'asl'", "ase"});
  expect_error_mentioning([&] { lex.add(sign("HOUSE", "xyz", "x")); }, {"'xyz'"});
  expect_error_mentioning([&] { lex.add(sign("", "ase", "x")); }, {"empty gloss"});
  expect_error_mentioning([&] { lex.add(sign("HOUSE", "ase", "")); }, {"no hamnosys notation"});
  EXPECT_EQ(lex.size(), 0u);
}

TEST(LexiconStore, ClipBlobsRoundTrip) {
  auto lex = Lexicon::in_memory();
  SignEntry e = sign("WAVE", "bfi", "");
  e.notation_kind = NotationKind::clip;
  e.clip = {0, 1, 2, 255, 0, 7};
  lex.add(e);
  EXPECT_EQ(lex.find("WAVE", "bfi")->clip, e.clip);
}

TEST(LexiconStore, KeywordLookupAndSearch) {
  auto lex = Lexicon::in_memory();
  lex.add(sign("HOUSE", "ase", "h", {"house", "home"}));
  lex.add(sign("HOME", "ase", "m", {"home"}));
  lex.add(sign("HAUS", "gsg", "g", {"house"}));
  lex.add(sign("MOUSE", "ase", "u", {"mouse"}));
  lex.add(sign("100%", "ase", "p", {"percent"}));

  EXPECT_EQ(glosses(lex.by_keyword("HOME")), (std::vector<std::string>{"HOME", "HOUSE"}));
  EXPECT_EQ(glosses(lex.by_keyword("house", "gsg")), std::vector<std::string>{"HAUS"});
  EXPECT_TRUE(lex.by_keyword("house", "ase", "deu").empty());
  EXPECT_TRUE(lex.by_keyword("hous").empty());  // keyword lookup is exact

  EXPECT_EQ(glosses(lex.search("ho", SearchMode::prefix)), (std::vector<std::string>{"HAUS", "HOME", "HOUSE"}));
  EXPECT_EQ(glosses(lex.search("ouse", SearchMode::substring)), (std::vector<std::string>{"HAUS", "HOUSE", "MOUSE"}));
  EXPECT_TRUE(lex.search("ouse", SearchMode::prefix).empty());
  EXPECT_EQ(glosses(lex.search("HOME")).front(), "HOME");  // exact gloss first
  EXPECT_EQ(glosses(lex.search("0%")), std::vector<std::string>{"100%"});  // % matched literally
  EXPECT_EQ(lex.list("ase").size(), 4u);
  EXPECT_EQ(lex.list().size(), 5u);
}

TEST(LexiconLayers, UserLayerAddsAndOverridesByGlossAndLanguage) {
  auto builtin = Lexicon::in_memory();
  builtin.add(sign("HOUSE", "ase", "builtin-house", {"house"}));
  SignEntry house2 = sign("HOUSE", "ase", "builtin-house-2", {"house"});
  house2.variant = 2;
  builtin.add(house2);
  builtin.add(sign("HOUSE", "bfi", "builtin-bsl-house", {"house"}));
  builtin.add(sign("CAT", "ase", "builtin-cat", {"cat"}));
  auto user = Lexicon::in_memory();
  user.add(sign("HOUSE", "ase", "my-house", {"house", "home"}));
  user.add(sign("DOG", "ase", "my-dog", {"dog"}));

  LayeredLexicon view;
  view.push_layer(builtin);
  view.push_layer(user);
  EXPECT_EQ(view.find("HOUSE", "ase")->notation, "my-house");
  EXPECT_FALSE(view.find("HOUSE", "ase", 2));  // the user's HOUSE hides all built-in ASL variants
  EXPECT_EQ(view.find("HOUSE", "bfi")->notation, "builtin-bsl-house");  // other language untouched
  EXPECT_EQ(view.find("CAT", "ase")->notation, "builtin-cat");
  EXPECT_EQ(view.find("DOG", "ase")->notation, "my-dog");

  user.add(sign("HOME", "ase", "my-home", {"house"}));
  const auto by_house = view.by_keyword("house");
  ASSERT_EQ(by_house.size(), 3u);  // user layer first, hidden built-in ASL HOUSE variants left out
  EXPECT_EQ(by_house[0].notation, "my-home");
  EXPECT_EQ(by_house[1].notation, "my-house");
  EXPECT_EQ(by_house[2].notation, "builtin-bsl-house");
  EXPECT_EQ(user.remove("HOME", "ase"), 1u);
  EXPECT_EQ(view.list().size(), 4u);  // CAT, DOG, HOUSE(ase, user), HOUSE(bfi)
  EXPECT_EQ(glosses(view.search("o", SearchMode::substring, "ase")), (std::vector<std::string>{"DOG", "HOUSE"}));
}

TEST(LexiconMigration, UpgradesVersion1DatabaseKeepingData) {
  TempDir dir;
  const std::string path = dir.file("old.sqlite");
  {
    sqlite::Database db(path, true);
    lexicon_schema::migrate(db, 1);
    EXPECT_EQ(lexicon_schema::version_of(db), 1);
    db.exec("INSERT INTO signs (gloss, lang, notation_kind, notation, source, created) "
            "VALUES ('TREE', 'ase', 'hamnosys', 'tree-notation', 'v1', 1234)");
    db.exec("INSERT INTO keywords (sign_id, word, lang) VALUES (1, 'tree', 'eng')");
  }
  auto lex = Lexicon::open(path);
  EXPECT_EQ(lexicon_schema::version_of(lex.database()), lexicon_schema::current_version());
  EXPECT_EQ(lexicon_schema::current_version(), 3);
  const auto tree = lex.find("TREE", "ase");
  ASSERT_TRUE(tree);
  EXPECT_EQ(tree->variant, 1);
  EXPECT_EQ(tree->notation, "tree-notation");
  EXPECT_EQ(tree->created, 1234);
  EXPECT_EQ(tree->updated, 1234);
  EXPECT_EQ(tree->licence, "");
  ASSERT_EQ(tree->keywords.size(), 1u);
  EXPECT_EQ(tree->keywords[0].meaning, "");
  // The v2 unique key allows a second variant of the same gloss.
  SignEntry second = sign("TREE", "ase", "tree-2");
  second.variant = 2;
  EXPECT_NO_THROW(lex.add(second));
}

TEST(LexiconMigration, UpgradesVersion2DatabaseKeepingRowsAndAddingAgreement) {
  // A user lexicon written by the program before agreement was a field: every row is kept, each gains
  // 'none', except the ASL verbs the grammar pass used to know by name, which stay agreement verbs.
  TempDir dir;
  const std::string path = dir.file("v2.sqlite");
  {
    sqlite::Database db(path, true);
    lexicon_schema::migrate(db, 2);
    EXPECT_EQ(lexicon_schema::version_of(db), 2);
    db.exec("INSERT INTO signs (gloss, lang, variant, notation_kind, notation, source, licence, created, updated) VALUES "
            "('TREE', 'ase', 1, 'hamnosys', 'tree-notation', 'mine', 'CC0-1.0', 1234, 1300), "
            "('GIVE', 'ase', 2, 'hamnosys', 'give-notation', 'mine', '', 1, 2), "
            "('BORROW', 'ase', 1, 'hamnosys', 'borrow-notation', 'mine', '', 1, 2), "
            "('GIVE', 'bfi', 1, 'hamnosys', 'bsl-give', 'mine', '', 1, 2)");
    db.exec("INSERT INTO keywords (sign_id, word, lang, meaning) VALUES (1, 'tree', 'eng', 'a plant')");
  }
  auto lex = Lexicon::open(path);
  EXPECT_EQ(lexicon_schema::version_of(lex.database()), 3);
  EXPECT_EQ(lex.list().size(), 4u);
  const auto tree = lex.find("TREE", "ase");
  ASSERT_TRUE(tree);
  EXPECT_EQ(tree->notation, "tree-notation");
  EXPECT_EQ(tree->source, "mine");
  EXPECT_EQ(tree->licence, "CC0-1.0");
  EXPECT_EQ(tree->created, 1234);
  EXPECT_EQ(tree->updated, 1300);
  ASSERT_EQ(tree->keywords.size(), 1u);
  EXPECT_EQ(tree->keywords[0].meaning, "a plant");
  EXPECT_EQ(tree->agreement, Agreement::none);
  EXPECT_EQ(lex.find("GIVE", "ase", 2)->agreement, Agreement::forward);
  EXPECT_EQ(lex.find("BORROW", "ase")->agreement, Agreement::backward);
  EXPECT_EQ(lex.find("GIVE", "bfi")->agreement, Agreement::none);  // another language's GIVE is not ASL's
  // The field is stored and read back, and the database refuses a value it does not know.
  SignEntry pay = sign("PAY-BACK", "ase", "pay-notation");
  pay.agreement = Agreement::backward;
  lex.add(pay);
  EXPECT_EQ(lex.find("PAY-BACK", "ase")->agreement, Agreement::backward);
  EXPECT_THROW(lex.database().exec("UPDATE signs SET agreement = 'sideways' WHERE gloss = 'TREE'"), std::exception);
}

TEST(LexiconMigration, RefusesNewerSchema) {
  TempDir dir;
  const std::string path = dir.file("future.sqlite");
  { sqlite::Database(path, true).exec("PRAGMA user_version = 99"); }
  expect_error_mentioning([&] { Lexicon::open(path); }, {path, "newer"});
}

TEST(LexiconFailures, CorruptFileNamesTheFile) {
  TempDir dir;
  std::string junk(4096, '\0');
  for (std::size_t i = 0; i < junk.size(); ++i) junk[i] = static_cast<char>((i * 131 + 7) % 251);
  const std::string path = dir.write("junk.sqlite", junk);
  expect_error_mentioning([&] { Lexicon::open(path); }, {path, "not a valid SQLite lexicon"});
}

TEST(LexiconFailures, MissingDirectoryNamesTheFile) {
  const std::string path = "/nonexistent-gestura-dir/lex.sqlite";
  expect_error_mentioning([&] { Lexicon::open(path); }, {path, "cannot open"});
}

TEST(LexiconFailures, LockedDatabaseTimesOutWithClearError) {
  TempDir dir;
  const std::string path = dir.file("locked.sqlite");
  auto holder = Lexicon::open(path);
  auto waiter = Lexicon::open(path, /*busy_timeout_ms=*/50);
  sqlite::Transaction hold(holder.database());  // a writer in the middle of its work
  holder.add(sign("A", "ase", "a"));
  expect_error_mentioning([&] { waiter.add(sign("B", "ase", "b")); }, {path, "locked"});
  EXPECT_EQ(waiter.size(), 0u);  // reading still works and sees the committed state
}

TEST(LexiconConcurrency, ReaderSeesOnlyCommittedImports) {
  TempDir dir;
  const std::string path = dir.file("shared.sqlite");
  auto writer = Lexicon::open(path);
  writer.add(sign("FIRST", "ase", "f"));
  auto reader = Lexicon::open(path);
  std::size_t seen_mid_import = 0;
  writer.atomically([&] {
    writer.add(sign("SECOND", "ase", "s"));
    writer.add(sign("THIRD", "ase", "t"));
    seen_mid_import = reader.size();
    EXPECT_FALSE(reader.find("SECOND", "ase"));
  });
  EXPECT_EQ(seen_mid_import, 1u);
  EXPECT_EQ(reader.size(), 3u);

  // A failing batch leaves the reader's view and the file unchanged.
  EXPECT_THROW(writer.atomically([&] {
    writer.add(sign("FOURTH", "ase", "x"));
    throw Error("abort");
  }),
               Error);
  EXPECT_EQ(reader.size(), 3u);
  EXPECT_FALSE(writer.find("FOURTH", "ase"));
}
