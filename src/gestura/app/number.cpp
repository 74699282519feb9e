#include "gestura/app/number.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "gestura/app/error.hpp"

namespace gestura::app {
namespace {

// Whole numbers in full ("1000000"), others as %g ("0.25", "1e-06").
std::string shown(double v) {
  char buf[32];
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15) std::snprintf(buf, sizeof buf, "%.0f", v);
  else std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string quoted(std::string_view text) {
  constexpr std::size_t kShown = 40;  // a huge value is quoted by its start
  return "'" + std::string(text.substr(0, kShown)) + (text.size() > kShown ? "…'" : "'");
}

}  // namespace

std::string range_text(const FieldInfo& field) {
  const bool low = std::isfinite(field.min), high = std::isfinite(field.max);
  if (low && high) return shown(field.min) + ".." + shown(field.max);
  if (low) return "at least " + shown(field.min);
  if (high) return "at most " + shown(field.max);
  return "";
}

void check_range(double value, const FieldInfo& field, bool whole) {
  const std::string range = range_text(field);
  const std::string kind = whole ? "a whole number" : "a number";
  if (!std::isfinite(value)) usage_error(field.name, "expected " + kind + (range.empty() ? "" : " " + range) + ", got " + shown(value));
  if (value < field.min || value > field.max) usage_error(field.name, shown(value) + " is outside " + range);
}

template <class T>
T parse_number(std::string_view text, const FieldInfo& field) {
  constexpr bool whole = std::is_integral_v<T>;
  T value{};
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') ++first;  // "+2" is 2; from_chars takes no '+'
  const auto [end, ec] = std::from_chars(first, last, value);
  const std::string range = range_text(field);
  if (text.empty() || ec != std::errc() || end != last || first == last)
    usage_error(field.name, quoted(text) + " is not " + (whole ? "a whole number" : "a number") +
                                (range.empty() ? "" : " (" + range + ")"));
  check_range(static_cast<double>(value), field, whole);
  return value;
}

template int parse_number<int>(std::string_view, const FieldInfo&);
template float parse_number<float>(std::string_view, const FieldInfo&);
template double parse_number<double>(std::string_view, const FieldInfo&);

std::vector<float> parse_number_list(std::string_view text, std::initializer_list<std::size_t> counts,
                                     const FieldInfo& field, char separator) {
  std::vector<float> values;
  for (std::size_t begin = 0;;) {
    const std::size_t end = text.find(separator, begin);
    const std::string_view item = text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
    values.push_back(parse_number<float>(item, FieldInfo{.name = field.name, .min = field.min, .max = field.max}));
    if (end == std::string_view::npos) break;
    begin = end + 1;
  }
  for (std::size_t n : counts)
    if (values.size() == n) return values;
  std::string expected;
  for (std::size_t n : counts) expected += (expected.empty() ? "" : " or ") + std::to_string(n);
  usage_error(field.name, quoted(text) + ": expected " + expected + " numbers separated by '" +
                              std::string(1, separator) + "'" + (field.value.empty() ? "" : " (" + std::string(field.value) + ")"));
}

}  // namespace gestura::app
