// Who keeps solved citation forms on disk (app/workspace.hpp, sentence/citation_store.hpp): the
// command line does, in the user lexicon, so a second `gestura say` starts warm; a Workspace given
// no file, and so every library user and test, writes nothing; GESTURA_CITATION_CACHE=off turns the
// command line's store off.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "gestura/app/workspace.hpp"
#include "gestura/lexicon/sqlite.hpp"
#include "gestura/sentence/citation_store.hpp"
#include "lexicon/temp_dir.hpp"
#include "support/cli.hpp"

namespace {

using namespace gestura;
namespace fs = std::filesystem;

std::int64_t stored_forms(const std::string& path) {
  sqlite::Database db(path, sqlite::Access::read);
  auto count = db.prepare("SELECT COUNT(*) FROM citation_cache");
  count.step();
  return count.integer(0);
}

// Sets an environment variable for one scope and puts the old value back.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() { had_ ? ::setenv(name_, old_.c_str(), 1) : ::unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

TEST(CitationStoreUse, TheUserStoreIsTheUserLexiconUnlessTurnedOff) {
  gestura::testing::TempDir dir;
  const ScopedEnv lexicon("GESTURA_LEXICON", dir.file("user.sqlite"));
  {
    const ScopedEnv on("GESTURA_CITATION_CACHE", "on");
    EXPECT_EQ(app::user_citation_store(), dir.file("user.sqlite"));
  }
  const ScopedEnv off("GESTURA_CITATION_CACHE", "off");
  EXPECT_EQ(app::user_citation_store(), "");
}

TEST(CitationStoreUse, AWorkspaceKeepsFormsOnDiskOnlyInTheFileItIsGiven) {
  gestura::testing::TempDir dir;
  // Even where the user's lexicon would be found, a workspace given no file writes nothing.
  const ScopedEnv lexicon("GESTURA_LEXICON", dir.file("user.sqlite"));
  const ScopedEnv on("GESTURA_CITATION_CACHE", "on");
  app::Workspace plain;
  const Signer& in_memory = plain.signer(app::AvatarChoice{});
  in_memory.say("mother");
  EXPECT_EQ(in_memory.store(), nullptr);
  EXPECT_FALSE(fs::exists(dir.file("user.sqlite")));

  const std::string path = dir.file("kept/citations.sqlite");
  app::Workspace keeping(path);
  const Signer& first = keeping.signer(app::AvatarChoice{});
  ASSERT_NE(first.store(), nullptr);
  EXPECT_TRUE(first.store()->writable()) << first.store()->problem();
  first.say("mother");
  EXPECT_GE(first.store()->saved(), 1u);
  EXPECT_EQ(stored_forms(path), static_cast<std::int64_t>(first.store()->saved()));

  // A second signer of the same avatar (as a second process would be) reads them, solving nothing.
  Signer second(keeping.avatar(app::AvatarChoice{}), keeping.lexicon());
  second.keep_citations_in(path);
  second.say("mother");
  EXPECT_EQ(second.store()->loaded(), first.store()->saved());
  EXPECT_EQ(second.store()->saved(), 0u);
}

TEST(CitationStoreUse, TheCommandLineKeepsFormsInTheUserLexiconUnlessTurnedOff) {
  gestura::testing::TempDir dir;
  const std::string user = dir.file("user.sqlite");
  // The test binary turns the store off for every program it starts (support/no_user_citation_store.cpp).
  const test::CliRun off = test::run_cli("say mother", "GESTURA_LEXICON='" + user + "'");
  ASSERT_EQ(off.status, 0) << off.output;
  EXPECT_FALSE(fs::exists(user));

  const test::CliRun on = test::run_cli("say mother", "GESTURA_LEXICON='" + user + "' GESTURA_CITATION_CACHE=on");
  ASSERT_EQ(on.status, 0) << on.output;
  EXPECT_GE(stored_forms(user), 1);
  EXPECT_EQ(on.output, off.output);  // the same signing, with or without the store
}

}  // namespace
