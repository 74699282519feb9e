// The programs tests start (gestura say, serve, worker) would keep the signs they solve in the
// user's own lexicon (app/workspace.hpp, user_citation_store). Nothing a test runs may write
// there: turned off for this process and every child, before any test starts. A test that wants
// the store gives its own GESTURA_LEXICON and GESTURA_CITATION_CACHE=on (a later assignment wins).
#include <cstdlib>

namespace {

[[maybe_unused]] const bool kUserCitationStoreOff = [] {
  ::setenv("GESTURA_CITATION_CACHE", "off", 1);
  return true;
}();

}  // namespace
