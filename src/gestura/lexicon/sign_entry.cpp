#include "gestura/lexicon/sign_entry.hpp"

#include "gestura/core/error.hpp"

namespace gestura {

std::string_view to_string(NotationKind kind) {
  switch (kind) {
    case NotationKind::hamnosys: return "hamnosys";
    case NotationKind::sigml: return "sigml";
    case NotationKind::clip: return "clip";
  }
  return "hamnosys";
}

NotationKind notation_kind_from_string(std::string_view text) {
  if (text == "hamnosys") return NotationKind::hamnosys;
  if (text == "sigml") return NotationKind::sigml;
  if (text == "clip") return NotationKind::clip;
  throw Error("unknown notation kind '" + std::string(text) + "' (expected hamnosys, sigml or clip)");
}

}  // namespace gestura
