#pragma once
// The one parser of numbers written as text (command-line values, "x,y,z" lists): the whole text
// must be one number of the type, finite, and inside the field's range. Failures are usage errors
// at the field, quoting the text.
#include <string_view>
#include <vector>

#include "gestura/app/field_info.hpp"

namespace gestura::app {

// T is int, float or double. "30", "0.5", "1e-3", "-2" (ints: no fraction, no exponent).
template <class T>
T parse_number(std::string_view text, const FieldInfo& field);

// `count` numbers separated by `separator` ("0.2,1.2,0.3"); counts lists the accepted lengths.
std::vector<float> parse_number_list(std::string_view text, std::initializer_list<std::size_t> counts,
                                     const FieldInfo& field, char separator = ',');

// Throws the usage error for a value outside [field.min, field.max] or not finite.
void check_range(double value, const FieldInfo& field, bool whole);

// "1..120", "≥ 0", "0.25..2" — the range as shown in messages.
std::string range_text(const FieldInfo& field);

}  // namespace gestura::app
