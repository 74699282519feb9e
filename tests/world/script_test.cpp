// Scripts: the text and JSON forms read into the same statements; mistakes are located at their line
// and column (or JSON pointer); names are checked against the scene.
#include <gtest/gtest.h>

#include "gestura/core/error.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/script.hpp"

namespace {

using namespace gestura;

std::string error_of(const std::string& text) {
  try {
    parse_script(text, "s.txt");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Script, ReadsTheIssuesExample) {
  const Script s = parse_script("anna walks to chair; anna says \"Hello, sit down please.\"; ben turns to anna", "s.txt");
  ASSERT_EQ(s.statements.size(), 3u);
  const ScriptAction& walk = s.statements[0].chains[0].actions[0];
  EXPECT_EQ(walk.kind, ActionKind::Walk);
  EXPECT_EQ(walk.actor, "anna");
  EXPECT_EQ(walk.target, "chair");
  const ScriptAction& say = s.statements[1].chains[0].actions[0];
  EXPECT_EQ(say.kind, ActionKind::Say);
  EXPECT_EQ(say.text, "Hello, sit down please.");
  EXPECT_EQ(say.where.line, 1);
  EXPECT_EQ(say.where.column, 22);
  const ScriptAction& turn = s.statements[2].chains[0].actions[0];
  EXPECT_EQ(turn.kind, ActionKind::Turn);
  EXPECT_EQ(turn.actor, "ben");
  EXPECT_EQ(turn.target, "anna");
}

TEST(Script, ChainsRunInTurnForOneCharacterAndSideBySideForTwo) {
  const Script s = parse_script(
      "Ben walks to the door and opens it\n"
      "meanwhile anna follows ben at 1.5, and carol looks at ben\n"
      "anna walks to the window while signing \"It rains.\"\n"
      "wait 2\n"
      "at 12 s: ben turns around",
      "s.txt");
  ASSERT_EQ(s.statements.size(), 5u);
  ASSERT_EQ(s.statements[0].chains.size(), 1u);
  ASSERT_EQ(s.statements[0].chains[0].actions.size(), 2u);
  EXPECT_EQ(s.statements[0].chains[0].actions[1].kind, ActionKind::Open);
  EXPECT_EQ(s.statements[0].chains[0].actions[1].target, "door");  // "it"
  EXPECT_EQ(s.statements[0].chains[0].actions[1].actor, "ben");
  EXPECT_TRUE(s.statements[1].with_previous);
  ASSERT_EQ(s.statements[1].chains.size(), 2u);
  EXPECT_FLOAT_EQ(s.statements[1].chains[0].actions[0].number, 1.5f);
  ASSERT_EQ(s.statements[2].chains.size(), 2u);  // "while": alongside
  EXPECT_EQ(s.statements[2].chains[1].actions[0].kind, ActionKind::Say);
  EXPECT_EQ(s.statements[3].chains[0].actions[0].kind, ActionKind::Wait);
  EXPECT_FLOAT_EQ(s.statements[3].chains[0].actions[0].number, 2.0f);
  ASSERT_TRUE(s.statements[4].at);
  EXPECT_FLOAT_EQ(*s.statements[4].at, 12.0f);
  EXPECT_FLOAT_EQ(*s.statements[4].chains[0].actions[0].angle, 180.0f);
}

TEST(Script, JsonFormReadsTheSameActions) {
  const Script s = parse_script(R"([
      {"actor": "anna", "do": "walk", "to": "chair"},
      {"actor": "anna", "do": "say", "text": "Hello"},
      {"actor": "ben", "do": "turn", "to": "anna", "with_previous": true},
      {"wait": 1.5},
      "ben opens the door"
    ])", "s.json");
  ASSERT_EQ(s.statements.size(), 4u);
  EXPECT_EQ(s.statements[1].chains.size(), 2u);
  EXPECT_EQ(s.statements[1].chains[1].actions[0].actor, "ben");
  EXPECT_FLOAT_EQ(s.statements[2].chains[0].actions[0].number, 1.5f);
  EXPECT_EQ(s.statements[3].chains[0].actions[0].kind, ActionKind::Open);
}

TEST(Script, MistakesAreLocated) {
  const std::pair<const char*, const char*> cases[] = {
      {"anna walks to chair\nanna jumps over the table", "s.txt:2:6: unknown verb 'jumps'"},
      {"anna says Hello", "s.txt:1:11: expected the text in quotes"},
      {"anna says \"Hello", "s.txt:1:11: the quote opened here is not closed"},
      {"anna walks chair", "s.txt:1:12: expected 'to'"},
      {"wait", "s.txt:1:5: expected how many seconds"},
      {"anna follows ben at 50", "following distance"},
      {"anna walks to chair at 9 m/s", "walking speed"},
      {"anna opens it", "'it' before anything was named"},
      {"[{\"actor\": \"anna\", \"do\": \"fly\"}]", "/0/do: unknown action 'fly'"},
      {"[{\"actor\": \"anna\", \"do\": \"walk\"}]", "needs \"to\""},
      {"[{\"actor\": \"anna\", \"do\": \"walk\", \"to\": \"x\", \"colour\": 1}]", "unknown member 'colour'"},
      {"[{\"actor\": \"anna\",]", "s.txt:1:"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(expected), std::string::npos) << text << "\n→ " << e;
  }
}

TEST(Script, NamesAreCheckedAgainstTheScene) {
  const Scene scene = parse_scene(R"({"objects": [
      {"name": "chair", "shape": "box"}, {"name": "door", "shape": "box", "door": {"handle": [0, 1, 0]}}],
      "places": {"window": [1, 1]}, "characters": [{"name": "Anna"}, {"name": "Ben"}]})", "scene.json");
  check_script(parse_script("anna walks to chair; ben walks to window; anna opens door; ben follows anna", "ok"), scene);
  auto error = [&](const char* text) {
    try {
      check_script(parse_script(text, "s.txt"), scene);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("carl walks to chair").find("s.txt:1:1: no character 'carl'"), std::string::npos);
  EXPECT_NE(error("anna walks to attic").find("'attic' is no place, object or character"), std::string::npos);
  EXPECT_NE(error("anna opens chair").find("'chair' is not a door"), std::string::npos);
  EXPECT_NE(error("anna follows anna").find("cannot follow itself"), std::string::npos);
  EXPECT_NE(error("anna reaches for window").find("only an object"), std::string::npos);
}

}  // namespace
