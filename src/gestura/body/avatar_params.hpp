#pragma once
// The few numbers that shape the default avatar. Everything else (joint positions, limb girths,
// finger radii) is derived from these by fixed anthropometric proportions, so every valid
// parameter set yields a plausible person.
#include <string>
#include <string_view>

#include "gestura/core/math.hpp"

namespace gestura {

enum class Sex { Neutral, Female, Male };

std::string_view to_string(Sex sex);
// "female", "male", "neutral" (case-insensitive); throws gestura::Error otherwise.
Sex parse_sex(std::string_view text);

// Hair over the scalp: short (cropped), buzz (shaved close), curly (a short rounded volume),
// bun (pulled back into a bun), bob (covering the ears down to the jaw).
enum class HairStyle { Short, Buzz, Curly, Bun, Bob };
std::string_view to_string(HairStyle style);
// The names above; throws gestura::Error listing them otherwise.
HairStyle parse_hair_style(std::string_view text);

// The avatar's colours (sRGB, 0..1): the rest (lips, nails, the eye's white, teeth, the mouth's
// lining) follow from these.
struct AvatarColors {
  vec3 skin{0.86f, 0.66f, 0.55f};
  vec3 hair{0.20f, 0.13f, 0.08f};
  vec3 iris{0.28f, 0.40f, 0.52f};
  vec3 cloth{0.17f, 0.20f, 0.26f};     // a dark slate top: the hands stand out against it
  vec3 trousers{0.13f, 0.13f, 0.15f};  // below the top's hem
};

struct AvatarParams {
  float height = 1.70f;            // metres, crown to floor; allowed [1.0, 2.5]
  float build = 1.0f;              // girth multiplier of trunk and limbs; allowed [0.6, 1.6]
  float shoulder_width = 1.0f;     // multiplier of the sex's default shoulder width; [0.7, 1.4]
  float arm_length = 1.0f;         // multiplier of upper arm and forearm lengths; [0.8, 1.25]
  float hand_size = 1.0f;          // multiplier of the whole hand (palm and fingers); [0.7, 1.4]
  float finger_length = 1.0f;      // extra multiplier of the phalanges only; [0.7, 1.4]
  float finger_thickness = 1.0f;   // multiplier of finger radii; [0.6, 1.5]
  Sex sex = Sex::Neutral;
  HairStyle hair = HairStyle::Short;
  float sleeve = 1.0f;             // the shirt's sleeve, as a share of the forearm it covers; [0.5, 1]
  float hem = 0.56f;               // the top's hem (where the trousers begin), a share of the height; [0.45, 0.7]
  AvatarColors colors;

  // Throws gestura::Error naming the parameter, its value and the allowed range for a negative,
  // NaN, infinite or absurd value.
  void validate() const;
};

}  // namespace gestura
