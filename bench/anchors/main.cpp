// gestura-anchors: gestura against ozz-animation and ACL, interleaved on one machine.
//
//   gestura-anchors [--rounds N] [--heavy-rounds N] [--batch-ms MS] [--filter TEXT]
//
// Each workload runs gestura's side and the anchor's side alternately (the order flips every
// round), each for a batch of about --batch-ms of CPU time. Times are thread CPU time per operation;
// the ratio column is the median over rounds of gestura / anchor, so load that comes and goes hits
// both sides of a round alike.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "harness.hpp"

namespace {

using anchors::Side;
using anchors::Workload;

double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Seconds of CPU per operation over a batch of n.
double time_batch(const Side& side, std::size_t n) {
  const double start = cpu_seconds();
  side.run(n);
  return (cpu_seconds() - start) / static_cast<double>(n);
}

// Operations per batch so that one batch takes about `seconds`.
std::size_t calibrate(const Side& side, double seconds) {
  side.run(1);  // first use builds lazily made data
  std::size_t n = 1;
  for (;;) {
    const double t = time_batch(side, n) * static_cast<double>(n);
    if (t >= seconds * 0.5 || n >= (std::size_t{1} << 30)) {
      const double per = t / static_cast<double>(n);
      return std::max<std::size_t>(1, static_cast<std::size_t>(seconds / std::max(per, 1e-12)));
    }
    n *= t < seconds * 0.05 ? 10 : 2;
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return in ? a + " " + b + " " + c : "unknown";
}

std::string format_time(double seconds) {
  char buf[64];
  if (seconds >= 1e-3) std::snprintf(buf, sizeof buf, "%.1f ms", seconds * 1e3);
  else if (seconds >= 1e-6) std::snprintf(buf, sizeof buf, "%.2f µs", seconds * 1e6);
  else std::snprintf(buf, sizeof buf, "%.1f ns", seconds * 1e9);
  return buf;
}

int usage(const char* error) {
  if (error) std::fprintf(stderr, "gestura-anchors: %s\n", error);
  std::fprintf(stderr, "usage: gestura-anchors [--rounds N] [--heavy-rounds N] [--batch-ms MS] [--filter TEXT]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 15, heavy_rounds = 5;
  double batch_ms = 20.0;
  std::string filter;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    const char* v = nullptr;
    if (arg == "--rounds" && (v = value())) rounds = std::atoi(v);
    else if (arg == "--heavy-rounds" && (v = value())) heavy_rounds = std::atoi(v);
    else if (arg == "--batch-ms" && (v = value())) batch_ms = std::atof(v);
    else if (arg == "--filter" && (v = value())) filter = v;
    else if (arg == "--help" || arg == "-h") return usage(nullptr), 0;
    else return usage(("unknown or incomplete option " + arg).c_str());
  }
  if (rounds < 1 || heavy_rounds < 1 || !(batch_ms > 0.0)) return usage("rounds and batch must be positive");

  std::printf("load average at start: %s\n", load_average().c_str());
  std::vector<Workload> all;
  try {
    anchors::add_ozz_workloads(all);
    anchors::add_acl_workloads(all);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gestura-anchors: %s\n", e.what());
    return 1;
  }

  std::printf("\n| workload | gestura | anchor | ratio (median of rounds) | rounds |\n|---|---|---|---|---|\n");
  std::fflush(stdout);
  for (const Workload& w : all) {
    if (!filter.empty() && w.name.find(filter) == std::string::npos) continue;
    const int n_rounds = w.heavy ? heavy_rounds : rounds;
    std::size_t ng = 1, na = 1;
    if (!w.heavy) {
      ng = calibrate(w.gestura, batch_ms * 1e-3);
      na = calibrate(w.anchor, batch_ms * 1e-3);
    } else {
      w.gestura.run(1);  // warm caches and lazily built data on both sides alike
      w.anchor.run(1);
    }
    std::vector<double> tg, ta, ratio;
    for (int r = 0; r < n_rounds; ++r) {
      double g, a;
      if (r % 2 == 0) g = time_batch(w.gestura, ng), a = time_batch(w.anchor, na);
      else a = time_batch(w.anchor, na), g = time_batch(w.gestura, ng);
      tg.push_back(g), ta.push_back(a), ratio.push_back(g / a);
    }
    std::printf("| %s | %s | %s %s | %.2f | %d |\n", w.name.c_str(), format_time(median(tg)).c_str(),
                w.anchor.name.c_str(), format_time(median(ta)).c_str(), median(ratio), n_rounds);
    std::fflush(stdout);
  }
  std::printf("\n");
  for (const std::string& line : anchors::all_notes()) std::printf("- %s\n", line.c_str());
  std::printf("\nload average at end: %s\n", load_average().c_str());
  return 0;
}
