#pragma once
// The lexicon a user signs with by default: the built-in one (data/lexicon/*.jsonl, or
// $GESTURA_BUILTIN_LEXICON) with the user's own SQLite lexicon on top when it exists
// (default_user_lexicon_path()). Owns the lexicons; not copyable or movable, because the layered
// view refers to them.
#include <memory>

#include "gestura/lexicon/layered_lexicon.hpp"

namespace gestura {

class DefaultLexicon {
 public:
  // Throws gestura::Error when no built-in lexicon is found or a lexicon file cannot be read.
  DefaultLexicon();
  DefaultLexicon(const DefaultLexicon&) = delete;
  DefaultLexicon& operator=(const DefaultLexicon&) = delete;

  LayeredLexicon& layers() { return layers_; }

 private:
  std::unique_ptr<Lexicon> builtin_, user_;
  LayeredLexicon layers_;
};

}  // namespace gestura
