#include "gestura/serve/metrics.hpp"

#include <cstdio>

namespace gestura::serve {

void Metrics::record(const std::string& route, int status, double seconds) {
  std::lock_guard lock(mutex_);
  ++requests_[{route, status}];
  Latency& l = latency_[route];
  for (std::size_t b = 0; b < kBuckets.size(); ++b)
    if (seconds <= kBuckets[b]) ++l.buckets[b];
  ++l.count;
  l.sum += seconds;
}

void Metrics::connection_opened() {
  std::lock_guard lock(mutex_);
  ++open_;
}
void Metrics::connection_closed() {
  std::lock_guard lock(mutex_);
  --open_;
}
void Metrics::rejected_connection() {
  std::lock_guard lock(mutex_);
  ++rejected_;
}
int Metrics::open_connections() const {
  std::lock_guard lock(mutex_);
  return open_;
}

std::string Metrics::prometheus(std::size_t queue_length, std::size_t jobs_running) const {
  std::lock_guard lock(mutex_);
  std::string out;
  char line[1024];
  out += "# HELP gestura_requests_total HTTP requests answered, by route and status.\n# TYPE gestura_requests_total counter\n";
  for (const auto& [key, n] : requests_) {
    std::snprintf(line, sizeof line, "gestura_requests_total{route=\"%s\",status=\"%d\"} %llu\n", key.first.c_str(), key.second,
                  static_cast<unsigned long long>(n));
    out += line;
  }
  out += "# HELP gestura_request_seconds Time from a request read to its response written, by route.\n# TYPE gestura_request_seconds histogram\n";
  for (const auto& [route, l] : latency_) {
    for (std::size_t b = 0; b < kBuckets.size(); ++b) {
      std::snprintf(line, sizeof line, "gestura_request_seconds_bucket{route=\"%s\",le=\"%g\"} %llu\n", route.c_str(), kBuckets[b],
                    static_cast<unsigned long long>(l.buckets[b]));
      out += line;
    }
    std::snprintf(line, sizeof line,
                  "gestura_request_seconds_bucket{route=\"%s\",le=\"+Inf\"} %llu\ngestura_request_seconds_sum{route=\"%s\"} %.6f\n"
                  "gestura_request_seconds_count{route=\"%s\"} %llu\n",
                  route.c_str(), static_cast<unsigned long long>(l.count), route.c_str(), l.sum, route.c_str(),
                  static_cast<unsigned long long>(l.count));
    out += line;
  }
  const double uptime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::snprintf(line, sizeof line,
                "# TYPE gestura_open_connections gauge\ngestura_open_connections %d\n"
                "# TYPE gestura_rejected_connections_total counter\ngestura_rejected_connections_total %llu\n"
                "# TYPE gestura_job_queue_length gauge\ngestura_job_queue_length %zu\n"
                "# TYPE gestura_jobs_running gauge\ngestura_jobs_running %zu\n"
                "# TYPE gestura_uptime_seconds gauge\ngestura_uptime_seconds %.1f\n",
                open_, static_cast<unsigned long long>(rejected_), queue_length, jobs_running, uptime);
  out += line;
  return out;
}

}  // namespace gestura::serve
