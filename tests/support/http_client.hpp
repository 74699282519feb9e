#pragma once
// A small blocking HTTP/1.1 client on Boost.Beast for the server tests: one request per
// connection, or raw bytes for malformed requests.
#include <map>
#include <string>

namespace gestura::test {

struct HttpReply {
  int status = 0;
  std::map<std::string, std::string> headers;  // lower-case names
  std::string body;
};

HttpReply http(int port, const std::string& method, const std::string& target, const std::string& body = {},
               const std::map<std::string, std::string>& headers = {{"Content-Type", "application/json"}});
// Sends `raw` as is and returns what came back before the server closed (empty when nothing).
std::string http_raw(int port, const std::string& raw);

}  // namespace gestura::test
