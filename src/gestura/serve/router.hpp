#pragma once
// Routes: a method and a path pattern ("/api/jobs/{id}") to a handler. A path that matches no
// pattern is 404; one that matches with another method is 405 naming the allowed ones.
#include <functional>
#include <string>
#include <vector>

#include "gestura/app/context.hpp"
#include "gestura/serve/message.hpp"

namespace gestura::serve {

using Handler = std::function<ApiResponse(ApiRequest& request, const app::RunContext& context)>;

class Router {
 public:
  // `name` labels the route in /metrics ("say", "avatar"); patterns are '/'-separated segments, a
  // segment "{x}" matches any one non-empty segment and is stored in request.params["x"]. A pattern
  // ending in "/*" matches any rest (static files).
  void add(std::string method, std::string pattern, std::string name, Handler handler);

  struct Match {
    const Handler* handler = nullptr;  // null: no route (status says 404 or 405)
    std::string name;                  // the route's label, or "unmatched"
    int status = 404;
    std::string allowed;               // 405: "GET, POST"
  };
  // Fills request.params on a match.
  Match match(ApiRequest& request) const;

 private:
  struct Route {
    std::string method, name;
    std::vector<std::string> segments;
    bool rest = false;
    Handler handler;
  };
  std::vector<Route> routes_;
};

std::vector<std::string> split_path(const std::string& path);

}  // namespace gestura::serve
