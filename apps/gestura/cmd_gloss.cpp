// gestura gloss "TEXT" — English to ASL glosses, with the reason for every word (app/gloss.hpp).
#include <iostream>
#include <memory>

#include "command.hpp"
#include "gestura/app/gloss.hpp"
#include "gestura/app/input_file.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  struct State {
    app::GlossRequest request;
    std::string file;
    bool json = false;
  };
  auto state = std::make_shared<State>();
  Invocation invocation;
  invocation.fields = bind_fields(state->request);
  invocation.fields.push_back(option({.name = "file", .help = "read TEXT from this file ('-': standard input)", .value = "FILE", .short_flag = 'f'}, state->file));
  invocation.fields.push_back(flag({.name = "json", .help = "machine-readable output: glosses (gloss, kind, span, letters, reason, places), notes, sentences, markers, role shifts"}, state->json));
  invocation.run = [state](const app::RunContext& context) {
    state->request.text = text_argument(state->request.text, state->file, app::kMaxTextInputBytes);
    const app::GlossResult r = app::run(state->request, context);
    if (state->json) {
      std::cout << app::to_json(r).dump(2) << "\n";
      return 0;
    }
    const Translation& t = r.translation;
    std::cout << t.text() << "\n\n";
    if (!r.have_signs) std::cout << "(no " << r.lang << " lexicon found: open vocabulary, every word taken as a sign)\n";
    for (const Sentence& s : t.sentences)
      if (!s.parse.empty()) std::cout << "  parse: " << s.parse << "\n";
    // Words of one phrase share their reason; print it once.
    for (std::size_t k = 0; k < t.notes.size(); ++k)
      if (k == 0 || t.notes[k].reason != t.notes[k - 1].reason) std::cout << "  " << t.notes[k].reason << "\n";
    for (const auto& m : t.markers) {
      std::cout << "  " << to_string(m.kind) << " marking over:";
      for (std::size_t k = m.first; k < m.last; ++k) std::cout << " " << t.glosses[k].gloss;
      std::cout << "\n";
    }
    for (const auto& r : t.role_shifts) {
      std::cout << "  role shift toward " << r.toward.name() << " (shoulders, head and eyes) over:";
      for (std::size_t k = r.first; k < r.last; ++k) std::cout << " " << t.glosses[k].gloss;
      std::cout << "\n";
    }
    return 0;
  };
  return invocation;
}

const Registration reg{{"gloss", "translate English text to ASL glosses, explaining each word",
                        "Translates English text to a sequence of ASL glosses and prints why each word became what it\n"
                        "became. Signs come from the lexicon (built-in data/lexicon/*.jsonl plus the user lexicon, see\n"
                        "gestura lexicon --help); words without a sign are fingerspelled. When there is no lexicon at\n"
                        "all, or with --open, every word is taken as signable and its gloss is the word's lemma in\n"
                        "capitals. TEXT '-' (or --file -) reads standard input; at most 4 MiB of text.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
