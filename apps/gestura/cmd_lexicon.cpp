// gestura lexicon — the user's sign lexicon (an SQLite file) on top of the built-in one
// (app/lexicon.hpp).
#include <cstdio>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "gestura/app/lexicon.hpp"

namespace gestura::cli {
namespace {

std::string keyword_list(const SignEntry& e) {
  std::string out;
  for (const auto& k : e.keywords) {
    if (!out.empty()) out += ", ";
    out += k.word;
    if (k.language != "eng") out += " (" + k.language + ")";
    if (!k.meaning.empty()) out += " [" + k.meaning + "]";
  }
  return out;
}

void print_line(const SignEntry& e) {
  std::cout << e.gloss;
  if (e.variant > 1) std::cout << '#' << e.variant;
  std::cout << "\t" << e.language << "\t" << to_string(e.notation_kind) << "\t" << keyword_list(e) << "\n";
}

void print_entry(const SignEntry& e) {
  std::cout << e.gloss << " (" << e.language << ", variant " << e.variant << ")\n"
            << "  notation (" << to_string(e.notation_kind)
            << "): " << (e.notation_kind == NotationKind::clip ? std::to_string(e.clip.size()) + " bytes" : e.notation)
            << "\n  keywords: " << keyword_list(e) << "\n  source: " << e.source << "\n  licence: " << e.licence << "\n";
  if (e.agreement != Agreement::none) std::cout << "  agreement: " << to_string(e.agreement) << "\n";
}

std::function<Invocation()> query(app::LexiconQueryKind kind) {
  return [kind] {
    auto request = std::make_shared<app::LexiconQuery>();
    request->kind = kind;
    Invocation invocation;
    invocation.fields = bind_fields(*request);
    unbind(invocation.fields, "kind");
    if (kind == app::LexiconQueryKind::list) unbind(invocation.fields, "text");
    if (kind != app::LexiconQueryKind::search) unbind(invocation.fields, "prefix");
    if (kind == app::LexiconQueryKind::show) binding(invocation.fields, "text").info.value = "GLOSS";
    invocation.run = [request](const app::RunContext& context) {
      const app::LexiconQueryResult r = app::run(*request, context);
      for (const SignEntry& e : r.entries) request->kind == app::LexiconQueryKind::show ? print_entry(e) : print_line(e);
      return 0;
    };
    return invocation;
  };
}

// A change request: its fields, and the line that says what it did.
template <class R>
std::function<Invocation()> change(std::function<void(const R&, const app::LexiconChangeResult&)> report) {
  return [report] {
    auto request = std::make_shared<R>();
    Invocation invocation;
    invocation.fields = bind_fields(*request);
    if constexpr (requires { request->licence; }) {
      // The American spelling is accepted too.
      FieldBinding license = binding(invocation.fields, "licence");
      license.info.name = "license";
      license.info.help = "same as --licence";
      invocation.fields.push_back(license);
    }
    invocation.run = [request, report](const app::RunContext& context) {
      report(*request, app::run(*request, context));
      return 0;
    };
    return invocation;
  };
}

const Registration reg{{
    "lexicon",
    "list, search, add, import and export signs of the lexicon",
    "The user lexicon is --db PATH, else $GESTURA_LEXICON, else $XDG_DATA_HOME/gestura/lexicon.sqlite,\n"
    "else ~/.local/share/gestura/lexicon.sqlite (created on first write). Reading actions also show the\n"
    "built-in lexicon (data/lexicon/*.jsonl, or $GESTURA_BUILTIN_LEXICON); user entries override built-in\n"
    "ones with the same gloss and language. Sign languages are ISO 639-3 codes: ase, bfi, gsg, pso, ins, ...",
    {},
    {Command{"list", "every sign (built-in and user), one per line", {}, query(app::LexiconQueryKind::list), {}},
     Command{"show", "all variants of GLOSS with notation and keywords", {}, query(app::LexiconQueryKind::show), {}},
     Command{"search", "glosses and keywords containing (or starting with) TEXT", {}, query(app::LexiconQueryKind::search), {}},
     Command{"add", "add a sign (--gloss G --lang L, --hamnosys S or --sigml FILE)", {},
             change<app::LexiconAddRequest>([](const auto& q, const app::LexiconChangeResult& r) {
               std::cout << "added " << q.gloss << " (" << q.lang << ") to " << r.path << "\n";
             }),
             {}},
     Command{"import", "import a .jsonl (one entry per line) or .sigml (needs --lang) file", {},
             change<app::LexiconImportRequest>([](const auto& q, const app::LexiconChangeResult& r) {
               for (const app::Notice& n : r.bad_lines) std::fprintf(stderr, "%s\n", n.text().c_str());
               std::cout << "imported " << r.count << " signs from " << q.file << " into " << r.path;
               if (q.skip_bad) std::cout << " (" << r.bad_lines.size() << " bad line" << (r.bad_lines.size() == 1 ? "" : "s") << " skipped)";
               std::cout << "\n";
             }),
             {}},
     Command{"export", "export to .jsonl (everything) or .sigml (SiGML entries only)", {},
             change<app::LexiconExportRequest>([](const auto& q, const app::LexiconChangeResult& r) {
               std::cout << "exported " << r.count << " signs to " << q.file;
               if (r.skipped > 0) std::cout << " (" << r.skipped << " without SiGML notation skipped)";
               std::cout << "\n";
             }),
             {}},
     Command{"remove", "remove GLOSS in --lang (one --variant, or all)", {},
             change<app::LexiconRemoveRequest>([](const auto&, const app::LexiconChangeResult& r) {
               std::cout << "removed " << r.count << " sign" << (r.count == 1 ? "" : "s") << "\n";
             }),
             {}}},
}};

}  // namespace
}  // namespace gestura::cli
