#include "gestura/io/face_channel_map.hpp"

#include <algorithm>
#include <cctype>

#include "gestura/body/face_morphs.hpp"

namespace gestura {
namespace {

struct Part {
  const char* source;
  float weight;
};
using Recipe = std::vector<Part>;

// From ARKit's 52 blend shapes. ARKit has one browInnerUp for both sides: each side takes half,
// so both at full weight give the whole shape. Visemes are mouth shapes mixed from the jaw, lips
// and tongue (an empty recipe is the resting mouth).
const std::map<std::string, Recipe>& arkit_recipes() {
  static const std::map<std::string, Recipe> r{
      {"eyeBlink_L", {{"eyeBlinkLeft", 1.0f}}},       {"eyeBlink_R", {{"eyeBlinkRight", 1.0f}}},
      {"eyeWide_L", {{"eyeWideLeft", 1.0f}}},         {"eyeWide_R", {{"eyeWideRight", 1.0f}}},
      {"eyeSquint_L", {{"eyeSquintLeft", 1.0f}}},     {"eyeSquint_R", {{"eyeSquintRight", 1.0f}}},
      {"browInnerUp_L", {{"browInnerUp", 0.5f}}},     {"browInnerUp_R", {{"browInnerUp", 0.5f}}},
      {"browOuterUp_L", {{"browOuterUpLeft", 1.0f}}}, {"browOuterUp_R", {{"browOuterUpRight", 1.0f}}},
      {"browDown_L", {{"browDownLeft", 1.0f}}},       {"browDown_R", {{"browDownRight", 1.0f}}},
      {"cheekPuff", {{"cheekPuff", 1.0f}}},
      {"mouthSmile_L", {{"mouthSmileLeft", 1.0f}}},   {"mouthSmile_R", {{"mouthSmileRight", 1.0f}}},
      {"mouthFrown_L", {{"mouthFrownLeft", 1.0f}}},   {"mouthFrown_R", {{"mouthFrownRight", 1.0f}}},
      {"mouthPucker", {{"mouthPucker", 1.0f}}},
      {"mouthPress", {{"mouthPressLeft", 1.0f}, {"mouthPressRight", 1.0f}}},
      {"mouthOpen", {{"jawOpen", 1.0f}}},             {"tongueOut", {{"tongueOut", 1.0f}}},
      {"sil", {}},
      {"PP", {{"mouthClose", 0.4f}, {"mouthPressLeft", 0.5f}, {"mouthPressRight", 0.5f}}},
      {"FF", {{"mouthRollLower", 0.6f}, {"mouthUpperUpLeft", 0.2f}, {"mouthUpperUpRight", 0.2f}, {"jawOpen", 0.05f}}},
      {"TH", {{"jawOpen", 0.15f}, {"tongueOut", 0.3f}}},
      {"DD", {{"jawOpen", 0.2f}, {"mouthStretchLeft", 0.2f}, {"mouthStretchRight", 0.2f}}},
      {"kk", {{"jawOpen", 0.25f}, {"mouthStretchLeft", 0.15f}, {"mouthStretchRight", 0.15f}}},
      {"CH", {{"jawOpen", 0.2f}, {"mouthFunnel", 0.5f}}},
      {"SS", {{"jawOpen", 0.08f}, {"mouthStretchLeft", 0.35f}, {"mouthStretchRight", 0.35f}}},
      {"nn", {{"jawOpen", 0.15f}, {"mouthClose", 0.1f}}},
      {"RR", {{"jawOpen", 0.15f}, {"mouthPucker", 0.4f}, {"mouthFunnel", 0.2f}}},
      {"aa", {{"jawOpen", 0.6f}, {"mouthStretchLeft", 0.1f}, {"mouthStretchRight", 0.1f}}},
      {"E", {{"jawOpen", 0.3f}, {"mouthStretchLeft", 0.4f}, {"mouthStretchRight", 0.4f}}},
      {"ih", {{"jawOpen", 0.2f}, {"mouthSmileLeft", 0.25f}, {"mouthSmileRight", 0.25f}}},
      {"oh", {{"jawOpen", 0.4f}, {"mouthFunnel", 0.6f}}},
      {"ou", {{"jawOpen", 0.15f}, {"mouthPucker", 0.8f}, {"mouthFunnel", 0.2f}}},
  };
  return r;
}

// From VRM expressions (named as read_vrm names them). VRM has five vowels and whole-face
// emotions: the other visemes lean on the nearest vowel, one-sided channels take half of the
// emotion that shows them. Alternatives are separated: the first recipe whose sources all exist.
const std::map<std::string, std::vector<Recipe>>& expression_recipes() {
  static const std::map<std::string, std::vector<Recipe>> r{
      {"aa", {{{"aa", 1.0f}}}}, {"ih", {{{"ih", 1.0f}}}}, {"ou", {{{"ou", 1.0f}}}}, {"E", {{{"E", 1.0f}}}},
      {"oh", {{{"oh", 1.0f}}}}, {"sil", {{}}}, {"PP", {{}}},
      {"FF", {{{"ih", 0.3f}}}}, {"TH", {{{"ih", 0.3f}, {"aa", 0.1f}}}}, {"DD", {{{"E", 0.4f}}}},
      {"kk", {{{"E", 0.3f}, {"aa", 0.2f}}}}, {"CH", {{{"ou", 0.4f}, {"E", 0.3f}}}}, {"SS", {{{"ih", 0.6f}}}},
      {"nn", {{{"ih", 0.3f}}}}, {"RR", {{{"ou", 0.5f}}}},
      {"mouthOpen", {{{"aa", 1.0f}}}}, {"mouthPucker", {{{"ou", 1.0f}}}},
      {"eyeBlink_L", {{{"eyeBlink_L", 1.0f}}, {{"blink", 1.0f}}}},
      {"eyeBlink_R", {{{"eyeBlink_R", 1.0f}}, {{"blink", 1.0f}}}},
      {"mouthSmile_L", {{{"joy", 0.5f}}}}, {"mouthSmile_R", {{{"joy", 0.5f}}}},
      {"mouthFrown_L", {{{"sadness", 0.5f}}}}, {"mouthFrown_R", {{{"sadness", 0.5f}}}},
      {"browInnerUp_L", {{{"sadness", 0.5f}}}}, {"browInnerUp_R", {{{"sadness", 0.5f}}}},
      {"browDown_L", {{{"anger", 0.5f}}}}, {"browDown_R", {{{"anger", 0.5f}}}},
      {"browOuterUp_L", {{{"surprise", 0.5f}}}}, {"browOuterUp_R", {{{"surprise", 0.5f}}}},
      {"eyeWide_L", {{{"surprise", 0.5f}}}}, {"eyeWide_R", {{{"surprise", 0.5f}}}},
  };
  return r;
}

// "blendShape1.EyeBlink_Left" → "eyeblinkleft": case, separators and a dotted prefix do not count.
std::string key(const std::string& name) {
  const std::string tail = name.substr(name.find_last_of('.') == std::string::npos ? 0 : name.find_last_of('.') + 1);
  std::string k;
  for (char c : tail)
    if (std::isalnum(static_cast<unsigned char>(c))) k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return k;
}

// One morph that is the weighted sum of others.
MorphTarget combine(const std::string& name, const Mesh& mesh, const std::vector<std::pair<int, float>>& parts) {
  std::map<std::uint32_t, vec3> sum;
  for (const auto& [m, w] : parts) {
    const MorphTarget& t = mesh.morphs[static_cast<std::size_t>(m)];
    for (std::size_t k = 0; k < t.vertices.size() && k < t.position_deltas.size(); ++k) sum[t.vertices[k]] += w * t.position_deltas[k];
  }
  MorphTarget out{name, {}, {}, {}};
  for (const auto& [v, d] : sum) {
    if (d == vec3(0.0f)) continue;
    out.vertices.push_back(v);
    out.position_deltas.push_back(d);
  }
  return out;
}

}  // namespace

FaceChannelReport map_face_channels(Mesh& mesh, const std::map<std::string, std::vector<VrmMorphBind>>& expressions) {
  FaceChannelReport report;
  std::map<std::string, int> by_key;
  for (std::size_t m = 0; m < mesh.morphs.size(); ++m) by_key.emplace(key(mesh.morphs[m].name), static_cast<int>(m));
  const bool any_arkit_mouth = by_key.contains("jawopen");
  std::vector<std::string> channels(kVisemeNames.begin(), kVisemeNames.end());
  channels.insert(channels.end(), kExpressionMorphNames.begin(), kExpressionMorphNames.end());
  std::vector<MorphTarget> added;
  for (const std::string& channel : channels) {
    if (mesh.find_morph(channel) >= 0) {
      report.mapped.push_back(channel + " (own morph)");
      ++report.from_own;
      continue;
    }
    // ARKit: every source of the recipe that exists contributes; an empty recipe (the resting
    // mouth) counts when the face has ARKit mouth shapes at all.
    if (const auto it = arkit_recipes().find(channel); it != arkit_recipes().end()) {
      std::vector<std::pair<int, float>> parts;
      for (const Part& p : it->second)
        if (const auto m = by_key.find(key(p.source)); m != by_key.end()) parts.push_back({m->second, p.weight});
      if (!parts.empty() || (it->second.empty() && any_arkit_mouth)) {
        added.push_back(combine(channel, mesh, parts));
        report.mapped.push_back(channel + " (ARKit blend shapes)");
        ++report.from_arkit;
        continue;
      }
    }
    bool made = false;
    if (const auto it = expression_recipes().find(channel); it != expression_recipes().end()) {
      const bool any_vowel = expressions.contains("aa") && !expressions.at("aa").empty();
      for (const Recipe& recipe : it->second) {
        std::vector<std::pair<int, float>> parts;
        bool complete = true;
        for (const Part& p : recipe) {
          const auto e = expressions.find(p.source);
          if (e == expressions.end() || e->second.empty()) { complete = false; break; }
          for (const VrmMorphBind& b : e->second) parts.push_back({b.morph, p.weight * b.weight});
        }
        if (!complete || (recipe.empty() && !any_vowel)) continue;
        added.push_back(combine(channel, mesh, parts));
        report.mapped.push_back(channel + " (VRM expressions)");
        ++report.from_expressions;
        made = true;
        break;
      }
    }
    if (!made) report.missing.push_back(channel);
  }
  for (MorphTarget& m : added) mesh.morphs.push_back(std::move(m));
  return report;
}

}  // namespace gestura
