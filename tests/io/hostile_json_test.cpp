// JSON nested far deeper than any real file: readers give an error, never a stack overflow. An
// error message that quoted the offending value by dumping it recursed once per level; a glTF node
// whose child was an array nested 200,000 deep crashed `gestura convert` (SIGSEGV).
#include <gtest/gtest.h>

#include <string>

#include "gestura/core/error.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/json_excerpt.hpp"
#include "gestura/io/openpose_json.hpp"

#include <nlohmann/json.hpp>

namespace {

using namespace gestura;

std::string nested_array(int depth) { return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']'); }

template <class Body>
std::string error_of(Body&& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

constexpr int kDeep = 200000;

TEST(HostileJson, DeepGltfChildIsAnErrorNotACrash) {
  const std::string gltf = R"({"asset":{"version":"2.0"},"nodes":[{"children":[)" + nested_array(kDeep) + "]}]}";
  const std::string message = error_of([&] { read_gltf_animation(gltf, "deep.gltf"); });
  EXPECT_NE(message.find("deep.gltf"), std::string::npos) << message.substr(0, 200);
  EXPECT_NE(message.find("not a node index: an array of 1"), std::string::npos) << message.substr(0, 200);
}

TEST(HostileJson, DeepOpenPoseValueIsAnErrorNotACrash) {
  const std::string frame = R"({"people":[{"pose_keypoints_2d":[)" + nested_array(kDeep) + ",0,1]}]}";
  const std::string message = error_of([&] { read_openpose_frame(frame, "deep.json"); });
  EXPECT_NE(message.find("pose_keypoints_2d[0]: not a number: an array of 1"), std::string::npos) << message.substr(0, 200);
}

TEST(HostileJson, ExcerptsAreShort) {
  EXPECT_EQ(json_excerpt(nlohmann::json(12)), "12");
  EXPECT_EQ(json_excerpt(nlohmann::json("node")), "\"node\"");
  EXPECT_EQ(json_excerpt(nlohmann::json(std::string(1000, 'x'))).size(), 45u);
  EXPECT_EQ(json_excerpt(nlohmann::json::parse(R"({"a":1,"b":[2]})")), "an object of 2 members");
  EXPECT_EQ(json_excerpt(nlohmann::json(std::string("\xff\xfe"))), "\"\xEF\xBF\xBD\xEF\xBF\xBD\"");  // invalid UTF-8 replaced
}

}  // namespace
