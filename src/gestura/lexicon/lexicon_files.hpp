#pragma once
// Moving lexicon entries in and out of files.
//
// JSON lines: one entry per line, e.g.
//   {"gloss":"HOUSE","lang":"ase","variant":1,"hamnosys":"…","keywords":["house","home"],
//    "source":"my notes","licence":"CC0-1.0"}
// An agreement verb adds "agreement":"forward" (or "backward"; "none", the default, is not written).
// The notation is one of "hamnosys" (text), "sigml" (one <hns_sign> element as text) or
// "clip_base64". "keywords" is a list of words or of {"word","lang","meaning"} objects (lang defaults
// to eng), or one comma-separated string. Blank lines are skipped. Unknown fields are ignored. A gloss
// repeated in one file without "variant" fields takes variants 1, 2, 3... in file order.
//
// SiGML: a <sigml> document with many <hns_sign gloss="…"> elements; each element is stored verbatim
// as the notation text (kind sigml) and its gloss, lowercased with '_' read as a space, becomes an
// English keyword.
//
// An import is one transaction: an error anywhere (reported with the file and line) stores nothing
// from that file and leaves what was committed before untouched, unless ImportOptions::skip_bad
// takes the bad lines (then every good line is stored and each bad one reported).
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <span>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "gestura/core/error.hpp"

#include "gestura/lexicon/lexicon.hpp"

namespace gestura {

struct ImportOptions {
  std::string language;  // sign language for entries that name none (required for SiGML)
  std::string source;    // fills entries without a source; defaults to the file name
  std::string licence;   // fills entries without a licence
  OnConflict on_conflict = OnConflict::replace;  // re-importing a file updates its entries
  // Runs on every entry before it is stored and throws gestura::Error to refuse it (e.g. notation
  // that does not parse). The lexicon itself does not read notation, so the caller supplies this.
  std::function<void(const SignEntry&)> check;
  // When set, a bad line (bad JSON, a missing field, an entry `check` refuses) is handed to this
  // with its file and line and skipped; when empty the first bad line fails the whole import.
  std::function<void(const Error&)> skip_bad;
};

// Parses one JSON object into an entry (no database involved). Throws gestura::Error.
SignEntry entry_from_json(const nlohmann::json& object, const ImportOptions& options = {});
nlohmann::json entry_to_json(const SignEntry& entry);

std::size_t import_jsonl(Lexicon& lexicon, std::istream& in, const std::string& name,
                         const ImportOptions& options = {});
std::size_t import_jsonl(Lexicon& lexicon, const std::string& path, const ImportOptions& options = {});
void export_jsonl(std::span<const SignEntry> entries, std::ostream& out);

std::size_t import_sigml(Lexicon& lexicon, const std::string& path, const ImportOptions& options);
// The same from a document in memory; `name` stands for the file in errors.
std::size_t import_sigml_text(Lexicon& lexicon, std::string_view text, const std::string& name,
                              const ImportOptions& options);
// Writes the SiGML-notated entries as one <sigml> document; returns how many were written (HamNoSys
// and clip entries are skipped: converting them is not a lexicon concern).
std::size_t export_sigml(std::span<const SignEntry> entries, std::ostream& out);

// The <hns_sign> element of `gloss` in a SiGML file as text (the only element when the file has one).
std::string read_sigml_sign(const std::string& path, std::string_view gloss);

// Imports by extension: .sigml / .xml as SiGML, anything else as JSON lines.
std::size_t import_file(Lexicon& lexicon, const std::string& path, const ImportOptions& options);
// Exports by extension: .sigml as SiGML (SiGML entries only), anything else as JSON lines; returns
// how many entries were written. All or nothing: the file is written to a temporary, every write
// checked, then renamed into place, so a full disk leaves no file and reports an error.
std::size_t export_file(std::span<const SignEntry> entries, const std::string& path);

// The built-in lexicon: an in-memory database filled from JSON-lines files shipped in data/lexicon/
// (one per sign language, e.g. ase.jsonl), so it is never written to and costs no disk state.
Lexicon load_builtin_lexicon(const std::string& jsonl_path);
Lexicon load_builtin_lexicon(std::span<const std::string> jsonl_paths);
// The .jsonl files of data/lexicon/ in the source tree, or of $GESTURA_BUILTIN_LEXICON (a file or a
// directory) when set; empty when there are none.
std::vector<std::string> builtin_lexicon_files();

// Where the user's own lexicon lives: $GESTURA_LEXICON when set, else
// $XDG_DATA_HOME/gestura/lexicon.sqlite, else ~/.local/share/gestura/lexicon.sqlite.
std::string default_user_lexicon_path();

}  // namespace gestura
