#pragma once
// `gestura worker`: renders /api/video jobs taken from the broker's stream (Redis Streams with
// the consumer group "render", layout in broker_keys.hpp) with the command layer's say request.
//
// One job at a time: claim a job a silent worker held (XAUTOCLAIM after --claim-after seconds),
// else read a new one (XREADGROUP); mark it running; render it into --data; store the video in
// Redis; then acknowledge and delete the entry. While rendering, a second connection renews the
// claim, publishes progress, and watches for a cancel. A worker killed mid-job leaves its entry
// pending, and another worker claims it once the claim is stale. Entries no worker can run
// (malformed payloads, jobs that took down every worker that held them) go to gestura:dead with
// the reason. A lost broker is reconnected with a log line; the job it held is claimed again.
#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "gestura/app/fields.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/serve/broker_url.hpp"

namespace gestura::serve {

class Redis;
struct RedisReply;

struct WorkerOptions {
  std::string broker;      // redis://… or unix://…
  std::string data;        // the scratch folder of renders; default: a new temporary folder
  std::string name;        // the consumer's name; default: host-pid
  std::string lexicon;     // the user lexicon (SQLite), as the API servers use
  int claim_after = 30;    // seconds a held job may go without a renewed claim before others take it
  int max_text = 2000;     // bytes of text a job may sign (the API servers' --max-text)

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    using app::FieldInfo;
    visit(self.broker, FieldInfo{.name = "broker", .help = "the job broker: redis://HOST[:PORT][/DB] or unix:///PATH/redis.sock", .value = "URL", .required = true});
    visit(self.data, FieldInfo{.name = "data", .help = "folder where videos are rendered before they are stored in the broker; default: a new temporary folder", .value = "DIR"});
    visit(self.name, FieldInfo{.name = "name", .help = "this worker's name in the consumer group; default: HOST-PID", .value = "NAME"});
    visit(self.lexicon, FieldInfo{.name = "lexicon", .help = "the user lexicon (SQLite) searched besides the built-in one (as the API servers')", .value = "DB"});
    visit(self.claim_after, FieldInfo{.name = "claim_after", .help = "seconds a job held by a silent worker waits before another worker takes it", .value = "S", .min = 1, .max = 3600});
    visit(self.max_text, FieldInfo{.name = "max_text", .help = "bytes of text one job may sign (as the API servers' --max-text)", .value = "BYTES", .min = 16, .max = 16 * 1024});
  }
};

class RenderWorker {
 public:
  using Log = std::function<void(const std::string& line)>;
  // Checks the options (a bad URL is a usage error at "broker"); does not connect yet.
  RenderWorker(WorkerOptions options, Log log);
  ~RenderWorker();

  // Takes and renders jobs until `stop` is raised: 1 finishes the job in hand first, 2 releases
  // it at once (another worker may take it without waiting). Broker losses are retried.
  void run(const std::atomic<int>& stop);

  const WorkerOptions& options() const { return options_; }
  const BrokerUrl& url() const { return url_; }

 private:
  struct Entry;
  bool next_entry(Redis& redis, Entry& entry);
  void process(Redis& redis, const Entry& entry, const std::atomic<int>& stop);
  void dead_letter(Redis& redis, const Entry& entry, const std::string& reason);
  void finish(Redis& redis, const Entry& entry);
  void fail(Redis& redis, const std::string& id, const std::string& error_json);

  WorkerOptions options_;
  BrokerUrl url_;
  Log log_;
  std::unique_ptr<app::Workspace> workspace_;
};

}  // namespace gestura::serve
