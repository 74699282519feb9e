#include "gestura/serve/redis.hpp"

#include <hiredis/hiredis.h>

#include <csignal>
#include <mutex>

namespace gestura::serve {
namespace {

timeval to_timeval(std::chrono::milliseconds ms) {
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(ms.count() / 1000);
  tv.tv_usec = static_cast<suseconds_t>((ms.count() % 1000) * 1000);
  return tv;
}

RedisReply copy(const redisReply& r) {
  RedisReply out;
  switch (r.type) {
    case REDIS_REPLY_STRING:
      out.type = RedisReply::Type::string;
      out.text.assign(r.str, r.len);
      break;
    case REDIS_REPLY_STATUS:
      out.type = RedisReply::Type::status;
      out.text.assign(r.str, r.len);
      break;
    case REDIS_REPLY_INTEGER:
      out.type = RedisReply::Type::integer;
      out.integer = r.integer;
      break;
    case REDIS_REPLY_ARRAY:
      out.type = RedisReply::Type::array;
      out.elements.reserve(r.elements);
      for (std::size_t i = 0; i < r.elements; ++i) out.elements.push_back(copy(*r.element[i]));
      break;
    default: break;  // nil
  }
  return out;
}

}  // namespace

std::string RedisReply::field(std::string_view name) const {
  for (std::size_t i = 0; i + 1 < elements.size(); i += 2)
    if (elements[i].text == name) return elements[i + 1].text;
  return {};
}

Redis::Redis(BrokerUrl url, std::chrono::milliseconds timeout) : url_(std::move(url)), timeout_(timeout) { connect(); }

Redis::~Redis() { drop(); }

void Redis::drop() {
  if (context_) redisFree(context_);
  context_ = nullptr;
}

void Redis::connect() {
  // hiredis writes with write(2): a broker that went away would raise SIGPIPE and end the process
  // (server or worker) instead of failing the command. Network processes never want SIGPIPE.
  static std::once_flag ignore_sigpipe;
  std::call_once(ignore_sigpipe, [] { std::signal(SIGPIPE, SIG_IGN); });
  drop();
  const timeval tv = to_timeval(timeout_);
  context_ = url_.socket.empty() ? redisConnectWithTimeout(url_.host.c_str(), url_.port, tv)
                                 : redisConnectUnixWithTimeout(url_.socket.c_str(), tv);
  if (!context_) throw BrokerUnavailable("cannot reach the broker at " + url_.shown + ": out of memory");
  if (context_->err) {
    const std::string why = context_->errstr;
    drop();
    throw BrokerUnavailable("cannot reach the broker at " + url_.shown + ": " + why);
  }
  redisSetTimeout(context_, tv);
  if (!url_.password.empty()) {
    const char* argv[] = {"AUTH", url_.password.c_str()};
    const std::size_t lengths[] = {4, url_.password.size()};
    run(2, argv, lengths);
  }
  if (url_.db != 0) {
    const std::string db = std::to_string(url_.db);
    const char* argv[] = {"SELECT", db.c_str()};
    const std::size_t lengths[] = {6, db.size()};
    run(2, argv, lengths);
  }
}

RedisReply Redis::run(int argc, const char** argv, const std::size_t* lengths) {
  auto* reply = static_cast<redisReply*>(redisCommandArgv(context_, argc, argv, lengths));
  if (!reply) {
    const std::string why = context_->errstr[0] ? context_->errstr : "no reply";
    drop();  // hiredis cannot use a context after an I/O error
    throw BrokerUnavailable("lost the broker at " + url_.shown + ": " + why);
  }
  if (reply->type == REDIS_REPLY_ERROR) {
    const std::string message(reply->str, reply->len);
    freeReplyObject(reply);
    throw RedisReplyError(message);
  }
  RedisReply out = copy(*reply);
  freeReplyObject(reply);
  return out;
}

RedisReply Redis::command(const std::vector<std::string>& args) {
  if (!context_) connect();
  std::vector<const char*> argv;
  std::vector<std::size_t> lengths;
  for (const std::string& a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  return run(static_cast<int>(argv.size()), argv.data(), lengths.data());
}

RedisReply Redis::command(std::initializer_list<std::string_view> args) {
  if (!context_) connect();
  std::vector<const char*> argv;
  std::vector<std::size_t> lengths;
  for (const std::string_view a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  return run(static_cast<int>(argv.size()), argv.data(), lengths.data());
}

}  // namespace gestura::serve
