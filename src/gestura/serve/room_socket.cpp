// Boost.Asio's awaitable uses std::exchange without including <utility> (Boost 1.74).
#include <utility>

#include "gestura/serve/room_socket.hpp"

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <memory>
#include <nlohmann/json.hpp>

#include "gestura/serve/room.hpp"

namespace gestura::serve {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;

constexpr std::size_t kHardMessageLimit = 1u << 20;  // past this a message is not even read
constexpr std::size_t kOutboxMessages = 1024;         // a client this far behind is dropped
constexpr std::size_t kOutboxBytes = 16u << 20;

struct RoomSocket {
  websocket::stream<beast::tcp_stream> ws;
  asio::steady_timer signal;
  std::deque<std::string> outbox;
  std::size_t outbox_bytes = 0;
  bool closing = false;  // the server ends the connection (replaced, flooding, too slow)
  bool done = false;     // the reader has finished

  explicit RoomSocket(beast::tcp_stream stream) : ws(std::move(stream)), signal(ws.get_executor()) {}
};

asio::awaitable<void> write_loop(std::shared_ptr<RoomSocket> s) {
  boost::system::error_code ec;
  for (;;) {
    while (!s->outbox.empty() && !s->closing && !s->done) {
      std::string text = std::move(s->outbox.front());
      s->outbox.pop_front();
      s->outbox_bytes -= text.size();
      s->ws.text(true);
      co_await s->ws.async_write(asio::buffer(text), asio::redirect_error(asio::use_awaitable, ec));
      if (ec) co_return;
    }
    if (s->done) co_return;
    if (s->closing) {
      co_await s->ws.async_close(websocket::close_reason(websocket::close_code::policy_error), asio::redirect_error(asio::use_awaitable, ec));
      co_return;
    }
    s->signal.expires_at(asio::steady_timer::time_point::max());
    co_await s->signal.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  }
}

}  // namespace

asio::awaitable<void> serve_room(beast::tcp_stream stream, beast::http::request<beast::http::string_body> request, Rooms& rooms,
                                 std::string room) {
  stream.expires_never();  // the WebSocket keeps its own timeouts (below); the HTTP read's would cut it
  auto s = std::make_shared<RoomSocket>(std::move(stream));
  s->ws.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));  // pings an idle client
  s->ws.read_message_max(kHardMessageLimit);
  boost::system::error_code ec;
  co_await s->ws.async_accept(request, asio::redirect_error(asio::use_awaitable, ec));
  if (ec) co_return;
  const auto executor = co_await asio::this_coro::executor;
  // Called by the rooms from any thread: the socket's own work happens on its strand.
  auto send = [s, executor](const std::string& text) {
    asio::post(executor, [s, text] {
      if (s->closing || s->done) return;
      s->outbox.push_back(text);
      s->outbox_bytes += text.size();
      if (s->outbox.size() > kOutboxMessages || s->outbox_bytes > kOutboxBytes) s->closing = true;  // it does not read
      s->signal.cancel();
    });
  };
  auto close = [s, executor] {
    asio::post(executor, [s] {
      s->closing = true;
      s->signal.cancel();
    });
  };
  const std::optional<std::uint64_t> id = rooms.connect(room, send, close);
  if (!id) {
    const std::string refusal = nlohmann::json{{"type", "error"}, {"error", {{"code", 503}, {"category", "busy"}, {"message", "the server has as many rooms as it holds; try again later"}, {"field", "room"}}}}.dump();
    s->ws.text(true);
    co_await s->ws.async_write(asio::buffer(refusal), asio::redirect_error(asio::use_awaitable, ec));
    co_await s->ws.async_close(websocket::close_code::try_again_later, asio::redirect_error(asio::use_awaitable, ec));
    co_return;
  }
  asio::co_spawn(executor, write_loop(s), asio::detached);
  beast::flat_buffer buffer;
  for (;;) {
    co_await s->ws.async_read(buffer, asio::redirect_error(asio::use_awaitable, ec));
    if (ec) break;  // closed, lost, timed out, or a message past the hard limit (Beast closes with 1009)
    const std::string_view text(static_cast<const char*>(buffer.data().data()), buffer.size());
    rooms.receive(*id, text);
    buffer.consume(buffer.size());
  }
  rooms.disconnect(*id);
  s->done = true;
  s->signal.cancel();
}

}  // namespace gestura::serve
