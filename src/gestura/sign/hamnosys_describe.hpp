#pragma once
// A compact one-line English-ish rendering of a parsed sign, for `gestura check --show` and for
// reading parse results while developing synthesis. Not a serialization: nothing parses it back.
#include <string>

#include "gestura/sign/hamnosys_model.hpp"

namespace gestura::sign {

std::string describe(const Handshape& h);
std::string describe(const Orientation& o);
std::string describe(const Location& l);
std::string describe(const Motion& m);
std::string describe(const Element& e);
std::string describe(const HamSign& sign);

}  // namespace gestura::sign
