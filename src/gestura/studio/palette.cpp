#include "gestura/studio/palette.hpp"

#include <algorithm>

namespace gestura::studio {
namespace {

using sign::SymbolClass;

struct GroupSpec {
  const char* title;
  const char* hint;
  std::vector<SymbolClass> classes;
};

std::vector<PaletteGroup> build() {
  const std::vector<GroupSpec> specs{
      {"Handshape", "the basic form of the hand", {SymbolClass::handshape}},
      {"Thumb", "after a handshape: where the thumb is", {SymbolClass::thumb_modifier}},
      {"Bending", "after a handshape: how the fingers bend", {SymbolClass::finger_bending}},
      {"Extended finger direction", "where the extended fingers point", {SymbolClass::extended_finger_direction}},
      {"Palm orientation", "where the palm faces", {SymbolClass::palm_direction}},
      {"Location", "where the hand is: body, arm and hand sites, fingers and their parts, sides",
       {SymbolClass::location_site, SymbolClass::location_side, SymbolClass::finger, SymbolClass::finger_part,
        SymbolClass::coreference}},
      {"Contact", "how the hand meets the location", {SymbolClass::contact}},
      {"Movement", "straight, circular, wrist and finger movements and their modifiers",
       {SymbolClass::straight_motion, SymbolClass::circular_motion, SymbolClass::circle_clock, SymbolClass::arc,
        SymbolClass::ellipse, SymbolClass::path_modifier, SymbolClass::spiral_modifier, SymbolClass::size_modifier,
        SymbolClass::manner_modifier, SymbolClass::wrist_motion, SymbolClass::finger_play, SymbolClass::replacement,
        SymbolClass::other_motion}},
      {"Repetition", "after a movement: how it repeats", {SymbolClass::repetition}},
      {"Symmetry and two hands", "at the start: the second hand mirrors or follows", {SymbolClass::two_handed}},
      {"Structure", "brackets for sequences, simultaneous parts and fusions; annotations; punctuation",
       {SymbolClass::structure, SymbolClass::annotation, SymbolClass::punctuation}},
      {"Non-manuals", "HamNoSys has no symbols for the face and body: they are SiGML tiers (head, eyes, mouth)", {}},
  };
  std::vector<PaletteGroup> groups;
  for (const GroupSpec& spec : specs) {
    PaletteGroup g{spec.title, spec.hint, {}};
    for (const sign::SymbolInfo& info : sign::symbol_table())
      if (std::find(spec.classes.begin(), spec.classes.end(), info.symbol_class) != spec.classes.end())
        g.symbols.push_back(info.symbol);
    groups.push_back(std::move(g));
  }
  return groups;
}

}  // namespace

const std::vector<PaletteGroup>& palette_groups() {
  static const std::vector<PaletteGroup> groups = build();
  return groups;
}

std::string_view short_name(sign::Symbol symbol) {
  std::string_view name = sign::symbol_name(symbol);
  if (name.starts_with("ham")) name.remove_prefix(3);
  return name;
}

}  // namespace gestura::studio
