// gestura lexicon — manage the user's sign lexicon (an SQLite file) on top of the built-in one.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"

namespace {

using gestura::Error;

constexpr const char* kUsage = R"(usage: gestura lexicon ACTION [ARGS] [--db PATH]

actions:
  list [--lang L]                       every sign (built-in and user), one per line
  show GLOSS [--lang L]                 all variants of GLOSS with notation and keywords
  search TEXT [--prefix] [--lang L]     glosses and keywords containing (or starting with) TEXT
  add --gloss G --lang L (--hamnosys S | --sigml FILE) [--keywords a,b] [--variant N]
      [--source S] [--licence L] [--replace]
  import FILE [--lang L] [--licence L]  .jsonl (one entry per line) or .sigml (needs --lang)
  export FILE [--lang L]                .jsonl (everything) or .sigml (SiGML entries only)
  remove GLOSS --lang L [--variant N]

The user lexicon is --db PATH, else $GESTURA_LEXICON, else $XDG_DATA_HOME/gestura/lexicon.sqlite,
else ~/.local/share/gestura/lexicon.sqlite (created on first write). Reading actions also show the
built-in lexicon (data/lexicon/*.jsonl, or $GESTURA_BUILTIN_LEXICON); user entries override built-in
ones with the same gloss and language. Sign languages are ISO 639-3 codes: ase, bfi, gsg, pso, ins, ...)";

struct Options {
  std::vector<std::string> positional;
  std::string db, lang, gloss, hamnosys, sigml_file, keywords, source, licence;
  std::optional<int> variant;
  bool prefix = false;
  bool replace = false;
};

int parse_variant(const std::string& text) {
  try {
    std::size_t used = 0;
    const int v = std::stoi(text, &used);
    if (used == text.size() && v >= 1) return v;
  } catch (const std::exception&) {
  }
  throw Error("--variant needs a whole number from 1, got '" + text + "'");
}

Options parse(const std::vector<std::string>& args) {
  Options o;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--db") o.db = gestura::cli::flag_value(args, i);
    else if (a == "--lang") o.lang = gestura::cli::flag_value(args, i);
    else if (a == "--gloss") o.gloss = gestura::cli::flag_value(args, i);
    else if (a == "--hamnosys") o.hamnosys = gestura::cli::flag_value(args, i);
    else if (a == "--sigml") o.sigml_file = gestura::cli::flag_value(args, i);
    else if (a == "--keywords") o.keywords = gestura::cli::flag_value(args, i);
    else if (a == "--source") o.source = gestura::cli::flag_value(args, i);
    else if (a == "--licence" || a == "--license") o.licence = gestura::cli::flag_value(args, i);
    else if (a == "--variant") o.variant = parse_variant(gestura::cli::flag_value(args, i));
    else if (a == "--prefix") o.prefix = true;
    else if (a == "--replace") o.replace = true;
    else if (a.rfind("--", 0) == 0) throw Error("unknown flag " + a + " (see gestura lexicon --help)");
    else o.positional.push_back(a);
  }
  return o;
}

std::string user_db_path(const Options& o) { return o.db.empty() ? gestura::default_user_lexicon_path() : o.db; }

gestura::Lexicon open_for_writing(const Options& o) {
  const std::filesystem::path path = user_db_path(o);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  return gestura::Lexicon::open(path.string());
}

const std::string& one_positional(const Options& o, const char* what) {
  if (o.positional.size() != 1) throw Error(std::string("expected one ") + what + " (see gestura lexicon --help)");
  return o.positional.front();
}

// The layers reading actions look through: built-in files (if any), then the user file (if it exists).
struct ReadView {
  std::optional<gestura::Lexicon> builtin, user;
  gestura::LayeredLexicon view;

  explicit ReadView(const Options& o) {
    if (const auto files = gestura::builtin_lexicon_files(); !files.empty()) {
      builtin.emplace(gestura::load_builtin_lexicon(files));
      view.push_layer(*builtin);
    }
    const std::string path = user_db_path(o);
    if (!o.db.empty() && !std::filesystem::exists(path)) throw Error(gestura::SourceLocation{path}, "no such lexicon");
    if (std::filesystem::exists(path)) {
      user.emplace(gestura::Lexicon::open_read_only(path));
      view.push_layer(*user);
    }
  }
};

std::string keyword_list(const gestura::SignEntry& e) {
  std::string out;
  for (const auto& k : e.keywords) {
    if (!out.empty()) out += ", ";
    out += k.word;
    if (k.language != "eng") out += " (" + k.language + ")";
    if (!k.meaning.empty()) out += " [" + k.meaning + "]";
  }
  return out;
}

void print_line(const gestura::SignEntry& e) {
  std::cout << e.gloss;
  if (e.variant > 1) std::cout << '#' << e.variant;
  std::cout << "\t" << e.language << "\t"
            << gestura::to_string(e.notation_kind) << "\t" << keyword_list(e) << "\n";
}

int run(const std::vector<std::string>& args) {
  if (args.empty()) throw Error("missing action (see gestura lexicon --help)");
  const std::string& action = args.front();
  const Options o = parse(args);

  if (action == "list") {
    ReadView r(o);
    for (const auto& e : r.view.list(o.lang)) print_line(e);
    return 0;
  }
  if (action == "show") {
    const std::string& gloss = one_positional(o, "GLOSS");
    ReadView r(o);
    const auto found = r.view.find_all(gloss, o.lang);
    if (found.empty()) throw Error("no sign '" + gloss + "'" + (o.lang.empty() ? "" : " in " + o.lang));
    for (const auto& e : found) {
      std::cout << e.gloss << " (" << e.language << ", variant " << e.variant << ")\n"
                << "  notation (" << gestura::to_string(e.notation_kind) << "): "
                << (e.notation_kind == gestura::NotationKind::clip ? std::to_string(e.clip.size()) + " bytes"
                                                                   : e.notation)
                << "\n  keywords: " << keyword_list(e) << "\n  source: " << e.source << "\n  licence: " << e.licence
                << "\n";
    }
    return 0;
  }
  if (action == "search") {
    const std::string& text = one_positional(o, "TEXT");
    ReadView r(o);
    for (const auto& e : r.view.search(text, o.prefix ? gestura::SearchMode::prefix : gestura::SearchMode::substring,
                                       o.lang))
      print_line(e);
    return 0;
  }
  if (action == "add") {
    if (o.gloss.empty() || o.lang.empty()) throw Error("add needs --gloss and --lang");
    if (o.hamnosys.empty() == o.sigml_file.empty()) throw Error("add needs exactly one of --hamnosys and --sigml");
    gestura::SignEntry e;
    e.gloss = o.gloss;
    e.language = o.lang;
    e.variant = o.variant.value_or(1);
    if (!o.hamnosys.empty()) {
      e.notation = o.hamnosys;
    } else {
      e.notation_kind = gestura::NotationKind::sigml;
      e.notation = gestura::read_sigml_sign(o.sigml_file, o.gloss);
    }
    std::stringstream list(o.keywords);
    for (std::string word; std::getline(list, word, ',');)
      if (!word.empty()) e.keywords.push_back(gestura::Keyword{word});
    e.source = o.source.empty() ? "gestura lexicon add" : o.source;
    e.licence = o.licence;
    auto lex = open_for_writing(o);
    lex.add(e, o.replace ? gestura::OnConflict::replace : gestura::OnConflict::fail);
    std::cout << "added " << e.gloss << " (" << e.language << ") to " << lex.path() << "\n";
    return 0;
  }
  if (action == "import") {
    const std::string& file = one_positional(o, "FILE");
    auto lex = open_for_writing(o);
    gestura::ImportOptions options;
    options.language = o.lang;
    options.licence = o.licence;
    options.source = o.source;
    const auto n = gestura::import_file(lex, file, options);
    std::cout << "imported " << n << " signs from " << file << " into " << lex.path() << "\n";
    return 0;
  }
  if (action == "export") {
    const std::string& file = one_positional(o, "FILE");
    const std::string path = user_db_path(o);
    if (!std::filesystem::exists(path)) throw Error(gestura::SourceLocation{path}, "no such lexicon");
    auto lex = gestura::Lexicon::open_read_only(path);
    const auto entries = lex.list(o.lang);
    const bool sigml = std::filesystem::path(file).extension() == ".sigml";
    const auto n = gestura::export_file(entries, file);
    std::cout << "exported " << n << " signs to " << file;
    if (sigml && n < entries.size()) std::cout << " (" << entries.size() - n << " without SiGML notation skipped)";
    std::cout << "\n";
    return 0;
  }
  if (action == "remove") {
    const std::string& gloss = one_positional(o, "GLOSS");
    if (o.lang.empty()) throw Error("remove needs --lang");
    auto lex = open_for_writing(o);
    const auto n = lex.remove(gloss, o.lang, o.variant);
    if (n == 0) throw Error("no sign '" + gloss + "' in " + o.lang + " in " + lex.path());
    std::cout << "removed " << n << " sign" << (n == 1 ? "" : "s") << "\n";
    return 0;
  }
  throw Error("unknown action '" + action + "' (see gestura lexicon --help)");
}

gestura::cli::Registration reg{{"lexicon", "list, search, add, import and export signs of the lexicon", kUsage, run}};

}  // namespace
