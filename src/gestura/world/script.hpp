#pragma once
// What the characters do, written by a user (alias-movement-through-environments.txt: "walk to the
// door and open it"; ch. 8's timeline of shots and motions):
//
//   anna walks to the chair; anna says "Hello, sit down please."; ben turns to anna
//   ben walks to the door and opens it
//   meanwhile anna follows ben at 1.5
//   anna walks to the window while signing "It is raining."
//   wait 2; at 12 s: ben looks at anna
//
// Statements run one after another (separated by ';' or a new line); a statement starting with
// "meanwhile" starts with the one before, "at N s:" at a given time. Within a statement, clauses
// joined by "and" / "," / "then" are done in turn by the same character, and at the same time by
// different ones; "while" runs the next clause alongside. "it" is the last thing named.
//
// Verbs (any form: walk/walks/walking): walk|go|run|move to T [at N m/s] · turn to|towards T ·
// turn left|right [N degrees] · turn around · face T · say|sign "TEXT" [to T] · look at T ·
// stop looking · follow T [at N [m]] · stop following · stop · reach for T · grasp|take T ·
// touch T · open T · close T · wait N [s]. T is a place, an object or a character of the scene
// (an article before it is ignored).
//
// The same script as JSON: an array of {"actor": "anna", "do": "walk", "to": "chair"}, {"wait": 2},
// {"actor": "ben", "do": "turn", "to": "anna", "with_previous": true}, or text statements as strings.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/world/scene.hpp"

namespace gestura {

enum class ActionKind : std::uint8_t { Walk, Turn, Say, LookAt, StopLooking, Follow, StopFollowing, Stop, Reach, Open, Close, Wait };
const char* action_name(ActionKind kind);

struct ScriptAction {
  ActionKind kind = ActionKind::Wait;
  std::string actor;             // empty for a plain "wait"
  std::string target;            // place, object or character
  std::optional<float> angle;    // turn by degrees (+ = left)
  std::string text;              // say / sign
  float number = 0.0f;           // wait: seconds; follow: distance
  std::optional<float> speed;    // walk: m/s
  SourceLocation where;          // line and column in the script text (or the JSON pointer in `pointer`)
  std::string pointer;
  std::string describe() const;  // "anna walks to chair"
};

// Actions one character does in turn.
struct ScriptChain {
  std::vector<ScriptAction> actions;
};

struct ScriptStatement {
  std::vector<ScriptChain> chains;  // run side by side
  bool with_previous = false;       // "meanwhile": starts when the previous statement starts
  std::optional<float> at;          // "at N s:": starts at that time
  SourceLocation where;
};

struct Script {
  std::vector<ScriptStatement> statements;
  std::string source;
};

inline constexpr std::size_t kMaxScriptBytes = std::size_t{1} << 20;

// Text or JSON (a script whose first character is '[' or '{'). Throws gestura::Error located at
// name:line:column (text) or name:line:column with the JSON pointer for malformed scripts: an unknown
// verb, a missing target or quote, a bad number.
Script parse_script(std::string_view text, const std::string& name);
Script read_script(const std::string& path);

// Checks the script against the scene: every character, place and object it names exists, doors
// are doors. Throws gestura::Error at the action's place, listing what the scene has.
void check_script(const Script& script, const Scene& scene);

}  // namespace gestura
