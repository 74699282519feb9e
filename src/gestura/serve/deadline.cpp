#include "gestura/serve/deadline.hpp"

namespace gestura::serve {

Deadlines::Deadlines() : thread_([this](std::stop_token stop) { loop(stop); }) {}

Deadlines::~Deadlines() {
  thread_.request_stop();
  wake_.notify_all();
}

Deadlines::Guard::Guard(Deadlines& owner, std::chrono::steady_clock::duration limit) : owner_(owner) {
  std::lock_guard lock(owner_.mutex_);
  key_ = owner_.next_key_++;
  owner_.active_[key_] = {std::chrono::steady_clock::now() + limit, source_};
  owner_.wake_.notify_all();
}

Deadlines::Guard::~Guard() {
  std::lock_guard lock(owner_.mutex_);
  owner_.active_.erase(key_);
}

void Deadlines::loop(std::stop_token stop) {
  std::unique_lock lock(mutex_);
  while (!stop.stop_requested()) {
    auto next = std::chrono::steady_clock::time_point::max();
    const auto now = std::chrono::steady_clock::now();
    for (auto& [key, entry] : active_) {
      if (entry.first <= now) entry.second->request_stop();
      else next = std::min(next, entry.first);
    }
    // Wake at the next deadline or when a request registers (its deadline may be sooner).
    const std::uint64_t seen = next_key_;
    const auto registered = [&] { return next_key_ != seen; };
    if (next == std::chrono::steady_clock::time_point::max()) wake_.wait(lock, stop, registered);
    else wake_.wait_until(lock, stop, next, registered);
  }
}

}  // namespace gestura::serve
