#pragma once
// Performing a script in a scene: the director runs the statements in order on the simulation
// (simulation.hpp) — walks planned and walked, turns, sentences signed with the sentence pipeline
// (sentence/signer.hpp) on each character's own avatar, looks, follows, reaches, doors opened — while
// every actor's behaviours run on their own (looking at whoever signs, keeping out of each other's
// way). Then each character's recorded body motion becomes its animation (character_motion.hpp).
// "walk to the door and open it" is one statement: the approach, the reach for the handle, the grasp
// and the door swinging open with the hand on it.
//
// A goal that cannot be reached is not an error: the action is skipped and the log says why, at the
// script's line and column ("no path: …"). Malformed scripts and unknown names are errors before
// anything runs.
#include <functional>
#include <memory>
#include <string>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/world/environment.hpp"
#include "gestura/world/performance.hpp"
#include "gestura/world/script.hpp"

namespace gestura {

struct PerformOptions {
  float fps = 30.0f;             // key rate of the characters' clips
  float tick = 1.0f / 60.0f;     // simulation step
  float tail = 1.0f;             // seconds kept after the last action
  float max_seconds = 600.0f;    // a script still running then is cut (and the log says so)
  float reach_seconds = 0.9f;    // reaching for something
  float door_seconds = 1.6f;     // a door swinging
  SayOptions say;
  std::function<void(const std::string&)> progress;  // what happens, as it happens (optional)
};

// Contract: `geometry` was built from `scene`. `lexicon` may be null (the built-in one is used).
// Throws gestura::Error for a script that does not fit the scene (check_script), avatars that
// cannot be built, or sentences the signer refuses.
ScenePerformance perform_scene(const Scene& scene, const SceneGeometry& geometry, const Script& script,
                               LayeredLexicon* lexicon = nullptr, const PerformOptions& options = {});

// Where a character stands at the start: its place or position, on the ground below it.
vec3 start_position(const Scene& scene, const SceneCharacter& character, const Environment& env, float* facing_degrees = nullptr);

}  // namespace gestura
