// Rough edges of the command line found by trying every command (issue 13): text from a file or
// standard input, check on a binary or broken file, extensions in any case, honest output types,
// every motion format for info, accented letters in fingerspelling, parser notes, and the README's
// own examples.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace {

using gestura::test::CliRun;
using gestura::test::run_cli;
using gestura::test::run_command;
namespace fs = std::filesystem;

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("gestura_edges_" + name); }

std::string write(const std::string& name, const std::string& content) {
  const fs::path path = temp(name);
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

std::string quoted_cli() { return "'" + gestura::test::cli_path() + "'"; }

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(CliEdges, GlossReadsAMegabyteFromStandardInputOrAFile) {
  std::string text;
  while (text.size() < (1u << 20)) text += "My mother is not home. Where do you live? ";
  const std::string file = write("gloss.txt", text);
  const CliRun piped = run_command(quoted_cli() + " gloss --json - < '" + file + "'");
  ASSERT_EQ(piped.status, 0) << piped.output.substr(0, 2000);
  const nlohmann::json j = nlohmann::json::parse(piped.output);
  EXPECT_GT(j.at("glosses").size(), 100000u) << "every sentence of the megabyte is glossed";
  EXPECT_EQ(j.at("glosses")[1].at("gloss"), "MOTHER") << j.at("glosses")[1];
  const CliRun from_file = run_cli("gloss --file " + file);
  ASSERT_EQ(from_file.status, 0);
  EXPECT_EQ(from_file.output.rfind(j.at("text").get<std::string>().substr(0, 200), 0), 0u) << "the same glosses";
  fs::remove(file);
}

TEST(CliEdges, AccentsTypedAsCombiningMarksGlossLikePrecomposedLetters) {
  const CliRun precomposed = run_cli("gloss --json 'José came.'");
  const CliRun combining = run_cli("gloss --json \"$(printf 'Jose\\314\\201 came.')\"");
  ASSERT_EQ(precomposed.status, 0) << precomposed.output;
  ASSERT_EQ(combining.status, 0) << combining.output;
  const nlohmann::json a = nlohmann::json::parse(precomposed.output), b = nlohmann::json::parse(combining.output);
  EXPECT_EQ(a.at("text"), b.at("text"));
  EXPECT_EQ(a.at("glosses")[0].at("gloss"), "FS-JOSE");
  EXPECT_EQ(b.at("glosses")[0].at("letters"), (nlohmann::json{"J", "O", "S", "E"}));
}

TEST(CliEdges, SubtitlesReadStandardInput) {
  const std::string srt = write("stdin.srt", "1\n00:00:00,000 --> 00:00:01,500\nHello\n");
  const std::string out = temp("stdin.mp4").string();
  const CliRun r = run_command(quoted_cli() + " subtitles - -o '" + out + "' --size 64x64 --fps 5 < '" + srt + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("HELLO"), std::string::npos) << r.output;
  EXPECT_GT(fs::file_size(out), 0u);
  fs::remove(srt);
  fs::remove(out);
}

TEST(CliEdges, CheckStopsAtMaxErrorsAndRefusesBinaryFilesInOneLine) {
  std::string bad;
  for (int i = 0; i < 40; ++i) bad += "not a sign\n";
  const std::string jsonl = write("bad.jsonl", bad);
  const CliRun capped = run_cli("check --parse-only --max-errors 3 " + jsonl);
  EXPECT_EQ(capped.status, 1);
  EXPECT_NE(capped.output.find("stopped after 3 failing signs"), std::string::npos) << capped.output;
  EXPECT_EQ(lines(capped.output), 5u) << capped.output;  // 3 failures, the stop, the summary
  const CliRun all = run_cli("check --parse-only --max-errors=0 " + jsonl);
  EXPECT_NE(all.output.find("40 signs: 0 parsed, 0 synthesized, 40 failed"), std::string::npos) << all.output;
  EXPECT_EQ(run_cli("check --max-errors -1 " + jsonl).status, 2);

  std::string binary(200000, '\0');
  for (std::size_t i = 0; i < binary.size(); i += 7) binary[i] = static_cast<char>(i % 251);
  for (std::size_t i = 0; i < binary.size(); i += 97) binary[i] = '\n';
  const std::string bin = write("binary.jsonl", binary);
  const CliRun refused = run_cli("check " + bin);
  EXPECT_EQ(refused.status, 1);
  EXPECT_EQ(lines(refused.output), 1u) << refused.output.substr(0, 500);
  EXPECT_NE(refused.output.find("not a text file"), std::string::npos) << refused.output;
  fs::remove(jsonl);
  fs::remove(bin);
}

TEST(CliEdges, LeniencyIsReportedAsANote) {
  // A group opened and never closed: accepted, with the note --help promises; refused with --strict.
  const std::string jsonl = write("open.jsonl", R"({"gloss":"OPEN","names":"hamflathand,hamextfingeru,hampalml,hamchest,hamparbegin,hammoveu"})"
                                                "\n");
  const CliRun lenient = run_cli("check --parse-only " + jsonl);
  EXPECT_EQ(lenient.status, 0) << lenient.output;
  EXPECT_NE(lenient.output.find("open.jsonl:1: OPEN: note: symbol 4: hamparbegin is never closed"), std::string::npos)
      << lenient.output;
  const CliRun strict = run_cli("check --parse-only --strict " + jsonl);
  EXPECT_EQ(strict.status, 1);
  EXPECT_NE(strict.output.find("never closed"), std::string::npos) << strict.output;
  fs::remove(jsonl);
}

TEST(CliEdges, ExtensionsAreReadInAnyCase) {
  const std::string json = temp("upper.JSON").string();
  const CliRun sign = run_cli("sign --names hamflathand,hamextfingeru,hampalml,hamchest --fps 10 -o " + json);
  ASSERT_EQ(sign.status, 0) << sign.output;
  EXPECT_TRUE(nlohmann::json::parse(std::ifstream(json)).contains("frames"));
  const std::string png = temp("upper.PNG").string();
  ASSERT_EQ(run_cli("render --rest --size 64x64 -o " + png).status, 0);
  EXPECT_GT(fs::file_size(png), 100u);
  const std::string bvh = temp("upper.BVH").string(), glb = temp("upper.Glb").string();
  ASSERT_EQ(run_cli("sign --names hamflathand,hamextfingeru,hampalml,hamchest --fps 10 -o " + bvh).status, 0);
  const CliRun convert = run_cli("convert " + bvh + " " + glb);
  ASSERT_EQ(convert.status, 0) << convert.output;
  const CliRun info = run_cli("info " + glb);
  EXPECT_EQ(info.status, 0) << info.output;
  EXPECT_NE(info.output.find("format:     glTF"), std::string::npos) << info.output;
  for (const std::string& f : {json, png, bvh, glb}) fs::remove(f);
}

TEST(CliEdges, AvatarExportWritesGlbOnly) {
  const std::string obj = temp("avatar.obj").string();
  const CliRun refused = run_cli("avatar export -o " + obj);
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find(".glb"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(obj)) << "no glTF bytes under another name";
  EXPECT_EQ(run_cli("avatar export -o " + temp("avatar.gltf").string()).status, 2);
}

TEST(CliEdges, InfoReadsEveryMotionFormat) {
  const std::string bvh = temp("info.bvh").string(), bap = temp("info.bap").string(), gcl = temp("info.gcl").string();
  ASSERT_EQ(run_cli("sign --names hamflathand,hamextfingeru,hampalml,hamchest --fps 10 -o " + bvh).status, 0);
  ASSERT_EQ(run_cli("convert " + bvh + " " + bap).status, 0);
  ASSERT_EQ(run_cli("compress " + bvh + " -o " + gcl).status, 0);
  struct Case {
    std::string args, format;
  };
  for (const Case& c : {Case{bvh, "BVH"}, Case{bap, "BAP"}, Case{gcl, "gcl (compressed clip)"},
                        Case{gcl + " --skeleton " + bvh, "gcl"},
                        Case{gestura::test::shared_data() + "/makehuman/poses/run01.bvh --scale 0.1 --z-up", "BVH"}}) {
    const CliRun r = run_cli("info " + c.args);
    ASSERT_EQ(r.status, 0) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("format:     " + c.format + "\n"), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("frames:"), std::string::npos) << r.output;
  }
  const CliRun unknown = run_cli("info " + write("x.txt", "hello"));
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.output.find(".bvh"), std::string::npos) << "lists what it reads: " << unknown.output;
  for (const std::string& f : {bvh, bap, gcl}) fs::remove(f);
}

TEST(CliEdges, FingerspellingSpellsAccentedLettersAsTheirBase) {
  const CliRun jose = run_cli("fingerspell José");
  ASSERT_EQ(jose.status, 0) << jose.output;
  EXPECT_NE(jose.output.find("ASL, 6.00 letters/s, 4 letters"), std::string::npos) << jose.output;
  EXPECT_NE(jose.output.find("\n     E "), std::string::npos) << jose.output;
  const CliRun combining = run_cli("fingerspell \"$(printf 'Jose\\314\\201')\"");
  EXPECT_EQ(combining.output, jose.output);
  const CliRun strasse = run_cli("fingerspell Straße");
  EXPECT_EQ(strasse.status, 1);
  EXPECT_NE(strasse.output.find("cannot fingerspell 'ß' (U+00DF)"), std::string::npos) << strasse.output;
  EXPECT_NE(strasse.output.find("symbol 4"), std::string::npos) << "the place: " << strasse.output;
}

TEST(CliEdges, TheReadmesExamplesOfCheckAndGlossWork) {
  std::ifstream readme(gestura::test::source_dir() + "/README.md");
  std::stringstream text;
  text << readme.rdbuf();
  const std::string body = text.str();
  const std::regex example(R"(\nbuild/bin/gestura ((check|gloss) [^\n]*))");
  int run = 0;
  for (auto it = std::sregex_iterator(body.begin(), body.end(), example); it != std::sregex_iterator(); ++it) {
    std::string args = (*it)[1];
    // The README is run from the checkout; ../shared/data is the shared data beside it.
    const std::size_t shared = args.find("../shared/data");
    if (shared != std::string::npos) args.replace(shared, 14, gestura::test::shared_data());
    const CliRun r = run_command("cd '" + gestura::test::source_dir() + "' && " + quoted_cli() + " " + args);
    EXPECT_EQ(r.status, 0) << args << "\n" << r.output;
    ++run;
  }
  EXPECT_GE(run, 2);
}

}  // namespace
