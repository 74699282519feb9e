#include "gestura/studio/sign_draft.hpp"

#include <sstream>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"

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

namespace {

// The symbols and non-manual tiers of a stored <hns_sign> element.
void read_sigml_notation(const SignEntry& entry, std::vector<std::string>& tokens, std::vector<DraftNonManual>& nonmanuals) {
  std::vector<sign::SigmlEntry> signs;
  try {
    signs = sign::read_sigml_entries(entry.notation, "sign '" + entry.gloss + "'");
  } catch (const Error& e) {
    throw Error("the SiGML of sign '" + entry.gloss + "' does not read (" + e.what() + "): it cannot be edited here");
  }
  if (signs.size() != 1) throw Error("the SiGML of sign '" + entry.gloss + "' holds " + std::to_string(signs.size()) + " signs, not one");
  const sign::SigmlEntry& one = signs.front();
  if (!one.sign) throw Error("the SiGML of sign '" + entry.gloss + "' does not parse (" + one.error->what() + ")");
  if (one.sign->gestural)
    throw Error("sign '" + entry.gloss + "' is written in gestural SiGML (<hamgestural_sign>): the notation editor edits HamNoSys symbols only");
  for (const sign::Symbol s : one.sign->symbols) tokens.emplace_back(sign::symbol_name(s));
  for (const NonManualTierInfo& t : nonmanual_tiers())
    for (const sign::NonManual& n : one.sign->nonmanual)
      if (n.tier == t.tier) nonmanuals.push_back({n.tier, n.value});
}

}  // namespace

SignDraft draft_from_entry(const SignEntry& entry, bool builtin) {
  if (entry.notation_kind == NotationKind::clip)
    throw Error("sign '" + entry.gloss + "' is a clip sign, not notation: open it in the timeline editor");
  SignDraft d;
  d.gloss = entry.gloss;
  d.language = entry.language;
  d.variant = entry.variant;
  std::vector<std::string> tokens;
  if (entry.notation_kind == NotationKind::sigml) {
    read_sigml_notation(entry, tokens, d.nonmanuals);
  } else {
    for (const sign::Symbol s : sign::symbols_from_unicode(entry.notation)) tokens.emplace_back(sign::symbol_name(s));
  }
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
  for (const DraftNonManual& n : draft.nonmanuals)
    if (const auto problem = nonmanual_value_problem(n.tier, n.value)) throw Error(*problem);
  SignEntry e;
  e.gloss = trimmed(draft.gloss);
  e.language = trimmed(draft.language);
  e.variant = draft.variant;
  if (draft.nonmanuals.empty()) {
    e.notation_kind = NotationKind::hamnosys;
    for (const sign::Symbol s : sign::symbols_from_names(draft.names)) utf8::append(e.notation, sign::symbol_info(s).codepoint);
  } else {
    e.notation_kind = NotationKind::sigml;
    SignDraft named = draft;
    named.gloss = e.gloss;
    e.notation = hns_sign_xml(named);
  }
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

std::string hns_sign_xml(const SignDraft& draft) {
  pugi::xml_document doc;
  pugi::xml_node sign = doc.append_child("hns_sign");
  sign.append_attribute("gloss") = draft.gloss.c_str();
  if (!draft.nonmanuals.empty()) {
    pugi::xml_node tiers = sign.append_child("hamnosys_nonmanual");
    for (const DraftNonManual& n : draft.nonmanuals) {
      const std::string element(tier_info(n.tier).element);
      tiers.append_child(element.c_str())
          .append_attribute(n.tier == sign::NonManualTier::mouth_picture ? "picture" : "tag") = n.value.c_str();
    }
  }
  pugi::xml_node manual = sign.append_child("hamnosys_manual");
  for (const sign::Symbol s : sign::symbols_from_names(draft.names)) manual.append_child(std::string(sign::symbol_name(s)).c_str());
  std::ostringstream out;
  sign.print(out, "", pugi::format_raw);
  return out.str();
}

nlohmann::json to_json(const SignDraft& d) {
  nlohmann::json j{{"gloss", d.gloss},       {"lang", d.language}, {"variant", d.variant}, {"names", d.names},
                   {"keywords", d.keywords}, {"meaning", d.meaning}, {"source", d.source},   {"licence", d.licence},
                   {"agreement", to_string(d.agreement)}, {"from_builtin", d.from_builtin}};
  auto& tiers = j["nonmanuals"] = nlohmann::json::array();
  for (const DraftNonManual& n : d.nonmanuals) tiers.push_back({{"tier", tier_info(n.tier).key}, {"value", n.value}});
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
  if (const auto t = j.find("nonmanuals"); t != j.end() && !t->is_null()) {
    if (!t->is_array()) throw Error("draft field 'nonmanuals' is not a list");
    for (const nlohmann::json& n : *t) {
      if (!n.is_object()) throw Error("a draft's non-manual is an object {\"tier\", \"value\"}");
      const std::string key = string_of(n, "tier");
      const auto tier = tier_from_key(key);
      if (!tier) throw Error("draft non-manual tier '" + key.substr(0, 40) + "' is not a tier");
      d.nonmanuals.push_back({*tier, string_of(n, "value")});
    }
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
