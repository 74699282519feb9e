#pragma once
// Caps on the work one sign may ask for. A sign's notation is short (kMaxSignSymbols), but
// repetitions multiply it: a repetition repeats the action before it, and a repeated group repeats
// the repetitions inside it, so a few dozen symbols could ask for millions of movements (a flat
// hand and a motion followed by hamrepeatfromstart ×2,000 was a 30-minute sign). The caps are
// checked where the notation is read, on the parsed model, so no later stage ever sees such a
// sign. They are far above what signs need: of 4,070 lexicon signs and 100 SiGML signs none has
// more than 2 repetitions or performs more than 20 actions.
#include "gestura/sign/hamnosys_model.hpp"

namespace gestura::sign {

// Repetition symbols (hamrepeat*) in one sign.
inline constexpr int kMaxRepetitions = 16;
// Actions one sign performs with its repetitions unrolled: each motion, replacement, contact, the
// move back before a repetition from the start, once per time it is performed.
inline constexpr int kMaxPerformedActions = 256;
// The longest one sign may last; for the stages that time it (the sign planner).
inline constexpr float kMaxSignSeconds = 60.0f;

// The actions `sign` performs with its repetitions unrolled, following the planner's reading (a
// repetition repeats the last action performed; a repetition from the start first moves back).
// Counting stops just past kMaxPerformedActions (an endless sign counts as that too).
int performed_actions(const HamSign& sign);

// Throws gestura::Error, located at the symbol that passes the limit and naming it, when the sign
// has more than kMaxRepetitions repetitions, performs more than kMaxPerformedActions actions, or
// has a repetition that would repeat the group it is written in (an endless sign).
void check_sign_limits(const HamSign& sign);

// Throws gestura::Error naming kMaxSignSeconds when a sign would last longer.
void check_sign_duration(float seconds);

}  // namespace gestura::sign
