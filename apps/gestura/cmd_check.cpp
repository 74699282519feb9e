// gestura check FILE: parse (and synthesize) every sign of a lexicon (.jsonl) or SiGML file and
// report failures (app/check.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/check.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::CheckRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::CheckResult result = app::run(*request, context);
    const sign::CheckReport& r = result.report;
    for (const std::string& d : r.descriptions) std::printf("%s\n", d.c_str());
    for (const std::string& n : r.notes) std::printf("%s\n", n.c_str());
    for (const std::string& f : r.failures) std::printf("%s\n", f.c_str());
    if (r.stopped)
      std::printf("stopped after %d failing signs (--max-errors %d; 0 checks every sign)\n", r.failed, request->max_errors);
    std::printf("%d signs: %d parsed, %d synthesized, %d failed", r.signs, r.parsed, r.synthesized, r.failed);
    if (r.clips > 0) std::printf(", %d clip signs (recorded motion, not checked)", r.clips);
    std::printf("\n");
    return r.failed == 0 ? 0 : 1;
  };
  return invocation;
}

const Registration reg{{
    "check",
    "parse (and synthesize) every sign of a .jsonl lexicon or .sigml file",
    "FILE is a .jsonl lexicon (one JSON object per line with a `hamnosys` Unicode string or a `names`\n"
    "list; a `clip_base64` line is a clip sign, listed and not checked) or a .sigml document. Prints\n"
    "what the parser accepted with a note (file:line: gloss: note: symbol N: what it did), one line\n"
    "per failing sign (file:line: gloss: reason), then\n"
    "  N signs: P parsed, S synthesized, F failed\n"
    "Synthesis runs on the default avatar: a sign fails when it cannot be performed, produces NaN,\n"
    "breaks a joint limit, puts a hand more than 1 cm inside the body, or (IK residual at the planned\n"
    "key postures) leaves a hand more than 2 cm from its planned place at the body (5 cm out in the\n"
    "signing space) or turned more than 25 degrees from its planned orientation. --parse-only skips it.\n"
    "--strict rejects notation that real lexicons contain but the standard does not allow (groups\n"
    "left open, misplaced modifiers) instead of accepting it with a note. A file that is not text\n"
    "(NUL bytes) is refused as a whole.\n"
    "Exit status 0 when no sign failed, 1 otherwise (2 for a bad command line).",
    prepare,
}};

}  // namespace
}  // namespace gestura::cli
