#include "gestura/body/avatar_params.hpp"

#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>

#include "gestura/core/error.hpp"

namespace gestura {

std::string_view to_string(Sex sex) {
  switch (sex) {
    case Sex::Female: return "female";
    case Sex::Male: return "male";
    case Sex::Neutral: break;
  }
  return "neutral";
}

Sex parse_sex(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "female" || lower == "f") return Sex::Female;
  if (lower == "male" || lower == "m") return Sex::Male;
  if (lower == "neutral" || lower == "n") return Sex::Neutral;
  throw Error("avatar sex '" + std::string(text) + "' is not one of female, male, neutral");
}

std::string_view to_string(HairStyle style) {
  switch (style) {
    case HairStyle::Buzz: return "buzz";
    case HairStyle::Curly: return "curly";
    case HairStyle::Bun: return "bun";
    case HairStyle::Bob: return "bob";
    case HairStyle::Short: break;
  }
  return "short";
}

HairStyle parse_hair_style(std::string_view text) {
  for (HairStyle s : {HairStyle::Short, HairStyle::Buzz, HairStyle::Curly, HairStyle::Bun, HairStyle::Bob})
    if (to_string(s) == text) return s;
  throw Error("hair style '" + std::string(text) + "' is not one of short, buzz, curly, bun, bob");
}

static void check_range(std::string_view name, float value, float lo, float hi, std::string_view unit) {
  if (std::isfinite(value) && value >= lo && value <= hi) return;
  std::ostringstream out;
  out << "avatar parameter " << name << " = " << value << unit << " is ";
  if (std::isnan(value))
    out << "not a number";
  else if (!std::isfinite(value))
    out << "infinite";
  else if (value <= 0.0f)
    out << "not positive";
  else
    out << "outside the plausible range";
  out << " (allowed " << lo << unit << " .. " << hi << unit << ")";
  throw Error(out.str());
}

void AvatarParams::validate() const {
  check_range("height", height, 1.0f, 2.5f, " m");
  check_range("build", build, 0.6f, 1.6f, "");
  check_range("shoulder_width", shoulder_width, 0.7f, 1.4f, "");
  check_range("arm_length", arm_length, 0.8f, 1.25f, "");
  check_range("hand_size", hand_size, 0.7f, 1.4f, "");
  check_range("finger_length", finger_length, 0.7f, 1.4f, "");
  check_range("finger_thickness", finger_thickness, 0.6f, 1.5f, "");
  check_range("sleeve", sleeve, 0.5f, 1.0f, "");
  check_range("hem", hem, 0.45f, 0.7f, "");
  if (sex != Sex::Neutral && sex != Sex::Female && sex != Sex::Male)
    throw Error("avatar parameter sex has an invalid value");
  if (static_cast<int>(hair) < 0 || static_cast<int>(hair) > static_cast<int>(HairStyle::Bob))
    throw Error("avatar parameter hair has an invalid value");
  const std::pair<const char*, vec3> colours[] = {{"skin", colors.skin}, {"hair", colors.hair}, {"iris", colors.iris},
                                                   {"cloth", colors.cloth},
                                                   {"trousers", colors.trousers}};
  for (const auto& [name, c] : colours)
    for (int i = 0; i < 3; ++i)
      if (!(c[i] >= 0.0f && c[i] <= 1.0f))
        throw Error(std::string("avatar colour ") + name + " has a component outside 0 .. 1");
}

}  // namespace gestura
