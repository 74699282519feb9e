// MPEG-4 BAP text files: the BAP ↔ joint table, reading/writing, clip conversion, malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bap.hpp"

namespace gestura {
namespace {

std::string mask_line(int count, std::initializer_list<int> sent_bap_numbers) {
  std::vector<char> flags(static_cast<std::size_t>(count), '0');
  for (int b : sent_bap_numbers) flags[static_cast<std::size_t>(b - 1)] = '1';
  std::string line;
  for (int i = 0; i < count; ++i) line += (i ? " " : ""), line += flags[static_cast<std::size_t>(i)];
  return line + "\n";
}

TEST(Bap, TableFollowsTheMpeg4Numbering) {
  const auto& table = bap_table();
  ASSERT_EQ(table.size(), 186u);
  std::set<std::string> names;
  for (const BapInfo& b : table) EXPECT_TRUE(names.insert(b.name).second) << b.name;
  // Spot checks against the MPEG-4 BAP list.
  EXPECT_EQ(find_bap("sacroiliac_tilt"), 1);
  EXPECT_EQ(find_bap("l_hip_flexion"), 4);
  EXPECT_EQ(find_bap("r_knee_twisting"), 13);
  EXPECT_EQ(find_bap("l_sternoclavicular_abduct"), 24);
  EXPECT_EQ(find_bap("l_shoulder_flexion"), 32);
  EXPECT_EQ(find_bap("r_elbow_twisting"), 41);
  EXPECT_EQ(find_bap("r_wrist_twisting"), 47);
  EXPECT_EQ(find_bap("skullbase_roll"), 48);
  EXPECT_EQ(find_bap("vc1_roll"), 51);
  EXPECT_EQ(find_bap("vt1_roll"), 72);
  EXPECT_EQ(find_bap("vl1_roll"), 108);
  EXPECT_EQ(find_bap("vl5_tilt"), 122);
  EXPECT_EQ(find_bap("l_pinky0_flexion"), 123);
  EXPECT_EQ(find_bap("l_ring0_flexion"), 135);
  EXPECT_EQ(find_bap("l_index0_flexion"), 159);
  EXPECT_EQ(find_bap("l_thumb1_flexion"), 171);
  EXPECT_EQ(find_bap("r_thumb3_flexion"), 180);
  EXPECT_EQ(find_bap("HumanoidRoot_tr_vertical"), 181);
  EXPECT_EQ(find_bap("HumanoidRoot_rt_body_tilt"), 186);
  EXPECT_EQ(find_bap("no_such_bap"), 0);
  EXPECT_EQ(table[31].joint, "l_shoulder");
  EXPECT_EQ(table[31].axis, 0);
  EXPECT_EQ(table[180].axis, 1);
  EXPECT_TRUE(table[180].translation);
}

TEST(Bap, ReadsMasksAndCarriesUnsentValues) {
  const std::string text = "2.1 wave 25 2\n" + mask_line(186, {32, 38}) + "0 1000 -2000\n" + mask_line(186, {38}) + "1 500\n";
  const BapFile file = read_bap(text, "wave.bap");
  EXPECT_EQ(file.version, "2.1");
  EXPECT_EQ(file.name, "wave");
  EXPECT_EQ(file.fps, 25.0f);
  ASSERT_EQ(file.frame_count(), 2);
  EXPECT_EQ(file.values[31], 1000);
  EXPECT_EQ(file.values[37], -2000);
  EXPECT_EQ(file.values[186 + 31], 1000);  // not sent in frame 1: kept
  EXPECT_EQ(file.values[186 + 37], 500);
  EXPECT_EQ(file.values[0], 0);
}

TEST(Bap, ExtendedFilesWith296ParametersAreRead) {
  const std::string text = "3.2 ext 30 1\n" + mask_line(296, {200}) + "0 7\n";
  const BapFile file = read_bap(text, "ext.bap");
  EXPECT_EQ(file.parameter_count, 296);
  EXPECT_EQ(file.values[199], 7);
}

TEST(Bap, TextRoundTrip) {
  const std::string text = "2.1 wave 25 3\n" + mask_line(186, {1, 32, 181}) + "0 10 1000 -5\n" + mask_line(186, {32}) + "1 1200\n" +
                           mask_line(186, {1}) + "2 -3\n";
  const BapFile a = read_bap(text, "a.bap");
  const BapFile b = read_bap(write_bap(a), "b.bap");
  EXPECT_EQ(b.values, a.values);
  EXPECT_EQ(b.fps, a.fps);
  EXPECT_EQ(b.name, a.name);
}

TEST(Bap, ClipConversionRoundTripsJointAngles) {
  const Skeleton s = synthetic_humanoid();
  BapFile file;
  file.name = "sines";
  file.fps = 30.0f;
  const int frames = 20;
  file.values.assign(static_cast<std::size_t>(frames) * 186, 0);
  int mapped = 0;
  for (std::size_t b = 0; b < 186; ++b) {
    if (s.find(bap_table()[b].joint) < 0) continue;
    ++mapped;
    for (int f = 0; f < frames; ++f)
      file.values[static_cast<std::size_t>(f) * 186 + b] =
          static_cast<std::int32_t>(std::lround((bap_table()[b].translation ? 2000.0 : 40000.0) * std::sin(0.3 * f + 0.1 * static_cast<double>(b))));
  }
  EXPECT_GT(mapped, 60);
  const Clip clip = bap_to_clip(file, s);
  EXPECT_NEAR(clip.duration, 19.0f / 30.0f, 1e-6f);
  const BapFile back = clip_to_bap(clip, s, 30.0f, "sines");
  ASSERT_EQ(back.frame_count(), frames);
  for (std::size_t i = 0; i < file.values.size(); ++i)
    EXPECT_NEAR(back.values[i], file.values[i], 2) << "BAP " << (i % 186) + 1 << " frame " << i / 186;
}

struct BadCase {
  std::string text;
  int line;
  const char* says;
};

TEST(Bap, MalformedInputNamesTheLine) {
  const std::string header = "2.1 x 30 1\n";
  const std::string good_mask = mask_line(186, {32});
  std::string mask_with_two = good_mask;
  mask_with_two[4] = '2';
  const std::vector<BadCase> cases = {
      {"", 1, "empty BAP file"},
      {"2.1 x 30\n", 1, "header needs 4 fields"},
      {"2.1 x abc 1\n", 1, "frame rate"},
      {"2.1 x 30 -1\n", 1, "frame count"},
      {"2.1 x 30 99999999\n", 1, "frame count"},
      {header + mask_line(185, {}), 2, "mask has 185 flags"},
      {header + mask_with_two, 2, "0 or 1"},
      {header + good_mask + "5 100\n", 3, "expected frame number 0"},
      {header + good_mask + "0 100 200\n", 3, "mask sends 1 values, line has 2"},
      {header + good_mask + "0 1.5\n", 3, "32-bit integer"},
      {header + good_mask + "0 99999999999\n", 3, "32-bit integer"},
      {header + good_mask, 2, "file ends before the values of frame 0"},
      {"2.1 x 30 2\n" + good_mask + "0 1\n", 3, "file ends after 1 of the header's 2 frames"},
      {header + good_mask + "0 1\n\n" + good_mask, 5, "more lines than"},
      {"2.1 x 30 2\n" + good_mask + "0 1\n" + mask_line(296, {}), 4, "the first frame had 186"},
  };
  for (const BadCase& c : cases) {
    try {
      read_bap(c.text, "bad.bap");
      ADD_FAILURE() << "accepted: " << c.says;
    } catch (const Error& e) {
      EXPECT_EQ(e.where().line, c.line) << e.what();
      EXPECT_EQ(e.where().file, "bad.bap");
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

TEST(Bap, BinaryJunkIsAnError) {
  std::string junk;
  std::uint64_t state = 5;
  for (int i = 0; i < 4096; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    junk += static_cast<char>(state >> 56);
  }
  EXPECT_THROW(read_bap(junk, "junk.bap"), Error);
  EXPECT_THROW(load_bap("/nonexistent/x.bap"), Error);
}

}  // namespace
}  // namespace gestura
