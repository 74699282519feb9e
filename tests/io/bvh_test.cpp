// BVH import/export: the MakeHuman files against numbers read from their text independently of the
// parser, lossless round trips, FK of a hand-made chain, every kind of malformed input, the CLI.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura;

using gestura::test::shared_data;

std::string read_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  EXPECT_TRUE(file) << path;
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<std::string> makehuman_files() {
  const std::string base = shared_data() + "/makehuman";
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(base + "/poses"))
    if (entry.path().extension() == ".bvh") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  files.push_back(base + "/poseunits/face-poseunits.bvh");
  return files;
}

// What a BVH text declares, read with a plain word scan (no use of the parser under test).
struct Scan {
  int roots = 0, joints = 0, end_sites = 0, channels = 0, frames_declared = -1;
  std::vector<std::string> names;             // ROOT / JOINT names in order
  std::vector<std::string> channel_lines;     // "6 Xposition ..." per joint
  std::vector<double> offsets;                // every OFFSET coordinate in order
  std::vector<std::vector<double>> frames;    // motion lines
  double frame_time = 0.0;
};

Scan scan(const std::string& text) {
  Scan s;
  std::istringstream lines(text);
  std::string line;
  bool motion = false;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (motion) {
      if (first == "Frames:") {
        words >> s.frames_declared;
      } else if (first == "Frame") {
        std::string time_word;
        words >> time_word >> s.frame_time;
      } else {
        std::vector<double> values{std::stod(first)};
        for (double v; words >> v;) values.push_back(v);
        s.frames.push_back(values);
      }
      continue;
    }
    if (first == "ROOT" || first == "JOINT") {
      (first == "ROOT" ? s.roots : s.joints)++;
      std::string name;
      words >> name;
      s.names.push_back(name);
    } else if (first == "End") {
      ++s.end_sites;
    } else if (first == "OFFSET") {
      for (double v; words >> v;) s.offsets.push_back(v);
    } else if (first == "CHANNELS") {
      int n = 0;
      words >> n;
      s.channels += n;
      std::string rest;
      std::getline(words, rest);
      s.channel_lines.push_back(std::to_string(n) + rest);
    } else if (first == "MOTION") {
      motion = true;
    }
  }
  return s;
}

TEST(Bvh, MakeHumanFilesMatchWhatTheyDeclare) {
  const auto files = makehuman_files();
  ASSERT_EQ(files.size(), 7u);
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const Scan declared = scan(read_text(path));
    const BvhFile bvh = load_bvh(path);
    ASSERT_EQ(declared.roots, 1);
    EXPECT_EQ(static_cast<int>(bvh.skeleton.size()), declared.roots + declared.joints + declared.end_sites);
    EXPECT_EQ(std::count(bvh.end_site.begin(), bvh.end_site.end(), 1), declared.end_sites);
    EXPECT_EQ(bvh.channel_count(), declared.channels);
    EXPECT_EQ(bvh.frame_count, declared.frames_declared);
    EXPECT_EQ(static_cast<int>(declared.frames.size()), declared.frames_declared);
    EXPECT_FLOAT_EQ(bvh.frame_time, static_cast<float>(declared.frame_time));
    EXPECT_EQ(bvh.skeleton.names[0], declared.names[0]);
    EXPECT_NO_THROW(bvh.skeleton.validate());
    EXPECT_NO_THROW(validate(bvh.clip, bvh.skeleton));
    // Every joint with channels has a rotation track with one key per frame.
    for (std::size_t j = 0; j < bvh.skeleton.size(); ++j)
      if (bvh.channels[j].has_rotation()) {
        EXPECT_EQ(bvh.clip.rotations[j].size(), static_cast<std::size_t>(bvh.frame_count));
      }
  }
}

// Writes `bvh`, then compares the written text with the original one value by value.
void expect_same_values(const std::string& original, const std::string& written, double tolerance) {
  const Scan a = scan(original), b = scan(written);
  EXPECT_EQ(a.names, b.names);
  EXPECT_EQ(a.channel_lines, b.channel_lines);
  EXPECT_EQ(a.end_sites, b.end_sites);
  EXPECT_EQ(a.frames_declared, b.frames_declared);
  EXPECT_NEAR(a.frame_time, b.frame_time, 1e-7);
  ASSERT_EQ(a.offsets.size(), b.offsets.size());
  for (std::size_t i = 0; i < a.offsets.size(); ++i) ASSERT_NEAR(a.offsets[i], b.offsets[i], 1e-6) << "offset " << i;
  ASSERT_EQ(a.frames.size(), b.frames.size());
  double worst = 0.0;
  for (std::size_t f = 0; f < a.frames.size(); ++f) {
    ASSERT_EQ(a.frames[f].size(), b.frames[f].size()) << "frame " << f;
    for (std::size_t c = 0; c < a.frames[f].size(); ++c) {
      worst = std::max(worst, std::abs(a.frames[f][c] - b.frames[f][c]));
      ASSERT_NEAR(a.frames[f][c], b.frames[f][c], tolerance) << "frame " << f << " value " << c;
    }
  }
  std::printf("    largest channel difference after the round trip: %.3g\n", worst);
}

TEST(Bvh, MakeHumanRoundTripKeepsEveryValue) {
  for (const std::string& path : makehuman_files()) {
    SCOPED_TRACE(path);
    const std::string original = read_text(path);
    const std::string written = write_bvh(read_bvh(original, path));
    expect_same_values(original, written, 1e-4);
    // And the written file reads back to the same model.
    expect_same_values(written, write_bvh(read_bvh(written, "written.bvh")), 1e-4);
  }
}

TEST(Bvh, ScaleMultipliesOffsetsAndPositionsOnly) {
  const std::string path = shared_data() + "/makehuman/poses/sit01.bvh";
  const BvhFile dm = load_bvh(path), m = load_bvh(path, {0.1f});
  const Scan declared = scan(read_text(path));
  for (std::size_t j = 0; j < dm.skeleton.size(); ++j)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(m.skeleton.rest_translations[j][a], 0.1f * dm.skeleton.rest_translations[j][a], 1e-6f);
  // Root position channels: declared values × 0.1 plus the scaled offset; rotations unchanged.
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(m.clip.translations[0].values[0][a],
                0.1 * (declared.offsets[static_cast<std::size_t>(a)] + declared.frames[0][static_cast<std::size_t>(a)]), 1e-5);
  EXPECT_EQ(m.clip.rotations[0].values[0], dm.clip.rotations[0].values[0]);
  EXPECT_THROW(load_bvh(path, {0.0f}), Error);
  EXPECT_THROW(load_bvh(path, {1e30f}), Error);
  EXPECT_THROW(load_bvh(path, {std::nanf("")}), Error);
}

std::vector<vec3> rest_positions(const Skeleton& skeleton) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  std::vector<vec3> out(model.size());
  model_positions(model, out);
  return out;
}

TEST(Bvh, MakeHumanIsDecimetresZUpAndConvertsToMetresYUp) {
  const std::string path = shared_data() + "/makehuman/poses/tpose.bvh";
  const BvhFile raw = load_bvh(path), ours = load_bvh(path, {0.1f, true});
  const auto p_raw = rest_positions(raw.skeleton), p = rest_positions(ours.skeleton);
  auto at = [&](const std::vector<vec3>& ps, const char* name) {
    const int j = raw.skeleton.find(name);
    EXPECT_GE(j, 0) << name;
    return ps[static_cast<std::size_t>(std::max(j, 0))];
  };
  // As written, the body stands along Z (head high, feet low), toes pointing to −Y: Z-up.
  EXPECT_GT(at(p_raw, "head").z - at(p_raw, "foot.L").z, 10.0f);
  EXPECT_LT(at(p_raw, "toe1-2.L").y, at(p_raw, "foot.L").y);
  // Converted: +Y up, facing +Z, left is +X, in metres (a 1.5–1.9 m tall person, head to toe tip).
  float lowest = 1e9f, highest = -1e9f;
  for (const vec3& q : p) lowest = std::min(lowest, q.y), highest = std::max(highest, q.y);
  EXPECT_GT(highest - lowest, 1.5f);
  EXPECT_LT(highest - lowest, 1.9f);
  EXPECT_GT(at(p, "head").y, at(p, "root").y + 0.5f);
  EXPECT_GT(at(p, "toe1-2.L").z, at(p, "foot.L").z);
  EXPECT_GT(at(p, "wrist.L").x, 0.3f);
  EXPECT_LT(at(p, "wrist.R").x, -0.3f);
  // The motion turns with the axes: frame-0 positions are the old ones mapped (x, y, z) → (x, z, −y).
  Pose pose_raw, pose;
  sample_clip(raw.clip, 0.0f, WrapMode::Clamp, rest_pose(raw.skeleton), pose_raw);
  sample_clip(ours.clip, 0.0f, WrapMode::Clamp, rest_pose(ours.skeleton), pose);
  std::vector<mat4> m_raw(raw.skeleton.size()), m(ours.skeleton.size());
  local_to_model(raw.skeleton, pose_raw, m_raw);
  local_to_model(ours.skeleton, pose, m);
  for (std::size_t j = 0; j < m.size(); ++j) {
    const vec3 a(m_raw[j][3]), b(m[j][3]);
    ASSERT_NEAR(b.x, 0.1f * a.x, 1e-4f) << j;
    ASSERT_NEAR(b.y, 0.1f * a.z, 1e-4f) << j;
    ASSERT_NEAR(b.z, -0.1f * a.y, 1e-4f) << j;
  }
}

// A two-joint chain whose positions are worked out by hand (see the comments on each frame).
constexpr const char* kChain = R"(HIERARCHY
ROOT base
{
	OFFSET 1 2 3
	CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
	JOINT arm
	{
		OFFSET 0 1 0
		CHANNELS 3 Zrotation Xrotation Yrotation
		End Site
		{
			OFFSET 0 2 0
		}
	}
}
MOTION
Frames: 3
Frame Time: 0.5
0 0 0 0 0 0 0 0 0
10 0 0 90 0 0 0 0 0
0 0 0 0 0 0 90 90 0
)";

std::vector<vec3> positions_at(const BvhFile& bvh, float time) {
  Pose pose;
  sample_clip(bvh.clip, time, WrapMode::Clamp, rest_pose(bvh.skeleton), pose);
  std::vector<mat4> model(bvh.skeleton.size());
  local_to_model(bvh.skeleton, pose, model);
  std::vector<vec3> out(model.size());
  model_positions(model, out);
  return out;
}

void expect_vec3(const vec3& got, const vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-5f);
  EXPECT_NEAR(got.y, want.y, 1e-5f);
  EXPECT_NEAR(got.z, want.z, 1e-5f);
}

TEST(Bvh, TwoJointChainForwardKinematicsByHand) {
  const BvhFile bvh = read_bvh(kChain, "chain.bvh");
  ASSERT_EQ(bvh.skeleton.size(), 3u);
  EXPECT_EQ(bvh.skeleton.names[2], "arm_end");
  EXPECT_EQ(bvh.end_site[2], 1);
  EXPECT_EQ(bvh.skeleton.dofs[1].order, RotationOrder::ZXY);
  EXPECT_FLOAT_EQ(bvh.clip.duration, 1.0f);

  // Frame 0: offsets only. base (1,2,3), arm one up, tip two further up.
  auto p = positions_at(bvh, 0.0f);
  expect_vec3(p[0], {1, 2, 3});
  expect_vec3(p[1], {1, 3, 3});
  expect_vec3(p[2], {1, 5, 3});
  // Frame 1: base moved by (10,0,0) and turned 90° about Z: +Y becomes −X.
  p = positions_at(bvh, 0.5f);
  expect_vec3(p[0], {11, 2, 3});
  expect_vec3(p[1], {10, 2, 3});
  expect_vec3(p[2], {8, 2, 3});
  // Frame 2: arm Z=90, X=90 read as Rz·Rx: Rx turns the tip offset (0,2,0) to (0,0,2), Rz keeps it.
  // (The other order, Rx·Rz, would put the tip at (-1,3,3).)
  p = positions_at(bvh, 1.0f);
  expect_vec3(p[1], {1, 3, 3});
  expect_vec3(p[2], {1, 3, 5});
  // Halfway between frames 0 and 1 the base has turned 45° (slerp) and moved 5.
  p = positions_at(bvh, 0.25f);
  expect_vec3(p[0], {6, 2, 3});
  expect_vec3(p[1], {6 - std::sqrt(0.5f), 2 + std::sqrt(0.5f), 3});
}

TEST(Bvh, ExportKeepsAnglesContinuousPastHalfTurns) {
  std::string text = R"(HIERARCHY
ROOT spin
{
	OFFSET 0 0 0
	CHANNELS 3 Yrotation Xrotation Zrotation
}
MOTION
Frames: 6
Frame Time: 0.1
0 10 0
100 10 0
200 10 0
300 10 0
400 10 0
350 10 0
)";
  const std::string written = write_bvh(read_bvh(text, "spin.bvh"));
  const Scan out = scan(written);
  ASSERT_EQ(out.frames.size(), 6u);
  const double want[] = {0, 100, 200, 300, 400, 350};
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_NEAR(out.frames[f][0], want[f], 1e-3) << "frame " << f;
    EXPECT_NEAR(out.frames[f][1], 10, 1e-3) << "frame " << f;
    EXPECT_NEAR(out.frames[f][2], 0, 1e-3) << "frame " << f;
  }
}

TEST(Bvh, JointNamesWithSpacesAndGluedBracesRead) {
  const std::string text =
      "HIERARCHY\nROOT Left Hip{\nOFFSET 0 0 0\nCHANNELS 1 Zrotation\nJOINT  Left   Knee \n{ OFFSET 0 -1 0\n"
      "CHANNELS 0 }}\nMOTION\nFrames: 1\nFrame Time: 0.1\n45\n";
  const BvhFile bvh = read_bvh(text, "names.bvh");
  ASSERT_EQ(bvh.skeleton.size(), 2u);
  EXPECT_EQ(bvh.skeleton.names[0], "Left Hip");
  EXPECT_EQ(bvh.skeleton.names[1], "Left Knee");
  EXPECT_EQ(read_bvh(write_bvh(bvh), "again.bvh").skeleton.names, bvh.skeleton.names);
}

TEST(Bvh, ChannelSubsetsAndOrdersRoundTrip) {
  const std::string text = R"(HIERARCHY
ROOT hips
{
	OFFSET 0 90 0
	CHANNELS 4 Yposition Xrotation Zrotation Xposition
	JOINT knee
	{
		OFFSET 0 -40 0
		CHANNELS 1 Xrotation
		JOINT ankle
		{
			OFFSET 0 -40 0
			CHANNELS 0
			End Site
			{
				OFFSET 0 0 10
			}
		}
	}
	JOINT spine
	{
		OFFSET 0 10 0
		CHANNELS 3 Yrotation Zrotation Xrotation
	}
}
MOTION
Frames: 2
Frame Time: 0.033333
1.5 -20 30 2.5 45 10 20 30
-1.5 20 -30 -2.5 -45 -10 -20 -30
)";
  const BvhFile bvh = read_bvh(text, "subset.bvh");
  EXPECT_EQ(bvh.channels[0].rotation_order(), RotationOrder::XZY);
  EXPECT_EQ(bvh.channels[4].rotation_order(), RotationOrder::YZX);
  EXPECT_TRUE(bvh.clip.translations[1].empty());
  // Missing position axes keep the offset: hips translation = (0 + 2.5, 90 + 1.5, 0).
  expect_vec3(bvh.clip.translations[0].values[0], {2.5f, 91.5f, 0.0f});
  expect_same_values(text, write_bvh(bvh), 1e-4);
}

TEST(Bvh, MakeBvhGivesADefaultLayoutForOtherClips) {
  Skeleton skeleton;
  skeleton.add_joint("hips", -1, {0, 1, 0});
  skeleton.add_joint("l_hip", 0, {0.1f, 0, 0}, euler_to_quat({0, 0, deg(30)}, RotationOrder::XYZ));
  skeleton.add_joint("l_knee", 1, {0, -0.4f, 0});
  Clip clip;
  clip.resize_joints(3);
  clip.duration = 1.0f;
  clip.rotations[2].add(0.0f, euler_to_quat({deg(10), 0, 0}, RotationOrder::XYZ));
  clip.rotations[2].add(1.0f, euler_to_quat({deg(50), 0, 0}, RotationOrder::XYZ));
  const BvhFile bvh = make_bvh(skeleton, clip, 0.25f);
  EXPECT_EQ(bvh.frame_count, 5);
  EXPECT_EQ(bvh.channels[0].count, 6);
  EXPECT_EQ(bvh.channels[1].count, 3);
  EXPECT_EQ(bvh.channels[1].rotation_order(), RotationOrder::ZXY);
  const BvhFile back = read_bvh(write_bvh(bvh), "made.bvh");
  // The hip keeps its rest orientation as a constant channel value; the knee's angle is sampled.
  EXPECT_NEAR(std::abs(glm::dot(back.clip.rotations[1].values[3], skeleton.rest_rotations[1])), 1.0f, 1e-6f);
  const vec3 knee = quat_to_euler(back.clip.rotations[2].values[2], RotationOrder::XYZ);
  EXPECT_NEAR(knee.x, deg(30), 1e-4f);  // slerp halfway from 10° to 50°
  // Two roots cannot be one BVH file; scale cannot be stored.
  Skeleton two = skeleton;
  two.add_joint("prop", -1, {1, 0, 0});
  Clip clip2 = clip;
  clip2.resize_joints(4);
  EXPECT_THROW(write_bvh(make_bvh(two, clip2, 0.25f)), Error);
  Skeleton braces = skeleton;
  braces.names[2] = "knee{1}";
  EXPECT_THROW(write_bvh(make_bvh(braces, clip, 0.25f)), Error);
  Clip scaled = clip;
  scaled.scales[1].add(0.0f, vec3(2.0f));
  EXPECT_THROW(write_bvh(make_bvh(skeleton, scaled, 0.25f)), Error);
}

// ---- malformed input -------------------------------------------------------------------------

std::vector<std::string> chain_lines() {
  std::vector<std::string> lines;
  std::istringstream in(kChain);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// Expects read_bvh to throw a gestura::Error located at `line` whose message mentions `words`.
void expect_error(const std::string& text, int line, const std::string& words, const std::string& label) {
  SCOPED_TRACE(label);
  try {
    read_bvh(text, "bad.bvh");
    ADD_FAILURE() << "no error for: " << label;
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.bvh:" + std::to_string(line) + ":"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// Replaces line `index` (1-based) of the chain file.
std::string with_line(int index, const std::string& replacement) {
  auto lines = chain_lines();
  lines[static_cast<std::size_t>(index - 1)] = replacement;
  return join(lines);
}

TEST(BvhErrors, MalformedHierarchy) {
  expect_error("", 1, "expected 'HIERARCHY'", "empty file");
  expect_error("   \n\n", 3, "expected 'HIERARCHY'", "blank file");
  expect_error(with_line(2, "JOINT base"), 2, "expected 'ROOT'", "no ROOT");
  expect_error(with_line(2, "ROOT"), 2, "joint name", "ROOT without a name");
  expect_error(with_line(6, std::string("\tJOINT a\0rm", 11)), 6, "contains control characters", "NUL in a name");
  expect_error(with_line(3, ""), 4, "expected '{'", "missing opening brace");
  expect_error(with_line(4, "\tOFFSET 1 2"), 5, "OFFSET coordinate", "short OFFSET");
  expect_error(with_line(4, "\tOFFSET 1 two 3"), 4, "found 'two'", "non-numeric OFFSET");
  expect_error(with_line(4, "\tOFFSET 1 1e400 3"), 4, "OFFSET", "OFFSET overflow");
  expect_error(with_line(4, "\tOFFSET 1 1e30 3"), 4, "out of range", "huge OFFSET");
  expect_error(with_line(4, "\tOFFSET nan 2 3"), 4, "found 'nan'", "nan OFFSET");
  expect_error(with_line(4, "\tOFFSET 1 -inf 3"), 4, "found '-inf'", "inf OFFSET");
  expect_error(with_line(5, "\tCHANNELS 6 Xposition Yposition Zposition Wrotation Xrotation Yrotation"), 5,
               "found 'Wrotation'", "unknown channel");
  expect_error(with_line(5, "\tCHANNELS 7 Xposition Yposition Zposition Zrotation Xrotation Yrotation"), 5,
               "channel count from 0 to 6", "seven channels");
  expect_error(with_line(5, "\tCHANNELS six Xposition"), 5, "channel count", "non-numeric channel count");
  expect_error(with_line(5, "\tCHANNELS 2 Xrotation Xrotation"), 5, "appears twice", "repeated channel");
  expect_error(with_line(9, "\t\tCHANNELS 4 Zrotation Xrotation Yrotation"), 10, "found 'End'",
               "fewer channel names than declared");
  expect_error(with_line(5, "\tOFFSET 0 0 0"), 5, "expected 'CHANNELS'", "CHANNELS missing");
  expect_error(with_line(10, "\t\tEnd Zone"), 10, "expected 'Site'", "End without Site");
  expect_error(with_line(13, "\t\tOFFSET 1 1 1"), 13, "expected '}' to close the End Site", "End Site not closed");
  expect_error(with_line(13, ""), 16, "in joint 'base' (opened at line 2), found 'MOTION'", "End Site brace missing");
  expect_error(with_line(15, ""), 16, "expected JOINT, End Site or '}'", "missing closing brace");
  expect_error(with_line(6, "\tJOINT base"), 6, "duplicate joint name 'base' (first at line 2)", "duplicate name");
  expect_error(with_line(16, "MOTON"), 16, "expected MOTION", "misspelt MOTION");
}

TEST(BvhErrors, SecondRootIsRejectedWithItsLine) {
  auto lines = chain_lines();
  const std::vector<std::string> second = {"ROOT other", "{", "\tOFFSET 0 0 0", "\tCHANNELS 0", "}"};
  lines.insert(lines.begin() + 15, second.begin(), second.end());
  expect_error(join(lines), 16, "second ROOT", "two roots");
}

TEST(BvhErrors, MalformedMotion) {
  expect_error(with_line(17, "Frames: -1"), 17, "frame count", "negative frames");
  expect_error(with_line(17, "Frames: 1.5"), 17, "frame count", "fractional frames");
  expect_error(with_line(17, "Frames:"), 17, "frame count", "frames missing");
  expect_error(with_line(17, "Frames: 99999999999999999999999"), 17, "frame count", "frames overflow");
  expect_error(with_line(17, "Frames: 20000000"), 17, "over the limit", "frame bomb");
  expect_error(with_line(17, "Frame: 3"), 17, "expected 'Frames:'", "Frames label");
  expect_error(with_line(18, "Frame Time: 0"), 18, "must be positive", "zero frame time");
  expect_error(with_line(18, "Frame Time: -0.5"), 18, "must be positive", "negative frame time");
  expect_error(with_line(18, "Frame Time: fast"), 18, "frame time", "non-numeric frame time");
  expect_error(with_line(18, "Frame Time: inf"), 18, "frame time", "infinite frame time");
  expect_error(with_line(18, "Frame Time:"), 18, "frame time", "frame time missing");
  expect_error(with_line(18, "Frame Time: 0.5 0.5"), 18, "after the frame time", "junk after frame time");
  expect_error(with_line(18, "Frame Rate: 0.5"), 18, "expected 'Time:'", "Frame Rate");
  expect_error(with_line(20, "10 0 0 90 0 0 0 0"), 20, "has 8 values, expected 9", "short motion line");
  expect_error(with_line(20, "10 0 0 90 0 0 0 0 0 0"), 20, "more than 9 values", "long motion line");
  expect_error(with_line(20, "10 0 0 ninety 0 0 0 0 0"), 20, "base.Zrotation", "non-numeric value");
  expect_error(with_line(20, "10 0 0 90 0 0 0 nan 0"), 20, "arm.Xrotation", "nan value");
  expect_error(with_line(20, "10 0 0 90 0 0 0 0 1e300"), 20, "out of range", "huge value");
  expect_error(with_line(20, "10 0 0 90 0 0 0 0 1e-400"), 20, "arm.Yrotation", "underflow value");
  expect_error(with_line(20, "10 0 0 90 0,5 0 0 0 0"), 20, "found '0,5'", "decimal comma");
  expect_error(with_line(17, "Frames: 4"), 22, "ends after 3 frames but line 17 declares 4", "too few frames");
  expect_error(with_line(17, "Frames: 2"), 21, "more frames than declared", "too many frames");
  auto no_motion = chain_lines();
  no_motion.resize(15);
  expect_error(join(no_motion), 16, "expected MOTION", "hierarchy only");
}

TEST(BvhErrors, TruncatedAnywhereIsAnErrorNotACrash) {
  // Cutting the file at every byte gives either a clean error or (at frame-line boundaries) a valid
  // file that has fewer frames than declared — which is an error too.
  const std::string text = kChain;
  const std::string last_line = "0 0 0 0 0 0 90 90 0\n";
  for (std::size_t cut = 0; cut + last_line.size() < text.size(); ++cut) {
    try {
      read_bvh(std::string_view(text).substr(0, cut), "cut.bvh");
      ADD_FAILURE() << "no error when cut at byte " << cut;
    } catch (const Error& e) {
      EXPECT_GT(e.where().line, 0) << e.what();
    }
  }
}

TEST(BvhErrors, RandomByteMutationsGiveAModelOrAnError) {
  // 3,000 deterministic mutations (overwrite, insert, delete a byte): each read either succeeds, and
  // then writes, or throws gestura::Error with a line; any other exception or a crash fails.
  const std::string base = kChain;
  std::uint32_t seed = 12345;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u, seed >> 8; };
  const char alphabet[] = "{}0123456789.-+eE \t\nXYZpositionrotationJOINTEnd Site\x00\xff";
  int parsed = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = base;
    for (int edits = 1 + static_cast<int>(next() % 3); edits > 0; --edits) {
      const std::size_t at = next() % text.size();
      const char c = alphabet[next() % (sizeof alphabet - 1)];
      switch (next() % 3) {
        case 0: text[at] = c; break;
        case 1: text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c); break;
        default: text.erase(at, 1); break;
      }
    }
    try {
      const BvhFile bvh = read_bvh(text, "mutant.bvh");
      ++parsed;
      EXPECT_NO_THROW(read_bvh(write_bvh(bvh), "rewritten.bvh")) << text;
    } catch (const Error& e) {
      EXPECT_GT(e.where().line, 0) << e.what();
    }
  }
  // Some mutations are harmless (a digit for a digit), most are not.
  std::printf("    %d of 3000 mutants read as valid BVH\n", parsed);
  EXPECT_GT(parsed, 0);
  EXPECT_LT(parsed, 3000);
}

TEST(BvhErrors, BinaryJunk) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk.push_back(static_cast<char>((i * 131 + 7) % 256));
  try {
    read_bvh(junk, "junk.bvh");
    ADD_FAILURE() << "junk accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 1);
    // Non-printable bytes are escaped in the message so it stays one readable line.
    EXPECT_EQ(std::string(e.what()).find('\0'), std::string::npos);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  constexpr char raw[] = "10 0 0 90 \x01\xff\x00 0 0 0 0";
  const std::string zeros = with_line(20, std::string(raw, sizeof raw - 1));
  expect_error(zeros, 20, "\\x01\\xff\\x00", "binary bytes in a motion line");
}

TEST(BvhErrors, JointBombsAndDeepNestingStopCleanly) {
  // 40,000 joints exceed the int16 parent index of Skeleton.
  std::string many = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  for (int i = 0; i < 40000; ++i) many += "JOINT j" + std::to_string(i) + "\n{\nOFFSET 0 0 0\nCHANNELS 0\n}\n";
  many += "}\nMOTION\nFrames: 0\nFrame Time: 1\n";
  expect_error(many, 6 + 5 * 32766, "too many joints", "joint bomb");  // joint 32767 is j32766
  // 30,000 nested joints never closed: no recursion, just an error at the end of the text.
  std::string deep = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  for (int i = 0; i < 30000; ++i) deep += "JOINT j" + std::to_string(i) + " {\nOFFSET 0 0 0\nCHANNELS 0\n";
  expect_error(deep, 5 + 3 * 30000 + 1, "expected JOINT, End Site or '}' in joint 'j29999'", "deep nesting");
}

TEST(BvhErrors, CrLfAndTabsAndByteOrderMarkAreFine) {
  std::string text = "\xEF\xBB\xBF";
  for (const auto& l : chain_lines()) text += l + "\r\n";
  const BvhFile bvh = read_bvh(text, "crlf.bvh");
  EXPECT_EQ(bvh.frame_count, 3);
  EXPECT_EQ(bvh.skeleton.names[1], "arm");
}

TEST(BvhErrors, MissingFileNamesThePath) {
  try {
    load_bvh("/nonexistent/dir/motion.bvh");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/motion.bvh"), std::string::npos);
  }
}

// ---- command line ----------------------------------------------------------------------------

using test::CliRun;
using test::run_cli;

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("gestura_bvh_test_" + std::to_string(getpid()) + "_" + name))
      .string();
}

TEST(BvhCli, InfoReportsFramesAndJoints) {
  const std::string path = shared_data() + "/makehuman/poseunits/face-poseunits.bvh";
  const Scan declared = scan(read_text(path));
  const CliRun run = run_cli("info '" + path + "'");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("frames:     " + std::to_string(declared.frames_declared) + "\n"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("joints:     " + std::to_string(declared.roots + declared.joints) + " (plus " +
                            std::to_string(declared.end_sites) + " end sites)"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("root:       root"), std::string::npos) << run.output;
}

TEST(BvhCli, ConvertWritesAFileThatReadsBackScaled) {
  const std::string in = shared_data() + "/makehuman/poses/run01.bvh";
  const std::string out = temp_path("run01_m.bvh");
  const CliRun run = run_cli("convert '" + in + "' '" + out + "' --scale 0.1");
  EXPECT_EQ(run.status, 0) << run.output;
  const Scan a = scan(read_text(in)), b = scan(read_text(out));
  ASSERT_EQ(a.offsets.size(), b.offsets.size());
  for (std::size_t i = 0; i < a.offsets.size(); ++i) EXPECT_NEAR(b.offsets[i], 0.1 * a.offsets[i], 1e-6);
  EXPECT_EQ(b.frames_declared, a.frames_declared);
  const CliRun info = run_cli("info '" + out + "'");
  EXPECT_EQ(info.status, 0);
  EXPECT_NE(info.output.find("frames:     1\n"), std::string::npos) << info.output;
  // --z-up renames the axes of every offset: (x, y, z) → (x, z, −y).
  const CliRun turned = run_cli("convert '" + in + "' '" + out + "' --z-up");
  EXPECT_EQ(turned.status, 0) << turned.output;
  const Scan c = scan(read_text(out));
  ASSERT_EQ(a.offsets.size(), c.offsets.size());
  for (std::size_t i = 0; i + 2 < a.offsets.size(); i += 3) {
    EXPECT_NEAR(c.offsets[i], a.offsets[i], 1e-5);
    EXPECT_NEAR(c.offsets[i + 1], a.offsets[i + 2], 1e-5);
    EXPECT_NEAR(c.offsets[i + 2], -a.offsets[i + 1], 1e-5);
  }
  std::filesystem::remove(out);
}

TEST(BvhCli, BadInputExitsOneWithOneClearLine) {
  const std::string bad = temp_path("bad.bvh");
  std::ofstream(bad) << with_line(20, "10 0 0 90 0 0 0 0");
  CliRun run = run_cli("info '" + bad + "'");
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_NE(run.output.find(bad + ":20:"), std::string::npos) << run.output;
  run = run_cli("convert '" + bad + "' '" + temp_path("out.bvh") + "'");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find(":20:"), std::string::npos) << run.output;
  std::filesystem::remove(bad);

  // A bad command line exits 2, naming the flag or argument.
  run = run_cli("convert in.bvh out.fbx");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("cannot write '.fbx' files (supported: "), std::string::npos) << run.output;
  run = run_cli("info notes.txt");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("unsupported file type '.txt'"), std::string::npos) << run.output;
  run = run_cli("convert only_one.bvh");
  EXPECT_EQ(run.status, 2);
  run = run_cli("convert a.bvh b.bvh --frobnicate");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--frobnicate"), std::string::npos) << run.output;
  run = run_cli("convert a.bvh b.bvh --scale -2");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--scale: -2 is outside"), std::string::npos) << run.output;
}

}  // namespace
