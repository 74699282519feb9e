#pragma once
// Batch check of sign files (.jsonl lexicons with a `hamnosys` field, .sigml documents): parse
// every sign and, when the caller passes a synthesis step, synthesize it. Backs `gestura check`.
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::sign {

// The synthesis step: the manual sign and its non-manual tiers (empty outside SiGML). Returns
// nullopt when the sign was synthesized, else the reason it was not. sign_synthesis.hpp makes one
// for an avatar (synthesis_check); a check without one parses only.
// Check runs it on every core (core/parallel_for.hpp), so it must be safe to call from several
// threads at once; the report stays the serial one.
using SynthesisCheck = std::function<std::optional<std::string>(const HamSign&, std::span<const NonManual>)>;

struct CheckOptions {
  ParseOptions parse;
  bool describe_parsed = false;  // fill CheckReport::descriptions (gestura check --show)
  SynthesisCheck synthesize;     // empty: parse only (CheckReport::synthesized stays 0)
  int max_failures = 0;          // stop after this many failed signs (0: check every sign)
};

struct CheckReport {
  int signs = 0;
  int parsed = 0;
  int synthesized = 0;
  int failed = 0;                     // not parsed, or parsed but synthesis failed
  int clips = 0;                      // clip signs (keyframed motion, no notation): listed in notes, not parsed
  std::vector<std::string> failures;  // one line per failing sign: "file:line: gloss: reason"
  std::vector<std::string> descriptions;  // "file:line: gloss: <describe(sign)>" when asked for
  // What the lenient parser accepted although the standard does not (a group left open, a modifier
  // out of place): "file:line: gloss: note: symbol N: what it did".
  std::vector<std::string> notes;
  bool synthesis_connected = false;  // a synthesis step was given
  bool stopped = false;  // max_failures was reached before the end of the file
};

// One object per line with a `hamnosys` string (Unicode) or, failing that, a `names` string.
// Bad lines (not JSON, no notation) count as failed signs; the rest go on.
CheckReport check_jsonl(std::string_view text, std::string_view file_name, const CheckOptions& options = {});
// Malformed XML throws gestura::Error (file:line:col); a bad sign inside counts as failed.
CheckReport check_sigml(std::string_view text, std::string_view file_name, const CheckOptions& options = {});
// Picks the reader by extension (.jsonl / .sigml); throws gestura::Error for others.
CheckReport check_file(const std::string& path, const CheckOptions& options = {});

}  // namespace gestura::sign
