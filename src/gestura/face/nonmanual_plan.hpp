#pragma once
// What the face layer needs from a planned sentence: the glosses with their times (from sign
// synthesis), the spans that carry non-manual markers (from the translator's Translation::markers,
// plus topics and affect), and the clause/sentence boundaries where people blink.
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/face/expressions.hpp"
#include "gestura/text/gloss.hpp"

namespace gestura::face {

struct TimedGloss {
  float start = 0.0f, end = 0.0f;  // seconds, the sign's manual articulation
  GlossKind kind = GlossKind::sign;
};

enum class NonManualKind { yes_no_question, wh_question, negation, topic, affect };

struct NonManualSpan {
  NonManualKind kind = NonManualKind::affect;
  std::size_t first = 0, last = 0;            // glosses [first, last) of NonManualPlan::glosses
  Expression expression = Expression::Neutral;  // affect only (affect_from_text picks one)
  float intensity = 1.0f;                       // affect only, 0..1
};

struct NonManualPlan {
  std::vector<TimedGloss> glosses;
  std::vector<NonManualSpan> spans;
  std::vector<float> boundaries;  // seconds: ends of clauses and sentences (a blink goes there)
  std::uint32_t seed = 1;         // the idle blinks' pseudo-random gaps depend only on this
};

}  // namespace gestura::face
