#include "gestura/studio/nonmanual_tiers.hpp"

#include <algorithm>
#include <array>

namespace gestura::studio {
namespace {

using T = sign::NonManualTier;

// The values sign/sign_nonmanual.cpp performs, with what they look like ("left"/"right" are the
// signer's). Mouth gestures and cheeks list the common ones; any D/J/L/C/T code can be typed.
constexpr NonManualCode kShoulder[] = {{"UB", "both raised"}, {"UL", "left raised"},   {"UR", "right raised"},
                                       {"HB", "both hunched"}, {"HL", "left hunched"}, {"HR", "right hunched"},
                                       {"SB", "shrug, both"},  {"SL", "shrug, left"},  {"SR", "shrug, right"}};
constexpr NonManualCode kBody[] = {{"RL", "rotated left"},  {"RR", "rotated right"}, {"TL", "tilted left"},
                                   {"TR", "tilted right"},  {"TF", "tilted forwards"}, {"TB", "tilted back"},
                                   {"SI", "sigh"},          {"HE", "heave"},         {"ST", "straight"},
                                   {"RD", "rounded"}};
constexpr NonManualCode kHead[] = {{"NO", "nod"},          {"SH", "shake"},         {"SL", "turned left"},
                                   {"SR", "turned right"}, {"TL", "tilted left"},   {"TR", "tilted right"},
                                   {"NF", "tilted forwards"}, {"NB", "tilted back"}, {"PF", "pushed forwards"},
                                   {"PB", "pushed back"},  {"LI", "turned with the gaze"}};
constexpr NonManualCode kGaze[] = {{"AD", "ahead"},          {"UP", "up"},         {"DN", "down"},
                                   {"LE", "left"},           {"RI", "right"},      {"LU", "left up"},
                                   {"LD", "left down"},      {"RU", "right up"},   {"RD", "right down"},
                                   {"HD", "at the hands"},   {"HI", "at the dominant hand"},
                                   {"HC", "at the other hand"}, {"RO", "rolling"}};
constexpr NonManualCode kBrows[] = {{"RB", "raised"}, {"RL", "left raised"}, {"RR", "right raised"}, {"FU", "furrowed"}};
constexpr NonManualCode kLids[] = {{"WB", "wide"},       {"WL", "left wide"},       {"WR", "right wide"},
                                   {"SB", "narrowed"},   {"SL", "left narrowed"},   {"SR", "right narrowed"},
                                   {"CB", "closed"},     {"CL", "left closed"},     {"CR", "right closed"},
                                   {"TB", "shut tight"}, {"TL", "left shut tight"}, {"TR", "right shut tight"},
                                   {"BB", "blink at the end"}};
constexpr NonManualCode kNose[] = {{"WR", "wrinkled"}};
constexpr NonManualCode kCheeks[] = {{"C01", "puffed"}, {"C02", "puffed, lips pursed"}, {"C04", "one cheek puffed"},
                                     {"C07", "sucked in"}, {"C12", "lips pressed"}};
constexpr NonManualCode kMouthGesture[] = {{"L04", "pursed lips"},  {"L02", "prrr"},          {"L09", "bam"},
                                           {"L20", "phh, cheeks puffed"}, {"L23", "mmm"},   {"L29", "corners down"},
                                           {"L34", "lips pressed, smile"}, {"D01", "eee-sss"}, {"D08", "teeth bared"},
                                           {"J02", "chewing"},      {"T04", "tongue out"},    {"C01", "cheeks puffed"}};

constexpr std::array kTiers{
    NonManualTierInfo{T::shoulder, "shoulder", "hnm_shoulder", "Shoulders", kShoulder},
    NonManualTierInfo{T::body, "body", "hnm_body", "Body", kBody},
    NonManualTierInfo{T::head, "head", "hnm_head", "Head", kHead},
    NonManualTierInfo{T::eye_gaze, "gaze", "hnm_eyegaze", "Eye gaze", kGaze},
    NonManualTierInfo{T::eyebrows, "eyebrows", "hnm_eyebrows", "Eyebrows", kBrows},
    NonManualTierInfo{T::eyelids, "eyelids", "hnm_eyelids", "Eyelids", kLids},
    NonManualTierInfo{T::nose, "nose", "hnm_nose", "Nose", kNose},
    NonManualTierInfo{T::cheeks, "cheeks", "hnm_cheeks", "Cheeks", kCheeks},
    NonManualTierInfo{T::mouth_gesture, "mouth-gesture", "hnm_mouthgesture", "Mouth gesture", kMouthGesture},
    NonManualTierInfo{T::mouth_picture, "mouth-picture", "hnm_mouthpicture", "Mouth picture (SAMPA)", {}},
    NonManualTierInfo{T::extra, "extra", "hnm_extra", "Extra", {}},
};

}  // namespace

std::span<const NonManualTierInfo> nonmanual_tiers() { return kTiers; }

const NonManualTierInfo& tier_info(sign::NonManualTier tier) {
  for (const NonManualTierInfo& t : kTiers)
    if (t.tier == tier) return t;
  return kTiers.back();
}

std::optional<sign::NonManualTier> tier_from_key(std::string_view key) {
  if (key == "eye-gaze" || key == "eyegaze") return T::eye_gaze;
  if (key == "brows") return T::eyebrows;
  if (key == "mouthing" || key == "mouthpicture") return T::mouth_picture;
  if (key == "shoulders") return T::shoulder;
  for (const NonManualTierInfo& t : kTiers)
    if (t.key == key || t.element == key) return t.tier;
  return std::nullopt;
}

std::string_view code_meaning(sign::NonManualTier tier, std::string_view code) {
  for (const NonManualCode& c : tier_info(tier).codes)
    if (c.code == code) return c.meaning;
  return {};
}

std::optional<std::string> nonmanual_value_problem(sign::NonManualTier tier, std::string_view value) {
  const std::string_view label = tier_info(tier).label;
  if (value.empty()) return std::string(label) + ": no value";
  if (value.size() > 64) return std::string(label) + ": a value is at most 64 characters";
  for (const char c : value) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x21 || u > 0x7e || c == '"' || c == '<' || c == '>' || c == '&')
      return std::string(label) + ": '" + std::string(value.substr(0, 64)) +
             "' has a character a tier value cannot hold (printable ASCII without spaces, quotes, <, > or &)";
  }
  return std::nullopt;
}

std::vector<std::string> tier_values(std::span<const DraftNonManual> list, sign::NonManualTier tier) {
  std::vector<std::string> out;
  for (const DraftNonManual& n : list)
    if (n.tier == tier) out.push_back(n.value);
  return out;
}

std::vector<DraftNonManual> with_tier_value(std::span<const DraftNonManual> list, sign::NonManualTier tier,
                                            const std::string& value) {
  std::vector<DraftNonManual> out;
  for (const NonManualTierInfo& t : kTiers) {
    if (t.tier == tier) {
      if (!value.empty()) out.push_back({tier, value});
      continue;
    }
    for (const DraftNonManual& n : list)
      if (n.tier == t.tier) out.push_back(n);
  }
  return out;
}

std::vector<sign::NonManual> to_sigml_tiers(std::span<const DraftNonManual> list) {
  std::vector<sign::NonManual> out;
  for (const DraftNonManual& n : list) out.push_back(sign::NonManual{n.tier, n.value, 0, 0.0f, 1.0f});
  return out;
}

}  // namespace gestura::studio
