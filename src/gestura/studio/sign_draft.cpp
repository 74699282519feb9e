#include "gestura/studio/sign_draft.hpp"

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/sign/hamnosys_parser.hpp"

namespace gestura::studio {
namespace {

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == ',')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == ',')) s.remove_suffix(1);
  return std::string(s);
}

std::string keywords_text(const std::vector<Keyword>& keywords) {
  std::string out;
  for (const Keyword& k : keywords) {
    if (k.language != "eng") continue;
    if (!out.empty()) out += ", ";
    out += k.word;
  }
  return out;
}

std::string string_of(const nlohmann::json& json, const char* key) {
  const auto it = json.find(key);
  if (it == json.end() || it->is_null()) return {};
  if (!it->is_string()) throw Error(std::string("draft field '") + key + "' is not text");
  return it->get<std::string>();
}

}  // namespace

EntryKey key_of(const SignEntry& entry) { return {entry.gloss, entry.language, entry.variant}; }

SignDraft draft_from_entry(const SignEntry& entry, bool builtin) {
  if (entry.notation_kind != NotationKind::hamnosys)
    throw Error("sign '" + entry.gloss + "' is written in " + std::string(to_string(entry.notation_kind)) +
                ", not HamNoSys: the notation editor edits HamNoSys signs only");
  SignDraft d;
  d.gloss = entry.gloss;
  d.language = entry.language;
  d.variant = entry.variant;
  std::vector<std::string> tokens;
  for (const sign::Symbol s : sign::symbols_from_unicode(entry.notation)) tokens.emplace_back(sign::symbol_name(s));
  d.names = join_names(tokens);
  d.keywords = keywords_text(entry.keywords);
  for (const Keyword& k : entry.keywords)
    if (!k.meaning.empty()) {
      d.meaning = k.meaning;
      break;
    }
  d.source = entry.source;
  d.licence = entry.licence;
  d.agreement = entry.agreement;
  d.origin = key_of(entry);
  d.from_builtin = builtin;
  return d;
}

std::vector<std::string> name_tokens(std::string_view names) {
  std::vector<std::string> out;
  std::string token;
  for (const char c : names) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      if (!token.empty()) out.push_back(std::move(token)), token.clear();
    } else {
      token += c;
    }
  }
  if (!token.empty()) out.push_back(std::move(token));
  return out;
}

std::string join_names(const std::vector<std::string>& tokens) {
  std::string out;
  for (const std::string& t : tokens) {
    if (!out.empty()) out += ',';
    out += t;
  }
  return out;
}

std::optional<NotationError> notation_error(const SignDraft& draft) {
  if (name_tokens(draft.names).empty()) return NotationError{-1, "no notation: add a handshape from the palette"};
  try {
    sign::parse_hamnosys_names(draft.names);
    return std::nullopt;
  } catch (const Error& e) {
    return NotationError{e.where().index, e.message()};
  }
}

SignEntry to_entry(const SignDraft& draft) {
  if (trimmed(draft.gloss).empty()) throw Error("the sign has no gloss");
  if (trimmed(draft.language).empty()) throw Error("the sign has no sign language");
  if (const auto error = notation_error(draft)) throw Error(SourceLocation{.index = error->symbol}, error->message);
  SignEntry e;
  e.gloss = trimmed(draft.gloss);
  e.language = trimmed(draft.language);
  e.variant = draft.variant;
  e.notation_kind = NotationKind::hamnosys;
  for (const sign::Symbol s : sign::symbols_from_names(draft.names)) utf8::append(e.notation, sign::symbol_info(s).codepoint);
  bool first = true;
  std::string word;
  auto flush = [&] {
    const std::string w = trimmed(word);
    if (!w.empty()) e.keywords.push_back(Keyword{w, "eng", first ? trimmed(draft.meaning) : std::string()}), first = false;
    word.clear();
  };
  for (const char c : draft.keywords) {
    if (c == ',') flush();
    else word += c;
  }
  flush();
  e.source = draft.source;
  e.licence = draft.licence;
  e.agreement = draft.agreement;
  return e;
}

nlohmann::json to_json(const SignDraft& d) {
  nlohmann::json j{{"gloss", d.gloss},       {"lang", d.language}, {"variant", d.variant}, {"names", d.names},
                   {"keywords", d.keywords}, {"meaning", d.meaning}, {"source", d.source},   {"licence", d.licence},
                   {"agreement", to_string(d.agreement)}, {"from_builtin", d.from_builtin}};
  if (d.origin) j["origin"] = {{"gloss", d.origin->gloss}, {"lang", d.origin->language}, {"variant", d.origin->variant}};
  return j;
}

SignDraft draft_from_json(const nlohmann::json& j) {
  if (!j.is_object()) throw Error("a draft is a JSON object");
  SignDraft d;
  d.gloss = string_of(j, "gloss");
  d.language = string_of(j, "lang");
  d.names = string_of(j, "names");
  d.keywords = string_of(j, "keywords");
  d.meaning = string_of(j, "meaning");
  d.source = string_of(j, "source");
  d.licence = string_of(j, "licence");
  d.agreement = agreement_from_string(string_of(j, "agreement"));
  if (const auto v = j.find("variant"); v != j.end()) {
    if (!v->is_number_integer() || v->get<long long>() < 1 || v->get<long long>() > 1000000)
      throw Error("draft field 'variant' must be a whole number from 1");
    d.variant = v->get<int>();
  }
  if (const auto b = j.find("from_builtin"); b != j.end() && b->is_boolean()) d.from_builtin = b->get<bool>();
  if (const auto o = j.find("origin"); o != j.end() && o->is_object()) {
    EntryKey k{string_of(*o, "gloss"), string_of(*o, "lang"), 1};
    if (const auto v = o->find("variant"); v != o->end() && v->is_number_integer()) k.variant = v->get<int>();
    d.origin = k;
  }
  return d;
}

}  // namespace gestura::studio
