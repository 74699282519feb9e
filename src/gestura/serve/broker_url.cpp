#include "gestura/serve/broker_url.hpp"

#include <charconv>

#include "gestura/app/error.hpp"

namespace gestura::serve {
namespace {

// The URL as an error shows it: a password (between "://" and "@") is hidden.
std::string shown(std::string_view url) {
  std::string out(url);
  const std::size_t scheme = out.find("://"), at = out.rfind('@');
  if (scheme != std::string::npos && at != std::string::npos && at > scheme) out.replace(scheme + 3, at - scheme - 3, "***");
  return out;
}

[[noreturn]] void bad(std::string_view url, const std::string& why) {
  app::usage_error("broker", "'" + shown(url) + "' " + why +
                                 " (expected redis://HOST[:PORT][/DB] or unix:///PATH/redis.sock)");
}

int number(std::string_view url, std::string_view text, int min, int max, const char* what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < min || value > max)
    bad(url, "has a bad " + std::string(what) + " '" + std::string(text) + "'");
  return value;
}

}  // namespace

BrokerUrl parse_broker_url(std::string_view url) {
  BrokerUrl out;
  if (url.empty()) bad(url, "is empty");
  if (url.find_first_of(" \t\r\n") != std::string_view::npos || url.find('\0') != std::string_view::npos) bad(url, "contains blanks");
  if (url.starts_with("unix://")) {
    std::string_view rest = url.substr(7);
    if (const std::size_t q = rest.find('?'); q != std::string_view::npos) {
      const std::string_view query = rest.substr(q + 1);
      rest = rest.substr(0, q);
      if (!query.starts_with("db=")) bad(url, "has an unknown parameter '" + std::string(query) + "' (known: db)");
      out.db = number(url, query.substr(3), 0, 1000, "database number");
    }
    if (!rest.starts_with('/') || rest.size() < 2) bad(url, "does not name a socket's absolute path");
    out.socket = std::string(rest);
    out.shown = "unix://" + out.socket + (out.db ? "?db=" + std::to_string(out.db) : "");
    return out;
  }
  if (!url.starts_with("redis://")) {
    const std::size_t colon = url.find("://");
    bad(url, colon == std::string_view::npos ? "is not a URL" : "has an unsupported scheme '" + std::string(url.substr(0, colon)) + "'");
  }
  std::string_view rest = url.substr(8);
  if (const std::size_t at = rest.rfind('@'); at != std::string_view::npos) {
    std::string_view user = rest.substr(0, at);
    rest = rest.substr(at + 1);
    const std::size_t colon = user.find(':');
    if (colon == std::string_view::npos) bad(url, "has a user but no password (redis://:PASSWORD@HOST)");
    out.password = std::string(user.substr(colon + 1));
  }
  std::string_view path;
  if (const std::size_t slash = rest.find('/'); slash != std::string_view::npos) {
    path = rest.substr(slash + 1);
    rest = rest.substr(0, slash);
  }
  if (!path.empty()) out.db = number(url, path, 0, 1000, "database number");
  std::string_view host = rest;
  if (host.starts_with('[')) {  // [::1]:6379
    const std::size_t close = host.find(']');
    if (close == std::string_view::npos) bad(url, "has an unclosed '[' in its host");
    out.host = std::string(host.substr(1, close - 1));
    host = host.substr(close + 1);
    if (!host.empty()) {
      if (host[0] != ':') bad(url, "has text after its host");
      out.port = number(url, host.substr(1), 1, 65535, "port");
    }
  } else {
    if (const std::size_t colon = host.rfind(':'); colon != std::string_view::npos) {
      out.port = number(url, host.substr(colon + 1), 1, 65535, "port");
      host = host.substr(0, colon);
    }
    out.host = std::string(host);
  }
  if (out.host.empty()) out.host = "127.0.0.1";
  out.shown = "redis://" + std::string(out.password.empty() ? "" : ":***@") + out.host + ":" + std::to_string(out.port) +
              (out.db ? "/" + std::to_string(out.db) : "");
  return out;
}

}  // namespace gestura::serve
