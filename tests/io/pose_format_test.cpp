// .pose export read back by a reader written here from the published layout (not the library's
// code), OpenPose JSON against the same projection, malformed inputs to the encoder, the CLI rows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/openpose_json.hpp"
#include "gestura/io/pose_format.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura;

// Independent reader: little-endian, strings are uint16 length + bytes.
struct SpecReader {
  const std::string& bytes;
  std::size_t at = 0;
  template <class T>
  T take() {
    if (at + sizeof(T) > bytes.size()) throw std::runtime_error("truncated at byte " + std::to_string(at));
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  std::string text() {
    const auto n = take<std::uint16_t>();
    if (at + n > bytes.size()) throw std::runtime_error("truncated string");
    std::string s = bytes.substr(at, n);
    at += n;
    return s;
  }
};

struct ParsedComponent {
  std::string name, format;
  std::vector<std::string> points;
  std::vector<std::pair<int, int>> limbs;
  int colors = 0;
};

struct Parsed {
  float version = 0, fps = 0;
  int width = 0, height = 0, depth = 0, people = 0;
  std::uint32_t frames = 0;
  std::vector<ParsedComponent> components;
  std::vector<float> data, confidence;
};

Parsed parse(const std::string& bytes) {
  SpecReader r{bytes};
  Parsed p;
  p.version = r.take<float>();
  p.width = r.take<std::uint16_t>();
  p.height = r.take<std::uint16_t>();
  p.depth = r.take<std::uint16_t>();
  const int components = r.take<std::uint16_t>();
  std::size_t points = 0, dims = 0;
  for (int c = 0; c < components; ++c) {
    ParsedComponent pc;
    pc.name = r.text();
    pc.format = r.text();
    const int np = r.take<std::uint16_t>(), nl = r.take<std::uint16_t>(), nc = r.take<std::uint16_t>();
    for (int i = 0; i < np; ++i) pc.points.push_back(r.text());
    for (int i = 0; i < nl; ++i) {
      const int a = r.take<std::uint16_t>();
      pc.limbs.emplace_back(a, r.take<std::uint16_t>());
    }
    for (int i = 0; i < nc * 3; ++i) r.take<std::uint16_t>();
    pc.colors = nc;
    points += pc.points.size();
    dims = std::max(dims, pc.format.size() - 1);
    p.components.push_back(std::move(pc));
  }
  p.fps = r.take<float>();
  p.frames = r.take<std::uint32_t>();
  p.people = r.take<std::uint16_t>();
  const std::size_t cells = std::size_t(p.frames) * std::size_t(p.people) * points;
  for (std::size_t i = 0; i < cells * dims; ++i) p.data.push_back(r.take<float>());
  for (std::size_t i = 0; i < cells; ++i) p.confidence.push_back(r.take<float>());
  EXPECT_EQ(r.at, bytes.size()) << "bytes after the body";
  return p;
}

// The avatar bending its left elbow by 90° over one second.
Clip elbow_clip(const Skeleton& s) {
  Clip clip;
  clip.resize_joints(s.size());
  clip.duration = 1.0f;
  QuatTrack& t = clip.rotations[static_cast<std::size_t>(s.find("l_elbow"))];
  t.add(0.0f, quat(1, 0, 0, 0));
  t.add(1.0f, glm::angleAxis(deg(-90.0f), vec3(1, 0, 0)));
  return clip;
}

TEST(PoseFormat, SkeletonLayoutReadsBackBySpec) {
  const Skeleton avatar = build_avatar_skeleton();
  const std::string bytes = encode_pose(pose_from_clip(avatar, elbow_clip(avatar), 10.0f, PoseLayout::Skeleton3D));
  const Parsed p = parse(bytes);
  EXPECT_FLOAT_EQ(p.version, 0.2f);
  ASSERT_EQ(p.components.size(), 1u);
  EXPECT_EQ(p.components[0].format, "XYZC");
  EXPECT_EQ(p.components[0].points, avatar.names);
  EXPECT_EQ(p.components[0].limbs.size(), avatar.size() - 1);
  EXPECT_EQ(p.components[0].colors, static_cast<int>(avatar.size() - 1));
  for (const auto& [from, to] : p.components[0].limbs) EXPECT_EQ(avatar.parents[static_cast<std::size_t>(to)], from);
  EXPECT_FLOAT_EQ(p.fps, 10.0f);
  EXPECT_EQ(p.frames, 11u);
  EXPECT_EQ(p.people, 1);
  // Frame 0 is the rest pose; the last frame has the wrist in front of the elbow (forearm forward).
  const auto rest = rest_joint_positions(avatar);
  const std::size_t n = avatar.size();
  for (std::size_t j = 0; j < n; ++j)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(p.data[j * 3 + static_cast<std::size_t>(d)], rest[j][d], 1e-5f);
  const std::size_t elbow = static_cast<std::size_t>(avatar.find("l_elbow")), wrist = static_cast<std::size_t>(avatar.find("l_wrist"));
  const std::size_t last = 10 * n * 3;
  const float forearm = glm::length(rest[wrist] - rest[elbow]);
  EXPECT_NEAR(p.data[last + wrist * 3 + 2] - p.data[last + elbow * 3 + 2], forearm, 0.02f * forearm);
  for (float c : p.confidence) EXPECT_EQ(c, 1.0f);
}

TEST(PoseFormat, OpenPoseLayoutProjectsAFrontView) {
  const Skeleton avatar = build_avatar_skeleton();
  Clip rest;
  rest.resize_joints(avatar.size());
  const PinholeCamera camera;
  const Parsed p = parse(encode_pose(pose_from_clip(avatar, rest, 25.0f, PoseLayout::OpenPose2D, camera)));
  ASSERT_EQ(p.components.size(), 3u);
  EXPECT_EQ(p.components[0].name, "pose_keypoints_2d");
  EXPECT_EQ(p.components[0].points.size(), 25u);
  EXPECT_EQ(p.components[1].points.size(), 21u);
  EXPECT_EQ(p.components[2].name, "hand_right_keypoints_2d");
  EXPECT_EQ(p.width, 1280);
  EXPECT_EQ(p.height, 720);
  EXPECT_EQ(p.frames, 1u);
  auto xy = [&](std::size_t point) { return vec2(p.data[point * 2], p.data[point * 2 + 1]); };
  // Seen from the front, the avatar's left (LShoulder = 5) is on the image's right.
  EXPECT_GT(xy(5).x, xy(2).x);
  EXPECT_LT(xy(0).y, xy(1).y) << "nose above neck (image y grows downwards)";
  EXPECT_LT(xy(1).y, xy(8).y) << "neck above mid-hip";
  EXPECT_NEAR(xy(8).x, 640.0f, 2.0f) << "mid-hip on the image's centre line";
  // Pinhole check by hand: the left shoulder's pixel from its rest position.
  const vec3 s = rest_joint_positions(avatar)[static_cast<std::size_t>(avatar.find("l_shoulder"))];
  const float focal = 360.0f / std::tan(deg(17.5f));
  EXPECT_NEAR(xy(5).x, 640.0f + focal * s.x / (3.2f - s.z), 0.01f);
  EXPECT_NEAR(xy(5).y, 360.0f - focal * (s.y - 1.0f) / (3.2f - s.z), 0.01f);
  for (float c : p.confidence) EXPECT_EQ(c, 1.0f);  // the avatar has every joint the keypoints need
}

// Found by fuzz_pose (UBSan, in its first thousand inputs): a file with no frames made the reader
// memcpy from an empty vector's null data(), undefined behaviour. A pose without frames (or
// without points) reads back empty; `make test-asan` runs this under UBSan.
TEST(PoseFormat, AFileWithoutFramesReadsBackEmpty) {
  PoseData pose;
  pose.components.push_back({"c", "XYZC", {"a", "b"}, {{0, 1}}, {}});
  pose.frames = 0;
  const PoseData read = decode_pose(encode_pose(pose), "empty.pose");
  EXPECT_EQ(read.frames, 0u);
  EXPECT_TRUE(read.data.empty());
  EXPECT_TRUE(read.confidence.empty());
  ASSERT_EQ(read.components.size(), 1u);
  EXPECT_EQ(read.components[0].points, (std::vector<std::string>{"a", "b"}));
  pose.people = 0;
  pose.frames = 3;
  const PoseData nobody = decode_pose(encode_pose(pose), "nobody.pose");
  EXPECT_EQ(nobody.frames, 3u);
  EXPECT_TRUE(nobody.data.empty());
}

// Found by fuzz_pose's round trip: a pose read from a version 0.1 file was written with its 0.1
// version number over a 0.2 body, so `convert old.pose new.pose` made a file that read back wrong
// (the people count taken from the fps field). Output is always 0.2.
TEST(PoseFormat, APoseReadFromVersionPointOneIsWrittenAsPointTwo) {
  PoseData pose;
  pose.version = 0.1f;
  pose.components.push_back({"c", "XYC", {"a"}, {}, {}});
  pose.fps = 25.0f;
  pose.frames = 2;
  pose.people = 3;
  pose.data.assign(2 * 3 * 2, 0.5f);
  pose.confidence.assign(2 * 3, 1.0f);
  const std::string bytes = encode_pose(pose);
  float version = 0.0f;
  std::memcpy(&version, bytes.data(), sizeof version);
  EXPECT_FLOAT_EQ(version, 0.2f);
  const PoseData read = decode_pose(bytes, "converted.pose");
  EXPECT_EQ(read.frames, 2u);
  EXPECT_EQ(read.people, 3);
  EXPECT_FLOAT_EQ(read.fps, 25.0f);
  EXPECT_EQ(read.data, pose.data);
}

TEST(PoseFormat, EncoderRejectsWhatTheFormatCannotHold) {
  PoseData pose;
  EXPECT_THROW(encode_pose(pose), Error);  // no component
  pose.components.push_back({"c", "XYC", {"a", "b"}, {{0, 5}}, {}});
  pose.frames = 1;
  pose.data = {0, 0, 0, 0};
  pose.confidence = {1, 1};
  try {
    encode_pose(pose);
    ADD_FAILURE() << "limb past the points accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("limb"), std::string::npos) << e.what();
  }
  pose.components[0].limbs = {{0, 1}};
  EXPECT_NO_THROW(encode_pose(pose));
  pose.data.pop_back();
  EXPECT_THROW(encode_pose(pose), Error);
  pose.data.push_back(0);
  pose.components[0].points[0] = std::string(70000, 'x');
  EXPECT_THROW(encode_pose(pose), Error);
}

TEST(OpenPoseJson, FramesCarryTheProjectedKeypoints) {
  const Skeleton avatar = build_avatar_skeleton();
  const Clip clip = elbow_clip(avatar);
  const std::vector<std::string> frames = openpose_json_frames(avatar, clip, 4.0f);
  ASSERT_EQ(frames.size(), 5u);
  const Parsed p = parse(encode_pose(pose_from_clip(avatar, clip, 4.0f, PoseLayout::OpenPose2D)));
  const std::size_t per_frame = 25 + 21 + 21;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const nlohmann::json doc = nlohmann::json::parse(frames[f]);
    const auto& person = doc.at("people").at(0);
    ASSERT_EQ(person.at("pose_keypoints_2d").size(), 75u);
    ASSERT_EQ(person.at("hand_left_keypoints_2d").size(), 63u);
    ASSERT_EQ(person.at("hand_right_keypoints_2d").size(), 63u);
    EXPECT_TRUE(person.at("face_keypoints_2d").empty());
    // Left wrist (BODY_25 #7) matches the .pose export's point of the same frame.
    const std::size_t at = f * per_frame + 7;
    EXPECT_NEAR(person["pose_keypoints_2d"][21].get<float>(), p.data[at * 2], 1e-3f);
    EXPECT_NEAR(person["pose_keypoints_2d"][22].get<float>(), p.data[at * 2 + 1], 1e-3f);
    EXPECT_EQ(person["pose_keypoints_2d"][23].get<float>(), 1.0f);
  }
}

using test::CliRun;
using test::run_cli;

using gestura::test::shared_data;

TEST(PoseFormatCli, ConvertWritesPoseAndOpenPoseJson) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("gestura_pose_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string in = shared_data() + "/makehuman/poses/standing01.bvh";
  const CliRun pose = run_cli("convert '" + in + "' '" + (dir / "out.pose").string() + "' --scale 0.1 --z-up");
  ASSERT_EQ(pose.status, 0) << pose.output;
  std::ifstream file(dir / "out.pose", std::ios::binary);
  std::stringstream bytes;
  bytes << file.rdbuf();
  const Parsed p = parse(bytes.str());
  const BvhFile bvh = load_bvh(in, {0.1f, true});
  EXPECT_EQ(p.components[0].points, bvh.skeleton.names);
  EXPECT_EQ(p.frames, static_cast<std::uint32_t>(bvh.frame_count));

  EXPECT_EQ(run_cli("convert '" + in + "' '" + (dir / "kp.json").string() + "'").status, 2) << "needs --openpose";
  const CliRun json = run_cli("convert '" + in + "' '" + (dir / "kp.json").string() + "' --scale 0.1 --z-up --openpose");
  ASSERT_EQ(json.status, 0) << json.output;
  std::ifstream frame0(dir / "kp_000000000000_keypoints.json");
  ASSERT_TRUE(frame0);
  const nlohmann::json doc = nlohmann::json::parse(frame0);
  // The MakeHuman skeleton's names map to H-Anim, so its wrists and finger tips become keypoints.
  EXPECT_EQ(doc["people"][0]["pose_keypoints_2d"][23].get<float>(), 1.0f);
  EXPECT_EQ(doc["people"][0]["hand_left_keypoints_2d"][8 * 3 + 2].get<float>(), 1.0f);
  std::filesystem::remove_all(dir);
}

}  // namespace
