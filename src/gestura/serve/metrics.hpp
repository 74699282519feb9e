#pragma once
// Counters of the server for /metrics (Prometheus text format): requests by route and status,
// latency histograms by route, requests in flight, open connections, and the job queue's length.
#include <array>
#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace gestura::serve {

class Metrics {
 public:
  // Upper bounds of the latency buckets, in seconds.
  static constexpr std::array<double, 10> kBuckets{0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 10};

  void record(const std::string& route, int status, double seconds);
  void connection_opened();
  void connection_closed();
  void rejected_connection();
  int open_connections() const;

  // queue_length, jobs_running: read from the job queue when /metrics is asked.
  std::string prometheus(std::size_t queue_length, std::size_t jobs_running) const;

 private:
  struct Latency {
    std::array<std::uint64_t, kBuckets.size()> buckets{};
    std::uint64_t count = 0;
    double sum = 0;
  };
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> requests_;
  std::map<std::string, Latency> latency_;
  int open_ = 0;
  std::uint64_t rejected_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace gestura::serve
