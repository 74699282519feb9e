#include "gestura/world/script.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "gestura/world/json_locate.hpp"

namespace gestura {
namespace {

enum class Tok : std::uint8_t { Word, Number, Quoted, Semi, Comma, Colon, Amp, End };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // words lower-cased; quoted text as written
  float number = 0.0f;
  int line = 1, column = 1;
};

std::vector<Token> tokenize(std::string_view s, const std::string& file) {
  std::vector<Token> out;
  int line = 1, column = 1;
  std::size_t i = 0;
  auto advance = [&](std::size_t n) {
    for (std::size_t k = 0; k < n && i < s.size(); ++k, ++i) {
      if (s[i] == '\n') ++line, column = 1;
      else if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) ++column;
    }
  };
  while (i < s.size()) {
    const char c = s[i];
    if (c == '#') {  // a comment to the end of the line
      while (i < s.size() && s[i] != '\n') advance(1);
      continue;
    }
    if (c == '\n') {
      out.push_back({Tok::Semi, "\n", 0, line, column});
      advance(1);
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      advance(1);
      continue;
    }
    Token t;
    t.line = line, t.column = column;
    if (c == ';' || c == ',' || c == ':' || c == '&') {
      t.kind = c == ';' ? Tok::Semi : c == ',' ? Tok::Comma : c == ':' ? Tok::Colon : Tok::Amp;
      t.text = std::string(1, c);
      advance(1);
      out.push_back(t);
      continue;
    }
    // Quoted text: "…" or the typographic “…”.
    const bool curly = s.substr(i, 3) == "\xE2\x80\x9C";
    if (c == '"' || curly) {
      advance(curly ? 3 : 1);
      const std::size_t start = i;
      while (i < s.size() && s[i] != '"' && s.substr(i, 3) != "\xE2\x80\x9D") {
        if (s[i] == '\n') throw Error(SourceLocation{file, t.line, t.column}, "the quote opened here is not closed on its line");
        advance(1);
      }
      if (i >= s.size()) throw Error(SourceLocation{file, t.line, t.column}, "the quote opened here is not closed");
      t.kind = Tok::Quoted;
      t.text = std::string(s.substr(start, i - start));
      advance(s[i] == '"' ? 1 : 3);
      out.push_back(t);
      continue;
    }
    if ((c >= '0' && c <= '9') || (c == '-' && i + 1 < s.size() && s[i + 1] >= '0' && s[i + 1] <= '9') || c == '.') {
      float v = 0.0f;
      const auto [end, ec] = std::from_chars(s.data() + i, s.data() + s.size(), v);
      if (ec != std::errc() || !std::isfinite(v)) throw Error(SourceLocation{file, line, column}, "a number that cannot be read");
      t.kind = Tok::Number;
      t.number = v;
      t.text = std::string(s.substr(i, static_cast<std::size_t>(end - (s.data() + i))));
      advance(static_cast<std::size_t>(end - (s.data() + i)));
      out.push_back(t);
      continue;
    }
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '\r' && s[i] != '\n' && s[i] != ';' && s[i] != ',' && s[i] != ':' &&
           s[i] != '"' && s[i] != '&' && s.substr(i, 3) != "\xE2\x80\x9C")
      advance(1);
    t.kind = Tok::Word;
    t.text = std::string(s.substr(start, i - start));
    // A full stop ends a sentence, not a name.
    while (!t.text.empty() && (t.text.back() == '.' || t.text.back() == '!')) t.text.pop_back();
    for (char& ch : t.text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (!t.text.empty()) out.push_back(t);
  }
  out.push_back({Tok::End, "", 0, line, column});
  return out;
}

// Verb forms: "walk", "walks", "walking" → "walk".
std::string verb_stem(const std::string& w) {
  static const std::pair<const char*, const char*> forms[] = {
      {"goes", "go"},         {"going", "go"},      {"runs", "run"},      {"running", "run"},   {"reaches", "reach"},
      {"reaching", "reach"},  {"says", "say"},      {"saying", "say"},    {"signs", "sign"},    {"signing", "sign"},
      {"faces", "face"},      {"facing", "face"},   {"closes", "close"},  {"closing", "close"}, {"moves", "move"},
      {"moving", "move"},     {"takes", "take"},    {"taking", "take"},   {"touches", "touch"}, {"touching", "touch"},
      {"stops", "stop"},      {"stopping", "stop"}, {"grasps", "grasp"},  {"grasping", "grasp"}};
  for (const auto& [form, stem] : forms)
    if (w == form) return stem;
  if (w.size() > 4 && w.ends_with("ing")) return w.substr(0, w.size() - 3);
  if (w.size() > 2 && w.ends_with("s") && !w.ends_with("ss")) return w.substr(0, w.size() - 1);
  return w;
}

bool is_verb(const std::string& stem) {
  static const char* verbs[] = {"walk", "go", "run", "move", "turn", "face", "say", "sign", "look", "follow", "stop",
                                "reach", "grasp", "take", "touch", "open", "close", "wait"};
  for (const char* v : verbs)
    if (stem == v) return true;
  return false;
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, std::string file) : t_(std::move(tokens)), file_(std::move(file)) {}

  Script run() {
    Script script;
    script.source = file_;
    while (true) {
      while (peek().kind == Tok::Semi) ++i_;
      if (peek().kind == Tok::End) break;
      script.statements.push_back(statement());
      if (peek().kind == Tok::Amp) {
        ++i_;
        continue_with_previous_ = true;
        continue;
      }
      if (peek().kind != Tok::Semi && peek().kind != Tok::End) fail(peek(), "expected ';' or a new line before '" + peek().text + "'");
    }
    return script;
  }

 private:
  const Token& peek(std::size_t ahead = 0) const { return t_[std::min(i_ + ahead, t_.size() - 1)]; }
  const Token& next() { return t_[std::min(i_++, t_.size() - 1)]; }
  [[noreturn]] void fail(const Token& at, const std::string& message) const {
    throw Error(SourceLocation{file_, at.line, at.column}, message);
  }
  bool word(const char* w) const { return peek().kind == Tok::Word && peek().text == w; }
  bool accept(const char* w) {
    if (!word(w)) return false;
    ++i_;
    return true;
  }
  void expect(const char* w, const char* context) {
    if (!accept(w)) fail(peek(), std::string("expected '") + w + "' " + context + (peek().kind == Tok::End ? "" : ", got '" + peek().text + "'"));
  }

  ScriptStatement statement() {
    ScriptStatement st;
    st.where = SourceLocation{file_, peek().line, peek().column};
    st.with_previous = continue_with_previous_;
    continue_with_previous_ = false;
    if (word("at") && peek(1).kind == Tok::Number) {
      ++i_;
      st.at = next().number;
      if (*st.at < 0.0f || *st.at > 36000.0f) fail(t_[i_ - 1], "a start time must be 0..36000 seconds");
      accept("s") || accept("seconds") || accept("sec");
      if (peek().kind != Tok::Colon) fail(peek(), "expected ':' after the start time");
      ++i_;
    }
    if (accept("meanwhile")) st.with_previous = true;
    accept("then");
    std::string actor;
    bool alongside = false;
    while (true) {
      ScriptAction a = clause(actor);
      // Same character: after its previous clause, unless "while"; another: its own chain.
      ScriptChain* chain = nullptr;
      if (!alongside)
        for (ScriptChain& c : st.chains)
          if (!c.actions.empty() && c.actions.front().actor == a.actor) chain = &c;
      if (!chain) chain = &st.chains.emplace_back();
      chain->actions.push_back(a);
      actor = a.actor;
      alongside = false;
      if (accept("while")) {
        alongside = true;
        continue;
      }
      if (peek().kind == Tok::Comma) {
        ++i_;
        accept("and"), accept("then");
        continue;
      }
      if (accept("and")) {
        accept("then");
        continue;
      }
      if (accept("then")) continue;
      break;
    }
    return st;
  }

  std::string name(const char* what) {
    accept("the") || accept("a") || accept("an");
    if (peek().kind != Tok::Word) fail(peek(), std::string("expected ") + what + (peek().kind == Tok::End ? "" : ", got '" + peek().text + "'"));
    const Token& t = next();
    if (t.text == "it") {
      if (last_target_.empty()) fail(t, "'it' before anything was named");
      return last_target_;
    }
    last_target_ = t.text;
    return t.text;
  }

  ScriptAction clause(const std::string& previous_actor) {
    ScriptAction a;
    const Token& first = peek();
    a.where = SourceLocation{file_, first.line, first.column};
    if (first.kind != Tok::Word) fail(first, "expected a character's name or a verb" + (first.kind == Tok::End ? std::string() : ", got '" + first.text + "'"));
    // "wait 2" with no character, or a clause whose character is the previous one's.
    if (is_verb(verb_stem(first.text)) && (verb_stem(first.text) == "wait" || !previous_actor.empty()) &&
        !(peek(1).kind == Tok::Word && is_verb(verb_stem(peek(1).text)))) {
      a.actor = verb_stem(first.text) == "wait" && previous_actor.empty() ? "" : previous_actor;
    } else {
      a.actor = next().text;
      a.where = SourceLocation{file_, first.line, first.column};
    }
    if (peek().kind != Tok::Word) fail(peek(), "expected a verb after '" + a.actor + "' (walks, turns, says, looks, follows, opens, …)");
    const Token& verb_token = next();
    const std::string verb = verb_stem(verb_token.text);
    if (verb == "walk" || verb == "go" || verb == "run" || verb == "move") {
      a.kind = ActionKind::Walk;
      accept("over") || accept("back");
      if (!accept("to") && !accept("towards") && !accept("toward")) expect("to", "after the verb");
      a.target = name("a place, object or character");
      if (verb == "run") a.speed = 2.6f;
      if (accept("at")) {
        if (peek().kind != Tok::Number) fail(peek(), "expected a speed in m/s after 'at'");
        a.speed = next().number;
        accept("m/s") || accept("mps");
        if (!(*a.speed >= 0.2f && *a.speed <= 3.0f)) fail(t_[i_ - 1], "a walking speed must be 0.2..3 m/s");
      }
    } else if (verb == "turn") {
      a.kind = ActionKind::Turn;
      if (accept("around")) a.angle = 180.0f;
      else if (accept("left") || accept("right")) {
        const bool left = t_[i_ - 1].text == "left";
        float degrees = 90.0f;
        if (peek().kind == Tok::Number) {
          degrees = next().number;
          accept("degrees") || accept("degree") || accept("deg");
          if (!(degrees > 0.0f && degrees <= 360.0f)) fail(t_[i_ - 1], "a turn of 0..360 degrees");
        }
        a.angle = left ? degrees : -degrees;
      } else {
        if (!accept("to") && !accept("towards") && !accept("toward")) expect("to", "after 'turns' (or left, right, around)");
        a.target = name("what to turn to");
      }
    } else if (verb == "face") {
      a.kind = ActionKind::Turn;
      a.target = name("what to face");
    } else if (verb == "say" || verb == "sign") {
      a.kind = ActionKind::Say;
      if (peek().kind != Tok::Quoted) fail(peek(), "expected the text in quotes after '" + verb_token.text + "'");
      a.text = next().text;
      if (a.text.empty()) fail(t_[i_ - 1], "nothing to say");
      if (accept("to")) a.target = name("whom it is said to");
    } else if (verb == "look") {
      if (accept("away")) {
        a.kind = ActionKind::StopLooking;
      } else {
        expect("at", "after 'looks'");
        a.kind = ActionKind::LookAt;
        a.target = name("what to look at");
      }
    } else if (verb == "follow") {
      a.kind = ActionKind::Follow;
      a.target = name("whom to follow");
      a.number = 1.2f;
      if (accept("at")) {
        if (peek().kind != Tok::Number) fail(peek(), "expected a distance in metres after 'at'");
        a.number = next().number;
        accept("m") || accept("metres") || accept("meters");
        if (!(a.number >= 0.5f && a.number <= 10.0f)) fail(t_[i_ - 1], "a following distance must be 0.5..10 m");
      }
    } else if (verb == "stop") {
      if (accept("following")) a.kind = ActionKind::StopFollowing;
      else if (accept("looking")) a.kind = ActionKind::StopLooking;
      else a.kind = ActionKind::Stop;
    } else if (verb == "reach") {
      a.kind = ActionKind::Reach;
      expect("for", "after 'reaches'");
      a.target = name("what to reach for");
    } else if (verb == "grasp" || verb == "take" || verb == "touch") {
      a.kind = ActionKind::Reach;
      a.target = name("what to take");
    } else if (verb == "open" || verb == "close") {
      a.kind = verb == "open" ? ActionKind::Open : ActionKind::Close;
      a.target = name("a door");
    } else if (verb == "wait") {
      a.kind = ActionKind::Wait;
      if (peek().kind != Tok::Number) fail(peek(), "expected how many seconds to wait");
      a.number = next().number;
      accept("s") || accept("seconds") || accept("second") || accept("sec");
      if (!(a.number >= 0.0f && a.number <= 600.0f)) fail(t_[i_ - 1], "a wait must be 0..600 seconds");
    } else {
      fail(verb_token, "unknown verb '" + verb_token.text + "' (walks, goes, runs, turns, faces, says, signs, looks, follows, stops, reaches, takes, opens, closes, waits)");
    }
    return a;
  }

  std::vector<Token> t_;
  std::string file_;
  std::size_t i_ = 0;
  bool continue_with_previous_ = false;
  std::string last_target_;
};

Script parse_json_script(std::string_view text, const std::string& name) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string what = e.what();
    if (const auto at = what.find("syntax error"); at != std::string::npos) what = what.substr(at);
    throw_json_syntax_error(text, name, e.byte, what);
  } catch (const nlohmann::json::exception& e) {
    throw Error(name + ": JSON: " + e.what());
  }
  const JsonLocator at(std::string(text), name);
  const nlohmann::json* list = &doc;
  std::string base;
  if (doc.is_object()) {
    if (!doc.contains("script")) at.fail("", "expected {\"script\": [...]} or an array of actions");
    list = &doc["script"];
    base = "/script";
  }
  if (!list->is_array()) at.fail(base, "expected an array of actions");
  Script script;
  script.source = name;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const nlohmann::json& item = (*list)[i];
    const std::string p = base + "/" + std::to_string(i);
    if (item.is_string()) {
      // A text statement inside the JSON: parsed as text, errors located by the pointer.
      try {
        Script inner = parse_script(item.get<std::string>(), name + p);
        for (ScriptStatement& s : inner.statements) script.statements.push_back(std::move(s));
      } catch (const Error& e) {
        at.fail(p, e.what());
      }
      continue;
    }
    if (!item.is_object()) at.fail(p, "expected an action object or a text statement");
    auto string_of = [&](const char* key) {
      if (!item.contains(key)) return std::string();
      if (!item[key].is_string()) at.fail(p + "/" + key, "expected a string");
      std::string v = item[key].get<std::string>();
      return v;
    };
    auto number_of = [&](const char* key, float fallback) {
      if (!item.contains(key)) return fallback;
      if (!item[key].is_number() || !std::isfinite(item[key].get<double>())) at.fail(p + "/" + key, "expected a number");
      return item[key].get<float>();
    };
    for (const auto& [key, value] : item.items()) {
      static const char* known[] = {"actor", "do", "to", "text", "angle", "seconds", "distance", "speed", "wait", "with_previous", "at"};
      bool ok = false;
      for (const char* k : known) ok = ok || key == k;
      if (!ok) at.fail(p + "/" + key, "unknown member '" + key + "' (actor, do, to, text, angle, seconds, distance, speed, wait, with_previous, at)");
    }
    ScriptAction a;
    a.where = at.locate(p);
    a.pointer = p;
    a.actor = string_of("actor");
    for (char& c : a.actor) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    a.target = string_of("to");
    for (char& c : a.target) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string verb = item.contains("wait") ? "wait" : string_of("do");
    if (verb.empty()) at.fail(p, "an action needs \"do\" (walk, turn, say, look, follow, stop, reach, open, close, wait)");
    const std::string stem = verb_stem(verb);
    if (stem == "walk" || stem == "go" || stem == "run" || stem == "move") a.kind = ActionKind::Walk;
    else if (stem == "turn" || stem == "face") a.kind = ActionKind::Turn;
    else if (stem == "say" || stem == "sign") a.kind = ActionKind::Say;
    else if (stem == "look") a.kind = a.target.empty() ? ActionKind::StopLooking : ActionKind::LookAt;
    else if (stem == "follow") a.kind = ActionKind::Follow;
    else if (stem == "stop") a.kind = ActionKind::Stop;
    else if (stem == "reach" || stem == "grasp" || stem == "take" || stem == "touch") a.kind = ActionKind::Reach;
    else if (stem == "open") a.kind = ActionKind::Open;
    else if (stem == "close") a.kind = ActionKind::Close;
    else if (stem == "wait") a.kind = ActionKind::Wait;
    else at.fail(p + "/do", "unknown action '" + verb + "' (walk, turn, say, look, follow, stop, reach, open, close, wait)");
    a.text = string_of("text");
    if (item.contains("angle")) a.angle = number_of("angle", 0.0f);
    a.number = a.kind == ActionKind::Wait ? number_of(item.contains("wait") ? "wait" : "seconds", 0.0f)
               : a.kind == ActionKind::Follow ? number_of("distance", 1.2f) : 0.0f;
    if (item.contains("speed")) a.speed = number_of("speed", 1.3f);
    if (a.kind != ActionKind::Wait && a.actor.empty()) at.fail(p, "an action needs an \"actor\"");
    if (a.kind == ActionKind::Say && a.text.empty()) at.fail(p, "\"say\" needs \"text\"");
    if ((a.kind == ActionKind::Walk || a.kind == ActionKind::Follow || a.kind == ActionKind::Reach || a.kind == ActionKind::Open ||
         a.kind == ActionKind::Close || a.kind == ActionKind::LookAt) && a.target.empty())
      at.fail(p, "\"" + verb + "\" needs \"to\" (what it is done to)");
    if (a.kind == ActionKind::Turn && a.target.empty() && !a.angle) at.fail(p, "\"turn\" needs \"to\" or \"angle\"");
    if (a.kind == ActionKind::Wait && !(a.number >= 0.0f && a.number <= 600.0f)) at.fail(p, "a wait must be 0..600 seconds");
    if (a.speed && !(*a.speed >= 0.2f && *a.speed <= 3.0f)) at.fail(p + "/speed", "a walking speed must be 0.2..3 m/s");
    const bool with_previous = item.contains("with_previous") && item["with_previous"].is_boolean() && item["with_previous"].get<bool>();
    if (with_previous && !script.statements.empty()) {
      script.statements.back().chains.push_back(ScriptChain{{a}});
    } else {
      ScriptStatement st;
      st.where = a.where;
      if (item.contains("at")) st.at = number_of("at", 0.0f);
      st.chains.push_back(ScriptChain{{a}});
      script.statements.push_back(std::move(st));
    }
  }
  return script;
}

}  // namespace

const char* action_name(ActionKind kind) {
  switch (kind) {
    case ActionKind::Walk: return "walks to";
    case ActionKind::Turn: return "turns";
    case ActionKind::Say: return "says";
    case ActionKind::LookAt: return "looks at";
    case ActionKind::StopLooking: return "stops looking";
    case ActionKind::Follow: return "follows";
    case ActionKind::StopFollowing: return "stops following";
    case ActionKind::Stop: return "stops";
    case ActionKind::Reach: return "reaches for";
    case ActionKind::Open: return "opens";
    case ActionKind::Close: return "closes";
    case ActionKind::Wait: return "waits";
  }
  return "?";
}

std::string ScriptAction::describe() const {
  std::string out = actor.empty() ? std::string("wait") : actor + " " + action_name(kind);
  if (kind == ActionKind::Turn) out += target.empty() ? " by " + std::to_string(static_cast<int>(angle.value_or(0.0f))) + "°" : " to " + target;
  else if (kind == ActionKind::Say) out += " \"" + text + "\"";
  else if (kind == ActionKind::Wait) out += " " + std::to_string(number).substr(0, 4) + " s";
  else if (!target.empty()) out += " " + target;
  return out;
}

Script parse_script(std::string_view text, const std::string& name) {
  if (text.size() > kMaxScriptBytes) throw Error(name + ": a script larger than 1 MiB");
  std::size_t first = 0;
  while (first < text.size() && std::isspace(static_cast<unsigned char>(text[first]))) ++first;
  if (first < text.size() && (text[first] == '[' || text[first] == '{')) return parse_json_script(text, name);
  return Parser(tokenize(text, name), name).run();
}

Script read_script(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error("cannot read script '" + path + "': no such file");
  if (std::filesystem::file_size(path, ec) > kMaxScriptBytes) throw Error(path + ": a script larger than 1 MiB");
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_script(buffer.str(), path);
}

void check_script(const Script& script, const Scene& scene) {
  auto located = [&](const ScriptAction& a, const std::string& message) {
    throw Error(a.where, (a.pointer.empty() ? "" : a.pointer + ": ") + message);
  };
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  auto character = [&](const std::string& n) -> const SceneCharacter* {
    for (const SceneCharacter& c : scene.characters)
      if (lower(c.name) == n) return &c;
    return nullptr;
  };
  auto object = [&](const std::string& n) -> const SceneObject* {
    for (const SceneObject& o : scene.objects)
      if (lower(o.name) == n) return &o;
    return nullptr;
  };
  auto place = [&](const std::string& n) {
    for (const auto& [k, p] : scene.places)
      if (lower(k) == n) return true;
    return false;
  };
  std::string characters;
  for (const SceneCharacter& c : scene.characters) characters += " " + c.name;
  for (const ScriptStatement& st : script.statements)
    for (const ScriptChain& chain : st.chains)
      for (const ScriptAction& a : chain.actions) {
        if (!a.actor.empty() && !character(a.actor)) located(a, "no character '" + a.actor + "' in the scene (it has:" + characters + ")");
        if (a.target.empty()) continue;
        const bool known = character(a.target) || object(a.target) || place(a.target);
        if (!known) {
          std::string names;
          for (const auto& [k, p] : scene.places) names += " " + k;
          for (const SceneObject& o : scene.objects)
            if (!o.name.empty()) names += " " + o.name;
          located(a, "'" + a.target + "' is no place, object or character of the scene (it has:" + names + characters + ")");
        }
        if ((a.kind == ActionKind::Open || a.kind == ActionKind::Close) && !(object(a.target) && object(a.target)->door))
          located(a, "'" + a.target + "' is not a door");
        if (a.kind == ActionKind::Follow && !character(a.target)) located(a, "only a character can be followed, not '" + a.target + "'");
        if (a.kind == ActionKind::Follow && a.target == a.actor) located(a, a.actor + " cannot follow itself");
        if (a.kind == ActionKind::Reach && !object(a.target)) located(a, "only an object can be reached for, not '" + a.target + "'");
      }
}

}  // namespace gestura
