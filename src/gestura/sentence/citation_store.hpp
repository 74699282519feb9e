#pragma once
// Citation forms solved in an earlier process, kept in the user's lexicon database so that a new
// `gestura say` starts warm (docs/say.md, "Speed"). The motion cache (sign_motion_cache.hpp) asks
// the store before it solves a sign and gives it what it solved.
//
//   CitationStore store(default_user_lexicon_path(), rig);
//   cache.persist_to(&store);
//
// What a stored form is keyed by, so that nothing stale is served:
// - the sign: the cache's key (its notation, and the place when it was changed in space) as a
//   64-bit hash, checked against the key text stored beside it;
// - the avatar: a hash of the rig's skeleton, relaxed posture, hands, sites and collision body;
// - the solver: the build id of the running program (any rebuild is a new solver, and a new
//   parser and planner) and the store's format version. Rows of other solvers are deleted when a
//   writable store opens.
// A stored form holds its plan too, so a warm start neither plans nor solves.
// The table (citation_cache) lives beside the lexicon's tables and outside its versioned schema:
// it is only a cache, dropping it loses nothing, and older programs ignore it.
//
// Never in the way: a database that cannot be opened, is read-only, damaged, busy or full makes
// the store load what it can and skip what it cannot; say() then solves as if nothing were stored.
// A file that does not exist yet is created as an empty user lexicon.
// Thread-safe: calls are serialised.
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "gestura/lexicon/sqlite.hpp"
#include "gestura/sentence/sign_motion_cache.hpp"

namespace gestura {

class CitationStore final : public CitationKeeper {
 public:
  // Opens (or creates) the database at `path`. Never throws: what failed is in problem().
  CitationStore(const std::string& path, const SigningRig& rig);
  ~CitationStore() override;
  CitationStore(const CitationStore&) = delete;
  CitationStore& operator=(const CitationStore&) = delete;

  // The form (plan and motion) stored under `key` for this avatar and solver; empty when none is
  // (or it cannot be read whole).
  std::unique_ptr<CitationMotion> load(std::string_view key) override;
  // Stores `motion` under `key`; skipped when the store cannot write.
  void save(std::string_view key, const CitationMotion& motion) override;

  bool readable() const { return db_ != nullptr; }
  bool writable() const { return db_ != nullptr && writable_; }
  // Why the store reads or writes nothing (empty when it does both).
  std::string problem() const;
  // Forms loaded and saved by this store so far.
  std::size_t loaded() const { return loaded_; }
  std::size_t saved() const { return saved_; }

  // The avatar's and the solver's part of the key (exposed for tests).
  std::uint64_t avatar_hash() const { return avatar_; }
  static std::string solver_version();

 private:
  void disable_writes(const std::string& why);

  mutable std::mutex mutex_;
  std::unique_ptr<sqlite::Database> db_;
  bool writable_ = false;
  std::string problem_;
  std::uint64_t avatar_ = 0;
  ByHand<std::size_t> joints_{};
  std::string solver_;
  std::size_t loaded_ = 0, saved_ = 0;
};

}  // namespace gestura
