#include "gestura/lexicon/default_lexicon.hpp"

#include <filesystem>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/lexicon_files.hpp"

namespace gestura {

DefaultLexicon::DefaultLexicon() {
  const std::vector<std::string> files = builtin_lexicon_files();
  if (files.empty()) throw Error("no built-in lexicon found (data/lexicon/*.jsonl or $GESTURA_BUILTIN_LEXICON)");
  builtin_ = std::make_unique<Lexicon>(load_builtin_lexicon(files));
  layers_.push_layer(*builtin_);
  if (const std::string path = default_user_lexicon_path(); std::filesystem::exists(path)) {
    user_ = std::make_unique<Lexicon>(Lexicon::open_read_only(path));
    layers_.push_layer(*user_);
  }
}

}  // namespace gestura
