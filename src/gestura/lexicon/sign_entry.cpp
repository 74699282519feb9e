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

std::string_view to_string(Agreement agreement) {
  switch (agreement) {
    case Agreement::none: return "none";
    case Agreement::forward: return "forward";
    case Agreement::backward: return "backward";
  }
  return "none";
}

Agreement agreement_from_string(std::string_view text) {
  if (text == "none" || text.empty()) return Agreement::none;
  if (text == "forward") return Agreement::forward;
  if (text == "backward") return Agreement::backward;
  throw Error("unknown agreement '" + std::string(text) + "' (expected none, forward or backward)");
}

}  // namespace gestura
