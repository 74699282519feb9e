#pragma once
// `gestura serve`: the API (api.hpp) behind HTTP/1.1 and WebSocket on Boost.Beast, in one process.
// The network side reads requests with limits (header 8 KiB, body --max-body, 10 s to send a
// request, --max-connections), hands them to the compute threads, and writes the answers; a job's
// progress is pushed over a WebSocket at /api/jobs/{id}/events. This is the only file that knows
// Beast.
#include <functional>
#include <memory>

#include "gestura/serve/serve_options.hpp"

namespace gestura::serve {

class Api;

class Server {
 public:
  // Builds the API and binds the port; throws AppError (usage at "port"/"host") when it cannot.
  explicit Server(ServeOptions options);
  ~Server();  // stops and joins
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  int port() const;        // the bound port (the chosen one when --port 0)
  Api& api();
  void start();            // serves on background threads
  void run();              // serves on this thread too until stop() (the CLI)
  void stop();             // from any thread (signal handler: see cmd_serve)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gestura::serve
