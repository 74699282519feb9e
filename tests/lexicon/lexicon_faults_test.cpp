// The lexicon under faults: read-only and immutable files can be read; a damaged file is never
// written to; `kill -9` in the middle of an import loses nothing that was committed and leaves no
// half-import behind.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/lexicon/schema.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/small_tmpfs.hpp"
#include "temp_dir.hpp"

namespace {

using namespace gestura;
using gestura::testing::TempDir;
using gestura::test::run_cli;

// hamfinger2 hamextfingeri hampalml hamchest hamtouch: the index finger touches the chest.
constexpr const char* kIndexAtChest = "\xee\x80\x82\xee\x80\xac\xee\x80\xbe\xee\x81\x92\xee\x83\x91";

SignEntry sign(const std::string& gloss, const std::string& notation = kIndexAtChest) {
  SignEntry e;
  e.gloss = gloss;
  e.language = "ase";
  e.notation = notation;
  e.keywords.push_back(Keyword{"word-" + gloss});
  return e;
}

// A lexicon file of `count` signs, closed (its WAL log folded into the file).
void make_lexicon(const std::string& path, int count) {
  Lexicon lexicon = Lexicon::open(path);
  lexicon.atomically([&] {
    for (int i = 0; i < count; ++i) lexicon.add(sign("SIGN" + std::to_string(i)));
  });
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

template <class Body>
std::string error_of(Body&& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(LexiconReadOnly, ReadOnlyMountIsListedAndRefusesWrites) {
  test::SmallTmpfs fs(1024 * 1024);
  if (!fs.mounted()) GTEST_SKIP() << fs.skip_reason();
  const std::string path = fs.path("lexicon.sqlite");
  make_lexicon(path, 30);
  fs.remount_read_only();

  Lexicon lexicon = Lexicon::open_read_only(path);
  EXPECT_EQ(lexicon.size(), 30u);
  EXPECT_TRUE(lexicon.find("SIGN7", "ase"));
  const std::string refused = error_of([&] { lexicon.add(sign("NEW")); });
  EXPECT_NE(refused.find(path), std::string::npos) << refused;
  EXPECT_NE(refused.find("read-only"), std::string::npos) << refused;

  const auto listed = run_cli("lexicon list --db " + path);
  EXPECT_EQ(listed.status, 0) << listed.output;
  EXPECT_NE(listed.output.find("SIGN29"), std::string::npos) << listed.output;
  const auto shown = run_cli("lexicon show SIGN3 --db " + path);
  EXPECT_EQ(shown.status, 0) << shown.output;
  const auto exported = run_cli("lexicon export " + ::testing::TempDir() + "ro_export.jsonl --db " + path);
  EXPECT_EQ(exported.status, 0) << exported.output;

  const auto added = run_cli("lexicon add --gloss NEW --lang ase --hamnosys '" + std::string(kIndexAtChest) + "' --db " + path);
  EXPECT_EQ(added.status, 1) << added.output;
  EXPECT_NE(added.output.find("read-only"), std::string::npos) << added.output;
}

TEST(LexiconReadOnly, ImmutableFileIsListed) {
  TempDir dir;
  const std::string path = dir.file("frozen.sqlite");
  make_lexicon(path, 5);
  const auto frozen = test::run_command("chattr +i " + path + " 2>&1");
  if (frozen.status != 0) GTEST_SKIP() << "chattr +i does not work here: " << frozen.output;
  const std::string before = bytes_of(path);
  const auto listed = run_cli("lexicon list --db " + path);
  const auto added = run_cli("lexicon add --gloss NEW --lang ase --hamnosys '" + std::string(kIndexAtChest) + "' --db " + path);
  test::run_command("chattr -i " + path);
  EXPECT_EQ(listed.status, 0) << listed.output;
  EXPECT_NE(listed.output.find("SIGN4"), std::string::npos) << listed.output;
  EXPECT_EQ(added.status, 1) << added.output;
  EXPECT_NE(added.output.find(path), std::string::npos) << added.output;
  EXPECT_EQ(bytes_of(path), before);
}

// A version-1 file with one sign (the first schema: no variants).
void make_version1_lexicon(const std::string& path) {
  sqlite::Database db(path, true);
  lexicon_schema::migrate(db, 1);
  db.exec("INSERT INTO signs (gloss, lang, notation_kind, notation) VALUES ('OLD', 'ase', 'hamnosys', 'x')");
}

TEST(LexiconReadOnly, AnOldSchemaIsUpgradedWhenWritableAndNamedWhenNot) {
  TempDir dir;
  const std::string path = dir.file("v1.sqlite");
  make_version1_lexicon(path);
  Lexicon upgraded = Lexicon::open_read_only(path);
  EXPECT_TRUE(upgraded.find("OLD", "ase"));
  EXPECT_NE(error_of([&] { Lexicon::open_read_only(dir.file("missing.sqlite")); }), "");

  test::SmallTmpfs fs(1024 * 1024);
  if (!fs.mounted()) GTEST_SKIP() << fs.skip_reason();
  make_version1_lexicon(fs.path("v1.sqlite"));
  fs.remount_read_only();
  const std::string message = error_of([&] { Lexicon::open_read_only(fs.path("v1.sqlite")); });
  EXPECT_NE(message.find("older"), std::string::npos) << message;
}

TEST(LexiconDamage, DamagedFileRefusesWritesAndIsLeftAsItIs) {
  TempDir dir;
  const std::string path = dir.file("damaged.sqlite");
  make_lexicon(path, 400);
  {
    // Give the last page a b-tree header that cannot be: 9 cells whose content starts past the page.
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(0, std::ios::end);
    const auto size = static_cast<std::streamoff>(file.tellp());
    ASSERT_EQ(size % 4096, 0);
    file.seekp(size - 4096);
    const char header[] = {0x0D, 0, 0, 0, 9, '\xff', '\xff', '\xff'};
    file.write(header, sizeof header);
  }
  const std::string before = bytes_of(path);
  const std::string message = error_of([&] { Lexicon::open(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("damaged"), std::string::npos) << message;
  EXPECT_NE(message.find("quick_check"), std::string::npos) << message;

  const auto added = run_cli("lexicon add --gloss NEW --lang ase --hamnosys '" + std::string(kIndexAtChest) + "' --db " + path);
  EXPECT_EQ(added.status, 1) << added.output;
  EXPECT_NE(added.output.find("damaged"), std::string::npos) << added.output;
  const auto imported = run_cli("lexicon remove SIGN1 --lang ase --db " + path);
  EXPECT_EQ(imported.status, 1) << imported.output;
  EXPECT_EQ(bytes_of(path), before);
}

TEST(LexiconHostile, DeepOrBrokenSigmlNotationIsRefusedAtImport) {
  // 300,000 nested elements once made `lexicon export` indent its way to 16 GB of memory.
  TempDir dir;
  std::string nested;
  for (int i = 0; i < 300000; ++i) nested += "<a>";
  for (int i = 0; i < 300000; ++i) nested += "</a>";
  const std::string sigml = dir.write("deep.sigml", "<sigml><hns_sign gloss=\"deep\"><hamnosys_manual>" + nested +
                                                        "</hamnosys_manual></hns_sign></sigml>");
  Lexicon lexicon = Lexicon::open(dir.file("l.sqlite"));
  const std::string message = error_of([&] { import_file(lexicon, sigml, ImportOptions{.language = "ins"}); });
  EXPECT_NE(message.find("deep.sigml:1"), std::string::npos) << message.substr(0, 300);
  EXPECT_NE(message.find("kMaxStoredSigmlDepth"), std::string::npos) << message.substr(0, 300);
  SignEntry broken = sign("BROKEN");
  broken.notation_kind = NotationKind::sigml;
  broken.notation = "<hns_sign gloss=\"x\"><hamnosys_manual>";
  EXPECT_NE(error_of([&] { lexicon.add(broken); }).find("not well-formed XML"), std::string::npos);
  EXPECT_EQ(lexicon.size(), 0u);
}

// Many signs of our own making, so that an import takes long enough to be killed in the middle.
std::string big_import_file(const TempDir& dir, int count) {
  std::string text;
  for (int i = 0; i < count; ++i)
    text += "{\"gloss\":\"IMPORTED" + std::to_string(i) +
            "\",\"lang\":\"ase\",\"hamnosys\":\"" + std::string(kIndexAtChest) + "\",\"keywords\":[\"w" + std::to_string(i) +
            "\",\"v" + std::to_string(i) + "\"]}\n";
  return dir.write("big.jsonl", text);
}

TEST(LexiconKill, KillNineDuringImportLosesNothingCommitted) {
  TempDir dir;
  const std::string path = dir.file("killed.sqlite");
  make_lexicon(path, 10);
  constexpr int kImported = 40000;
  const std::string file = big_import_file(dir, kImported);
  int interrupted = 0;
  for (const int after_ms : {30, 120, 250, 400, 700, 1000}) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 1);
      dup2(null, 2);
      execl(test::cli_path().c_str(), "gestura", "lexicon", "import", file.c_str(), "--db", path.c_str(),
            static_cast<char*>(nullptr));
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(after_ms));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    const bool killed = WIFSIGNALED(status);
    interrupted += killed;

    // The file is sound, the signs committed before are there, and the import is all or nothing.
    Lexicon lexicon = Lexicon::open(path);  // runs quick_check
    EXPECT_TRUE(lexicon.find("SIGN0", "ase") && lexicon.find("SIGN9", "ase")) << "after " << after_ms << " ms";
    const std::size_t size = lexicon.size();
    EXPECT_TRUE(size == 10u || size == 10u + kImported) << size << " signs after " << after_ms << " ms";
    if (size != 10u) {  // the import finished before the kill: start again from the 10 signs
      lexicon.atomically([&] {
        for (int i = 0; i < kImported; ++i) lexicon.remove("IMPORTED" + std::to_string(i), "ase");
      });
    }
  }
  EXPECT_GE(interrupted, 3) << "the import was too quick to be interrupted";
}

}  // namespace
