#pragma once
// A note or warning a request produced on its way to a result (a word fingerspelled because the
// lexicon lacks it, a non-manual value that could not be performed). Results carry them; the CLI
// prints them on stderr, the server returns them with the result.
#include <string>
#include <vector>

#include "gestura/core/error.hpp"

namespace gestura::app {

struct Notice {
  enum class Level { note, warning };
  Level level = Level::note;
  SourceLocation where;
  std::string message;

  // "note: MESSAGE" / "warning: file:line: MESSAGE"
  std::string text() const;
};

inline Notice note(std::string message) { return {Notice::Level::note, {}, std::move(message)}; }
inline Notice warning(std::string message, SourceLocation where = {}) {
  return {Notice::Level::warning, std::move(where), std::move(message)};
}

}  // namespace gestura::app
