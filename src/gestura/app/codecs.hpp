#pragma once
// How the value types of request fields are written as text (TextCodec, fields.hpp): the same
// spelling on the command line, in JSON and in messages.
//
//   ImageSize        "1280x720"
//   CameraList       "front" or "front,side,top" (a split view)
//   Sex              female | male | neutral
//   SkinWeightMethod field | spheres | two-layer
//   ManualAlphabet   asl | bsl
//   vec3             "x,y,z" in metres
//   HexColor         "#rrggbb"
//   OrbitView        "YAW,PITCH,DIST[,X,Y,Z]"
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/app/fields.hpp"
#include "gestura/body/avatar_params.hpp"
#include "gestura/body/skin_weights.hpp"
#include "gestura/core/math.hpp"
#include "gestura/render/camera.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"

namespace gestura::app {

using CameraList = std::vector<CameraPreset>;

// An sRGB colour (0..1) written "#rrggbb".
struct HexColor {
  vec3 rgb{0.0f};
};

// A free camera about a target: degrees about +Y from the front, degrees up, metres away; the target
// is the body's centre unless given.
struct OrbitView {
  float yaw_degrees = 0.0f, pitch_degrees = 0.0f, distance = 3.0f;
  std::optional<vec3> target;
};

template <>
struct TextCodec<ImageSize> {
  static ImageSize parse(std::string_view text);
  static std::string format(const ImageSize& size);
};
template <>
struct TextCodec<CameraList> {
  static CameraList parse(std::string_view text);
  static std::string format(const CameraList& cameras);
};
template <>
struct TextCodec<Sex> {
  static Sex parse(std::string_view text) { return parse_sex(text); }
  static std::string format(Sex sex) { return std::string(to_string(sex)); }
};
template <>
struct TextCodec<SkinWeightMethod> {
  static SkinWeightMethod parse(std::string_view text) { return parse_skin_weight_method(text); }
  static std::string format(SkinWeightMethod method) { return std::string(to_string(method)); }
};
template <>
struct TextCodec<ManualAlphabet> {
  static ManualAlphabet parse(std::string_view text);
  static std::string format(ManualAlphabet alphabet);
};
template <>
struct TextCodec<vec3> {
  static vec3 parse(std::string_view text);
  static std::string format(const vec3& v);
};
template <>
struct TextCodec<HexColor> {
  static HexColor parse(std::string_view text);
  static std::string format(const HexColor& color);
};
template <>
struct TextCodec<OrbitView> {
  static OrbitView parse(std::string_view text);
  static std::string format(const OrbitView& orbit);
};

}  // namespace gestura::app
