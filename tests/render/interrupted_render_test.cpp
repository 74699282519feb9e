// A video export interrupted by Ctrl-C (SIGINT) or SIGTERM leaves nothing: neither the video nor
// its temporary. `kill -9` cannot be caught: the video still never appears, only its temporary
// (NAME.part-XXXXXX) stays behind.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <random>
#include <thread>

#include "support/build_paths.hpp"

namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path path;
  Folder() {
    std::random_device random;
    path = fs::temp_directory_path() / ("gestura-interrupt-" + std::to_string(random()) + std::to_string(random()));
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path)) names.push_back(e.path().filename().string());
    return names;
  }
};

// Starts a long render into `folder`, waits until its temporary exists and frames are being encoded,
// sends `signal_number`, and returns the wait status.
int interrupt_render(const Folder& folder, int signal_number) {
  const std::string out = (folder.path / "talk.mp4").string();
  const pid_t child = fork();
  if (child == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execl(gestura::test::cli_path().c_str(), "gestura", "render", "--rest", "--seconds", "600", "--size", "160x120",
          "--msaa", "1", "-o", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // The temporary appears before the GL context is made; give the encoder a moment after it.
  for (int i = 0; i < 600 && folder.entries().empty(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  kill(child, signal_number);
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

void expect_clean_interrupt(int signal_number) {
  Folder folder;
  const int status = interrupt_render(folder, signal_number);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "status " << status;
  EXPECT_TRUE(folder.entries().empty()) << folder.entries().front();
}

TEST(InterruptedRender, SigintLeavesNothing) { expect_clean_interrupt(SIGINT); }
TEST(InterruptedRender, SigtermLeavesNothing) { expect_clean_interrupt(SIGTERM); }

TEST(InterruptedRender, KillNineNeverLeavesAPartialVideo) {
  Folder folder;
  const int status = interrupt_render(folder, SIGKILL);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "status " << status;
  const std::vector<std::string> left = folder.entries();
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].rfind("talk.mp4.part-", 0), 0u) << left[0];  // the temporary, never talk.mp4
}

}  // namespace
