// `gestura compress` end to end: writes a loadable .gcl within the bound, rejects bad input.
#include <gtest/gtest.h>

#include "support/cli.hpp"

#include <array>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <string>

#include "gestura/anim/sampler.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/io/bvh.hpp"
#include "support/shared_data.hpp"

namespace {

using gestura::test::CliRun;
using gestura::test::run_cli;

TEST(CompressCli, WritesAClipWithinTheBound) {
  const std::string path = ::testing::TempDir() + "cli.gcl";
  const CliRun r = run_cli("compress synthetic:2 -o " + path + " --error-cm 0.05");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto at = r.output.find("error:       max ");
  ASSERT_NE(at, std::string::npos) << r.output;
  EXPECT_LE(std::stod(r.output.substr(at + 17)), 0.05);
  const gestura::CompressedClip c = gestura::load_gcl(path);
  EXPECT_EQ(c.joint_count(), 67u);
  EXPECT_EQ(c.frame_count(), 61u);
  std::remove(path.c_str());
}

double reported_max_error_cm(const std::string& output) {
  const auto at = output.find("error:       max ");
  return at == std::string::npos ? 1e9 : std::stod(output.substr(at + 17));
}

// The largest displacement of the points 3 cm along each joint's axes, in model space, between two
// clips on one skeleton, over every frame of `a` (measured here, independently of the encoder).
double virtual_point_error(const gestura::BvhFile& a, const gestura::BvhFile& b) {
  using namespace gestura;
  const Skeleton& s = a.skeleton;
  const Pose rest = rest_pose(s);
  Pose pa = rest, pb = rest;
  std::vector<mat4> ma(s.size()), mb(s.size());
  double worst = 0.0;
  for (int f = 0; f < a.frame_count; ++f) {
    const float t = static_cast<float>(f) * a.frame_time;
    sample_clip(a.clip, t, WrapMode::Clamp, rest, pa);
    sample_clip(b.clip, t, WrapMode::Clamp, rest, pb);
    local_to_model(s, pa, ma);
    local_to_model(s, pb, mb);
    for (std::size_t j = 0; j < s.size(); ++j)
      for (int axis = 0; axis < 3; ++axis) {
        vec4 p(0.0f, 0.0f, 0.0f, 1.0f);
        p[axis] = 0.03f;
        worst = std::max(worst, static_cast<double>(glm::length(vec3(ma[j] * p) - vec3(mb[j] * p))));
      }
  }
  return worst;
}

using gestura::test::shared_data;
const std::string kData = shared_data();

// The 60-frame MakeHuman face pose units (212 joints with end sites, dm, Z-up): compressed within the bound, and
// decompressed back to BVH within the bound as measured here.
TEST(CompressCli, MakeHumanBvhRoundTripsWithinTheBound) {
  const std::string bvh = kData + "/makehuman/poseunits/face-poseunits.bvh";
  const std::string gcl = ::testing::TempDir() + "face.gcl", back = ::testing::TempDir() + "face_back.bvh";
  for (const char* bound : {"0.01", "0.1"}) {
    const CliRun r = run_cli("compress " + bvh + " --scale 0.1 --z-up --error-cm " + bound + " -o " + gcl);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("60 frames"), std::string::npos) << r.output;
    EXPECT_LE(reported_max_error_cm(r.output), std::stod(bound)) << r.output;
    const CliRun d = run_cli("decompress " + gcl + " --skeleton " + bvh + " --scale 0.1 --z-up -o " + back);
    ASSERT_EQ(d.status, 0) << d.output;
    const gestura::BvhReadOptions metres{0.1f, true};
    const gestura::BvhFile original = gestura::load_bvh(bvh, metres), decoded = gestura::load_bvh(back);
    ASSERT_EQ(decoded.frame_count, 60);
    ASSERT_EQ(decoded.skeleton.names, original.skeleton.names);
    // Plus 1 µm for the decimal BVH text of the decoded angles.
    EXPECT_LE(virtual_point_error(original, decoded), std::stod(bound) * 0.01 + 1e-6);
  }
  std::remove(gcl.c_str());
  std::remove(back.c_str());
}

// Single-frame pose files compress within the bound too (a still clip).
TEST(CompressCli, MakeHumanPosesHonourTheBound) {
  for (const char* pose : {"run01", "sit01", "standing01", "tpose"}) {
    const CliRun r = run_cli("compress " + kData + "/makehuman/poses/" + pose + ".bvh --scale 0.1 --z-up --error-cm 0.01");
    ASSERT_EQ(r.status, 0) << pose << "\n" << r.output;
    EXPECT_LE(reported_max_error_cm(r.output), 0.01) << pose << "\n" << r.output;
  }
}

TEST(CompressCli, GclInputNeedsAMatchingSkeleton) {
  const std::string gcl = ::testing::TempDir() + "synthetic.gcl";
  ASSERT_EQ(run_cli("compress synthetic:1 -o " + gcl).status, 0);
  const CliRun no_skeleton = run_cli("compress " + gcl);
  EXPECT_EQ(no_skeleton.status, 2) << "a usage error: the command line lacks --skeleton";
  EXPECT_NE(no_skeleton.output.find("--skeleton"), std::string::npos) << no_skeleton.output;
  const CliRun wrong = run_cli("decompress " + gcl + " --skeleton " + kData + "/makehuman/poses/tpose.bvh -o /dev/null");
  EXPECT_EQ(wrong.status, 1);
  EXPECT_NE(wrong.output.find("has 67 joints"), std::string::npos) << wrong.output;
  std::remove(gcl.c_str());
}

TEST(CompressCli, DecompressRejectsJunkAndMissingArguments) {
  const std::string junk = ::testing::TempDir() + "junk.gcl";
  {
    std::FILE* f = std::fopen(junk.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("GCL\x01 not a clip", f);
    std::fclose(f);
  }
  const std::string ref = kData + "/makehuman/poses/tpose.bvh";
  const CliRun bad = run_cli("decompress " + junk + " --skeleton " + ref + " -o /dev/null");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find(junk + ": byte"), std::string::npos) << bad.output;
  for (const std::string& args : std::vector<std::string>{"decompress", "decompress " + junk, "decompress " + junk + " -o x.bvh --bogus"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << ": a usage error";
    EXPECT_NE(r.output.find("gestura decompress: "), std::string::npos) << args << "\n" << r.output;
  }
  std::remove(junk.c_str());
}

TEST(CompressCli, BadInputIsAClearError) {
  for (const char* args : {"compress", "compress synthetic --error-cm 0", "compress synthetic --error-cm x",
                           "compress synthetic:-1", "compress synthetic --bogus", "compress a b", "compress synthetic -o",
                           "compress synthetic --scale -2"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << ": a usage error";
    EXPECT_NE(r.output.find("gestura compress: "), std::string::npos) << args << "\n" << r.output;
  }
  const CliRun missing = run_cli("compress /nonexistent.bvh");
  EXPECT_EQ(missing.status, 1) << "a file that is not there is not a usage error";
  EXPECT_NE(missing.output.find("/nonexistent.bvh: no such file"), std::string::npos) << missing.output;
}

}  // namespace
