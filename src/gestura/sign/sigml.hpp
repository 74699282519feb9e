#pragma once
// SiGML reader: <sigml> documents holding <hns_sign> (HamNoSys written as one XML element per
// symbol, plus non-manual tiers) and <hamgestural_sign> (the gestural form with attributes).
// Both end in the same typed HamSign. XML errors name the line; a sign whose notation does not
// parse keeps its own error so one bad sign does not hide the others.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hamnosys_parser.hpp"

namespace gestura::sign {

// Non-manual tiers of <hamnosys_nonmanual>, one per hnm_* element (and of the gestural form's
// <sign_nonmanual>: head_movement, eye_brows, mouth_picture, ... in *_tier elements).
enum class NonManualTier : std::uint8_t {
  shoulder,       // hnm_shoulder tag, e.g. "UB" (both shoulders raised)
  body,           // hnm_body
  head,           // hnm_head, e.g. "NO" nod, "SH" shake
  eye_gaze,       // hnm_eyegaze
  eyebrows,       // hnm_eyebrows, e.g. "RB" raised, "FU" furrowed
  eyelids,        // hnm_eyelids
  nose,           // hnm_nose
  cheeks,         // hnm_cheeks
  mouth_gesture,  // hnm_mouthgesture, e.g. "C01"
  mouth_picture,  // hnm_mouthpicture: spoken word as SAMPA phonemes
  extra,          // hnm_extra
};

std::string_view nonmanual_tier_name(NonManualTier t);

struct NonManual {
  NonManualTier tier = NonManualTier::head;
  // The tier's code as written (tag attribute); for mouth pictures the SAMPA string (picture).
  // Codes stay strings: the tier is typed, the value sets differ between SiGML producers.
  std::string value;
  int line = 0;
  // The part of the sign it spans, as fractions of the sign's duration. <hamnosys_nonmanual> has
  // no timing (0..1 for every element); in the gestural form's <sign_nonmanual> each tier is a
  // sequence: its elements follow one another in equal shares, a *_par group taking one share.
  float from = 0.0f, to = 1.0f;
};

struct SigmlSign {
  std::string gloss;
  int line = 0;                    // line of the sign element
  bool gestural = false;           // from <hamgestural_sign>
  std::vector<Symbol> symbols;     // hns_sign: the manual symbols in order
  std::vector<int> symbol_lines;   // line of each symbol element
  std::vector<NonManual> nonmanual;
  HamSign manual;
};

// One sign of a document: either parsed, or the reason it was not (with its line).
struct SigmlEntry {
  std::string gloss;
  int line = 0;
  std::optional<SigmlSign> sign;
  std::optional<Error> error;  // why not, when sign is empty (file:line, symbol index)
};

// Reads every sign of the document. Throws gestura::Error (file:line:col) when the XML itself is
// malformed or the root is not <sigml> (a bare <hns_sign> root is accepted).
std::vector<SigmlEntry> read_sigml_entries(std::string_view xml, std::string_view file_name = {},
                                           const ParseOptions& options = {});
// As above, but throws the first sign error too.
std::vector<SigmlSign> read_sigml(std::string_view xml, std::string_view file_name = {},
                                  const ParseOptions& options = {});

// Reads a whole file (at most kMaxSigmlBytes) into memory; throws gestura::Error when unreadable.
inline constexpr std::size_t kMaxSigmlBytes = 64u << 20;
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxSigmlBytes);

}  // namespace gestura::sign
