#pragma once
// The non-manual tiers the notation editor edits, as SiGML's <hamnosys_nonmanual> holds them
// (hnm_eyebrows tag="RB", hnm_mouthpicture picture="hUs", ...), with the values the avatar performs
// (sign/sign_nonmanual.hpp) listed for the editor's menus. A draft keeps each value as written: a
// code from another SiGML producer stays in the sign (the preview reports it as not performed).
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/sign/sigml.hpp"

namespace gestura::studio {

// One value of one tier, untimed (it spans the sign, as in <hamnosys_nonmanual>).
struct DraftNonManual {
  sign::NonManualTier tier = sign::NonManualTier::head;
  std::string value;  // the tag (e.g. "RB"), or SAMPA for a mouth picture
  bool operator==(const DraftNonManual&) const = default;
};

struct NonManualCode {
  std::string_view code, meaning;
};

struct NonManualTierInfo {
  sign::NonManualTier tier;
  std::string_view key;      // the script's and the draft file's name: "eyebrows", "mouth-picture"
  std::string_view element;  // the SiGML element: "hnm_eyebrows"
  std::string_view label;    // what the editor shows: "Eyebrows"
  std::span<const NonManualCode> codes;  // the values the avatar performs; empty: free text (SAMPA)
};

// Every tier, in the order SiGML writes them (and the editor shows them).
std::span<const NonManualTierInfo> nonmanual_tiers();
const NonManualTierInfo& tier_info(sign::NonManualTier tier);
// By key ("eyebrows", "mouth-picture"; "gaze" and "eye-gaze" both name the eye gaze).
std::optional<sign::NonManualTier> tier_from_key(std::string_view key);
// The meaning of a tier's code ("raised" for eyebrows RB), empty when the avatar does not know it.
std::string_view code_meaning(sign::NonManualTier tier, std::string_view code);

// A value the tier can hold: non-empty, printable ASCII without quotes or angle brackets, at most
// 64 characters (SAMPA is ASCII). nullopt when fine, else why not.
std::optional<std::string> nonmanual_value_problem(sign::NonManualTier tier, std::string_view value);

// The values of one tier in a list (a tier may hold several, performed together).
std::vector<std::string> tier_values(std::span<const DraftNonManual> list, sign::NonManualTier tier);
// The list with `tier` holding only `value` (empty: the tier removed), in the tiers' order.
std::vector<DraftNonManual> with_tier_value(std::span<const DraftNonManual> list, sign::NonManualTier tier,
                                            const std::string& value);

// As the synthesis reads them (spanning the whole sign).
std::vector<sign::NonManual> to_sigml_tiers(std::span<const DraftNonManual> list);

}  // namespace gestura::studio
