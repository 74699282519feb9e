#include "gestura/app/codecs.hpp"

#include <cstdio>

#include "gestura/core/error.hpp"
#include "gestura/render/look.hpp"

namespace gestura::app {
namespace {

// Numbers inside a coded value: the field's error is raised by the caller (as_field_error), so
// these name only the part.
std::vector<float> numbers(std::string_view text, std::initializer_list<std::size_t> counts, std::string_view expected) {
  try {
    return parse_number_list(text, counts, FieldInfo{.name = "", .value = expected});
  } catch (const AppError& e) {
    throw Error(e.message());
  }
}

std::string shown(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
  return buf;
}

}  // namespace

ImageSize TextCodec<ImageSize>::parse(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  const auto side = [&](std::string_view part) {
    int value = 0;
    if (part.empty() || part.size() > 6 || part.find_first_not_of("0123456789") != std::string_view::npos) return -1;
    for (char c : part) value = value * 10 + (c - '0');
    return value;
  };
  const ImageSize size = x == std::string_view::npos ? ImageSize{-1, -1}
                                                     : ImageSize{side(text.substr(0, x)), side(text.substr(x + 1))};
  if (size.width < 0 || size.height < 0)
    throw Error("'" + std::string(text.substr(0, 40)) + "' is not WIDTHxHEIGHT (e.g. 1280x720)");
  check_image_size(size);
  return size;
}

std::string TextCodec<ImageSize>::format(const ImageSize& size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

CameraList TextCodec<CameraList>::parse(std::string_view text) { return parse_camera_list(std::string(text)); }

std::string TextCodec<CameraList>::format(const CameraList& cameras) {
  std::string out;
  for (CameraPreset c : cameras) out += (out.empty() ? "" : ",") + std::string(preset_name(c));
  return out;
}

ManualAlphabet TextCodec<ManualAlphabet>::parse(std::string_view text) {
  if (text == "asl" || text == "ASL") return ManualAlphabet::Asl;
  if (text == "bsl" || text == "BSL") return ManualAlphabet::Bsl;
  throw Error("'" + std::string(text.substr(0, 40)) + "' is not asl or bsl");
}

std::string TextCodec<ManualAlphabet>::format(ManualAlphabet alphabet) {
  return alphabet == ManualAlphabet::Asl ? "asl" : "bsl";
}

vec3 TextCodec<vec3>::parse(std::string_view text) {
  const std::vector<float> v = numbers(text, {3}, "x,y,z in metres");
  return {v[0], v[1], v[2]};
}

std::string TextCodec<vec3>::format(const vec3& v) { return shown(v.x) + "," + shown(v.y) + "," + shown(v.z); }

HexColor TextCodec<HexColor>::parse(std::string_view text) { return {parse_hex_color(std::string(text))}; }

std::string TextCodec<HexColor>::format(const HexColor& color) {
  char buf[8];
  const auto byte = [](float c) { return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(color.rgb.x), byte(color.rgb.y), byte(color.rgb.z));
  return buf;
}

OrbitView TextCodec<OrbitView>::parse(std::string_view text) {
  const std::vector<float> v = numbers(text, {3, 6}, "YAW,PITCH,DISTANCE[,X,Y,Z], e.g. 30,10,2.5");
  if (!(v[2] > 0.0f && v[2] < 1000.0f)) throw Error("the distance " + shown(v[2]) + " must be more than 0 and under 1000 m");
  OrbitView orbit{v[0], v[1], v[2], std::nullopt};
  if (v.size() == 6) orbit.target = vec3(v[3], v[4], v[5]);
  return orbit;
}

std::string TextCodec<OrbitView>::format(const OrbitView& orbit) {
  std::string out = shown(orbit.yaw_degrees) + "," + shown(orbit.pitch_degrees) + "," + shown(orbit.distance);
  if (orbit.target) out += "," + TextCodec<vec3>::format(*orbit.target);
  return out;
}

}  // namespace gestura::app
