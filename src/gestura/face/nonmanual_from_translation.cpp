#include "gestura/face/nonmanual_from_translation.hpp"

#include <string>

#include "gestura/core/error.hpp"

namespace gestura::face {
namespace {

NonManualKind kind_of(MarkerKind kind) {
  switch (kind) {
    case MarkerKind::yes_no_question: return NonManualKind::yes_no_question;
    case MarkerKind::wh_question: return NonManualKind::wh_question;
    case MarkerKind::negation: return NonManualKind::negation;
    case MarkerKind::exclamation: return NonManualKind::affect;
  }
  return NonManualKind::affect;
}

}  // namespace

NonManualPlan plan_from_translation(const Translation& translation, std::string_view english,
                                    std::span<const TimedGloss> timed) {
  if (timed.size() != translation.glosses.size())
    throw Error("non-manual plan: " + std::to_string(timed.size()) + " timed glosses for " +
                std::to_string(translation.glosses.size()) + " glosses of the translation");
  NonManualPlan plan;
  plan.glosses.assign(timed.begin(), timed.end());
  for (std::size_t i = 0; i < plan.glosses.size(); ++i) {
    plan.glosses[i].kind = translation.glosses[i].kind;
    if (translation.glosses[i].kind == GlossKind::pause)
      plan.boundaries.push_back(0.5f * (timed[i].start + timed[i].end));
  }
  // Exclamations become affect spans below, with the expression their sentence carries.
  for (const Marker& m : translation.markers)
    if (m.kind != MarkerKind::exclamation && m.first < m.last) plan.spans.push_back({kind_of(m.kind), m.first, m.last});

  for (std::size_t s = 0; s < translation.sentences.size(); ++s) {
    const Sentence& sentence = translation.sentences[s];
    if (sentence.begin > sentence.end || sentence.end > english.size())
      throw Error("non-manual plan: sentence " + std::to_string(s) + " lies outside the text");
    if (sentence.first >= sentence.last || sentence.last > timed.size()) continue;
    plan.boundaries.push_back(timed[sentence.last - 1].end);
    const Expression affect = affect_from_text(english.substr(sentence.begin, sentence.end - sentence.begin));
    if (affect == Expression::Neutral) continue;
    const float intensity = sentence.type == SentenceType::exclamation ? 1.0f : 0.6f;
    plan.spans.push_back({NonManualKind::affect, sentence.first, sentence.last, affect, intensity});
  }
  return plan;
}

}  // namespace gestura::face
