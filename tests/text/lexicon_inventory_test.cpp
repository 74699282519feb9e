#include "gestura/text/lexicon_inventory.hpp"

#include <gtest/gtest.h>

#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/text/translator.hpp"
#include "../lexicon/temp_dir.hpp"

using namespace gestura;

TEST(LexiconInventory, TheLexiconDecidesWhatIsSigned) {
  gestura::testing::TempDir dir;
  const std::string builtin_file = dir.write("ase.jsonl",
                                             R"({"gloss":"GO","lang":"ase","hamnosys":"g","keywords":["go"]})"
                                             "\n"
                                             R"({"gloss":"STORE","lang":"ase","hamnosys":"s","keywords":["store"]})"
                                             "\n"
                                             R"({"gloss":"MOTHER","lang":"ase","hamnosys":"m","keywords":["mother"]})"
                                             "\n"
                                             R"({"gloss":"LAUF","lang":"gsg","hamnosys":"l","keywords":["run"]})"
                                             "\n");
  Lexicon builtin = load_builtin_lexicon(builtin_file);
  Lexicon user = Lexicon::in_memory();
  // The user's own sign for "store" is preferred to the built-in one; "run" is only known in DGS.
  user.add(SignEntry{.gloss = "STORE-MINE", .language = "ase", .notation = "mine", .keywords = {Keyword{"store"}}});
  LayeredLexicon layers;
  layers.push_layer(builtin);
  layers.push_layer(user);
  LexiconInventory ase(layers, "ase");

  EXPECT_EQ(translate_to_gloss("Mom went to the store.", ase).text(), "MOTHER GO STORE-MINE");
  EXPECT_EQ(translate_to_gloss("I run.", ase).text(), "IX-1 FS-RUN");
  LexiconInventory dgs(layers, "gsg");
  EXPECT_EQ(translate_to_gloss("I run.", dgs).text(), "IX-1 LAUF");
}
