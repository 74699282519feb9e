#include "gestura/lexicon/lexicon_files.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "gestura/core/error.hpp"
#include "temp_dir.hpp"
#include "support/shared_data.hpp"

using namespace gestura;
using gestura::testing::TempDir;

namespace {

using gestura::test::shared_data;

const std::string kIslDir = shared_data() + "/sigml-isl/";

std::string error_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(LexiconJsonl, ImportReadsEveryNotationAndKeywordForm) {
  TempDir dir;
  const std::string path = dir.write("signs.jsonl",
                                     R"({"gloss":"HOUSE","lang":"ase","hamnosys":"H1","keywords":["house","home"],"licence":"CC0-1.0"})"
                                     "\n\n"
                                     R"({"gloss":"BANK","lang":"ase","variant":2,"sigml":"<hns_sign gloss=\"BANK\"/>","keywords":[{"word":"bank","meaning":"money"},{"word":"Bank","lang":"deu"}]})"
                                     "\n"
                                     R"({"gloss":"WAVE","hamnosys":"W","keywords":"hello, hi ,wave"})"
                                     "\n");
  auto lex = Lexicon::in_memory();
  ImportOptions options;
  options.language = "bfi";  // default for lines without "lang"
  EXPECT_EQ(import_jsonl(lex, path, options), 3u);
  const auto house = lex.find("HOUSE", "ase");
  ASSERT_TRUE(house);
  EXPECT_EQ(house->source, "signs.jsonl");
  EXPECT_EQ(house->licence, "CC0-1.0");
  const auto bank = lex.find("BANK", "ase", 2);
  ASSERT_TRUE(bank);
  EXPECT_EQ(bank->notation_kind, NotationKind::sigml);
  EXPECT_EQ(bank->keywords[0], (Keyword{"bank", "eng", "money"}));
  EXPECT_EQ(bank->keywords[1], (Keyword{"bank", "deu", ""}));
  const auto wave = lex.find("WAVE", "bfi");
  ASSERT_TRUE(wave);
  ASSERT_EQ(wave->keywords.size(), 3u);
  EXPECT_EQ(wave->keywords[1].word, "hi");
}

TEST(LexiconJsonl, ExportImportRoundTrip) {
  auto original = Lexicon::in_memory();
  SignEntry house{.gloss = "HOUSE", .language = "ase", .notation = "\xee\x80\x81", .source = "s", .licence = "l"};
  house.keywords = {Keyword{"house"}, Keyword{"haus", "deu", "building"}};
  house.agreement = Agreement::forward;  // not a verb, but the field travels whatever it says
  original.add(house);
  SignEntry clip{.gloss = "WAVE", .language = "ase", .variant = 3, .notation_kind = NotationKind::clip};
  clip.clip = {0, 255, 1, 2, 3};  // length not a multiple of 3 exercises base64 padding
  original.add(clip);

  std::stringstream file;
  const auto all = original.list();
  export_jsonl(all, file);
  auto copy = Lexicon::in_memory();
  EXPECT_EQ(import_jsonl(copy, file, "memory"), 2u);
  const auto copied = copy.list();
  ASSERT_EQ(copied.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(copied[i].gloss, all[i].gloss);
    EXPECT_EQ(copied[i].language, all[i].language);
    EXPECT_EQ(copied[i].variant, all[i].variant);
    EXPECT_EQ(copied[i].notation_kind, all[i].notation_kind);
    EXPECT_EQ(copied[i].notation, all[i].notation);
    EXPECT_EQ(copied[i].clip, all[i].clip);
    EXPECT_EQ(copied[i].keywords, all[i].keywords);
    EXPECT_EQ(copied[i].source, all[i].source);
    EXPECT_EQ(copied[i].licence, all[i].licence);
    EXPECT_EQ(copied[i].agreement, all[i].agreement);
  }
  EXPECT_EQ(copied[0].agreement, Agreement::forward);
  EXPECT_NE(file.str().find("\"agreement\":\"forward\""), std::string::npos) << file.str();
}

TEST(LexiconJsonl, FailingLineRollsBackTheWholeImport) {
  TempDir dir;
  const std::string path = dir.file("lex.sqlite");
  auto lex = Lexicon::open(path);
  lex.add(SignEntry{.gloss = "EARLIER", .language = "ase", .notation = "e"});
  const std::string bad = dir.write("bad.jsonl",
                                    R"({"gloss":"ONE","lang":"ase","hamnosys":"1"})"
                                    "\n"
                                    R"({"gloss":"TWO","lang":"ase","hamnosys":"2"})"
                                    "\n"
                                    R"({"gloss":"THREE","lang":"asl","hamnosys":"3"})"
                                    "\n"
                                    R"({"gloss":"FOUR","lang":"ase","hamnosys":"4"})"
                                    "\n"
                                    R"({"gloss":"FIVE","lang":"ase","hamnosys":"5"})"
                                    "\n");
  const std::string message = error_of([&] { import_jsonl(lex, bad); });
  EXPECT_NE(message.find(bad + ":3"), std::string::npos) << message;
  EXPECT_NE(message.find("'asl'"), std::string::npos) << message;
  // Nothing of the failed import, the earlier content intact — also for a fresh connection.
  auto reopened = Lexicon::open(path);
  ASSERT_EQ(reopened.size(), 1u);
  EXPECT_TRUE(reopened.find("EARLIER", "ase"));
  EXPECT_FALSE(reopened.find("ONE", "ase"));
}

TEST(LexiconJsonl, ErrorsNameTheLine) {
  auto lex = Lexicon::in_memory();
  auto import_text = [&](const std::string& text) {
    std::istringstream in(text);
    return error_of([&] { import_jsonl(lex, in, "x.jsonl"); });
  };
  EXPECT_NE(import_text("{\"gloss\":\"A\",\"lang\":\"ase\",\"hamnosys\":\"a\"}\n{not json\n").find("x.jsonl:2: bad JSON"),
            std::string::npos);
  EXPECT_NE(import_text("[1,2]\n").find("x.jsonl:1: expected a JSON object"), std::string::npos);
  EXPECT_NE(import_text("{\"gloss\":\"A\",\"lang\":\"ase\"}").find("x.jsonl:1: entry 'A' needs exactly one of"),
            std::string::npos);
  EXPECT_NE(import_text("{\"gloss\":\"A\",\"lang\":\"ase\",\"hamnosys\":\"a\",\"variant\":-3}").find("variant"),
            std::string::npos);
  EXPECT_NE(import_text("{\"gloss\":\"A\",\"hamnosys\":\"a\"}").find("no 'lang'"), std::string::npos);
  EXPECT_NE(import_text("{\"gloss\":\"A\",\"lang\":\"ase\",\"hamnosys\":\"a\",\"agreement\":\"sideways\"}")
                .find("x.jsonl:1: unknown agreement 'sideways'"),
            std::string::npos);
  EXPECT_NE(import_text(std::string("\x89PNG\r\n\x1a\n\xff\xfe", 10)).find("x.jsonl:1: bad JSON"), std::string::npos);
  EXPECT_EQ(lex.size(), 0u);
}

TEST(LexiconBuiltin, LoadsJsonlIntoMemory) {
  TempDir dir;
  const std::string path = dir.write("ase.jsonl",
                                     R"({"gloss":"HELLO","lang":"ase","hamnosys":"h","keywords":["hello","hi"]})"
                                     "\n"
                                     R"({"gloss":"THANK-YOU","lang":"ase","hamnosys":"t","keywords":["thank you","thanks"]})"
                                     "\n");
  auto builtin = load_builtin_lexicon(path);
  EXPECT_EQ(builtin.path(), ":memory:");
  EXPECT_EQ(builtin.size(), 2u);
  ASSERT_EQ(builtin.by_keyword("thanks").size(), 1u);
  EXPECT_EQ(builtin.by_keyword("thanks")[0].gloss, "THANK-YOU");
  EXPECT_EQ(builtin.find("HELLO", "ase")->source, "builtin");
}

TEST(LexiconSigml, ImportsIslFileInPlaceAndRoundTrips) {
  const std::string path = kIslDir + "absorb.sigml";
  auto lex = Lexicon::in_memory();
  ImportOptions options;
  options.language = "ins";
  EXPECT_EQ(import_sigml(lex, path, options), 1u);
  const auto absorb = lex.find("absorb", "ins");
  ASSERT_TRUE(absorb);
  EXPECT_EQ(absorb->notation_kind, NotationKind::sigml);
  // The element as written in the file, whitespace between elements dropped.
  EXPECT_EQ(absorb->notation,
            "<hns_sign gloss=\"absorb\"><hamnosys_nonmanual/><hamnosys_manual><hamsymmpar/><hamfinger2345/>"
            "<hamthumboutmod/><hamextfingerir/><hampalmd/><hamchest/><hammoveol/><hamparbegin/><hamreplace/>"
            "<hamfinger2345/><hamfingerbendmod/><hamextfingero/><hamparend/><hamtouch/></hamnosys_manual></hns_sign>");
  EXPECT_EQ(absorb->keywords.at(0).word, "absorb");
  EXPECT_EQ(absorb->source, "absorb.sigml");

  // Export as one <sigml> document and import it into a fresh lexicon: same elements.
  TempDir dir;
  const std::string exported = dir.file("out.sigml");
  {
    std::ofstream out(exported);
    const auto all = lex.list();
    EXPECT_EQ(export_sigml(all, out), 1u);
  }
  auto copy = Lexicon::in_memory();
  EXPECT_EQ(import_sigml(copy, exported, options), 1u);
  EXPECT_EQ(copy.find("absorb", "ins")->notation, absorb->notation);
}

TEST(LexiconSigml, ManySignsInOneFileAndErrors) {
  TempDir dir;
  const std::string many = dir.write("many.sigml",
                                     "<sigml>\n"
                                     "<hns_sign gloss=\"one\"><hamnosys_manual><hamfinger2/></hamnosys_manual></hns_sign>\n"
                                     "<hns_sign gloss=\"two_words\"><hamnosys_manual><hamflathand/></hamnosys_manual></hns_sign>\n"
                                     "</sigml>\n");
  auto lex = Lexicon::in_memory();
  ImportOptions options{.language = "ins"};
  EXPECT_EQ(import_file(lex, many, options), 2u);
  EXPECT_EQ(lex.by_keyword("two words").at(0).gloss, "two_words");

  const std::string no_gloss = dir.write("nogloss.sigml",
                                         "<sigml>\n<hns_sign gloss=\"ok\"/>\n\n<hns_sign>\n</hns_sign>\n</sigml>\n");
  auto fresh = Lexicon::in_memory();
  EXPECT_NE(error_of([&] { import_sigml(fresh, no_gloss, options); }).find(no_gloss + ":4: <hns_sign> has no gloss"),
            std::string::npos);
  EXPECT_EQ(fresh.size(), 0u);  // "ok" was rolled back with the rest

  const std::string broken = dir.write("broken.sigml", "<sigml>\n<hns_sign gloss=\"a\">\n</sigml>\n");
  EXPECT_NE(error_of([&] { import_sigml(fresh, broken, options); }).find(broken + ":3: bad XML"), std::string::npos);
  EXPECT_NE(error_of([&] { import_sigml(fresh, many, ImportOptions{}); }).find("--lang"), std::string::npos);
  const std::string junk = dir.write("junk.sigml", std::string("\0\1\2\3\xff", 5));
  EXPECT_NE(error_of([&] { import_sigml(fresh, junk, options); }).find(junk), std::string::npos);
}

TEST(LexiconJsonl, CheckRefusesAnEntryAndSkipBadImportsTheRest) {
  const std::string text = R"({"gloss":"ONE","lang":"ase","hamnosys":"good"})"
                           "\n"
                           R"({"gloss":"TWO","lang":"ase","hamnosys":"bad"})"
                           "\n"
                           "{not json\n"
                           R"({"gloss":"THREE","lang":"ase","hamnosys":"good"})"
                           "\n";
  ImportOptions options;
  options.check = [](const SignEntry& e) {
    if (e.notation == "bad") throw Error("notation of '" + e.gloss + "' refused");
  };
  // Without skip_bad the refused entry fails the whole import at its line.
  auto strict = Lexicon::in_memory();
  std::istringstream in(text);
  const std::string message = error_of([&] { import_jsonl(strict, in, "x.jsonl", options); });
  EXPECT_NE(message.find("x.jsonl:2: notation of 'TWO' refused"), std::string::npos) << message;
  EXPECT_EQ(strict.size(), 0u);

  // With skip_bad each bad line is reported with its line and the good ones are stored.
  std::vector<std::string> skipped;
  options.skip_bad = [&](const Error& e) { skipped.push_back(e.what()); };
  auto lenient = Lexicon::in_memory();
  std::istringstream again(text);
  EXPECT_EQ(import_jsonl(lenient, again, "x.jsonl", options), 2u);
  ASSERT_EQ(skipped.size(), 2u);
  EXPECT_NE(skipped[0].find("x.jsonl:2: notation of 'TWO' refused"), std::string::npos) << skipped[0];
  EXPECT_NE(skipped[1].find("x.jsonl:3: bad JSON"), std::string::npos) << skipped[1];
  EXPECT_TRUE(lenient.find("ONE", "ase"));
  EXPECT_TRUE(lenient.find("THREE", "ase"));
  EXPECT_FALSE(lenient.find("TWO", "ase"));
}

TEST(LexiconJsonl, AGlossRepeatedWithoutVariantsBecomesTheNextVariant) {
  auto lex = Lexicon::in_memory();
  std::istringstream in(R"({"gloss":"BANK","lang":"ase","hamnosys":"money"})"
                        "\n"
                        R"({"gloss":"BANK","lang":"ase","hamnosys":"river"})"
                        "\n"
                        R"({"gloss":"BANK","lang":"bfi","hamnosys":"british"})"
                        "\n");
  EXPECT_EQ(import_jsonl(lex, in, "x.jsonl"), 3u);
  EXPECT_EQ(lex.size(), 3u);
  ASSERT_TRUE(lex.find("BANK", "ase", 2));
  EXPECT_EQ(lex.find("BANK", "ase", 2)->notation, "river");
  EXPECT_EQ(lex.find("BANK", "ase", 1)->notation, "money");
  EXPECT_EQ(lex.find("BANK", "bfi", 1)->notation, "british");
  // Importing the file again updates the same entries rather than adding more.
  std::istringstream again(R"({"gloss":"BANK","lang":"ase","hamnosys":"money2"})"
                           "\n"
                           R"({"gloss":"BANK","lang":"ase","hamnosys":"river2"})"
                           "\n");
  import_jsonl(lex, again, "x.jsonl");
  EXPECT_EQ(lex.size(), 3u);
  EXPECT_EQ(lex.find("BANK", "ase", 2)->notation, "river2");
}
