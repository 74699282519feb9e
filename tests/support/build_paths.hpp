#pragma once
// Paths fixed when the build is configured: the checkout, the shared test data beside it, the CLI binary.
// They are compiled into one source file only, so that no other test object depends on where the checkout
// lies (a compiler cache can then share objects between checkouts).
#include <string>

namespace gestura::test {

const std::string& source_dir();           // the checkout's root
const std::string& configured_shared_data();  // ../shared/data beside the checkout
const std::string& cli_path();             // the gestura binary under test

}  // namespace gestura::test
