#include "gestura/app/gloss.hpp"

#include <filesystem>
#include <memory>
#include <optional>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace gestura::app {

void validate(const GlossRequest& request) {
  check_fields(request);
  if (request.text.size() > kMaxGlossBytes)
    throw AppError(ErrorCategory::too_large, Place{"text", {}},
                   std::to_string(request.text.size()) + " bytes of text; gloss translates at most " +
                       std::to_string(kMaxGlossBytes) + " bytes per call");
}

GlossResult run(const GlossRequest& request, const RunContext&) {
  validate(request);
  std::optional<Lexicon> builtin, user;
  LayeredLexicon layers;
  if (!request.open) {
    if (const auto files = builtin_lexicon_files(); !files.empty()) {
      builtin.emplace(load_builtin_lexicon(files));
      layers.push_layer(*builtin);
    }
    const std::string path = request.db.empty() ? default_user_lexicon_path() : request.db;
    if (!request.db.empty() && !std::filesystem::exists(path)) throw AppError(ErrorCategory::not_found, Place{"db", {path}}, "no such lexicon");
    if (std::filesystem::exists(path)) {
      user.emplace(Lexicon::open_read_only(path));
      layers.push_layer(*user);
    }
  }
  GlossResult result;
  result.lang = request.lang;
  result.have_signs = !layers.list(request.lang).empty();
  std::unique_ptr<SignInventory> inventory;
  if (result.have_signs) inventory = std::make_unique<LexiconInventory>(layers, request.lang);
  else inventory = std::make_unique<OpenVocabulary>();
  result.translation = as_field_error(ErrorCategory::input, "text", [&] { return translate_to_gloss(request.text, *inventory); });
  return result;
}

nlohmann::json to_json(const GlossResult& result) {
  const Translation& t = result.translation;
  nlohmann::json out;
  out["text"] = t.text();
  auto& glosses = out["glosses"] = nlohmann::json::array();
  for (const auto& g : t.glosses) {
    nlohmann::json j{{"gloss", g.gloss}, {"kind", to_string(g.kind)}, {"begin", g.begin}, {"end", g.end}, {"reason", g.reason}};
    if (!g.letters.empty()) j["letters"] = g.letters;
    // Spatial grammar (docs/grammar.md): the lexicon sign and the places it is signed at.
    if (!g.lexeme.empty()) j["sign"] = g.lexeme;
    if (g.at) j["at"] = g.at.name();
    if (g.from && g.to) j["from"] = g.from.name(), j["to"] = g.to.name();
    if (!g.over.empty()) {
      auto& over = j["over"] = nlohmann::json::array();
      for (const Locus& l : g.over) over.push_back(l.name());
    }
    glosses.push_back(std::move(j));
  }
  auto& notes = out["notes"] = nlohmann::json::array();
  for (const auto& n : t.notes) notes.push_back({{"word", n.word}, {"begin", n.begin}, {"end", n.end}, {"reason", n.reason}});
  auto& sentences = out["sentences"] = nlohmann::json::array();
  for (const auto& s : t.sentences)
    sentences.push_back({{"type", to_string(s.type)}, {"negated", s.negated}, {"first", s.first}, {"last", s.last},
                         {"begin", s.begin}, {"end", s.end}, {"parse", s.parse}});
  auto& markers = out["markers"] = nlohmann::json::array();
  for (const auto& m : t.markers) markers.push_back({{"kind", to_string(m.kind)}, {"first", m.first}, {"last", m.last}});
  auto& shifts = out["role_shifts"] = nlohmann::json::array();
  for (const auto& r : t.role_shifts) shifts.push_back({{"toward", r.toward.name()}, {"first", r.first}, {"last", r.last}});
  return out;
}

}  // namespace gestura::app
