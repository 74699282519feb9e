#pragma once
// A room's WebSocket (GET /ws/room/NAME with Upgrade: websocket): the Beast side of rooms
// (room.hpp). One coroutine reads the client's messages and hands them to the rooms; another writes
// what the rooms send it, from a bounded queue: a client that does not read is dropped rather than
// let the server's memory grow. Messages of more than 1 MiB end the connection (close code 1009);
// smaller ones over the room's limit get an error message and the connection stays.
#include <boost/asio/awaitable.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/http/string_body.hpp>
#include <string>

namespace gestura::serve {

class Rooms;

// Runs on the stream's executor (a strand: the server accepts every connection on its own).
boost::asio::awaitable<void> serve_room(boost::beast::tcp_stream stream, boost::beast::http::request<boost::beast::http::string_body> request,
                                        Rooms& rooms, std::string room);

}  // namespace gestura::serve
