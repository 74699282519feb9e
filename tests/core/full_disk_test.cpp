// Every writer of gestura on a full disk: each one, given a small tmpfs with only 8 KB left, fails
// with an error naming the file and the reason, and leaves nothing at the destination (no partial
// file, no temporary) and an older file of that name untouched. The same writer succeeds when
// there is room, so the failure is the disk's. Needs root to mount the tmpfs; skips otherwise.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/io/bap.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/gltf_export.hpp"
#include "gestura/io/joint_positions_json.hpp"
#include "gestura/io/openpose_json.hpp"
#include "gestura/io/pose_format.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/video_writer.hpp"
#include "support/cli.hpp"
#include "support/small_tmpfs.hpp"
#include "support/test_figure.hpp"

namespace {

using namespace gestura;
using gestura::test::SmallTmpfs;

struct Motion {
  Skeleton skeleton = synthetic_humanoid();
  Clip clip = synthetic_clip(skeleton, 2.0f, 30.0f);
};

const Motion& motion() {
  static const Motion m;
  return m;
}

Image noise(int width, int height, unsigned seed) {
  Image image(width, height);
  std::mt19937 random(seed);
  for (auto& byte : image.rgba) byte = static_cast<std::uint8_t>(random());
  return image;
}

void write_video(const std::string& path) {
  VideoWriter video(path, 128, 96, 25);
  for (unsigned f = 0; f < 12; ++f) video.write(noise(128, 96, f));
  video.finish();
}

std::vector<SignEntry> many_entries() {
  std::vector<SignEntry> entries;
  for (int i = 0; i < 200; ++i) {
    SignEntry e;
    e.gloss = "SIGN" + std::to_string(i);
    e.language = "ase";
    e.notation_kind = NotationKind::sigml;
    e.notation = "<hns_sign gloss=\"sign" + std::to_string(i) +
                 "\"><hamnosys_manual><hamflathand/><hamextfingeru/><hampalml/><hamchest/><hammoveo/>"
                 "</hamnosys_manual></hns_sign>";
    e.keywords.push_back(Keyword{"word" + std::to_string(i)});
    entries.push_back(e);
  }
  return entries;
}

// One writer: the file name it is given and how it writes it. OpenPose writes NAME_<frame>_keypoints.json.
struct Writer {
  std::string name, file;
  std::function<void(const std::string&)> write;
};

std::vector<Writer> every_writer() {
  const Motion& m = motion();
  return {
      {"bvh", "motion.bvh", [&m](const std::string& p) { save_bvh(p, make_bvh(m.skeleton, m.clip, 1.0f / 30.0f)); }},
      {"glb", "motion.glb", [&m](const std::string& p) { save_gltf(p, m.skeleton, m.clip); }},
      {"gltf", "motion.gltf", [&m](const std::string& p) { save_gltf(p, m.skeleton, m.clip); }},
      {"avatar_glb", "avatar.glb",
       [](const std::string& p) {
         const RenderSubject figure = make_test_figure();
         write_glb(p, figure.skeleton, figure.mesh, "figure");
       }},
      {"bap", "motion.bap", [&m](const std::string& p) { save_bap(p, clip_to_bap(m.clip, m.skeleton, 30.0f, "m")); }},
      {"pose", "motion.pose",
       [&m](const std::string& p) { save_pose(p, pose_from_clip(m.skeleton, m.clip, 30.0f, PoseLayout::Skeleton3D)); }},
      {"openpose", "motion.json", [&m](const std::string& p) { save_openpose_json(p, m.skeleton, m.clip, 30.0f); }},
      {"joint_json", "joints.json",
       [&m](const std::string& p) { write_joint_positions_json(p, m.skeleton, m.clip, 30.0f); }},
      {"gcl", "motion.gcl", [&m](const std::string& p) { save_gcl(p, compress(m.clip, m.skeleton)); }},
      {"png", "frame.png", [](const std::string& p) { write_png(p, noise(96, 96, 1)); }},
      {"gif", "video.gif", write_video},
      {"mp4", "video.mp4", write_video},
      {"webm", "video.webm", write_video},
      {"lexicon_jsonl", "signs.jsonl", [](const std::string& p) { export_file(many_entries(), p); }},
      {"lexicon_sigml", "signs.sigml", [](const std::string& p) { export_file(many_entries(), p); }},
      {"bytes", "sites.json", [](const std::string& p) { write_file_atomically(p, std::string(64 * 1024, 'x')); }},
  };
}

class FullDisk : public ::testing::TestWithParam<Writer> {};

TEST_P(FullDisk, FailsWithTheReasonAndLeavesNothing) {
  const Writer& w = GetParam();
  SmallTmpfs fs(2 * 1024 * 1024);
  if (!fs.mounted()) GTEST_SKIP() << fs.skip_reason();

  // With room, the writer writes (and leaves only its output).
  w.write(fs.path(w.file));
  const std::vector<std::string> written = fs.entries();
  ASSERT_FALSE(written.empty()) << w.name << " wrote nothing";
  for (const std::string& name : written) EXPECT_EQ(name.find(".part"), std::string::npos) << name;
  std::uintmax_t bytes = 0;
  for (const std::string& name : written) bytes += std::filesystem::file_size(fs.path(name));
  ASSERT_GT(bytes, 12u * 1024u) << w.name << ": too small an output to meet the full disk";
  for (const std::string& name : written) std::filesystem::remove(fs.path(name));

  // An older file of the same name stays as it was.
  const std::string old_path = fs.path(w.name == "openpose" ? "motion_000000000000_keypoints.json" : w.file);
  std::ofstream(old_path) << "old";
  fs.fill(8 * 1024);
  const std::vector<std::string> before = fs.entries();
  try {
    w.write(fs.path(w.file));
    ADD_FAILURE() << w.name << ": no error on a full disk";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(fs.root()), std::string::npos) << message;
    EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  }
  EXPECT_EQ(fs.entries(), before) << w.name << " left a file behind";
  std::ifstream old(old_path);
  std::stringstream content;
  content << old.rdbuf();
  EXPECT_EQ(content.str(), "old");
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, FullDisk, ::testing::ValuesIn(every_writer()),
                         [](const ::testing::TestParamInfo<Writer>& info) { return info.param.name; });

// The two silent losses the command line had: `convert` to .bap said "wrote" over a truncated file,
// `lexicon export` said "exported" over an empty one. Both must now fail and leave nothing.
TEST(FullDiskCli, ConvertAndLexiconExportFailAndLeaveNothing) {
  SmallTmpfs fs(1024 * 1024);
  if (!fs.mounted()) GTEST_SKIP() << fs.skip_reason();
  const std::string bvh = ::testing::TempDir() + "full_disk_source.bvh";
  save_bvh(bvh, make_bvh(motion().skeleton, motion().clip, 1.0f / 30.0f));
  const std::string db = ::testing::TempDir() + "full_disk_lexicon.sqlite";
  std::filesystem::remove(db);
  {
    Lexicon lexicon = Lexicon::open(db);
    for (const SignEntry& e : many_entries()) lexicon.add(e);
  }
  fs.fill(8 * 1024);
  const std::vector<std::string> before = fs.entries();

  const auto bap = test::run_cli("convert " + bvh + " " + fs.path("out.bap"));
  EXPECT_EQ(bap.status, 1) << bap.output;
  EXPECT_NE(bap.output.find("No space left on device"), std::string::npos) << bap.output;
  EXPECT_EQ(bap.output.find("wrote"), std::string::npos) << bap.output;

  const auto exported = test::run_cli("lexicon export " + fs.path("out.jsonl") + " --db " + db);
  EXPECT_EQ(exported.status, 1) << exported.output;
  EXPECT_NE(exported.output.find("No space left on device"), std::string::npos) << exported.output;
  EXPECT_EQ(exported.output.find("exported"), std::string::npos) << exported.output;

  EXPECT_EQ(fs.entries(), before);
}

}  // namespace
