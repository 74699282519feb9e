#pragma once
// Stops requests that compute past their time: each request registers its stop source with a
// deadline; one thread requests the stop when the deadline passes (the command layer checks its
// stop token between steps and throws Cancelled).
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <stop_token>
#include <thread>

namespace gestura::serve {

class Deadlines {
 public:
  Deadlines();
  ~Deadlines();

  // Held while the request runs; expired() tells whether the stop came from the deadline.
  class Guard {
   public:
    Guard(Deadlines& owner, std::chrono::steady_clock::duration limit);
    ~Guard();
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;
    std::stop_token token() const { return source_->get_token(); }
    bool expired() const { return source_->stop_requested(); }

   private:
    Deadlines& owner_;
    std::shared_ptr<std::stop_source> source_ = std::make_shared<std::stop_source>();
    std::uint64_t key_;
  };

 private:
  void loop(std::stop_token stop);
  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::uint64_t next_key_ = 0;
  std::map<std::uint64_t, std::pair<std::chrono::steady_clock::time_point, std::shared_ptr<std::stop_source>>> active_;
  std::jthread thread_;
};

}  // namespace gestura::serve
