#pragma once
// Where the job broker is: `redis://[:PASSWORD@]HOST[:PORT][/DB]` or `unix:///PATH/redis.sock[?db=N]`.
// A malformed URL is a usage error at the field "broker" (the --broker flag of serve and worker).
#include <string>
#include <string_view>

namespace gestura::serve {

struct BrokerUrl {
  std::string socket;    // a unix socket's path; empty: TCP
  std::string host;      // TCP
  int port = 6379;
  int db = 0;
  std::string password;  // empty: none
  std::string shown;     // the URL without its password, for logs
};

BrokerUrl parse_broker_url(std::string_view url);

}  // namespace gestura::serve
