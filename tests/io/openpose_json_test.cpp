// Reading OpenPose keypoint JSON: what gestura writes reads back to the same numbers; what OpenPose
// writes (other body models, faces, 3D arrays) reads; malformed frames and broken sequences give
// errors naming the file and the place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include <nlohmann/json.hpp>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/openpose_json.hpp"

namespace {

using namespace gestura;
namespace fs = std::filesystem;

struct Folder {
  fs::path path;
  Folder() {
    std::random_device random;
    path = fs::temp_directory_path() / ("gestura-openpose-" + std::to_string(random()) + std::to_string(random()));
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream((path / name).string(), std::ios::binary) << text;
    return (path / name).string();
  }
};

std::string error_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OpenPoseRead, WhatGesturaWritesReadsBack) {
  Folder dir;
  const Skeleton skeleton = synthetic_humanoid();
  const Clip clip = synthetic_clip(skeleton, 1.0f, 30.0f);
  const std::vector<std::string> written = save_openpose_json((dir.path / "kp.json").string(), skeleton, clip, 10.0f);
  ASSERT_EQ(written.size(), 11u);
  const std::vector<std::string> texts = openpose_json_frames(skeleton, clip, 10.0f);

  for (const std::string& from : {(dir.path / "kp.json").string(), dir.path.string()}) {
    const OpenPoseSequence sequence = load_openpose_json(from);
    ASSERT_EQ(sequence.frames.size(), written.size()) << from;
    EXPECT_EQ(sequence.files, written);
    for (std::size_t f = 0; f < texts.size(); ++f) {
      const auto expected = nlohmann::json::parse(texts[f])["people"][0];
      ASSERT_EQ(sequence.frames[f].people.size(), 1u);
      const OpenPosePerson& p = sequence.frames[f].people[0];
      EXPECT_EQ(p.person_id, -1);
      ASSERT_EQ(p.pose_2d.size(), 75u);
      ASSERT_EQ(p.hand_left_2d.size(), 63u);
      ASSERT_EQ(p.hand_right_2d.size(), 63u);
      EXPECT_TRUE(p.face_2d.empty() && p.pose_3d.empty());
      for (std::size_t i = 0; i < 75; ++i) EXPECT_FLOAT_EQ(p.pose_2d[i], expected["pose_keypoints_2d"][i].get<float>());
      for (std::size_t i = 0; i < 63; ++i)
        EXPECT_FLOAT_EQ(p.hand_right_2d[i], expected["hand_right_keypoints_2d"][i].get<float>());
    }
  }
  // One existing file is one frame.
  const OpenPoseSequence one = load_openpose_json(written[3]);
  ASSERT_EQ(one.frames.size(), 1u);
  EXPECT_EQ(one.files[0], written[3]);
}

TEST(OpenPoseRead, ReadsOpenPosesOwnOutput) {
  // COCO's 18 body points, a 70-point face, two people, 3D arrays, version 1.1 style.
  nlohmann::json person = {{"person_id", {-1}}, {"pose_keypoints_2d", std::vector<double>(54, 1.5)},
                           {"face_keypoints_2d", std::vector<double>(210, 2.0)},
                           {"hand_left_keypoints_2d", nlohmann::json::array()},
                           {"pose_keypoints_3d", std::vector<double>(72, 0.25)}};
  nlohmann::json other = person;
  other["person_id"] = 7;
  const nlohmann::json doc = {{"version", 1.1}, {"people", {person, other}}, {"part_candidates", nlohmann::json::array()}};
  const OpenPoseFrame frame = read_openpose_frame(doc.dump(), "coco.json");
  ASSERT_EQ(frame.people.size(), 2u);
  EXPECT_EQ(frame.people[0].pose_2d.size(), 54u);
  EXPECT_EQ(frame.people[0].face_2d.size(), 210u);
  EXPECT_EQ(frame.people[0].pose_3d.size(), 72u);
  EXPECT_TRUE(frame.people[0].hand_left_2d.empty() && frame.people[0].hand_right_2d.empty());
  EXPECT_EQ(frame.people[1].person_id, 7);
  EXPECT_TRUE(read_openpose_frame(R"({"version":1.3,"people":[]})", "empty.json").people.empty());
}

TEST(OpenPoseRead, MalformedFramesNameTheFileAndPlace) {
  const std::string not_json = error_of([] { read_openpose_frame("{\"people\": [\n  {\"pose_keypoints_2d\": [1, 2,]}]}", "a.json"); });
  EXPECT_NE(not_json.find("a.json:2:"), std::string::npos) << not_json;
  EXPECT_NE(error_of([] { read_openpose_frame(R"({"version":1.3})", "b.json"); }).find("no \"people\""), std::string::npos);
  const std::string odd = error_of([] { read_openpose_frame(R"({"people":[{},{"pose_keypoints_2d":[1,2,3,4]}]})", "c.json"); });
  EXPECT_NE(odd.find("c.json: people[1].pose_keypoints_2d: 4 numbers"), std::string::npos) << odd;
  const std::string text = error_of([] { read_openpose_frame(R"({"people":[{"hand_left_keypoints_2d":[1,"x",3]}]})", "d.json"); });
  EXPECT_NE(text.find("people[0].hand_left_keypoints_2d[1]: not a number"), std::string::npos) << text;
  const std::string huge = error_of([] { read_openpose_frame(R"({"people":[{"pose_keypoints_2d":[1e300,0,1]}]})", "e.json"); });
  EXPECT_NE(huge.find("finite"), std::string::npos) << huge;
  EXPECT_NE(error_of([] { read_openpose_frame("[1,2,3]", "f.json"); }), "");
  // Found by fuzz_openpose_json: a number past a double's range made the JSON library throw an
  // exception of another kind than a parse error, which escaped the reader.
  const std::string overflow = error_of([] { read_openpose_frame(R"({"people":[{"pose_keypoints_2d":[552.11e308036376953125,0,1]}]})", "o.json"); });
  EXPECT_NE(overflow.find("o.json"), std::string::npos) << overflow;
  EXPECT_NE(error_of([] { read_openpose_frame(std::string(1000, '['), "g.json"); }), "");
  EXPECT_NE(error_of([] { read_openpose_frame(std::string("\x00\xff\x01", 3), "h.json"); }), "");
  const std::string people = error_of([] {
    std::string many = "{\"people\":[";
    for (std::size_t i = 0; i <= kMaxOpenPosePeople; ++i) many += i ? ",{}" : "{}";
    read_openpose_frame(many + "]}", "i.json");
  });
  EXPECT_NE(people.find("kMaxOpenPosePeople"), std::string::npos) << people;
}

TEST(OpenPoseRead, BrokenSequencesNameTheFrame) {
  Folder dir;
  const std::string frame = R"({"version":1.3,"people":[]})";
  dir.write("s_000000000000_keypoints.json", frame);
  dir.write("s_000000000002_keypoints.json", frame);
  const std::string gap = error_of([&] { load_openpose_json((dir.path / "s.json").string()); });
  EXPECT_NE(gap.find("frame 1 is missing"), std::string::npos) << gap;
  dir.write("s_000000000001_keypoints.json", "{\"people\": 3}");
  const std::string bad = error_of([&] { load_openpose_json((dir.path / "s.json").string()); });
  EXPECT_NE(bad.find("s_000000000001_keypoints.json: people: not an array"), std::string::npos) << bad;
  dir.write("s_000000000001_keypoints.json", frame);
  EXPECT_EQ(load_openpose_json((dir.path / "s.json").string()).frames.size(), 3u);
  dir.write("t_1_keypoints.json", frame);  // another sequence's frame 1 in the same folder
  const std::string twice = error_of([&] { load_openpose_json(dir.path.string()); });
  EXPECT_NE(twice.find("appears twice"), std::string::npos) << twice;
  const std::string none = error_of([&] { load_openpose_json((dir.path / "missing.json").string()); });
  EXPECT_NE(none.find("no OpenPose keypoint files"), std::string::npos) << none;
}

}  // namespace
