#pragma once
// Fills a NonManualPlan from the translator's output and the times sign synthesis gave the glosses:
//   markers yes/no question, wh-question, negation → spans of the same kind over the same glosses;
//   every sentence whose words or '!' carry an affect (affect_from_text) → an affect span over the
//   sentence (intensity 1 for an exclamation, 0.6 otherwise);
//   boundaries → the end of every sentence and the middle of every PAUSE gloss (clause breaks).
// Topics are not marked by the translator yet, so none are produced.
#include <span>
#include <string_view>

#include "gestura/face/nonmanual_plan.hpp"
#include "gestura/text/gloss.hpp"

namespace gestura::face {

// `timed` holds one entry per translation.glosses entry, in the same order (its kinds are taken
// from the translation). Throws gestura::Error when the counts differ or a sentence's byte span
// lies outside `english`.
NonManualPlan plan_from_translation(const Translation& translation, std::string_view english,
                                    std::span<const TimedGloss> timed);

}  // namespace gestura::face
