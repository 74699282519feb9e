#pragma once
// Requests are plain structs that list their fields once, in a static member
//
//   template <class Self, class Visit> static void fields(Self& self, Visit&& visit) {
//     visit(self.text, FieldInfo{.name = "text", .help = "English text to sign", .positional = true});
//     visit(self.speed, FieldInfo{.name = "speed", .help = "tempo", .min = 0.25, .max = 2});
//     MotionOutput::fields(self.output, visit);   // a shared group of fields, flattened
//   }
//
// and everything that reads, writes or checks a request walks that list: JSON in and out (the
// server), the command line (apps/gestura binds each field to its flag), and check_fields, which
// every run() calls first. So a field is spelled, bounded and documented in one place.
//
// Field types: bool, int, float, double, std::string, std::vector<std::string> (repeatable or a
// list of arguments), std::optional of those, and any type with a TextCodec (below), which is
// written as a string in JSON and on the command line (sizes "1280x720", camera lists, enums).
#include <algorithm>
#include <concepts>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "gestura/app/error.hpp"
#include "gestura/app/field_info.hpp"
#include "gestura/app/number.hpp"

namespace gestura::app {

// How a value type is written as text. A specialisation has
//   static T parse(std::string_view text);      // throws gestura::Error (becomes a usage error at the field)
//   static std::string format(const T& value);
template <class T>
struct TextCodec;

template <class T>
concept Coded = requires(std::string_view text, const T& value) {
  { TextCodec<T>::parse(text) } -> std::convertible_to<T>;
  { TextCodec<T>::format(value) } -> std::convertible_to<std::string>;
};

template <class T>
concept Number = std::same_as<T, int> || std::same_as<T, float> || std::same_as<T, double>;

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

template <class R>
concept FieldTable = requires(R& r) { R::fields(r, [](auto&, const FieldInfo&) {}); };

// ---- one value ------------------------------------------------------------------------------------

// From command-line text. Bools take true/false/yes/no/1/0; a list gets the text appended.
template <class T>
void set_from_text(T& value, std::string_view text, const FieldInfo& field) {
  if constexpr (IsOptional<T>::value) {
    typename T::value_type inner{};
    set_from_text(inner, text, field);
    value = std::move(inner);
  } else if constexpr (std::same_as<T, bool>) {
    if (text == "true" || text == "yes" || text == "1") value = true;
    else if (text == "false" || text == "no" || text == "0") value = false;
    else usage_error(field.name, "'" + std::string(text) + "' is not true or false");
  } else if constexpr (Number<T>) {
    value = parse_number<T>(text, field);
  } else if constexpr (std::same_as<T, std::string>) {
    value = std::string(text);
  } else if constexpr (std::same_as<T, std::vector<std::string>>) {
    value.emplace_back(text);
  } else {
    static_assert(Coded<T>, "a field type needs a TextCodec");
    value = as_field_error(ErrorCategory::usage, field.name, [&] { return TextCodec<T>::parse(text); });
  }
}

// From a JSON value of the matching type (numbers as numbers, coded values as strings).
template <class T>
void set_from_json(T& value, const nlohmann::json& json, const FieldInfo& field) {
  const auto wrong = [&](const char* expected) {
    usage_error(field.name, std::string("expected ") + expected + ", got " + json.type_name());
  };
  if constexpr (IsOptional<T>::value) {
    if (json.is_null()) {
      value.reset();
      return;
    }
    typename T::value_type inner{};
    set_from_json(inner, json, field);
    value = std::move(inner);
  } else if constexpr (std::same_as<T, bool>) {
    if (!json.is_boolean()) wrong("true or false");
    value = json.get<bool>();
  } else if constexpr (Number<T>) {
    if (!json.is_number()) wrong(std::is_integral_v<T> ? "a whole number" : "a number");
    const double v = json.get<double>();
    if constexpr (std::is_integral_v<T>)
      if (v != static_cast<double>(static_cast<long long>(v))) usage_error(field.name, "expected a whole number");
    check_range(v, field, std::is_integral_v<T>);
    value = static_cast<T>(v);
  } else if constexpr (std::same_as<T, std::string>) {
    if (!json.is_string()) wrong("a string");
    value = json.get<std::string>();
  } else if constexpr (std::same_as<T, std::vector<std::string>>) {
    if (json.is_string()) {
      value = {json.get<std::string>()};
      return;
    }
    if (!json.is_array()) wrong("an array of strings");
    value.clear();
    for (const auto& item : json) {
      if (!item.is_string()) wrong("an array of strings");
      value.push_back(item.get<std::string>());
    }
  } else {
    if (!json.is_string()) wrong("a string");
    set_from_text(value, json.get<std::string>(), field);
  }
}

template <class T>
nlohmann::json value_to_json(const T& value) {
  if constexpr (IsOptional<T>::value) {
    return value ? value_to_json(*value) : nlohmann::json();
  } else if constexpr (std::same_as<T, bool> || Number<T> || std::same_as<T, std::string> ||
                       std::same_as<T, std::vector<std::string>>) {
    return value;
  } else {
    return TextCodec<T>::format(value);
  }
}

// The limits every value must keep, however it was set.
template <class T>
void check_value(const T& value, const FieldInfo& field) {
  if constexpr (IsOptional<T>::value) {
    if (value) check_value(*value, field);
    else if (field.required) usage_error(field.name, "missing");
  } else if constexpr (Number<T>) {
    check_range(static_cast<double>(value), field, std::is_integral_v<T>);
  } else if constexpr (std::same_as<T, std::string> || std::same_as<T, std::vector<std::string>>) {
    if (field.required && value.empty()) usage_error(field.name, "missing");
  }
}

// ---- whole requests -------------------------------------------------------------------------------

// Every field's limits; run() calls this before the request's own rules.
template <FieldTable R>
void check_fields(const R& request) {
  R::fields(request, [](const auto& value, const FieldInfo& field) { check_value(value, field); });
}

// Fields from a JSON object; absent keys keep their defaults, unknown keys are usage errors.
template <FieldTable R>
void read_json(const nlohmann::json& json, R& request) {
  if (!json.is_object()) usage_error("", std::string("the request must be a JSON object, got ") + json.type_name());
  std::size_t known = 0;
  R::fields(request, [&](auto& value, const FieldInfo& field) {
    const auto it = json.find(std::string(field.name));
    if (it == json.end()) return;
    ++known;
    set_from_json(value, *it, field);
  });
  if (known == json.size()) return;
  std::vector<std::string> names;
  R::fields(request, [&](auto&, const FieldInfo& field) { names.emplace_back(field.name); });
  for (const auto& [key, item] : json.items())
    if (std::find(names.begin(), names.end(), key) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      usage_error(key, "unknown field (known: " + list + ")");
    }
}

template <FieldTable R>
R request_from_json(const nlohmann::json& json) {
  R request;
  read_json(json, request);
  return request;
}

template <FieldTable R>
nlohmann::json to_json(const R& request) {
  nlohmann::json out = nlohmann::json::object();
  R::fields(request, [&](const auto& value, const FieldInfo& field) { out[std::string(field.name)] = value_to_json(value); });
  return out;
}

// The field list of a request type, in order (for help texts and API descriptions).
template <FieldTable R>
std::vector<FieldInfo> field_list() {
  R request{};
  std::vector<FieldInfo> out;
  R::fields(request, [&](auto&, const FieldInfo& field) { out.push_back(field); });
  return out;
}

}  // namespace gestura::app
