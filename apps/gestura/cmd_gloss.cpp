// gestura gloss "TEXT" — English to ASL glosses, with the reason for every word.
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace {

using gestura::Error;

constexpr const char* kUsage = R"(usage: gestura gloss "TEXT" [--json] [--lang L] [--db PATH] [--open]

Translates English text to a sequence of ASL glosses and prints why each word became what it became.
Signs come from the lexicon (built-in data/lexicon/*.jsonl plus the user lexicon, see gestura lexicon
--help); words without a sign are fingerspelled. When there is no lexicon at all, or with --open,
every word is taken as signable and its gloss is the word's lemma in capitals.
  --json     machine-readable output: glosses (gloss, kind, span, letters, reason), notes, sentences,
             markers (non-manual spans over gloss indices)
  --lang L   sign language of the lexicon lookups (default ase))";

nlohmann::json to_json(const gestura::Translation& t) {
  nlohmann::json out;
  out["text"] = t.text();
  auto& glosses = out["glosses"] = nlohmann::json::array();
  for (const auto& g : t.glosses) {
    nlohmann::json j{{"gloss", g.gloss}, {"kind", gestura::to_string(g.kind)}, {"begin", g.begin}, {"end", g.end},
                     {"reason", g.reason}};
    if (!g.letters.empty()) j["letters"] = g.letters;
    glosses.push_back(std::move(j));
  }
  auto& notes = out["notes"] = nlohmann::json::array();
  for (const auto& n : t.notes) notes.push_back({{"word", n.word}, {"begin", n.begin}, {"end", n.end}, {"reason", n.reason}});
  auto& sentences = out["sentences"] = nlohmann::json::array();
  for (const auto& s : t.sentences)
    sentences.push_back({{"type", gestura::to_string(s.type)}, {"negated", s.negated}, {"first", s.first},
                         {"last", s.last}, {"begin", s.begin}, {"end", s.end}});
  auto& markers = out["markers"] = nlohmann::json::array();
  for (const auto& m : t.markers)
    markers.push_back({{"kind", gestura::to_string(m.kind)}, {"first", m.first}, {"last", m.last}});
  return out;
}

int run(const std::vector<std::string>& args) {
  std::optional<std::string> text;
  std::string lang = "ase", db;
  bool json = false, open = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--json") json = true;
    else if (args[i] == "--open") open = true;
    else if (args[i] == "--lang") lang = gestura::cli::flag_value(args, i);
    else if (args[i] == "--db") db = gestura::cli::flag_value(args, i);
    else if (args[i].rfind("--", 0) == 0) throw Error("unknown flag " + args[i] + " (see gestura gloss --help)");
    else if (text) throw Error("give the text as one argument (quote it)");
    else text = args[i];
  }
  if (!text) throw Error("missing TEXT (see gestura gloss --help)");

  std::optional<gestura::Lexicon> builtin, user;
  gestura::LayeredLexicon layers;
  if (!open) {
    if (const auto files = gestura::builtin_lexicon_files(); !files.empty()) {
      builtin.emplace(gestura::load_builtin_lexicon(files));
      layers.push_layer(*builtin);
    }
    const std::string path = db.empty() ? gestura::default_user_lexicon_path() : db;
    if (!db.empty() && !std::filesystem::exists(path)) throw Error(gestura::SourceLocation{path}, "no such lexicon");
    if (std::filesystem::exists(path)) {
      user.emplace(gestura::Lexicon::open_read_only(path));
      layers.push_layer(*user);
    }
  }
  const bool have_signs = !layers.list(lang).empty();
  std::unique_ptr<gestura::SignInventory> inventory;
  if (have_signs) inventory = std::make_unique<gestura::LexiconInventory>(layers, lang);
  else inventory = std::make_unique<gestura::OpenVocabulary>();

  const gestura::Translation t = gestura::translate_to_gloss(*text, *inventory);
  if (json) {
    std::cout << to_json(t).dump(2) << "\n";
    return 0;
  }
  std::cout << t.text() << "\n\n";
  if (!have_signs) std::cout << "(no " << lang << " lexicon found: open vocabulary, every word taken as a sign)\n";
  // Words of one phrase share their reason; print it once.
  for (std::size_t k = 0; k < t.notes.size(); ++k)
    if (k == 0 || t.notes[k].reason != t.notes[k - 1].reason) std::cout << "  " << t.notes[k].reason << "\n";
  for (const auto& m : t.markers) {
    std::cout << "  " << gestura::to_string(m.kind) << " marking over:";
    for (std::size_t k = m.first; k < m.last; ++k) std::cout << " " << t.glosses[k].gloss;
    std::cout << "\n";
  }
  return 0;
}

gestura::cli::Registration reg{{"gloss", "translate English text to ASL glosses, explaining each word", kUsage, run}};

}  // namespace
