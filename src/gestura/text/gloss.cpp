#include "gestura/text/gloss.hpp"

namespace gestura {

std::string_view to_string(GlossKind kind) {
  switch (kind) {
    case GlossKind::sign: return "sign";
    case GlossKind::fingerspell: return "fingerspell";
    case GlossKind::number: return "number";
    case GlossKind::pause: return "pause";
  }
  return "sign";
}

std::string_view to_string(SentenceType type) {
  switch (type) {
    case SentenceType::statement: return "statement";
    case SentenceType::yes_no_question: return "yes/no question";
    case SentenceType::wh_question: return "wh-question";
    case SentenceType::exclamation: return "exclamation";
  }
  return "statement";
}

std::string_view to_string(MarkerKind kind) {
  switch (kind) {
    case MarkerKind::yes_no_question: return "yes/no question";
    case MarkerKind::wh_question: return "wh-question";
    case MarkerKind::negation: return "negation";
    case MarkerKind::exclamation: return "exclamation";
  }
  return "negation";
}

std::string Locus::name() const {
  if (person == 0) return "";
  std::string out = std::to_string(person);
  if (person == 3) out.push_back(static_cast<char>('a' + index % 26));
  return out;
}

std::string Translation::text() const {
  std::string out;
  for (const GlossToken& g : glosses) {
    if (!out.empty()) out.push_back(' ');
    out += g.kind == GlossKind::pause ? "/" : g.gloss;
  }
  return out;
}

}  // namespace gestura
