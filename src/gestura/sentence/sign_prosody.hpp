#pragma once
// Prosody of running signing: how long each sign of an utterance lasts, how long it is held, and
// how long the pauses between phrases are (docs/say.md has the sources and the measurements).
//
// A lexicon entry is a citation form: the planner times its movement from the notation (movement
// size and path, repetitions, contacts, handshape and orientation changes; sign_planner.cpp and
// movement_timing.hpp). In running signing the same movement is performed faster, so it is
// compressed by kRunningTempo, and the sign gets short holds at both ends. A sign whose movement is
// tiny or absent (MY: a flat hand placed on the chest) is still held long enough to be seen: every
// sign lasts at least kMinSignSeconds from its first posture to the end of its final hold.
// The last sign of a phrase is lengthened (Grosjean 1979: signs are longer at the end of sentences):
// its movement runs slower, its final hold is longer, and it lasts at least kMinPhraseFinalSeconds.
// Everything is divided by the global speed (0.25–2).
namespace gestura {

// Reference rate of fluent running signing used to judge the result: 2.0 signs/s (docs/say.md).
inline constexpr float kReferenceSignsPerSecond = 2.0f;

// Citation-form movement time / running movement time.
inline constexpr float kRunningTempo = 3.2f;
// Citation movement beyond this many seconds (repetitions, long paths) is compressed twice as much:
// running signing reduces repeated and long movements more than short ones.
inline constexpr float kLongMovementSeconds = 0.6f;
// Running signing compresses a sign's movement, and long or repeated movement more, but never
// below this share of the citation time of one of its movements (planner seconds; 0.55 of the
// citation model's seconds): LIBRARY's circle played in 0.25 s was a blur. A circle then takes
// ≥ 0.29 s, while a straight movement keeps its compressed 0.19 s and repeats stay fast (docs/say.md).
inline constexpr float kMinRunningShare = 0.30f;
// And each cycle of a repeated movement (the stroke and its return) lasts at least this long in
// running signing, about a fluent fingerspelled letter (6/s): at the compression above, MUST's two
// strokes took 0.13 s each, faster than viewers resolve.
inline constexpr float kMinRepeatCycleSeconds = 0.15f;
// Transitions between signs (movement epenthesis, movement_timing.hpp's transition_duration) are
// sped up likewise.
inline constexpr float kTransitionTempo = 3.0f;
inline constexpr float kInitialHold = 0.04f;            // seconds the first posture is held
inline constexpr float kFinalHold = 0.06f;              // seconds the last posture is held
inline constexpr float kMinSignSeconds = 0.30f;         // first posture → end of final hold
inline constexpr float kPhraseFinalSlowing = 1.25f;      // movement of a phrase's last sign
inline constexpr float kPhraseFinalHold = 0.2f;        // at least this final hold there
inline constexpr float kMinPhraseFinalSeconds = 0.40f;  // and at least this long in all
inline constexpr float kSentencePause = 0.5f;           // between sentences ('.', '!', '?')
inline constexpr float kClausePause = 0.25f;            // at a comma or other clause break

struct SignTiming {
  float tempo = 1.0f;         // citation movement seconds per running second
  float initial_hold = 0.0f;  // seconds, after the sign's first posture is reached
  float movement = 0.0f;      // seconds of the (compressed) movement
  float final_hold = 0.0f;    // seconds, after the movement
  float span() const { return initial_hold + movement + final_hold; }
};

// Timing of one sign in running signing. `citation_movement`: seconds from the first posture to the
// end of the movement in citation form (the planner's plan at speed 1 without holds); `extra_hold`:
// seconds added to the final hold (a yes/no question's last sign); `speed`: global tempo.
// `citation_once`: the citation seconds of one of the sign's movements (their mean, repetitions
// left out): the movement lasts at least kMinRunningShare of it.
// `repeats`: how many times the movement is repeated (each cycle at least kMinRepeatCycleSeconds).
// Contract: citation_movement >= 0, extra_hold >= 0, speed in [0.25, 2], 0 <= citation_once, repeats >= 0.
SignTiming running_sign_timing(float citation_movement, bool phrase_final, float extra_hold, float speed,
                               float citation_once = 0.0f, int repeats = 0);

// Timing of a recorded sign (a clip sign keyframed in the studio): its author timed it, holds
// included, so it keeps its own pace — divided by the global speed, and slowed at the end of a
// phrase like any sign, whose final hold and least length it also gets.
// Contract: recorded_seconds >= 0, extra_hold >= 0, speed in [0.25, 2].
SignTiming recorded_sign_timing(float recorded_seconds, bool phrase_final, float extra_hold, float speed);

}  // namespace gestura
