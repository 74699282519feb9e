// gestura worker: renders the /api/video jobs of `gestura serve --broker` taken from Redis
// (src/gestura/serve/render_worker.hpp).
#include <csignal>
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/serve/render_worker.hpp"

namespace gestura::cli {
namespace {

// Raised by SIGTERM/SIGINT: 1 finishes the job in hand and stops, 2 releases it and stops.
std::atomic<int> stop_level{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void on_stop_signal(int) { stop_level.fetch_add(1); }

Invocation prepare() {
  auto options = std::make_shared<serve::WorkerOptions>();
  Invocation invocation;
  invocation.fields = bind_fields(*options);
  invocation.run = [options](const app::RunContext&) {
    serve::RenderWorker worker(*options, [](const std::string& line) {
      std::fprintf(stderr, "%s\n", line.c_str());
      std::fflush(stderr);
    });
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
    worker.run(stop_level);
    return 0;
  };
  return invocation;
}

const Registration reg{{
    "worker",
    "render the video jobs of `gestura serve --broker` (Redis)",
    "Takes /api/video jobs from the broker's stream (Redis Streams, consumer group \"render\"), one at\n"
    "a time, renders each with the say command and stores the video in Redis, where any API server\n"
    "started with the same --broker serves it. Start as many workers as you like, on any machine that\n"
    "reaches the broker. A job held by a worker that went silent (killed, cut off) is taken over after\n"
    "--claim-after seconds; malformed job entries go to the stream gestura:dead with the reason.\n"
    "SIGTERM or Ctrl-C: finish the job in hand, then stop; a second one releases the job at once.\n"
    "A lost broker is retried with a log line. Example:\n"
    "  redis-server --unixsocket /tmp/redis.sock --port 0 &\n"
    "  gestura worker --broker unix:///tmp/redis.sock &\n"
    "  gestura serve --broker unix:///tmp/redis.sock --web web",
    prepare,
}};

}  // namespace
}  // namespace gestura::cli
