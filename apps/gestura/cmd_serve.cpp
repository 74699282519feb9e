// gestura serve: the HTTP/WebSocket API, the web page and the embeddable player (src/gestura/serve).
#include <cstdio>
#include <memory>
#include <thread>

#include "command.hpp"
#include "gestura/serve/api.hpp"
#include "gestura/serve/server.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto options = std::make_shared<serve::ServeOptions>();
  Invocation invocation;
  invocation.fields = bind_fields(*options);
  invocation.run = [options](const app::RunContext&) {
    serve::Server server(*options);
    const serve::ServeOptions& used = server.api().options();
    std::printf("gestura serve: listening on http://%s:%d/  (data: %s%s%s)\n", used.host.c_str(), server.port(), used.data.c_str(),
                used.web.empty() ? "" : ", page: ", used.web.c_str());
    std::fflush(stdout);
    std::jthread warm([&server] { server.api().warm_up(); });
    server.run();
    std::printf("gestura serve: stopped\n");
    return 0;
  };
  return invocation;
}

const Registration reg{{
    "serve",
    "serve the HTTP/WebSocket API and the web player",
    "One process answers the JSON API (docs/api.md): POST /api/say, /api/sign, /api/video (a job), GET\n"
    "/api/gloss, /api/lexicon, /api/avatar.glb, /api/jobs/ID, /health, /metrics; a job's progress over a\n"
    "WebSocket at /api/jobs/ID/events. --web DIR serves the page at / (the checkout's web/ folder).\n"
    "Rendered videos go under --data, the only place the server writes. Ctrl-C stops it.\n"
    "With --broker URL (Redis) video jobs go to `gestura worker` processes on any machine instead.\n"
    "Example: gestura serve --port 8080 --web web   then open http://127.0.0.1:8080/",
    prepare,
}};

}  // namespace
}  // namespace gestura::cli
