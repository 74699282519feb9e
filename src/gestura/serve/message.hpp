#pragma once
// A request and a response as the handlers see them: plain data, no network types, so handlers
// are tested without sockets and the Beast adapter (server.cpp) is the only code that knows HTTP.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace gestura::serve {

struct ApiRequest {
  std::string method;                        // "GET", "POST", ...
  std::string path;                          // percent-decoded, without the query
  std::map<std::string, std::string> query;  // decoded; a repeated key keeps its last value
  std::string content_type;                  // without parameters ("application/json")
  std::string accept;
  std::string if_none_match;
  std::string body;
  std::map<std::string, std::string> params;  // filled by the router: {id} in "/api/jobs/{id}"
};

struct ApiResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  // extra ones (ETag, Cache-Control, Location)
  std::string file;  // when set, the body is this file's content, streamed by the adapter

  static ApiResponse json(int status, std::string body) {
    ApiResponse r;
    r.status = status;
    r.body = std::move(body);
    return r;
  }
};

}  // namespace gestura::serve
