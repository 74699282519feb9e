#include "gestura/lexicon/lexicon_files.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <optional>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {

namespace {

constexpr std::string_view kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64_encode(const std::vector<std::uint8_t>& bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = std::uint32_t{bytes[i]} << 16;
    if (n > 1) v |= std::uint32_t{bytes[i + 1]} << 8;
    if (n > 2) v |= bytes[i + 2];
    for (std::size_t k = 0; k < 4; ++k) out.push_back(k <= n ? kBase64[(v >> (18 - 6 * k)) & 63] : '=');
  }
  return out;
}

std::vector<std::uint8_t> base64_decode(std::string_view text) {
  std::vector<std::uint8_t> out;
  std::uint32_t v = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    const auto pos = kBase64.find(c);
    if (pos == std::string_view::npos) throw Error("clip_base64 has a character outside base64");
    v = (v << 6) | static_cast<std::uint32_t>(pos);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>((v >> bits) & 0xff));
    }
  }
  return out;
}

std::string string_field(const nlohmann::json& o, const char* key) {
  const auto it = o.find(key);
  if (it == o.end() || it->is_null()) return {};
  if (!it->is_string()) throw Error(std::string("field '") + key + "' must be a string");
  return it->get<std::string>();
}

std::string trimmed(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::vector<Keyword> keywords_from_json(const nlohmann::json& value) {
  std::vector<Keyword> out;
  if (value.is_null()) return out;
  if (value.is_string()) {
    std::stringstream list(value.get<std::string>());
    for (std::string word; std::getline(list, word, ',');)
      if (auto w = trimmed(word); !w.empty()) out.push_back(Keyword{w});
    return out;
  }
  if (!value.is_array()) throw Error("field 'keywords' must be a list or a comma-separated string");
  for (const auto& k : value) {
    if (k.is_string()) {
      out.push_back(Keyword{k.get<std::string>()});
    } else if (k.is_object()) {
      Keyword kw{string_field(k, "word")};
      if (auto lang = string_field(k, "lang"); !lang.empty()) kw.language = lang;
      kw.meaning = string_field(k, "meaning");
      out.push_back(std::move(kw));
    } else {
      throw Error("each keyword must be a string or an object with 'word'");
    }
  }
  return out;
}

SourceLocation at(const std::string& file, int line) { return SourceLocation{file, line}; }

// 1-based line of a byte offset into `text`.
int line_of(std::string_view text, std::ptrdiff_t offset) {
  const auto end = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(offset, 0, std::ssize(text)));
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

SignEntry entry_from_json(const nlohmann::json& o, const ImportOptions& options) {
  if (!o.is_object()) throw Error("expected a JSON object per line");
  SignEntry e;
  e.gloss = string_field(o, "gloss");
  if (e.gloss.empty()) throw Error("entry has no 'gloss'");
  e.language = string_field(o, "lang");
  if (e.language.empty()) e.language = options.language;
  if (e.language.empty()) throw Error("entry '" + e.gloss + "' has no 'lang' (and no default language was given)");
  if (const auto v = o.find("variant"); v != o.end()) {
    if (!v->is_number_integer() || v->get<long long>() < 1 || v->get<long long>() > 1000000)
      throw Error("field 'variant' must be a whole number from 1");
    e.variant = v->get<int>();
  }
  const std::string hamnosys = string_field(o, "hamnosys");
  const std::string sigml = string_field(o, "sigml");
  const std::string clip = string_field(o, "clip_base64");
  const int notations = !hamnosys.empty() + !sigml.empty() + !clip.empty();
  if (notations != 1)
    throw Error("entry '" + e.gloss + "' needs exactly one of 'hamnosys', 'sigml', 'clip_base64' (has " +
                std::to_string(notations) + ")");
  if (!hamnosys.empty()) {
    e.notation_kind = NotationKind::hamnosys;
    e.notation = hamnosys;
  } else if (!sigml.empty()) {
    e.notation_kind = NotationKind::sigml;
    e.notation = sigml;
  } else {
    e.notation_kind = NotationKind::clip;
    e.clip = base64_decode(clip);
  }
  if (const auto k = o.find("keywords"); k != o.end()) e.keywords = keywords_from_json(*k);
  e.source = string_field(o, "source");
  if (e.source.empty()) e.source = options.source;
  e.licence = string_field(o, "licence");
  if (e.licence.empty()) e.licence = options.licence;
  e.agreement = agreement_from_string(string_field(o, "agreement"));
  return e;
}

nlohmann::json entry_to_json(const SignEntry& e) {
  nlohmann::json o;
  o["gloss"] = e.gloss;
  o["lang"] = e.language;
  o["variant"] = e.variant;
  switch (e.notation_kind) {
    case NotationKind::hamnosys: o["hamnosys"] = e.notation; break;
    case NotationKind::sigml: o["sigml"] = e.notation; break;
    case NotationKind::clip: o["clip_base64"] = base64_encode(e.clip); break;
  }
  auto keywords = nlohmann::json::array();
  for (const Keyword& k : e.keywords) {
    if (k.language == "eng" && k.meaning.empty())
      keywords.push_back(k.word);
    else
      keywords.push_back({{"word", k.word}, {"lang", k.language}, {"meaning", k.meaning}});
  }
  o["keywords"] = std::move(keywords);
  o["source"] = e.source;
  o["licence"] = e.licence;
  if (e.agreement != Agreement::none) o["agreement"] = to_string(e.agreement);
  return o;
}

std::size_t import_jsonl(Lexicon& lexicon, std::istream& in, const std::string& name, const ImportOptions& options) {
  std::size_t count = 0;
  std::map<std::string, int> occurrences;  // language + gloss → entries so far in this file
  lexicon.atomically([&] {
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      if (trimmed(line).empty()) continue;
      std::optional<Error> bad;
      try {
        const auto object = nlohmann::json::parse(line);
        SignEntry entry = entry_from_json(object, options);
        // A gloss the file repeats without naming variants is a homonym (another sign with the same
        // gloss), not a correction: it becomes the next variant instead of replacing the first.
        const int seen = ++occurrences[entry.language + '\n' + entry.gloss];
        if (!object.contains("variant")) entry.variant = seen;
        if (options.check) options.check(entry);
        lexicon.add(std::move(entry), options.on_conflict);
      } catch (const nlohmann::json::exception& e) {
        bad.emplace(at(name, line_number), std::string("bad JSON: ") + e.what());
      } catch (const Error& e) {
        bad.emplace(at(name, line_number), e.what());
      }
      if (bad) {
        if (!options.skip_bad) throw *bad;
        options.skip_bad(*bad);
        continue;
      }
      ++count;
    }
    if (in.bad()) throw Error(SourceLocation{name}, "read error");
  });
  return count;
}

std::size_t import_jsonl(Lexicon& lexicon, const std::string& path, const ImportOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot open file");
  ImportOptions with_source = options;
  if (with_source.source.empty()) with_source.source = std::filesystem::path(path).filename().string();
  return import_jsonl(lexicon, in, path, with_source);
}

void export_jsonl(std::span<const SignEntry> entries, std::ostream& out) {
  for (const SignEntry& e : entries) out << entry_to_json(e).dump() << '\n';
}

std::size_t import_sigml(Lexicon& lexicon, const std::string& path, const ImportOptions& options) {
  if (options.language.empty())
    throw Error(SourceLocation{path}, "SiGML files do not name their sign language; give one (e.g. --lang ins)");
  ImportOptions with_source = options;
  if (with_source.source.empty()) with_source.source = std::filesystem::path(path).filename().string();
  return import_sigml_text(lexicon, read_file(path), path, with_source);
}

std::size_t import_sigml_text(Lexicon& lexicon, std::string_view text, const std::string& path,
                              const ImportOptions& options) {
  if (options.language.empty())
    throw Error(SourceLocation{path}, "SiGML files do not name their sign language; give one (e.g. --lang ins)");
  pugi::xml_document doc;
  const auto parsed = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed)
    throw Error(at(path, line_of(text, parsed.offset)), std::string("bad XML: ") + parsed.description());
  const pugi::xml_node root = doc.child("sigml");
  if (!root) throw Error(SourceLocation{path}, "not a SiGML file: the root element must be <sigml>");
  const std::string source = options.source.empty() ? path : options.source;
  std::size_t count = 0;
  lexicon.atomically([&] {
    for (const pugi::xml_node sign : root.children("hns_sign")) {
      const std::ptrdiff_t offset = sign.offset_debug();  // its line is counted only for an error
      try {
        SignEntry e;
        e.gloss = sign.attribute("gloss").value();
        if (e.gloss.empty()) throw Error("<hns_sign> has no gloss attribute");
        e.language = options.language;
        e.notation_kind = NotationKind::sigml;
        std::ostringstream element;
        sign.print(element, "", pugi::format_raw);
        e.notation = element.str();
        std::string keyword = e.gloss;
        std::replace(keyword.begin(), keyword.end(), '_', ' ');
        e.keywords.push_back(Keyword{keyword});
        e.source = source;
        e.licence = options.licence;
        if (options.check) options.check(e);
        lexicon.add(std::move(e), options.on_conflict);
      } catch (const Error& e) {
        const Error bad(at(path, line_of(text, offset)), e.what());
        if (!options.skip_bad) throw bad;
        options.skip_bad(bad);
        continue;
      }
      ++count;
    }
  });
  return count;
}

std::size_t export_sigml(std::span<const SignEntry> entries, std::ostream& out) {
  pugi::xml_document doc;
  pugi::xml_node root = doc.append_child("sigml");
  std::size_t written = 0;
  for (const SignEntry& e : entries) {
    if (e.notation_kind != NotationKind::sigml) continue;
    pugi::xml_document element;
    if (!element.load_string(e.notation.c_str()) || !element.first_child())
      throw Error("stored SiGML of '" + e.gloss + "' is not well-formed XML");
    root.append_copy(element.first_child());
    ++written;
  }
  doc.save(out, "  ");
  return written;
}

std::string read_sigml_sign(const std::string& path, std::string_view gloss) {
  const std::string text = read_file(path);
  pugi::xml_document doc;
  const auto parsed = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed)
    throw Error(at(path, line_of(text, parsed.offset)), std::string("bad XML: ") + parsed.description());
  const pugi::xml_node root = doc.child("sigml");
  if (!root) throw Error(SourceLocation{path}, "not a SiGML file: the root element must be <sigml>");
  std::vector<pugi::xml_node> signs;
  for (const pugi::xml_node sign : root.children("hns_sign")) signs.push_back(sign);
  const auto named = std::find_if(signs.begin(), signs.end(),
                                  [&](const pugi::xml_node& n) { return gloss == n.attribute("gloss").value(); });
  pugi::xml_node chosen;
  if (named != signs.end())
    chosen = *named;
  else if (signs.size() == 1)
    chosen = signs.front();
  else
    throw Error(SourceLocation{path}, "no <hns_sign gloss=\"" + std::string(gloss) + "\"> among " +
                                          std::to_string(signs.size()) + " signs");
  std::ostringstream element;
  chosen.print(element, "", pugi::format_raw);
  return element.str();
}

std::size_t import_file(Lexicon& lexicon, const std::string& path, const ImportOptions& options) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".sigml" || ext == ".xml") return import_sigml(lexicon, path, options);
  return import_jsonl(lexicon, path, options);
}

std::size_t export_file(std::span<const SignEntry> entries, const std::string& path) {
  std::ostringstream out;
  const bool sigml = has_extension(path, ".sigml");
  const std::size_t count = sigml ? export_sigml(entries, out) : (export_jsonl(entries, out), entries.size());
  write_file_atomically(path, out.str());
  return count;
}

Lexicon load_builtin_lexicon(const std::string& jsonl_path) {
  return load_builtin_lexicon(std::span<const std::string>(&jsonl_path, 1));
}

Lexicon load_builtin_lexicon(std::span<const std::string> jsonl_paths) {
  Lexicon builtin = Lexicon::in_memory();
  ImportOptions options;
  options.source = "builtin";
  for (const std::string& path : jsonl_paths) import_jsonl(builtin, path, options);
  return builtin;
}

std::vector<std::string> builtin_lexicon_files() {
  const char* from_env = std::getenv("GESTURA_BUILTIN_LEXICON");
  const std::filesystem::path where =
      from_env && *from_env ? std::filesystem::path(from_env)
                            : std::filesystem::path(GESTURA_SOURCE_DIR) / "data" / "lexicon";
  std::vector<std::string> files;
  std::error_code ec;
  if (std::filesystem::is_regular_file(where, ec)) return {where.string()};
  for (const auto& item : std::filesystem::directory_iterator(where, ec))
    if (item.path().extension() == ".jsonl") files.push_back(item.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string default_user_lexicon_path() {
  if (const char* path = std::getenv("GESTURA_LEXICON"); path && *path) return path;
  if (const char* data = std::getenv("XDG_DATA_HOME"); data && *data)
    return (std::filesystem::path(data) / "gestura" / "lexicon.sqlite").string();
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw Error("cannot find the user lexicon: neither GESTURA_LEXICON nor HOME is set");
  return (std::filesystem::path(home) / ".local" / "share" / "gestura" / "lexicon.sqlite").string();
}

}  // namespace gestura
