#pragma once
// What requests build once and reuse: avatars (seconds to build), the default lexicon (built-in
// plus the user's), and signers with their cache of performed signs. A long-lived adapter (the
// server, the studio) keeps one Workspace for many requests; the CLI uses a fresh one per run.
// Safe to share between threads: building is serialised, and what is built is never changed.
//
// Solved citation forms (sentence/citation_store.hpp) are kept on disk only when the workspace is
// given a file for them: the CLI and the server pass user_citation_store(); a library user or a
// test that passes nothing writes no file.
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura::app {

// Where the command line and the server keep solved citation forms between runs: the user lexicon
// (default_user_lexicon_path()). Empty (solve in memory only) when GESTURA_CITATION_CACHE=off, or
// when there is no user lexicon path (neither GESTURA_LEXICON nor HOME set).
std::string user_citation_store();

class Workspace {
 public:
  // `citation_store`: the SQLite database where signers read the citation forms earlier runs
  // solved and keep the ones they solve; empty: in memory only. A database that cannot be used
  // (read-only, damaged, busy) only makes signs be solved again (sentence/citation_store.hpp).
  explicit Workspace(std::string citation_store = {});
  ~Workspace();
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  // Built on first use and kept; the references stay valid for the workspace's life.
  const Avatar& avatar(const AvatarChoice& choice);
  const SigningRig& rig(const AvatarChoice& choice);
  const Signer& signer(const AvatarChoice& choice);
  LayeredLexicon& lexicon();

  // Drops the lexicon and the signers that use it (call after the user lexicon changed). Not safe
  // while another thread is running a request on this workspace.
  void reload_lexicon();

 private:
  std::mutex mutex_;
  std::string citation_store_;
  std::map<std::string, std::unique_ptr<Avatar>> avatars_;
  std::map<std::string, std::unique_ptr<SigningRig>> rigs_;
  std::unique_ptr<DefaultLexicon> lexicon_;
  std::map<std::string, std::unique_ptr<Signer>> signers_;

  const Avatar& avatar_locked(const AvatarChoice& choice);
  LayeredLexicon& lexicon_locked();
};


// The workspace a run uses: the context's, or one of its own for this run only.
class RunWorkspace {
 public:
  explicit RunWorkspace(const RunContext& context)
      : own_(context.workspace ? nullptr : std::make_unique<Workspace>(context.citation_store)), used_(context.workspace ? context.workspace : own_.get()) {}
  Workspace* operator->() const { return used_; }
  Workspace& operator*() const { return *used_; }

 private:
  std::unique_ptr<Workspace> own_;
  Workspace* used_;
};

}  // namespace gestura::app
