// Boost.Asio's awaitable uses std::exchange without including <utility> (Boost 1.74).
#include <utility>

#include "gestura/serve/server.hpp"

#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "gestura/app/error.hpp"
#include "gestura/serve/api.hpp"
#include "gestura/serve/api_error.hpp"
#include "gestura/serve/gzip.hpp"
#include "gestura/serve/room.hpp"
#include "gestura/serve/room_socket.hpp"
#include "gestura/serve/url.hpp"

namespace gestura::serve {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using namespace std::chrono_literals;

constexpr std::uint32_t kHeaderLimit = 8 * 1024;
constexpr auto kReadTimeout = 10s;   // to send one request: slow clients cannot hold a slot for long
constexpr auto kWriteTimeout = 60s;  // to take one response (a video download on a slow line)
constexpr auto kIdleTimeout = 30s;   // between keep-alive requests

ApiRequest to_api(const http::request<http::string_body>& req) {
  ApiRequest r;
  r.method = std::string(req.method_string());
  const auto raw = req.target();
  Target target = parse_target(std::string_view(raw.data(), raw.size()));
  r.path = std::move(target.path);
  r.query = std::move(target.query);
  std::string type(req[http::field::content_type]);
  if (const std::size_t semi = type.find(';'); semi != std::string::npos) type.resize(semi);
  while (!type.empty() && type.back() == ' ') type.pop_back();
  for (char& c : type) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  r.content_type = type;
  r.accept = std::string(req[http::field::accept]);
  r.if_none_match = std::string(req[http::field::if_none_match]);
  r.body = req.body();
  return r;
}

void common_headers(http::response_header<>& h, bool api) {
  h.set(http::field::server, "gestura");
  if (api) h.set(http::field::access_control_allow_origin, "*");  // the widget calls from any page
  h.set("X-Content-Type-Options", "nosniff");
}

asio::awaitable<ApiResponse> compute(Api& api, ApiRequest& request) { co_return api.handle(request); }

}  // namespace

struct Server::Impl {
  ServeOptions options;
  std::unique_ptr<Api> api;
  asio::io_context io;
  asio::thread_pool pool;
  tcp::acceptor acceptor{io};
  std::vector<std::jthread> threads;
  std::atomic<int> computing{0};
  std::atomic<bool> stopped{false};

  explicit Impl(ServeOptions o) : options(std::move(o)), pool(static_cast<std::size_t>(options.threads)) {
    api = std::make_unique<Api>(options);
    boost::system::error_code ec;
    const auto address = asio::ip::make_address(options.host, ec);
    if (ec) throw app::AppError(app::ErrorCategory::usage, app::Place{"host", {}}, "'" + options.host + "' is not an IP address");
    const tcp::endpoint endpoint(address, static_cast<unsigned short>(options.port));
    acceptor.open(endpoint.protocol(), ec);
    if (!ec) acceptor.set_option(asio::socket_base::reuse_address(true), ec);
    if (!ec) acceptor.bind(endpoint, ec);
    if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
    if (ec) throw app::AppError(app::ErrorCategory::usage, app::Place{"port", {}}, "cannot listen on " + options.host + ":" + std::to_string(options.port) + ": " + ec.message());
    asio::co_spawn(io, listen(), asio::detached);
    api->rooms().set_post([this](std::function<void()> work) { asio::post(pool, std::move(work)); });
    asio::co_spawn(io, room_ticks(), asio::detached);
  }

  // The rooms' clock: clips end, seats of the gone are freed, the host turns.
  asio::awaitable<void> room_ticks() {
    asio::steady_timer timer(io);
    while (!stopped) {
      timer.expires_after(200ms);
      boost::system::error_code ec;
      co_await timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
      api->rooms().tick();
    }
  }

  asio::awaitable<void> listen() {
    for (;;) {
      boost::system::error_code ec;
      // Each connection on its own strand: a room's WebSocket reads and writes from two coroutines.
      tcp::socket socket = co_await acceptor.async_accept(asio::make_strand(io), asio::redirect_error(asio::use_awaitable, ec));
      if (ec) {
        if (!acceptor.is_open()) co_return;
        continue;  // EMFILE and the like: the next accept may work
      }
      if (api->metrics().open_connections() >= options.max_connections) {
        api->metrics().rejected_connection();
        socket.close(ec);
        continue;
      }
      const auto executor = socket.get_executor();
      asio::co_spawn(executor, session(std::move(socket)), asio::detached);
    }
  }

  template <class Body>
  asio::awaitable<bool> send(beast::tcp_stream& stream, http::response<Body>& res) {
    boost::system::error_code ec;
    stream.expires_after(kWriteTimeout);
    co_await http::async_write(stream, res, asio::redirect_error(asio::use_awaitable, ec));
    co_return !ec;
  }

  GzipCache gzip_cache;

  // The response with its body compressed when the client accepts gzip and it is worth it; a
  // file becomes a body then (compressed once per file version).
  ApiResponse compress(ApiResponse r) {
    if (!compressible(r.content_type) || r.status != 200) return r;
    std::string etag;
    for (const auto& [k, v] : r.headers)
      if (k == "ETag") etag = v;
    try {
      if (!r.file.empty()) {
        std::error_code ec;
        const auto size = std::filesystem::file_size(r.file, ec);
        if (ec || size > (8u << 20)) return r;
        std::ifstream in(r.file, std::ios::binary);
        std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        r.body = etag.empty() ? gzip(data) : gzip_cache.get(r.file + etag, data);
        r.file.clear();
      } else {
        if (r.body.size() < 1024) return r;
        r.body = etag.empty() ? gzip(r.body) : gzip_cache.get("body" + etag, r.body);
      }
    } catch (const std::exception&) {
      return r;  // zlib failed: send it plain
    }
    r.headers.emplace_back("Content-Encoding", "gzip");
    return r;
  }

  // Writes an API response; false when the connection is gone.
  asio::awaitable<bool> write(beast::tcp_stream& stream, const ApiResponse& r, bool head, bool keep_alive, int version) {
    if (!r.file.empty()) {
      http::response<http::file_body> res{http::status::ok, static_cast<unsigned>(version)};
      beast::error_code ec;
      res.body().open(r.file.c_str(), beast::file_mode::scan, ec);
      if (!ec) {
        common_headers(res, true);
        res.set(http::field::content_type, r.content_type);
        for (const auto& [k, v] : r.headers) res.set(k, v);
        res.keep_alive(keep_alive);
        res.prepare_payload();
        if (head) {
          http::response<http::empty_body> h{http::status::ok, static_cast<unsigned>(version)};
          h.base() = res.base();
          co_return co_await send(stream, h);
        }
        co_return co_await send(stream, res);
      }
      co_return co_await write(stream, error_response(404, "not_found", "the file is gone"), head, keep_alive, version);
    }
    http::response<http::string_body> res{static_cast<http::status>(r.status), static_cast<unsigned>(version)};
    common_headers(res, true);
    if (!r.content_type.empty()) res.set(http::field::content_type, r.content_type);
    for (const auto& [k, v] : r.headers) res.set(k, v);
    res.keep_alive(keep_alive);
    if (head) {
      res.content_length(r.body.size());
    } else {
      res.body() = r.body;
      if (r.status != 304 && r.status != 204) res.prepare_payload();
    }
    co_return co_await send(stream, res);
  }

  asio::awaitable<void> session(tcp::socket socket) {
    api->metrics().connection_opened();
    // Counted down when the frame goes, which may be after the Api (see Api::shared_metrics).
    struct Closed {
      std::shared_ptr<Metrics> m;
      ~Closed() { m->connection_closed(); }
    } closed{api->shared_metrics()};
    beast::tcp_stream stream(std::move(socket));
    beast::flat_buffer buffer;
    for (bool first = true;; first = false) {
      http::request_parser<http::string_body> parser;
      parser.header_limit(kHeaderLimit);
      parser.body_limit(static_cast<std::uint64_t>(options.max_body));
      stream.expires_after(first ? kReadTimeout : kIdleTimeout);
      boost::system::error_code ec;
      co_await http::async_read(stream, buffer, parser, asio::redirect_error(asio::use_awaitable, ec));
      if (ec == http::error::end_of_stream || ec == beast::error::timeout || ec == asio::error::connection_reset || ec == asio::error::eof) break;
      if (ec) {
        // A request we will not read to its end: answer, then close (the rest of it is garbage).
        ApiResponse r = ec == http::error::body_limit
                            ? error_response(413, "too_large", "the body is larger than " + std::to_string(options.max_body) + " bytes", "body")
                        : ec == http::error::header_limit ? error_response(431, "too_large", "the request header is larger than 8 KiB")
                                                          : error_response(400, "usage", "malformed HTTP request: " + ec.message());
        api->metrics().record("invalid", r.status, 0.0);
        co_await write(stream, r, false, false, 11);
        break;
      }
      http::request<http::string_body> req = parser.release();
      const bool head = req.method() == http::verb::head;
      const int version = static_cast<int>(req.version());
      ApiResponse response;
      bool upgrade = false;
      std::string job_id, room;
      try {
        ApiRequest request = to_api(req);
        if (websocket::is_upgrade(req)) {
          if (api->job_events(request, job_id)) upgrade = true;
          else if (api->room_socket(request, room) && valid_room_name(room)) upgrade = true;
          else if (!room.empty()) response = error_response(400, "usage", "a room's name is 1 to 40 letters, digits, '-' or '_'", "room");
          else response = error_response(404, "not_found", "no WebSocket at " + request.path);
        } else if (req.method() == http::verb::options) {
          response.status = 204;
          response.content_type.clear();
          response.headers = {{"Access-Control-Allow-Methods", "GET, POST, DELETE, OPTIONS"},
                              {"Access-Control-Allow-Headers", "Content-Type, Accept"},
                              {"Access-Control-Max-Age", "86400"}};
        } else if (api->quick(request)) {
          response = api->handle(request);  // reads state only: never queued behind signing
        } else if (computing.load() >= options.max_connections) {  // every connection may wait for one; more is a bug's flood
          response = error_response(503, "busy", "too many requests are waiting; try again shortly");
          response.headers.emplace_back("Retry-After", "1");
          api->metrics().record("busy", 503, 0.0);
        } else {
          ++computing;
          response = co_await asio::co_spawn(pool.get_executor(), compute(*api, request), asio::use_awaitable);
          --computing;
        }
      } catch (...) {  // the target's escapes, or anything the adapter did not expect
        response = current_error_response();
        api->metrics().record("invalid", response.status, 0.0);
      }
      if (upgrade && !room.empty()) {
        co_await serve_room(std::move(stream), std::move(req), api->rooms(), room);
        co_return;
      }
      if (upgrade) {
        co_await job_events(std::move(stream), std::move(req), job_id);
        co_return;
      }
      if (accepts_gzip(std::string_view(req[http::field::accept_encoding].data(), req[http::field::accept_encoding].size())))
        response = compress(std::move(response));
      response.headers.emplace_back("Vary", "Accept-Encoding");
      if (!co_await write(stream, response, head, req.keep_alive(), version) || !req.keep_alive()) break;
    }
    boost::system::error_code ec;
    stream.socket().shutdown(tcp::socket::shutdown_send, ec);
  }

  // A job's progress as JSON text messages until it ends: {id, status, stage, done, total}.
  asio::awaitable<void> job_events(beast::tcp_stream stream, http::request<http::string_body> req, std::string id) {
    websocket::stream<beast::tcp_stream> ws(std::move(stream));
    // The WebSocket keeps its own timeouts; the HTTP deadline still armed on the stream would cut a
    // long job's progress off mid-way (Beast: disable the tcp_stream's timer for a websocket).
    beast::get_lowest_layer(ws).expires_never();
    ws.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws.read_message_max(4096);
    boost::system::error_code ec;
    co_await ws.async_accept(req, asio::redirect_error(asio::use_awaitable, ec));
    if (ec) co_return;
    asio::steady_timer timer(co_await asio::this_coro::executor);
    std::uint64_t sent = ~std::uint64_t{0};
    for (;;) {
      const std::optional<JobState> s = api->jobs().state(id);
      nlohmann::json message;
      bool last = !s;
      if (!s) {
        message = {{"error", {{"code", 404}, {"category", "not_found"}, {"message", "no job " + id}, {"field", "id"}}}};
      } else if (s->version != sent) {
        sent = s->version;
        message = {{"id", s->id}, {"status", to_string(s->status)}, {"stage", s->stage}, {"done", s->done}, {"total", s->total}};
        if (s->status == JobStatus::done) message["download"] = "/api/jobs/" + s->id + "/download";
        last = s->status != JobStatus::queued && s->status != JobStatus::running;
      }
      if (!message.is_null()) {
        ws.text(true);
        co_await ws.async_write(asio::buffer(message.dump()), asio::redirect_error(asio::use_awaitable, ec));
        if (ec) co_return;
      }
      if (last || stopped) break;
      timer.expires_after(200ms);
      co_await timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    }
    co_await ws.async_close(websocket::close_code::normal, asio::redirect_error(asio::use_awaitable, ec));
  }
};

Server::Server(ServeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

Server::~Server() {
  stop();
  impl_->threads.clear();  // joins
  impl_->pool.join();
  // The rooms hold their connections' WebSocket streams, which live on the io_context: they must go
  // while it still exists (members would otherwise be destroyed io first, api last).
  impl_->api.reset();
}

int Server::port() const { return impl_->acceptor.local_endpoint().port(); }
Api& Server::api() { return *impl_->api; }

void Server::start() {
  for (int i = 0; i < 2; ++i) impl_->threads.emplace_back([this] { impl_->io.run(); });
}

void Server::run() {
  // Ctrl-C or a service manager's SIGTERM: stop accepting, finish, return.
  auto signals = std::make_shared<asio::signal_set>(impl_->io, SIGINT, SIGTERM);
  signals->async_wait([this, signals](const boost::system::error_code& ec, int) {
    if (!ec) stop();
  });
  start();
  impl_->threads.clear();  // waits until stop()
}

void Server::stop() {
  if (impl_->stopped.exchange(true)) return;
  asio::post(impl_->io, [this] {
    boost::system::error_code ec;
    impl_->acceptor.close(ec);
  });
  impl_->io.stop();
}

}  // namespace gestura::serve
