#pragma once
// A progress bar on stderr for long renders: shown only when stderr is a terminal and the work has
// already taken more than a second; silent otherwise (pipes, tests, quick jobs).
#include <chrono>
#include <string>

namespace gestura {

class Progress {
 public:
  Progress(std::string label, int total);
  ~Progress();  // ends the bar's line if one was drawn
  void update(int done);

 private:
  std::string label_;
  int total_;
  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace gestura
