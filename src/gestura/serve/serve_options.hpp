#pragma once
// What `gestura serve` is started with: where it listens, which lexicon it reads, the one folder
// it may write (--data), the page it serves (--web), and its limits. One field table, like every
// request of the command layer, so the CLI binds each field to its flag.
#include <string>

#include "gestura/app/fields.hpp"

namespace gestura::serve {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;         // 0: any free port (tests)
  std::string lexicon;     // the user lexicon (SQLite) on top of the built-in one; empty: the user's
  std::string data;        // the only folder the server writes (rendered videos, temporary SiGML)
  std::string web;         // the page's folder served at /; empty: no page
  int threads = 2;         // threads running requests (signing, glossing)
  int jobs = 1;            // render jobs running at once
  int queue = 16;          // render jobs waiting at most
  int max_body = 64 * 1024;       // bytes of a request body
  int max_text = 2000;            // bytes of text a say/gloss/video request signs
  int timeout = 20;               // seconds a request may compute (reading it has its own 10 s)
  int max_connections = 256;      // connections open at once
  std::string broker;             // empty: render jobs in this process; redis://… or unix://…: Redis Streams

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    using app::FieldInfo;
    visit(self.host, FieldInfo{.name = "host", .help = "address to listen on (0.0.0.0: every interface)", .value = "ADDR"});
    visit(self.port, FieldInfo{.name = "port", .help = "TCP port (0: any free port, printed at start)", .value = "N", .min = 0, .max = 65535, .short_flag = 'p'});
    visit(self.lexicon, FieldInfo{.name = "lexicon", .help = "the user lexicon (SQLite) searched besides the built-in one", .value = "DB"});
    visit(self.data, FieldInfo{.name = "data", .help = "folder for rendered videos (the only place the server writes); default: a new temporary folder", .value = "DIR"});
    visit(self.web, FieldInfo{.name = "web", .help = "folder of the web page served at / (the checkout's web/)", .value = "DIR"});
    visit(self.threads, FieldInfo{.name = "threads", .help = "threads computing requests", .value = "N", .min = 1, .max = 64, .group = "Limits"});
    visit(self.jobs, FieldInfo{.name = "jobs", .help = "video render jobs running at once", .value = "N", .min = 1, .max = 16, .group = "Limits"});
    visit(self.queue, FieldInfo{.name = "queue", .help = "video jobs waiting at most (more: 503)", .value = "N", .min = 0, .max = 10000, .group = "Limits"});
    visit(self.max_body, FieldInfo{.name = "max_body", .help = "bytes of a request body (more: 413)", .value = "BYTES", .min = 1024, .max = 16 * 1024 * 1024, .group = "Limits"});
    visit(self.max_text, FieldInfo{.name = "max_text", .help = "bytes of text one request signs (more: 413)", .value = "BYTES", .min = 16, .max = 16 * 1024, .group = "Limits"});
    visit(self.timeout, FieldInfo{.name = "timeout", .help = "seconds a request may compute (more: 503)", .value = "S", .min = 1, .max = 3600, .group = "Limits"});
    visit(self.broker, FieldInfo{.name = "broker", .help = "send /api/video jobs to `gestura worker` processes through Redis (redis://HOST[:PORT][/DB] or unix:///PATH/redis.sock); default: render in this process", .value = "URL"});
    visit(self.max_connections, FieldInfo{.name = "max_connections", .help = "connections open at once (more are closed at once)", .value = "N", .min = 1, .max = 100000, .group = "Limits"});
  }
};

}  // namespace gestura::serve
