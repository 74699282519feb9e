// The gestura lexicon and gestura gloss commands, run as a user would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "temp_dir.hpp"
#include "support/shared_data.hpp"

using gestura::testing::TempDir;

namespace {

using gestura::test::CliRun;

// Runs the CLI with a private user lexicon and built-in directory; stdout and stderr together.
CliRun gestura_cli(const TempDir& dir, const std::string& args) {
  return gestura::test::run_cli(args, "GESTURA_LEXICON='" + dir.file("user.sqlite") + "' GESTURA_BUILTIN_LEXICON='" +
                                          dir.file("builtin") + "'");
}

// HamNoSys in Unicode: a flat hand, fingers up, palm left, at the chest — and one that does not
// parse (a closing bracket nothing opened).
const std::string kGoodHamnosys = "\xee\x80\x81\xee\x80\xa0\xee\x80\xbe\xee\x81\x92";
const std::string kBadHamnosys = "\xee\x80\x81\xee\x83\xa3";

}  // namespace

TEST(LexiconCli, AddShowSearchExportRemove) {
  TempDir dir;
  EXPECT_EQ(gestura_cli(dir, "lexicon add --gloss HOUSE --lang ase --hamnosys '" + kGoodHamnosys + "' --keywords house,home").status, 0);
  const CliRun show = gestura_cli(dir, "lexicon show house");
  EXPECT_EQ(show.status, 0);
  EXPECT_NE(show.output.find("HOUSE (ase, variant 1)"), std::string::npos) << show.output;
  EXPECT_NE(show.output.find("keywords: house, home"), std::string::npos) << show.output;
  EXPECT_NE(gestura_cli(dir, "lexicon search hom").output.find("HOUSE\tase\thamnosys"), std::string::npos);

  EXPECT_EQ(gestura_cli(dir, "lexicon export '" + dir.file("out.jsonl") + "'").status, 0);
  std::ifstream exported(dir.file("out.jsonl"));
  std::string line;
  std::getline(exported, line);
  EXPECT_NE(line.find("\"gloss\":\"HOUSE\""), std::string::npos) << line;

  EXPECT_EQ(gestura_cli(dir, "lexicon remove HOUSE --lang ase").status, 0);
  EXPECT_EQ(gestura_cli(dir, "lexicon list").output, "");
}

TEST(LexiconCli, AgreementIsStoredShownAndExported) {
  TempDir dir;
  EXPECT_EQ(gestura_cli(dir, "lexicon add --gloss NUDGE --lang ase --agreement forward --hamnosys '" + kGoodHamnosys +
                                 "' --keywords nudge").status, 0);
  const CliRun show = gestura_cli(dir, "lexicon show NUDGE");
  EXPECT_NE(show.output.find("agreement: forward"), std::string::npos) << show.output;
  EXPECT_EQ(gestura_cli(dir, "lexicon export '" + dir.file("out.jsonl") + "'").status, 0);
  std::ifstream exported(dir.file("out.jsonl"));
  std::string line;
  std::getline(exported, line);
  EXPECT_NE(line.find("\"agreement\":\"forward\""), std::string::npos) << line;
  // The sign agrees in a sentence: from the boy's place to the girl's.
  const CliRun gloss = gestura::test::run_cli("gloss 'The boy nudged the girl.'",
                                              "GESTURA_LEXICON='" + dir.file("user.sqlite") + "' GESTURA_BUILTIN_LEXICON='" +
                                                  gestura::test::source_dir() + "/data/lexicon'");
  EXPECT_NE(gloss.output.find("NUDGE:3a→3b"), std::string::npos) << gloss.output;
  const CliRun bad = gestura_cli(dir, "lexicon add --gloss POKE --lang ase --agreement sideways --hamnosys '" +
                                          kGoodHamnosys + "'");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.output.find("agreement"), std::string::npos) << bad.output;
}

TEST(LexiconCli, AddFromSigmlAndImportSigml) {
  TempDir dir;
  const std::string data = gestura::test::shared_data();
  const std::string absorb = data + "/sigml-isl/absorb.sigml";
  EXPECT_EQ(gestura_cli(dir, "lexicon add --gloss absorb --lang ins --sigml '" + absorb + "'").status, 0);
  const CliRun show = gestura_cli(dir, "lexicon show absorb --lang ins");
  EXPECT_NE(show.output.find("notation (sigml): <hns_sign gloss=\"absorb\"><hamnosys_nonmanual/>"), std::string::npos)
      << show.output;
  const CliRun no_lang = gestura_cli(dir, "lexicon import '" + data + "/sigml-isl/10.sigml'");
  EXPECT_EQ(no_lang.status, 1);
  EXPECT_NE(no_lang.output.find("--lang ins"), std::string::npos) << no_lang.output;
  EXPECT_EQ(gestura_cli(dir, "lexicon import '" + data + "/sigml-isl/10.sigml' --lang ins").status, 0);
  EXPECT_EQ(gestura_cli(dir, "lexicon list --lang ins").output, "10\tins\tsigml\t10\nabsorb\tins\tsigml\t\n");
}

TEST(LexiconCli, ClearErrors) {
  TempDir dir;
  const CliRun bad_lang = gestura_cli(dir, "lexicon add --gloss X --lang asl --hamnosys x");
  EXPECT_EQ(bad_lang.status, 1);
  EXPECT_NE(bad_lang.output.find("unknown sign-language code 'asl' (did you mean 'ase'?)"), std::string::npos);
  EXPECT_NE(gestura_cli(dir, "lexicon add --gloss X --lang ase").output.find("exactly one of --hamnosys and --sigml"),
            std::string::npos);
  const CliRun unknown = gestura_cli(dir, "lexicon frobnicate");
  EXPECT_NE(unknown.output.find("unknown action 'frobnicate' (list, show, search, add, import, export, remove"),
            std::string::npos) << unknown.output;
  EXPECT_EQ(unknown.status, 2);
  const std::string junk = dir.write("junk.sqlite", std::string(2048, '\x5a'));
  const CliRun corrupt = gestura_cli(dir, "lexicon list --db '" + junk + "'");
  EXPECT_EQ(corrupt.status, 1);
  EXPECT_NE(corrupt.output.find(junk), std::string::npos) << corrupt.output;
}

TEST(GlossCli, UsesTheLexiconAndExplains) {
  TempDir dir;
  dir.write("builtin",
            R"({"gloss":"GO","lang":"ase","hamnosys":"g","keywords":["go"]})"
            "\n"
            R"({"gloss":"STORE","lang":"ase","hamnosys":"s","keywords":["store","shop"]})"
            "\n");
  const CliRun run = gestura_cli(dir, "gloss 'I went to the shop yesterday.'");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(run.output.substr(0, run.output.find('\n')), "YESTERDAY IX-1 GO STORE");
  EXPECT_NE(run.output.find("'went' → GO: verb, WordNet lemma 'go'"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("parse: (S (NP I.p) (VP went.v-d"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("'the' dropped: article"), std::string::npos) << run.output;

  const CliRun json = gestura_cli(dir, "gloss 'Where is Bob?' --json");
  EXPECT_NE(json.output.find("\"gloss\": \"FS-BOB\""), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"kind\": \"wh-question\""), std::string::npos) << json.output;

  const CliRun invalid = gestura_cli(dir, "gloss \"$(printf 'caf\\303')\"");
  EXPECT_EQ(invalid.status, 1);
  EXPECT_NE(invalid.output.find("invalid UTF-8 at byte 3"), std::string::npos) << invalid.output;
}

TEST(LexiconCli, NotationThatDoesNotParseIsRefusedNamingLineAndSymbol) {
  TempDir dir;
  const CliRun add = gestura_cli(dir, "lexicon add --gloss X --lang ase --hamnosys '" + kBadHamnosys + "'");
  EXPECT_EQ(add.status, 1);
  EXPECT_NE(add.output.find("--hamnosys"), std::string::npos) << add.output;
  EXPECT_NE(add.output.find("symbol 1 (hamparend, U+E0E3)"), std::string::npos) << add.output;
  const CliRun letters = gestura_cli(dir, "lexicon add --gloss X --lang ase --hamnosys abc");
  EXPECT_EQ(letters.status, 1);
  EXPECT_NE(letters.output.find("unknown code point U+0061"), std::string::npos) << letters.output;
  EXPECT_EQ(gestura_cli(dir, "lexicon list").output, "");

  const std::string file = dir.write("mixed.jsonl",
                                     R"({"gloss":"ONE","lang":"ase","hamnosys":")" + kGoodHamnosys + "\"}\n" +
                                         R"({"gloss":"TWO","lang":"ase","hamnosys":")" + kBadHamnosys + "\"}\n" +
                                         R"({"gloss":"THREE","lang":"ase"})" "\n" +
                                         R"({"gloss":"FOUR","lang":"ase","hamnosys":")" + kGoodHamnosys + "\"}\n");
  const CliRun refused = gestura_cli(dir, "lexicon import '" + file + "'");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.output.find(file + ":2: sign 'TWO': HamNoSys does not parse at symbol 1 (hamparend, U+E0E3)"),
            std::string::npos) << refused.output;
  EXPECT_EQ(gestura_cli(dir, "lexicon list").output, "");  // one transaction: nothing stored

  const CliRun skipped = gestura_cli(dir, "lexicon import '" + file + "' --skip-bad");
  EXPECT_EQ(skipped.status, 0) << skipped.output;
  EXPECT_NE(skipped.output.find("warning: " + file + ":2: skipped: sign 'TWO': HamNoSys does not parse"),
            std::string::npos) << skipped.output;
  EXPECT_NE(skipped.output.find("warning: " + file + ":3: skipped: entry 'THREE' needs exactly one of"),
            std::string::npos) << skipped.output;
  EXPECT_NE(skipped.output.find("imported 2 signs"), std::string::npos) << skipped.output;
  EXPECT_NE(skipped.output.find("(2 bad lines skipped)"), std::string::npos) << skipped.output;
  const CliRun list = gestura_cli(dir, "lexicon list");
  EXPECT_NE(list.output.find("ONE\tase"), std::string::npos) << list.output;
  EXPECT_NE(list.output.find("FOUR\tase"), std::string::npos) << list.output;
  EXPECT_EQ(list.output.find("TWO"), std::string::npos) << list.output;
}

TEST(LexiconCli, TheSharedHamburgAndWarsawSignsImportWithSkipBad) {
  TempDir dir;
  const std::string file = gestura::test::shared_data() + "/hamnosys/signs.jsonl";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not present";
  // One line of the file has neither gloss nor notation: without --skip-bad nothing is imported.
  const CliRun whole = gestura_cli(dir, "lexicon import '" + file + "' --lang gsg");
  EXPECT_EQ(whole.status, 1);
  EXPECT_NE(whole.output.find(":3569: entry has no 'gloss'"), std::string::npos) << whole.output;
  const CliRun run = gestura_cli(dir, "lexicon import '" + file + "' --lang gsg --skip-bad");
  EXPECT_EQ(run.status, 0) << run.output.substr(0, 2000);
  EXPECT_NE(run.output.find("imported 4069 signs"), std::string::npos) << run.output.substr(0, 2000);
  EXPECT_NE(run.output.find("(1 bad line skipped)"), std::string::npos);
  const CliRun list = gestura_cli(dir, "lexicon list --lang gsg");
  EXPECT_EQ(std::count(list.output.begin(), list.output.end(), '\n'), 4069);  // homonyms kept as variants
}
