#pragma once
// Where a sign to perform comes from, as `gestura sign` and `gestura view` read it from their flags:
// HamNoSys in Unicode (--hamnosys), HamNoSys symbol names (--names), or a SiGML file (--sigml, with
// --gloss choosing one of its signs). A further source (text to sign) adds a member and a branch in
// load_sign.
#include <string>
#include <vector>

#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::cli {

struct SignSource {
  std::string hamnosys, names, sigml_path, gloss;
  std::string text;  // English to translate and sign (gestura view "TEXT"); performed by the Signer

  bool given() const { return !hamnosys.empty() || !names.empty() || !sigml_path.empty() || !text.empty(); }
};

// When args[i] is one of the source flags, reads its value into `source` (advancing i) and returns true.
bool parse_sign_source_flag(const std::vector<std::string>& args, std::size_t& i, SignSource& source);

// The sign's manual part. Throws gestura::Error unless exactly one source is given, for parse errors
// (symbol index or file:line:col from the parsers) and when the SiGML file has no (such) sign.
sign::HamSign load_sign(const SignSource& source);

// The non-manual tiers of the sign load_sign picks: those of the SiGML sign, none for HamNoSys
// (its Unicode form has no non-manual tiers). Throws as load_sign does.
std::vector<sign::NonManual> load_nonmanuals(const SignSource& source);

}  // namespace gestura::cli
