// gestura check FILE: parse every sign of a lexicon (.jsonl) or SiGML file and report failures.
#include <cstdio>
#include <optional>

#include "command.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/sign_check.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace {

int run_check(const std::vector<std::string>& args) {
  gestura::sign::CheckOptions options;
  std::string path;
  bool synthesize = true;
  for (const std::string& a : args) {
    if (a == "--strict") options.parse.strict = true;
    else if (a == "--parse-only") synthesize = false;
    else if (a == "--show") options.describe_parsed = true;
    else if (!a.empty() && a[0] == '-') throw gestura::Error("unknown flag " + a + " (see gestura check --help)");
    else if (path.empty()) path = a;
    else throw gestura::Error("check takes one FILE, got also " + a);
  }
  if (path.empty()) throw gestura::Error("check needs a FILE (.jsonl or .sigml)");
  // One avatar and rig for the whole run, when signs are synthesized.
  std::optional<gestura::Avatar> avatar;
  std::optional<gestura::SigningRig> rig;
  if (synthesize) {
    avatar.emplace(gestura::build_avatar());
    rig.emplace(gestura::make_signing_rig(*avatar));
    options.synthesize = gestura::synthesis_check(*rig);
  }
  const gestura::sign::CheckReport r = gestura::sign::check_file(path, options);
  for (const std::string& d : r.descriptions) std::printf("%s\n", d.c_str());
  for (const std::string& f : r.failures) std::printf("%s\n", f.c_str());
  std::printf("%d signs: %d parsed, %d synthesized, %d failed\n", r.signs, r.parsed, r.synthesized, r.failed);
  return r.failed == 0 ? 0 : 1;
}

const gestura::cli::Registration reg{{
    "check",
    "parse (and synthesize) every sign of a .jsonl lexicon or .sigml file",
    "usage: gestura check [--strict] [--show] [--parse-only] FILE\n\n"
    "FILE is a .jsonl lexicon (one JSON object per line with a `hamnosys` Unicode string or a `names`\n"
    "list) or a .sigml document. Prints one line per failing sign (file:line: gloss: reason), then\n"
    "  N signs: P parsed, S synthesized, F failed\n"
    "Synthesis runs on the default avatar: a sign fails when it cannot be performed, produces NaN,\n"
    "breaks a joint limit, puts a hand more than 1 cm inside the body, or (IK residual at the planned\n"
    "key postures) leaves a hand more than 2 cm from its planned place at the body (5 cm out in the\n"
    "signing space) or turned more than 25 degrees from its planned orientation. --parse-only skips it.\n"
    "--strict rejects notation that real lexicons contain but the standard does not allow (groups\n"
    "left open, misplaced modifiers) instead of accepting it with a note.\n"
    "--show also prints each parsed sign as one line (posture; actions).\n"
    "Exit status 0 when no sign failed, 1 otherwise.",
    run_check,
}};

}  // namespace
