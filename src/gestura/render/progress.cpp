#include "gestura/render/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace gestura {

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), terminal_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (drawn_) std::fputc('\n', stderr);
}

void Progress::update(int done) {
  if (!terminal_ || total_ <= 0) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (elapsed < 1.0) return;
  constexpr int kWidth = 30;
  const int filled = done * kWidth / total_;
  std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d  %.1f s", label_.c_str(), filled, "##############################",
               kWidth - filled, "", done, total_, elapsed);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace gestura
