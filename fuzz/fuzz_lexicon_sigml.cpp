// Fuzz target: lexicon import of SiGML documents into a real (in-memory) SQLite lexicon, rolled
// back after each input; then the export of what was imported.
#include <sstream>

#include "fuzz_target.hpp"
#include "gestura/lexicon/lexicon_files.hpp"

namespace {
struct RollBack {};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static gestura::Lexicon lexicon = gestura::Lexicon::in_memory();
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] {
    try {
      lexicon.atomically([&] {
        gestura::import_sigml_text(lexicon, text, "fuzz.sigml", gestura::ImportOptions{.language = "ins"});
        std::ostringstream out;
        (void)gestura::export_sigml(lexicon.list(), out);
        throw RollBack{};
      });
    } catch (const RollBack&) {
    }
  });
  return 0;
}
