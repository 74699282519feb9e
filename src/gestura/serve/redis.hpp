#pragma once
// A blocking Redis connection (hiredis) for the job broker: one command at a time, replies copied
// into plain values. Not thread-safe: each thread keeps its own connection.
//
//   Redis redis(parse_broker_url("unix:///run/redis.sock"));
//   RedisReply r = redis.command({"XLEN", "gestura:jobs"});   // r.integer
//
// A lost or refused connection throws BrokerUnavailable; the next command connects again. An
// error reply of the server (a wrong command, a missing group) throws RedisReplyError.
#include <chrono>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/serve/broker_url.hpp"

struct redisContext;

namespace gestura::serve {

class BrokerUnavailable : public std::runtime_error {
  using std::runtime_error::runtime_error;
};
class RedisReplyError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RedisReply {
  enum class Type { nil, string, integer, array, status } type = Type::nil;
  std::string text;                 // string and status
  long long integer = 0;
  std::vector<RedisReply> elements; // array

  bool is_nil() const { return type == Type::nil; }
  // An array of alternating names and values (HGETALL, a stream entry's fields) as a lookup.
  std::string field(std::string_view name) const;
};

class Redis {
 public:
  // Connects at once (throws BrokerUnavailable when it cannot). `timeout` bounds connecting and
  // each reply; blocking commands (XREADGROUP BLOCK) must block for less.
  explicit Redis(BrokerUrl url, std::chrono::milliseconds timeout = std::chrono::seconds(5));
  ~Redis();
  Redis(const Redis&) = delete;
  Redis& operator=(const Redis&) = delete;

  RedisReply command(const std::vector<std::string>& args);
  RedisReply command(std::initializer_list<std::string_view> args);
  const BrokerUrl& url() const { return url_; }

 private:
  void connect();
  void drop();
  RedisReply run(int argc, const char** argv, const std::size_t* lengths);

  BrokerUrl url_;
  std::chrono::milliseconds timeout_;
  redisContext* context_ = nullptr;
};

}  // namespace gestura::serve
