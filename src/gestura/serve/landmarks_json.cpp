#include "gestura/serve/landmarks_json.hpp"

#include <cmath>
#include <string>

#include "gestura/app/error.hpp"

namespace gestura::serve {
namespace {

using nlohmann::json;

std::string at(const std::string& part, std::size_t i) { return part + "[" + std::to_string(i) + "]"; }

// A part: null / absent (nothing found) or exactly `count` points (or `alternative`, the face with
// refined irises), each [x, y, z] or [x, y, z, visibility].
std::vector<vec3> read_part(const json& message, const std::string& part, std::size_t count, std::size_t alternative,
                            std::vector<float>* visibility) {
  std::vector<vec3> out;
  const auto it = message.find(part);
  if (it == message.end() || it->is_null()) return out;
  const std::string expected = std::to_string(count) + (alternative ? " (or " + std::to_string(alternative) + ")" : "");
  if (!it->is_array()) app::usage_error(part, "expected the " + expected + " landmarks of MediaPipe Holistic as [[x, y, z], …]");
  if (it->size() != count && (alternative == 0 || it->size() != alternative))
    app::usage_error(part, "has " + std::to_string(it->size()) + " points; MediaPipe Holistic reports " + expected);
  out.resize(it->size());
  if (visibility) visibility->assign(it->size(), 1.0f);
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& point = (*it)[i];
    if (!point.is_array() || point.size() < 3 || point.size() > 4)
      app::usage_error(at(part, i), "expected [x, y, z] or [x, y, z, visibility]");
    for (std::size_t k = 0; k < point.size(); ++k) {
      const json& v = point[k];
      const std::string where = at(part, i) + "[" + std::to_string(k) + "]";
      if (!v.is_number()) app::usage_error(where, "expected a number");
      const double x = v.get<double>();
      if (!std::isfinite(x)) app::usage_error(where, "is not a finite number");
      if (k == 3) {
        if (x < 0.0 || x > 1.0) app::usage_error(where, "a visibility is between 0 and 1");
        if (visibility) (*visibility)[i] = static_cast<float>(x);
        continue;
      }
      if (std::abs(x) > kLandmarkRange)
        app::usage_error(where, std::to_string(x) + " is outside ±" + std::to_string(static_cast<int>(kLandmarkRange)) +
                                    " (picture-normalised coordinates)");
      out[i][static_cast<int>(k)] = static_cast<float>(x);
    }
  }
  return out;
}

}  // namespace

HolisticFrame landmarks_from_json(const json& message) {
  HolisticFrame frame;
  if (!message.contains("pose") || message["pose"].is_null())
    app::usage_error("pose", "expected the 33 body landmarks of MediaPipe Holistic as [[x, y, z, visibility], …]");
  frame.pose = read_part(message, "pose", kHolisticPosePoints, 0, &frame.pose_visibility);
  frame.left_hand = read_part(message, "left", kHolisticHandPoints, 0, nullptr);
  frame.right_hand = read_part(message, "right", kHolisticHandPoints, 0, nullptr);
  frame.face = read_part(message, "face", kHolisticFacePoints, 478, nullptr);
  if (message.contains("aspect")) {
    const json& a = message["aspect"];
    if (!a.is_number() || !(a.get<double>() >= 0.1 && a.get<double>() <= 10.0))
      app::usage_error("aspect", "expected the picture's width / height, a number from 0.1 to 10");
    frame.aspect = a.get<float>();
  }
  for (const auto& [key, value] : message.items())
    if (key != "type" && key != "pose" && key != "left" && key != "right" && key != "face" && key != "aspect")
      app::usage_error(key, "unknown field of a landmarks message (known: pose, left, right, face, aspect)");
  return frame;
}

}  // namespace gestura::serve
