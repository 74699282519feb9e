// Fuzz target: the studio's recovery file (the draft autosaved beside the user lexicon, offered back
// after a crash): parse_recovery, then what the studio does with a recovered draft — find where its
// notation fails, turn it into a lexicon row — and the rule that a draft survives its own save:
// written by to_json it reads back equal (else abort: a finding).
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "fuzz_target.hpp"
#include "gestura/studio/recovery.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gestura;
  const std::string_view text = fuzz::text_of(data, size);
  fuzz::expect_result_or_error([&] {
    const studio::SignDraft draft = studio::parse_recovery(text, "fuzz.studio-draft.json");
    nlohmann::json saved = nlohmann::json::object();
    saved["draft"] = studio::to_json(draft);
    try {
      if (!(studio::parse_recovery(saved.dump(), "saved.json") == draft)) std::abort();
    } catch (const Error&) {
      std::abort();  // a draft that was read must read back after it is saved
    }
    (void)studio::notation_error(draft);
    (void)studio::to_entry(draft);
  });
  return 0;
}
