#include "gestura/io/avatar_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_synthesis.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

using namespace gestura;

namespace {

std::string makehuman_dir() { return test::shared_data() + "/makehuman"; }

// Loaded once: the OBJ and the weights take a moment.
const Avatar* makehuman() {
  static const std::optional<Avatar> a = [] {
    if (!std::filesystem::exists(makehuman_dir() + "/base.obj")) return std::optional<Avatar>();
    return std::optional<Avatar>(load_avatar("makehuman:" + makehuman_dir()));
  }();
  return a ? &*a : nullptr;
}

std::vector<mat4> bind_model(const Skeleton& s) {
  Pose rest;
  rest.translations = s.rest_translations;
  rest.rotations = s.rest_rotations;
  rest.scales = s.rest_scales;
  std::vector<mat4> model(s.size());
  local_to_model(s, rest, model);
  return model;
}

vec3 joint_at(const Skeleton& s, const char* name) {
  const int j = s.find(name);
  EXPECT_GE(j, 0) << name;
  return j < 0 ? vec3(0.0f) : vec3(bind_model(s)[static_cast<std::size_t>(j)][3]);
}

#define NEED_MAKEHUMAN()                                                     \
  const Avatar* mh = makehuman();                                            \
  if (!mh) GTEST_SKIP() << "no MakeHuman assets at " << makehuman_dir()

}  // namespace

TEST(AvatarSource, MakeHumanStandsOnTheFloorAtHumanHeight) {
  NEED_MAKEHUMAN();
  float low = 1e9f, high = -1e9f;
  for (const vec3& p : mh->mesh.positions) low = std::min(low, p.y), high = std::max(high, p.y);
  EXPECT_NEAR(low, 0.0f, 0.02f);
  EXPECT_GT(high - low, 1.5f);
  EXPECT_LT(high - low, 1.9f);
  // The joints moved with the mesh: the ankles just above the floor, the head near the top.
  EXPECT_GT(joint_at(mh->skeleton, "l_ankle").y, 0.03f);
  EXPECT_LT(joint_at(mh->skeleton, "l_ankle").y, 0.15f);
  EXPECT_GT(joint_at(mh->skeleton, "skullbase").y, high - 0.35f);
  EXPECT_NEAR(joint_at(mh->skeleton, "skull_tip").y, high, 0.03f);
}

TEST(AvatarSource, MakeHumanFacesPlusZWithItsLeftOnPlusX) {
  NEED_MAKEHUMAN();
  const vec3 skull = joint_at(mh->skeleton, "skullbase");
  EXPECT_GT(joint_at(mh->skeleton, "l_eyeball_joint").z, skull.z + 0.03f);
  EXPECT_GT(joint_at(mh->skeleton, "r_eyeball_joint").z, skull.z + 0.03f);
  EXPECT_GT(joint_at(mh->skeleton, "l_shoulder").x, 0.1f);
  EXPECT_LT(joint_at(mh->skeleton, "r_shoulder").x, -0.1f);
  // The nose (the most forward point of the head) is in front of the skull base.
  float nose_z = -1e9f;
  for (const vec3& p : mh->mesh.positions)
    if (p.y > skull.y && std::abs(p.x) < 0.05f) nose_z = std::max(nose_z, p.z);
  EXPECT_GT(nose_z, skull.z + 0.07f);
}

TEST(AvatarSource, MakeHumanHasEyesAndOnlyTheBody) {
  NEED_MAKEHUMAN();
  ASSERT_EQ(mh->mesh.materials.size(), mh->mesh.positions.size());
  const auto count = [&](MaterialId m) {
    return std::count(mh->mesh.materials.begin(), mh->mesh.materials.end(), static_cast<std::uint8_t>(m));
  };
  EXPECT_GT(count(MaterialId::Skin), 10000);
  EXPECT_GT(count(MaterialId::Iris), 0);
  EXPECT_GT(count(MaterialId::Pupil), 0);
  EXPECT_GT(count(MaterialId::EyeWhite), count(MaterialId::Iris));
  // Every kept vertex is skinned (weights sum to one) to a joint of the skeleton.
  for (std::size_t v = 0; v < mh->mesh.vertex_count(); v += 97) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      sum += mh->mesh.weights[v][k];
      EXPECT_LT(static_cast<std::size_t>(mh->mesh.joints[v][k]), mh->skeleton.size());
    }
    EXPECT_NEAR(sum, 1.0f, 1e-3f);
  }
}

TEST(AvatarSource, ASignIsPerformedOnTheMakeHumanAvatar) {
  NEED_MAKEHUMAN();
  const SigningRig rig = make_signing_rig(*mh);
  const sign::HamSign s =
      sign::parse_hamnosys_names("hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch");
  const SignSynthesis r = synthesize_sign(s, rig);
  EXPECT_GT(r.stats.frames, 10);
  const auto problem = synthesis_problem(r, rig, SynthesisTolerance{0.05f});
  EXPECT_FALSE(problem.has_value()) << *problem;
  // In the held posture the right (dominant) hand is at the chin, the left hand stays down.
  Pose pose;
  sample_clip(r.clip, 0.5f * (r.plan.sign_start + r.plan.sign_end), WrapMode::Clamp, rig.rest, pose);
  std::vector<mat4> model(mh->skeleton.size());
  local_to_model(mh->skeleton, pose, model);
  const BodySite* chin = find_site(rig.sites, "chin");
  ASSERT_NE(chin, nullptr);
  const vec3 chin_at = vec3(model[static_cast<std::size_t>(chin->joint)] * vec4(chin->local_offset, 1.0f));
  const auto joint = [&](const char* name) { return vec3(model[static_cast<std::size_t>(mh->skeleton.find(name))][3]); };
  // hamtouch: some part of the hand touches the chin (joint centres sit ~1–2 cm under the skin).
  float nearest = 1e9f;
  for (const char* part : {"r_wrist", "r_thumb_tip", "r_index1", "r_index_tip", "r_middle1", "r_middle2", "r_middle_tip",
                           "r_ring1", "r_pinky1", "r_pinky_tip"})
    nearest = std::min(nearest, glm::distance(joint(part), chin_at));
  EXPECT_LT(nearest, 0.05f);
  EXPECT_LT(joint("l_wrist").y, joint("l_elbow").y);
}

TEST(AvatarSource, MakeHumanArmsHangLikeTheDefaultAvatarsWithItsLimits) {
  NEED_MAKEHUMAN();
  // MakeHuman's A-pose is re-posed: the wrists hang well below the shoulders, close to the body.
  for (const char* side : {"l_", "r_"}) {
    const vec3 shoulder = joint_at(mh->skeleton, (std::string(side) + "shoulder").c_str());
    const vec3 wrist = joint_at(mh->skeleton, (std::string(side) + "wrist").c_str());
    EXPECT_GT(shoulder.y - wrist.y, 0.4f) << side;
    EXPECT_LT(std::abs(wrist.x - shoulder.x), 0.12f) << side;
  }
  const int elbow = mh->skeleton.find("r_elbow");
  ASSERT_GE(elbow, 0);
  EXPECT_GT(mh->skeleton.dofs[static_cast<std::size_t>(elbow)].count(), 0);
}

TEST(AvatarSource, DefaultSpecBuildsTheGeneratedAvatar) {
  const Avatar a = load_avatar("default");
  EXPECT_GE(a.skeleton.find("vt1"), 0);
  EXPECT_GT(a.mesh.vertex_count(), 1000u);
}

TEST(AvatarSource, BadSpecsSayWhatIsWrong) {
  const auto message = [](const std::string& spec) {
    try {
      load_avatar(spec);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("robot").find("unknown avatar 'robot'"), std::string::npos) << message("robot");
  EXPECT_NE(message("makehuman:").find("directory"), std::string::npos);
  const std::string missing = "/nonexistent/makehuman";
  EXPECT_NE(message("makehuman:" + missing).find("no such directory"), std::string::npos);
  // A directory without the assets: the reader names the missing file.
  const std::string empty = std::filesystem::temp_directory_path() / "gestura_avatar_source_empty";
  std::filesystem::create_directories(empty);
  EXPECT_NE(message("makehuman:" + empty).find("base.obj"), std::string::npos) << message("makehuman:" + empty);
}

TEST(AvatarSourceCli, AvatarFlagChoosesTheMakeHumanAvatarOrNamesTheBadSpec) {
  using gestura::test::run_cli;
  const gestura::test::CliRun robot = run_cli("render --rest --avatar robot -o /tmp/gestura_avatar_source_bad.png");
  EXPECT_NE(robot.status, 0);
  EXPECT_NE(robot.output.find("unknown avatar 'robot'"), std::string::npos) << robot.output;
  const gestura::test::CliRun missing =
      run_cli("sign --avatar makehuman:/nonexistent --names hamflathand,hamchest -o /tmp/x.json");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.output.find("no such directory"), std::string::npos) << missing.output;
  if (!std::filesystem::exists(makehuman_dir() + "/base.obj")) GTEST_SKIP() << "no MakeHuman assets";
  const gestura::test::CliRun info = run_cli("avatar info --avatar makehuman:" + makehuman_dir());
  ASSERT_EQ(info.status, 0) << info.output;
  EXPECT_NE(info.output.find("skull_tip"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("l_pinky_tip"), std::string::npos) << info.output;
}
