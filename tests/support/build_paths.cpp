#include "support/build_paths.hpp"

namespace gestura::test {

const std::string& source_dir() {
  static const std::string path = GESTURA_SOURCE_DIR;
  return path;
}

const std::string& configured_shared_data() {
  static const std::string path = GESTURA_SHARED_DATA;
  return path;
}

const std::string& cli_path() {
  static const std::string path = GESTURA_CLI;
  return path;
}

}  // namespace gestura::test
