#pragma once
// Where the shared test data lives: $GESTURA_SHARED_DATA when set (worktrees outside the project
// root), else the path fixed at configure time.
#include <cstdlib>
#include <string>

#include "support/build_paths.hpp"

namespace gestura::test {

inline std::string shared_data() {
  if (const char* env = std::getenv("GESTURA_SHARED_DATA"); env && *env) return env;
  return configured_shared_data();
}

}  // namespace gestura::test
