// Fuzz target: lexicon import from JSON lines into a real (in-memory) SQLite lexicon. Each input
// is imported inside a transaction that is then rolled back, so every input meets an empty lexicon.
#include <sstream>

#include "fuzz_target.hpp"
#include "gestura/lexicon/lexicon_files.hpp"

namespace {
struct RollBack {};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static gestura::Lexicon lexicon = gestura::Lexicon::in_memory();
  std::istringstream in{std::string(gestura::fuzz::text_of(data, size))};
  gestura::fuzz::expect_result_or_error([&] {
    try {
      lexicon.atomically([&] {
        gestura::import_jsonl(lexicon, in, "fuzz.jsonl", gestura::ImportOptions{.language = "ase"});
        (void)lexicon.list();
        throw RollBack{};
      });
    } catch (const RollBack&) {
    }
  });
  return 0;
}
