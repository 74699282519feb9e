#pragma once
// check: parse — and by default synthesize on the default avatar — every sign of a .jsonl lexicon
// or a .sigml document, reporting each sign that fails and what the lenient parser accepted.
#include <string>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/sign/sign_check.hpp"

namespace gestura::app {

struct CheckRequest {
  std::string file;
  bool strict = false;
  bool parse_only = false;
  bool show = false;
  int max_errors = 100;  // stop after this many failing signs; 0: check every sign

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.file, FieldInfo{.name = "file", .help = "a .jsonl lexicon or a .sigml document", .value = "FILE", .positional = true, .required = true});
    visit(self.strict, FieldInfo{.name = "strict", .help = "reject notation the standard does not allow instead of accepting it with a note"});
    visit(self.parse_only, FieldInfo{.name = "parse_only", .help = "parse only, do not synthesize"});
    visit(self.show, FieldInfo{.name = "show", .help = "also print each parsed sign as one line (posture; actions)"});
    visit(self.max_errors, FieldInfo{.name = "max_errors", .help = "stop after this many failing signs (0: check them all)", .value = "N", .min = 0, .max = 1e9});
  }
};

struct CheckResult {
  sign::CheckReport report;
  bool synthesized = true;  // false with parse_only
};

void validate(const CheckRequest& request);
// A file that is not text (NUL bytes) is one input error, not a failure per line.
CheckResult run(const CheckRequest& request, const RunContext& context = {});
nlohmann::json to_json(const CheckResult& result);

}  // namespace gestura::app
