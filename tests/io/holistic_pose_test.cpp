// MediaPipe Holistic landmarks of the avatar (io/holistic_landmarks) and their .pose layout, the
// .pose reader, and the CLI rows that write, describe and re-encode .pose files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/io/holistic_landmarks.hpp"
#include "gestura/io/pose_format.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/signing_avatar.hpp"

namespace {

using namespace gestura;

const Avatar& avatar() { return test::signing_avatar().avatar; }

FaceLandmarkBinding binding() {
  static const FaceLandmarkBinding b = bind_face_landmarks(avatar().skeleton, avatar().mesh);
  return b;
}

vec3 rest_point(int landmark) {
  const std::int32_t v = binding().vertex[static_cast<std::size_t>(landmark)];
  EXPECT_GE(v, 0) << "face landmark " << landmark << " not bound";
  return v >= 0 ? avatar().mesh.positions[static_cast<std::size_t>(v)] : vec3(0.0f);
}

// A clip that holds the rest pose and drives one morph channel from 0 to `weight` over a second.
Clip morph_clip(const std::string& channel, float weight) {
  Clip clip;
  clip.duration = 1.0f;
  clip.resize_joints(avatar().skeleton.size());
  FloatTrack& track = clip.channel(channel);
  track.add(0.0f, 0.0f);
  track.add(1.0f, weight);
  return clip;
}

TEST(HolisticLandmarks, FaceContoursAreBoundWhereTheFaceHasThem) {
  const FaceLandmarkBinding& b = binding();
  // Lips 40, eyes 32, brows 20, oval 36, nose tip 1.
  EXPECT_GE(b.bound(), 120);
  for (int i : {61, 291, 0, 17, 13, 14, 33, 133, 263, 362, 159, 145, 386, 374, 105, 334, 10, 152, 234, 454, 1})
    EXPECT_GE(b.vertex[static_cast<std::size_t>(i)], 0) << i;
  // The signer's right (-X) carries the low face-mesh indices, the left (+X) the high ones.
  EXPECT_LT(rest_point(61).x, -0.01f);
  EXPECT_GT(rest_point(291).x, 0.01f);
  EXPECT_LT(rest_point(33).x, rest_point(133).x);
  EXPECT_LT(rest_point(133).x, 0.0f);
  EXPECT_GT(rest_point(362).x, 0.0f);
  EXPECT_LT(rest_point(362).x, rest_point(263).x);
  // Top to bottom: forehead, brow, upper lid, lower lid, nose tip, upper lip, lower lip, chin.
  const float ys[] = {rest_point(10).y, rest_point(105).y, rest_point(159).y, rest_point(145).y, rest_point(1).y,
                      rest_point(0).y, rest_point(17).y, rest_point(152).y};
  for (std::size_t k = 1; k < std::size(ys); ++k) EXPECT_GT(ys[k - 1], ys[k]) << "order broken at " << k;
  // The face is about as wide as a face: cheek to cheek 10–20 cm, nose tip in front of the lips.
  EXPECT_GT(rest_point(454).x - rest_point(234).x, 0.10f);
  EXPECT_LT(rest_point(454).x - rest_point(234).x, 0.20f);
  EXPECT_GT(rest_point(1).z, rest_point(0).z);
}

TEST(HolisticLandmarks, NoHeadMeansNoFacePoints) {
  Skeleton bare;
  bare.add_joint("humanoid_root", -1, vec3(0.0f, 1.0f, 0.0f));
  Mesh mesh;
  mesh.positions = {vec3(0, 1, 0), vec3(1, 1, 0), vec3(0, 2, 0)};
  mesh.normals.assign(3, vec3(0, 0, 1));
  mesh.materials.assign(3, 0);
  mesh.joints.assign(3, JointIndices(0));
  mesh.weights.assign(3, vec4(1, 0, 0, 0));
  mesh.indices = {0, 1, 2};
  EXPECT_EQ(bind_face_landmarks(bare, mesh).bound(), 0);
}

TEST(HolisticLandmarks, TheMouthOpensWithTheMouthingAndTheLidsCloseWithABlink) {
  const HolisticTrack open = holistic_track(avatar().skeleton, &avatar().mesh, morph_clip("mouthOpen", 1.0f), 10.0f);
  ASSERT_EQ(open.frames, 11);
  const auto face = [&](const HolisticTrack& t, int frame, int i) {
    return t.face[static_cast<std::size_t>(frame) * kHolisticFaceCount + static_cast<std::size_t>(i)];
  };
  const float closed_gap = glm::distance(face(open, 0, 13), face(open, 0, 14));
  const float open_gap = glm::distance(face(open, 10, 13), face(open, 10, 14));
  EXPECT_GT(open_gap, closed_gap + 0.008f) << "the inner lips part by less than 8 mm on mouthOpen";
  const HolisticTrack blink = holistic_track(avatar().skeleton, &avatar().mesh, morph_clip("eyeBlink_L", 1.0f), 10.0f);
  EXPECT_LT(glm::distance(face(blink, 10, 386), face(blink, 10, 374)), 0.5f * glm::distance(face(blink, 0, 386), face(blink, 0, 374)));
  // The right eye did not blink.
  EXPECT_NEAR(glm::distance(face(blink, 10, 159), face(blink, 10, 145)), glm::distance(face(blink, 0, 159), face(blink, 0, 145)), 1e-4f);
}

TEST(HolisticPose, LayoutIsPoseFormatsHolisticAndPixelsAreTheCamerasProjection) {
  Clip clip = morph_clip("aa", 0.5f);
  const HolisticTrack track = holistic_track(avatar().skeleton, &avatar().mesh, clip, 5.0f);
  PinholeCamera camera;
  camera.position = vec3(0.1f, 1.4f, 2.5f);
  camera.target = vec3(0.0f, 1.3f, 0.0f);
  camera.width = 640, camera.height = 360;
  const PoseData pose = holistic_pose(track, std::span(&camera, 1), 5.0f);
  ASSERT_EQ(pose.components.size(), 5u);
  const char* names[] = {"POSE_LANDMARKS", "FACE_LANDMARKS", "LEFT_HAND_LANDMARKS", "RIGHT_HAND_LANDMARKS", "POSE_WORLD_LANDMARKS"};
  const std::size_t counts[] = {33, 468, 21, 21, 33};
  for (std::size_t c = 0; c < 5; ++c) {
    EXPECT_EQ(pose.components[c].name, names[c]);
    EXPECT_EQ(pose.components[c].format, "XYZC");
    EXPECT_EQ(pose.components[c].points.size(), counts[c]);
  }
  EXPECT_EQ(pose.components[0].points[15], "LEFT_WRIST");
  EXPECT_EQ(pose.components[2].points[8], "INDEX_FINGER_TIP");
  EXPECT_EQ(pose.width, 640);
  EXPECT_EQ(pose.height, 360);
  EXPECT_EQ(pose.frames, 6u);
  // The left wrist, projected here independently of the writer.
  std::vector<mat4> model(avatar().skeleton.size());
  local_to_model(avatar().skeleton, rest_pose(avatar().skeleton), model);
  const vec3 wrist(model[static_cast<std::size_t>(avatar().skeleton.find("l_wrist"))][3]);
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, vec3(0, 1, 0))), up = glm::cross(right, forward);
  const float focal = 0.5f * 360.0f / std::tan(0.5f * camera.vertical_fov);
  const vec3 d = wrist - camera.position;
  const float px = 320.0f + focal * glm::dot(d, right) / glm::dot(d, forward);
  const float py = 180.0f - focal * glm::dot(d, up) / glm::dot(d, forward);
  const std::size_t points = pose.point_count();
  for (std::size_t f = 0; f < pose.frames; ++f) {
    const std::size_t k = f * points + 15;
    EXPECT_NEAR(pose.data[k * 3], px, 0.05f);
    EXPECT_NEAR(pose.data[k * 3 + 1], py, 0.05f);
    EXPECT_EQ(pose.confidence[k], 1.0f);
    // The hand's first point is its wrist, at depth 0 about itself.
    const std::size_t hand = f * points + 33 + 468;
    EXPECT_NEAR(pose.data[hand * 3], px, 0.05f);
    EXPECT_FLOAT_EQ(pose.data[hand * 3 + 2], 0.0f);
  }
  // The signer's left wrist is on the image's right in a front view; the nose is above the wrists.
  EXPECT_GT(px, 320.0f);
  EXPECT_LT(pose.data[0 * 3 + 1], py);
  // Unbound face points (e.g. 5, on the nose bridge) say so.
  EXPECT_EQ(pose.confidence[33 + 5], 0.0f);
}

TEST(PoseReader, ReadsBackWhatTheWriterWrote) {
  const HolisticTrack track = holistic_track(avatar().skeleton, &avatar().mesh, morph_clip("oh", 1.0f), 4.0f);
  const PoseData written = holistic_pose(track, std::vector<PinholeCamera>(1), 4.0f);
  const PoseData read = decode_pose(encode_pose(written), "mem.pose");
  EXPECT_FLOAT_EQ(read.version, 0.2f);
  EXPECT_EQ(read.width, written.width);
  EXPECT_EQ(read.frames, written.frames);
  EXPECT_EQ(read.fps, 4.0f);
  ASSERT_EQ(read.components.size(), written.components.size());
  for (std::size_t c = 0; c < read.components.size(); ++c) {
    EXPECT_EQ(read.components[c].points, written.components[c].points);
    EXPECT_EQ(read.components[c].limbs, written.components[c].limbs);
    EXPECT_EQ(read.components[c].colors, written.components[c].colors);
  }
  EXPECT_EQ(read.data, written.data);
  EXPECT_EQ(read.confidence, written.confidence);
  EXPECT_EQ(pose_component_offset(read, "LEFT_HAND_LANDMARKS"), 33 + 468);
  EXPECT_EQ(pose_component_offset(read, "nope"), -1);
}

// A tiny version 0.1 file, written byte by byte: fps and frame count are uint16, the count is what
// the remaining bytes hold.
TEST(PoseReader, ReadsVersion01) {
  std::string b;
  const auto raw = [&](const void* p, std::size_t n) { b.append(static_cast<const char*>(p), n); };
  const auto u16 = [&](std::uint16_t v) { raw(&v, 2); };
  const auto f32 = [&](float v) { raw(&v, 4); };
  const auto str = [&](const std::string& s) { u16(static_cast<std::uint16_t>(s.size())); raw(s.data(), s.size()); };
  f32(0.1f);
  u16(100), u16(50), u16(0), u16(1);
  str("P"), str("XYC"), u16(2), u16(1), u16(0), str("a"), str("b"), u16(0), u16(1);
  u16(25), u16(65535), u16(1);  // fps 25, a wrong 16-bit count
  for (float v : {1.f, 2.f, 3.f, 4.f, 5.f, 6.f, 7.f, 8.f}) f32(v);  // 2 frames × 2 points × XY
  for (float v : {1.f, 0.f, 1.f, 1.f}) f32(v);
  const PoseData pose = decode_pose(b, "old.pose");
  EXPECT_EQ(pose.fps, 25.0f);
  EXPECT_EQ(pose.frames, 2u);
  EXPECT_EQ(pose.data[6], 7.0f);
  EXPECT_EQ(pose.confidence[1], 0.0f);
}

TEST(PoseReader, BadFilesAreNamedErrors) {
  const std::string good = encode_pose(holistic_pose(holistic_track(avatar().skeleton, nullptr, morph_clip("aa", 1.0f), 2.0f),
                                                     std::vector<PinholeCamera>(1), 2.0f));
  const auto error_of = [](const std::string& bytes) {
    try {
      decode_pose(bytes, "bad.pose");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of(good.substr(0, good.size() - 3)).find("bad.pose: byte"), std::string::npos);
  EXPECT_NE(error_of(good.substr(0, 40)).find("ends inside"), std::string::npos);
  EXPECT_NE(error_of("").find("bad.pose"), std::string::npos);
  std::string version = good;
  const float v = 0.3f;
  std::memcpy(version.data(), &v, 4);
  EXPECT_NE(error_of(version).find("version"), std::string::npos);
  // A limb past its component's points: the first limb of POSE_LANDMARKS (after the header, two
  // strings, three counts and 33 names).
  std::string limb = good;
  std::size_t at = 4 + 6 + 2;
  const auto skip_str = [&] { std::uint16_t n; std::memcpy(&n, limb.data() + at, 2); at += 2 + n; };
  skip_str(), skip_str();
  at += 6;
  for (int i = 0; i < 33; ++i) skip_str();
  const std::uint16_t past = 900;
  std::memcpy(limb.data() + at, &past, 2);
  EXPECT_NE(error_of(limb).find("past its 33 points"), std::string::npos);
  EXPECT_EQ(error_of(good), "no error");
}

TEST(HolisticPoseCli, SayWritesAPoseThatInfoDescribesAndConvertReencodes) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("gestura_holistic_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "house.pose").string();
  const test::CliRun say = test::run_cli("say house -o '" + out + "' --size 640x360");
  ASSERT_EQ(say.status, 0) << say.output;
  const PoseData pose = load_pose(out);
  EXPECT_EQ(pose.width, 640);
  EXPECT_EQ(pose.fps, 30.0f);
  EXPECT_GT(pose.frames, 20u);
  // Both hands are in the picture at some moment, and the face is placed.
  const std::size_t points = pose.point_count();
  bool left_seen = false;
  for (std::size_t f = 0; f < pose.frames; ++f) {
    const std::size_t k = f * points + 15;
    left_seen |= pose.confidence[k] > 0 && pose.data[k * 3] > 0 && pose.data[k * 3] < 640 && pose.data[k * 3 + 1] < 360;
  }
  EXPECT_TRUE(left_seen);
  const test::CliRun info = test::run_cli("info '" + out + "'");
  EXPECT_EQ(info.status, 0) << info.output;
  EXPECT_NE(info.output.find("FACE_LANDMARKS"), std::string::npos);
  EXPECT_NE(info.output.find("640 x 360"), std::string::npos);
  const std::string copy = (dir / "copy.pose").string();
  EXPECT_EQ(test::run_cli("convert '" + out + "' '" + copy + "'").status, 0);
  EXPECT_EQ(load_pose(copy).data, pose.data);
  const test::CliRun to_bvh = test::run_cli("convert '" + out + "' '" + (dir / "x.bvh").string() + "'");
  EXPECT_EQ(to_bvh.status, 2) << "a usage error";
  EXPECT_NE(to_bvh.output.find("converts to .pose only"), std::string::npos);
  const test::CliRun ortho = test::run_cli("say house -o '" + (dir / "top.pose").string() + "' --camera top");
  EXPECT_EQ(ortho.status, 1);
  EXPECT_NE(ortho.output.find("orthographic"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "top.pose"));
  std::filesystem::remove_all(dir);
}

// sign.mt's own reader (the npm package pose-format) reads what gestura writes: the Holistic
// components and names, and the same numbers as gestura's reader.
TEST(HolisticPoseCli, PoseFormatsJavaScriptReaderReadsIt) {
  const std::string reader = test::source_dir() + "/tools/read-pose.mjs";
  if (!std::filesystem::exists(test::source_dir() + "/tools/node_modules/pose-format"))
    GTEST_SKIP() << "tools/node_modules/pose-format missing (cd tools && npm install)";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("gestura_posejs_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "sad.pose").string();
  ASSERT_EQ(test::run_cli("say sad -o '" + out + "' --size 640x360").status, 0);
  const test::CliRun read = test::run_command("node '" + reader + "' '" + out + "' 12 2>&1");
  ASSERT_EQ(read.status, 0) << read.output;
  const nlohmann::json j = nlohmann::json::parse(read.output);
  const PoseData ours = load_pose(out);
  EXPECT_EQ(j["width"], 640);
  EXPECT_EQ(j["height"], 360);
  EXPECT_EQ(j["fps"], 30);
  EXPECT_EQ(j["frames"], ours.frames);
  ASSERT_EQ(j["components"].size(), 5u);
  EXPECT_EQ(j["components"][0]["name"], "POSE_LANDMARKS");
  EXPECT_EQ(j["components"][0]["points"][16], "RIGHT_WRIST");
  EXPECT_EQ(j["components"][1]["points"].size(), 468u);
  EXPECT_EQ(j["components"][3]["points"][4], "THUMB_TIP");
  const std::size_t frame = 12, points = ours.point_count();
  for (const auto& [component, index] : {std::pair{"POSE_LANDMARKS", 16}, {"FACE_LANDMARKS", 14}, {"LEFT_HAND_LANDMARKS", 8}}) {
    const std::size_t k = frame * points + static_cast<std::size_t>(pose_component_offset(ours, component) + index);
    const nlohmann::json& p = j["points"][component][index];
    EXPECT_FLOAT_EQ(p[0].get<float>(), ours.data[k * 3]) << component;
    EXPECT_FLOAT_EQ(p[1].get<float>(), ours.data[k * 3 + 1]) << component;
    EXPECT_FLOAT_EQ(p[3].get<float>(), ours.confidence[k]) << component;
    EXPECT_EQ(p[3].get<float>(), 1.0f) << component;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
