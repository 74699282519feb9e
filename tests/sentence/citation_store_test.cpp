// Citation forms kept in the user lexicon database between processes (sentence/citation_store):
// what is read back is what was solved, and nothing stale or damaged is served.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

#include "gestura/body/avatar.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/sentence/citation_store.hpp"
#include "gestura/sentence/sign_motion_cache.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"
#include "lexicon/temp_dir.hpp"
#include "support/hamnosys_text.hpp"
#include "support/signing_avatar.hpp"
#include "support/small_tmpfs.hpp"

using namespace gestura;

namespace {

const test::SigningAvatar& fx() { return test::signing_avatar(); }

std::string unicode(const std::string& names) { return test::hamnosys_text(names); }

// MOTHER at the chin; the same sign at the forehead is FATHER.
const std::string kMother = unicode("hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart");
const std::string kFather = unicode("hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamforehead,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart");

void expect_same_plan(const SignPlan& a, const SignPlan& b) {
  EXPECT_EQ(a.sign_start, b.sign_start);
  EXPECT_EQ(a.sign_end, b.sign_end);
  for (Hand hand : kBothHands) {
    const HandTimeline& x = a.hand(hand);
    const HandTimeline& y = b.hand(hand);
    ASSERT_EQ(x.segments.size(), y.segments.size());
    for (std::size_t i = 0; i < x.segments.size(); ++i) {
      EXPECT_EQ(x.segments[i].start, y.segments[i].start);
      EXPECT_EQ(x.segments[i].end, y.segments[i].end);
      EXPECT_EQ(x.segments[i].paths.size(), y.segments[i].paths.size());
      EXPECT_EQ(x.segments[i].oscillation, y.segments[i].oscillation);
    }
    if (x.segments.empty()) continue;
    // What the performer asks of the plan: every hand state along it, all fields.
    for (float t = 0.0f; t <= x.end_time() + 0.01f; t += 0.01f) {
      const HandState p = sample_hand(x, t), q = sample_hand(y, t);
      EXPECT_EQ(p.position, q.position) << t;
      EXPECT_EQ(p.orientation, q.orientation) << t;
      EXPECT_EQ(p.active, q.active);
      EXPECT_EQ(p.at_body, q.at_body);
      EXPECT_EQ(p.body_weight, q.body_weight);
      EXPECT_EQ(p.shape.thumb.cmc_opposition, q.shape.thumb.cmc_opposition);
      EXPECT_EQ(p.shape.fingers[1].pip, q.shape.fingers[1].pip);
      EXPECT_EQ(p.shape.spread, q.shape.spread);
      EXPECT_EQ(p.shape.thumb_tip_contacts, q.shape.thumb_tip_contacts);
    }
  }
}

void expect_same_motion(const CitationMotion& a, const CitationMotion& b) {
  expect_same_plan(a.plan, b.plan);
  EXPECT_EQ(a.rate, b.rate);
  EXPECT_EQ(a.first_posture, b.first_posture);
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.plan.sign_end, b.plan.sign_end);
  for (Hand hand : kBothHands) {
    EXPECT_EQ(a.joints[hand], b.joints[hand]);
    ASSERT_EQ(a.samples[hand].size(), b.samples[hand].size());
    // Bit for bit: what is stored is the solver's output, not an approximation of it.
    EXPECT_EQ(std::memcmp(a.samples[hand].data(), b.samples[hand].data(), a.samples[hand].size() * sizeof(quat)), 0);
  }
}

std::int64_t rows(const std::string& path) {
  sqlite::Database db(path, sqlite::Access::read);
  auto count = db.prepare("SELECT COUNT(*) FROM citation_cache");
  count.step();
  return count.integer(0);
}

void exec(const std::string& path, const std::string& sql) {
  sqlite::Database db(path, sqlite::Access::write);
  db.exec(sql);
}

}  // namespace

TEST(CitationStore, APersistedFormEqualsTheFreshlySolvedOne) {
  gestura::testing::TempDir dir;
  const std::string path = dir.file("user/lexicon.sqlite");  // its folder does not exist yet
  {
    CitationStore store(path, fx().rig);
    EXPECT_TRUE(store.writable()) << store.problem();
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    cache.sign(kMother);
    EXPECT_EQ(store.saved(), 1u);
    EXPECT_EQ(store.loaded(), 0u);
  }
  // The new file is a user lexicon like any other (empty), with the cache beside it.
  EXPECT_EQ(Lexicon::open_read_only(path).size(), 0u);
  EXPECT_EQ(rows(path), 1);

  SignMotionCache fresh(fx().rig);
  const CitationMotion& solved = fresh.sign(kMother);

  CitationStore store(path, fx().rig);  // as a second process would
  SignMotionCache warm(fx().rig);
  warm.persist_to(&store);
  const CitationMotion& loaded = warm.sign(kMother);
  EXPECT_EQ(store.loaded(), 1u);
  EXPECT_EQ(store.saved(), 0u);
  expect_same_motion(loaded, solved);
}

TEST(CitationStore, AChangedNotationAvatarOrSolverIsNotServedStale) {
  gestura::testing::TempDir dir;
  const std::string path = dir.file("lexicon.sqlite");
  {
    CitationStore store(path, fx().rig);
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    cache.sign(kMother);
  }
  // Another notation is solved, not served MOTHER's motion.
  {
    CitationStore store(path, fx().rig);
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    const CitationMotion& father = cache.sign(kFather);
    EXPECT_EQ(store.loaded(), 0u);
    EXPECT_EQ(store.saved(), 1u);
    SignMotionCache fresh(fx().rig);
    expect_same_motion(father, fresh.sign(kFather));
  }
  // Rows of another avatar are not read; rows of another solver are deleted on opening.
  exec(path, "UPDATE citation_cache SET avatar = avatar + 1 WHERE sign = '" + kFather + "'");
  exec(path, "UPDATE citation_cache SET solver = 'f1:another-build' WHERE sign = '" + kMother + "'");
  EXPECT_EQ(rows(path), 2);
  CitationStore store(path, fx().rig);
  EXPECT_EQ(rows(path), 1);  // MOTHER's row of the other solver is gone
  EXPECT_EQ(store.load(kFather), nullptr);
  EXPECT_EQ(store.load(kMother), nullptr);
}

TEST(CitationStore, AnotherAvatarIsNotServedTheFormsOfThisOne) {
  gestura::testing::TempDir dir;
  const std::string path = dir.file("lexicon.sqlite");
  {
    CitationStore store(path, fx().rig);
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    cache.sign(kMother);
  }
  // The same avatar with forearms 2 cm longer: its arm must be solved again.
  Avatar longer = fx().avatar;
  for (const char* wrist : {"l_wrist", "r_wrist"}) {
    const int j = longer.skeleton.find(wrist);
    ASSERT_GE(j, 0);
    const vec3 t = longer.skeleton.rest_translations[j];
    longer.skeleton.rest_translations[j] = t * ((glm::length(t) + 0.02f) / glm::length(t));
  }
  const SigningRig rig = make_signing_rig(longer);
  CitationStore store(path, rig);
  EXPECT_NE(store.avatar_hash(), CitationStore(path, fx().rig).avatar_hash());
  EXPECT_EQ(store.load(kMother), nullptr);
  SignMotionCache cache(rig);
  cache.persist_to(&store);
  const CitationMotion& solved = cache.sign(kMother);
  EXPECT_EQ(store.loaded(), 0u);
  EXPECT_EQ(store.saved(), 1u);
  SignMotionCache fresh(rig);
  expect_same_motion(solved, fresh.sign(kMother));
  // Both avatars' forms are kept side by side; the first avatar still gets its own.
  EXPECT_EQ(rows(path), 2);
  CitationStore first(path, fx().rig);
  SignMotionCache first_cache(fx().rig);
  expect_same_motion(*first.load(kMother), first_cache.sign(kMother));
}

TEST(CitationStore, ADamagedRowOrFileIsSolvedAfresh) {
  gestura::testing::TempDir dir;
  const std::string path = dir.file("lexicon.sqlite");
  {
    CitationStore store(path, fx().rig);
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    cache.sign(kMother);
  }
  exec(path, "UPDATE citation_cache SET motion = x'0100000000'");
  SignMotionCache fresh(fx().rig);
  const CitationMotion& solved = fresh.sign(kMother);
  {
    CitationStore store(path, fx().rig);
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    expect_same_motion(cache.sign(kMother), solved);
    EXPECT_EQ(store.loaded(), 0u);
    EXPECT_EQ(store.saved(), 1u);  // the good form replaces the damaged one
  }
  // Not a database at all: the store reads and writes nothing, signs are solved as usual, and
  // the file is left as it was.
  const std::string junk = dir.write("junk.sqlite", std::string(8192, '\x5a'));
  CitationStore store(junk, fx().rig);
  EXPECT_FALSE(store.writable());
  EXPECT_FALSE(store.problem().empty());
  SignMotionCache cache(fx().rig);
  cache.persist_to(store.readable() ? &store : nullptr);
  expect_same_motion(cache.sign(kMother), solved);
  std::ifstream in(junk, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), std::string(8192, '\x5a'));
}

TEST(CitationStore, AReadOnlyDatabaseIsReadAndNotWritten) {
  test::SmallTmpfs fs(2 * 1024 * 1024);
  if (!fs.mounted()) GTEST_SKIP() << fs.skip_reason();
  const std::string path = fs.path("lexicon.sqlite");
  {
    CitationStore store(path, fx().rig);
    SignMotionCache cache(fx().rig);
    cache.persist_to(&store);
    cache.sign(kMother);
  }
  fs.remount_read_only();
  CitationStore store(path, fx().rig);
  EXPECT_TRUE(store.readable()) << store.problem();
  EXPECT_FALSE(store.writable());
  SignMotionCache cache(fx().rig);
  cache.persist_to(&store);
  cache.sign(kMother);
  EXPECT_EQ(store.loaded(), 1u);
  cache.sign(kFather);  // solved; storing it is skipped without an error
  EXPECT_EQ(store.saved(), 0u);
  EXPECT_EQ(cache.signs_stored(), 2u);
}
