#pragma once
// Where one sign to perform comes from: HamNoSys in Unicode, HamNoSys symbol names, or a SiGML
// file (its first sign, or the one with the given gloss). `sign` and `view` take these fields.
#include <string>
#include <vector>

#include "gestura/app/fields.hpp"
#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::app {

struct SignSource {
  std::string hamnosys, names, sigml, gloss;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.hamnosys, FieldInfo{.name = "hamnosys", .help = "the sign in HamNoSys 4 Unicode", .value = "TEXT"});
    visit(self.names, FieldInfo{.name = "names", .help = "the sign as comma-separated HamNoSys symbol names (hamflathand,hamextfingeru,...)", .value = "SYMBOLS"});
    visit(self.sigml, FieldInfo{.name = "sigml", .help = "a SiGML file; its first sign unless --gloss names one", .value = "FILE"});
    visit(self.gloss, FieldInfo{.name = "gloss", .help = "with --sigml: the sign with this gloss", .value = "NAME"});
  }

  bool given() const { return !hamnosys.empty() || !names.empty() || !sigml.empty(); }
};

// Exactly one source, and a gloss only with a SiGML file; throws AppError (usage).
void validate(const SignSource& source);

// A sign as read: its manual part and, from SiGML, its non-manual tiers.
struct LoadedSign {
  sign::HamSign manual;
  std::vector<sign::NonManual> nonmanual;
  std::string file;  // the SiGML file, for the places of non-manual warnings
};

// Parse errors are input errors at the symbol or file:line:col; a SiGML file without the sign is
// not_found.
LoadedSign load_sign(const SignSource& source);

}  // namespace gestura::app
