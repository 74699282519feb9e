// `gestura render CLIP.bvh` end to end: a BVH written on the avatar's skeleton (make_bvh) raising
// the left arm moves the hand's pixels; clips on other skeletons, unreadable files and unknown
// formats fail clearly without writing anything.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "gestura/io/bvh.hpp"
#include "gestura/render/camera.hpp"
#include "support/avatar_subject.hpp"
#include "support/cli.hpp"
#include "support/png_file.hpp"


namespace gestura {
namespace {

namespace fs = std::filesystem;
constexpr int kW = 320, kH = 180;

class RenderBvh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gestura_render_bvh_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Runs `gestura render ARGS`; returns the exit status, stderr (alone) in `errors`.
  static int render(const std::string& args, std::string* errors = nullptr) {
    const test::CliRun run = test::run_cli("render " + args + " >/dev/null");
    if (errors) *errors = run.output;
    return run.status;
  }
  fs::path dir_;
};

// --background #808080
bool background(const test::PngPixels& image, glm::ivec2 px) {
  const std::uint8_t* p = image.at(px.x, px.y);
  return std::abs(p[0] - 128) <= 1 && std::abs(p[1] - 128) <= 1 && std::abs(p[2] - 128) <= 1;
}

glm::ivec2 project(const Camera& camera, vec3 p) {
  const vec4 clip = camera.projection * camera.view * vec4(p, 1.0f);
  const vec3 ndc = vec3(clip) / clip.w;
  return {int((ndc.x * 0.5f + 0.5f) * kW), int((0.5f - ndc.y * 0.5f) * kH)};
}

TEST_F(RenderBvh, RaisedArmMovesTheHandPixels) {
  const RenderSubject& avatar = default_avatar_subject();
  const Skeleton& s = avatar.skeleton;
  const int shoulder = s.find("l_shoulder");
  ASSERT_GE(shoulder, 0);
  const quat raised = joint_rotation(s, shoulder, vec3(0.0f, 0.0f, deg(80.0f)));  // abduction: arm out to the side
  Clip clip;
  clip.duration = 1.0f;
  clip.resize_joints(s.size());
  clip.rotations[static_cast<std::size_t>(shoulder)].add(0.0f, quat(1.0f, 0.0f, 0.0f, 0.0f));
  clip.rotations[static_cast<std::size_t>(shoulder)].add(1.0f, raised);
  const std::string bvh = path("raise.bvh");
  save_bvh(bvh, make_bvh(s, clip, 0.1f));

  const std::string common = " --size 320x180 --background '#808080' --camera front";
  ASSERT_EQ(render(bvh + " --time 1 -o " + path("raised.png") + common), 0);
  // Time 0 of the same clip is the rest pose, framed as the raised frame is (the framing holds the clip).
  ASSERT_EQ(render(bvh + " --time 0 -o " + path("rest.png") + common), 0);
  const test::PngPixels up = test::read_png(path("raised.png"), 3), down = test::read_png(path("rest.png"), 3);
  ASSERT_EQ(up.width, kW);
  ASSERT_EQ(down.width, kW);

  auto hand_at = [&](const quat& shoulder_rotation) {
    Pose pose = rest_pose(s);
    pose.rotations[static_cast<std::size_t>(shoulder)] = shoulder_rotation;
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    return glm::mix(vec3(model[static_cast<std::size_t>(s.find("l_wrist"))][3]),
                    vec3(model[static_cast<std::size_t>(s.find("l_middle1"))][3]), 0.6f);
  };
  const Camera camera = preset_camera(CameraPreset::Front, framing_box(avatar.mesh, s, &clip), float(kW) / kH);
  const glm::ivec2 hand_up = project(camera, hand_at(raised));
  const glm::ivec2 hand_down = project(camera, hand_at(quat(1.0f, 0.0f, 0.0f, 0.0f)));
  for (glm::ivec2 px : {hand_up, hand_down}) ASSERT_TRUE(px.x >= 0 && px.x < kW && px.y >= 0 && px.y < kH) << px.x << "," << px.y;
  EXPECT_FALSE(background(up, hand_up)) << "the raised hand is drawn where the BVH put it";
  EXPECT_TRUE(background(down, hand_up)) << "nothing there at rest";
  EXPECT_FALSE(background(down, hand_down));
  EXPECT_TRUE(background(up, hand_down)) << "the hand has left its rest place";
}

TEST_F(RenderBvh, ClipOnAnotherSkeletonIsAClearError) {
  const std::string bvh = path("other.bvh");
  std::ofstream(bvh) << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                        "  JOINT LeftUpLeg\n  {\n    OFFSET 0.1 -0.1 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                        "    End Site\n    {\n      OFFSET 0 -0.4 0\n    }\n  }\n}\n"
                        "MOTION\nFrames: 1\nFrame Time: 0.033333\n0 0 0 0 0 0\n";
  std::string errors;
  EXPECT_EQ(render(bvh + " -o " + path("out.png"), &errors), 1);
  EXPECT_NE(errors.find("Hips"), std::string::npos) << errors;
  EXPECT_NE(errors.find("LeftUpLeg"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(RenderBvh, MalformedAndUnknownMotionFilesAreClearErrors) {
  const std::string bad = path("bad.bvh");
  std::ofstream(bad) << "HIERARCHY\nROOT l_shoulder\n{\n  OFFSET 0 zero 0\n";
  std::string errors;
  EXPECT_EQ(render(bad + " -o " + path("out.png"), &errors), 1);
  EXPECT_NE(errors.find("bad.bvh:4:"), std::string::npos) << errors;
  const std::string junk = path("motion.fbx");
  std::ofstream(junk) << "\x01\x02\x03";
  EXPECT_EQ(render(junk + " -o " + path("out.png"), &errors), 2) << "a kind of file render does not play: a usage error";
  EXPECT_NE(errors.find(".fbx"), std::string::npos) << errors;
  EXPECT_EQ(render(path("missing.bvh") + " -o " + path("out.png"), &errors), 1);
  EXPECT_NE(errors.find("missing.bvh"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

}  // namespace
}  // namespace gestura
