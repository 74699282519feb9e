#include "gestura/serve/router.hpp"

#include <map>

namespace gestura::serve {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (begin <= path.size()) {
    const std::size_t end = path.find('/', begin);
    const std::string part = path.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    if (!part.empty()) out.push_back(part);
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return out;
}

void Router::add(std::string method, std::string pattern, std::string name, Handler handler) {
  Route r{std::move(method), std::move(name), split_path(pattern), false, std::move(handler)};
  if (!r.segments.empty() && r.segments.back() == "*") r.segments.pop_back(), r.rest = true;
  routes_.push_back(std::move(r));
}

Router::Match Router::match(ApiRequest& request) const {
  const std::vector<std::string> parts = split_path(request.path);
  Match result;
  result.name = "unmatched";
  std::string allowed;
  // Exact patterns first: a path they know with another method is 405, not a static file.
  for (int pass = 0; pass < 2; ++pass)
  for (const Route& r : routes_) {
    if (r.rest != (pass == 1) || (pass == 1 && !allowed.empty())) continue;
    if (r.rest ? parts.size() < r.segments.size() : parts.size() != r.segments.size()) continue;
    std::map<std::string, std::string> params;
    bool same = true;
    for (std::size_t i = 0; i < r.segments.size() && same; ++i) {
      const std::string& s = r.segments[i];
      if (s.size() > 2 && s.front() == '{' && s.back() == '}') params[s.substr(1, s.size() - 2)] = parts[i];
      else same = s == parts[i];
    }
    if (!same) continue;
    const bool head_of_get = request.method == "HEAD" && r.method == "GET";
    if (r.method != request.method && !head_of_get) {
      if (allowed.find(r.method) == std::string::npos) allowed += (allowed.empty() ? "" : ", ") + r.method;
      continue;
    }
    request.params = std::move(params);
    result.handler = &r.handler;
    result.name = r.name;
    result.status = 200;
    return result;
  }
  if (!allowed.empty()) result.status = 405, result.allowed = allowed;
  return result;
}

}  // namespace gestura::serve
