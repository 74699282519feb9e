#pragma once
// The HamNoSys symbol palette, grouped as the notation is written: handshape, thumb, bending,
// extended-finger direction, palm orientation, location, contact, movement, repetition, symmetry
// and two hands, structure, non-manuals. Every symbol of the inventory is in exactly one group.
#include <string>
#include <string_view>
#include <vector>

#include "gestura/sign/hamnosys_symbol.hpp"

namespace gestura::studio {

struct PaletteGroup {
  std::string title;
  std::string hint;  // what the group is for, shown beside it
  std::vector<sign::Symbol> symbols;
};

const std::vector<PaletteGroup>& palette_groups();

// A palette button's label: the name without its "ham" prefix ("flathand").
std::string_view short_name(sign::Symbol symbol);

}  // namespace gestura::studio
