#include "gestura/app/workspace.hpp"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <utility>

#include "gestura/lexicon/lexicon_files.hpp"

namespace gestura::app {

std::string user_citation_store() {
  if (const char* cache = std::getenv("GESTURA_CITATION_CACHE"); cache && std::strcmp(cache, "off") == 0) return {};
  try {
    return default_user_lexicon_path();
  } catch (const std::exception&) {
    return {};  // no HOME and no GESTURA_LEXICON: nowhere to keep them
  }
}

Workspace::Workspace(std::string citation_store) : citation_store_(std::move(citation_store)) {}
Workspace::~Workspace() = default;

const Avatar& Workspace::avatar_locked(const AvatarChoice& choice) {
  std::unique_ptr<Avatar>& slot = avatars_[choice.key()];
  if (!slot) slot = std::make_unique<Avatar>(build(choice));
  return *slot;
}

LayeredLexicon& Workspace::lexicon_locked() {
  if (!lexicon_) lexicon_ = std::make_unique<DefaultLexicon>();
  return lexicon_->layers();
}

const Avatar& Workspace::avatar(const AvatarChoice& choice) {
  const std::lock_guard lock(mutex_);
  return avatar_locked(choice);
}

const SigningRig& Workspace::rig(const AvatarChoice& choice) {
  const std::lock_guard lock(mutex_);
  std::unique_ptr<SigningRig>& slot = rigs_[choice.key()];
  if (!slot) slot = std::make_unique<SigningRig>(make_signing_rig(avatar_locked(choice)));
  return *slot;
}

const Signer& Workspace::signer(const AvatarChoice& choice) {
  const std::lock_guard lock(mutex_);
  std::unique_ptr<Signer>& slot = signers_[choice.key()];
  if (!slot) {
    slot = std::make_unique<Signer>(avatar_locked(choice), lexicon_locked());
    // Signs solved by earlier runs are read from the store, and new ones kept there (docs/say.md,
    // "Speed"); never throws.
    if (!citation_store_.empty()) slot->keep_citations_in(citation_store_);
  }
  return *slot;
}

LayeredLexicon& Workspace::lexicon() {
  const std::lock_guard lock(mutex_);
  return lexicon_locked();
}

void Workspace::reload_lexicon() {
  const std::lock_guard lock(mutex_);
  signers_.clear();
  lexicon_.reset();
}

}  // namespace gestura::app
