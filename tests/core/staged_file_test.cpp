// The one way gestura writes files: all or nothing, temporaries removed on failure, on destruction
// and on SIGINT / SIGTERM / SIGHUP; groups of files appear together.
#include "gestura/core/staged_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"

namespace {

using namespace gestura;
namespace fs = std::filesystem;

class Folder {
 public:
  Folder() {
    std::random_device random;
    path_ = fs::temp_directory_path() / ("gestura-staged-" + std::to_string(random()) + std::to_string(random()));
    fs::create_directories(path_);
  }
  ~Folder() { fs::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(StagedFile, WritesAllOrNothing) {
  Folder dir;
  const std::string target = dir.file("out.txt");
  write_file_atomically(target, "first");
  EXPECT_EQ(contents(target), "first");
  write_file_atomically(target, "second, longer");
  EXPECT_EQ(contents(target), "second, longer");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});

  {
    StagedFile abandoned(target);
    abandoned.write("never committed");
    EXPECT_TRUE(fs::exists(abandoned.temp_path()));
    EXPECT_EQ(abandoned.temp_path().rfind(target + ".part-", 0), 0u) << abandoned.temp_path();
  }
  EXPECT_EQ(contents(target), "second, longer");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});
}

TEST(StagedFile, NamesTheTargetWhenItCannotWrite) {
  Folder dir;
  const std::string missing = dir.file("no/such/dir/out.bvh");
  try {
    write_file_atomically(missing, "x");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_file_atomically(dir.path().string(), "x"), Error);  // a directory
  StagedFile done(dir.file("a"));
  done.commit();
  EXPECT_THROW(done.write("late"), Error);
  EXPECT_THROW(done.commit(), Error);
}

TEST(StagedFile, DevicesAndPipesAreWrittenStraightAndStayWhatTheyAre) {
  write_file_atomically("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  Folder dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = contents(fifo); });
  write_file_atomically(fifo, "through the pipe");
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"pipe"});
}

TEST(StagedFile, ASymbolicLinkStaysALinkToTheNewFile) {
  Folder dir;
  write_file_atomically(dir.file("real.txt"), "old");
  fs::create_symlink("real.txt", dir.file("link.txt"));
  write_file_atomically(dir.file("link.txt"), "new");
  EXPECT_TRUE(fs::is_symlink(dir.file("link.txt")));
  EXPECT_EQ(contents(dir.file("real.txt")), "new");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST(StagedFile, MovedFileKeepsOneOwner) {
  Folder dir;
  std::vector<StagedFile> files;
  files.emplace_back(dir.file("a"));
  files.emplace_back(dir.file("b"));  // may move the first
  files[0].write("A");
  files[1].write("B");
  files[0].commit();
  files.clear();  // b is dropped uncommitted
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a"});
  EXPECT_EQ(contents(dir.file("a")), "A");
}

TEST(StagedFileGroup, AllFilesAppearTogetherOrNone) {
  Folder dir;
  {
    StagedFileGroup group(dir.path().string(), "frames");
    group.write("f0.json", "{}");
    group.write("f1.json", "[]");
    EXPECT_TRUE(dir.entries().size() == 1 && dir.entries()[0].rfind(".frames.part-", 0) == 0) << dir.entries()[0];
  }  // abandoned: nothing remains
  EXPECT_TRUE(dir.entries().empty());

  StagedFileGroup group(dir.path().string(), "frames");
  group.write("f0.json", "{}");
  group.write("f1.json", "[]");
  EXPECT_THROW(group.write("../escape.json", "x"), Error);
  const std::vector<std::string> written = group.commit();
  EXPECT_EQ(written, (std::vector<std::string>{dir.file("f0.json"), dir.file("f1.json")}));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"f0.json", "f1.json"}));
  EXPECT_EQ(contents(dir.file("f1.json")), "[]");
}

TEST(OutputLimits, NameTheLimit) {
  EXPECT_EQ(check_output_length(2.0, 30.0, "x.mp4"), 61);
  try {
    check_output_length(5.0 * 3600.0, 30.0, "x.mp4");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("x.mp4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("kMaxUtteranceSeconds"), std::string::npos) << e.what();
  }
  try {
    check_output_length(3600.0, 1000.0, "joints.json");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("kMaxOutputFrames"), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_output_length(std::nan(""), 30.0, "x"), Error);
  EXPECT_NO_THROW(check_output_size(kMaxOutputBytes, "x"));
  try {
    check_output_size(kMaxOutputBytes + 1, "big.bvh");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("kMaxOutputBytes"), std::string::npos) << e.what();
  }
}

// A child process stages a file and a group, tells the parent, and waits to be signalled. The
// signal must end it as the signal would (so its parent sees why) and leave the folder empty.
void expect_signal_removes_temporaries(int signal_number) {
  Folder dir;
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(ready[0]);
    remove_staged_files_on_signals();
    StagedFile file(dir.file("video.mp4"));
    file.write("partial");
    StagedFileGroup group(dir.path().string(), "frames");
    group.write("f0.json", "{}");
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) _exit(3);
    for (;;) pause();
  }
  close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  close(ready[0]);
  EXPECT_EQ(dir.entries().size(), 2u);  // the temporary file and the staging folder
  kill(child, signal_number);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "status " << status;
  EXPECT_TRUE(dir.entries().empty()) << dir.entries().front();
}

TEST(StagedFileSignals, SigtermRemovesTemporaries) { expect_signal_removes_temporaries(SIGTERM); }
TEST(StagedFileSignals, SigintRemovesTemporaries) { expect_signal_removes_temporaries(SIGINT); }
TEST(StagedFileSignals, SighupRemovesTemporaries) { expect_signal_removes_temporaries(SIGHUP); }

}  // namespace
