#pragma once
// Shared signing rooms (VLNET in realtime-virtual-humans.txt: people in different places share one
// virtual space, each shown by a virtual human, with autonomous actors among them). The rooms'
// state is the server's: who sits where with which look, what each is signing and since when, where
// the host looks. Clients only show it.
//
// This file is the rooms without a network: connections are numbers, a connection's outgoing
// messages go to a Send callback (the WebSocket adapter, room_socket.cpp, queues them), and slow
// work (a sentence signed, a body pose solved) goes to a Post callback (the server's compute
// threads). The protocol (docs/api.md, "Rooms") is JSON text messages with a "type":
//
//   client → server   join {name, look, token?} · say {text, speed?} · landmarks {pose, left?, right?, face?, aspect?}
//                     · ping {t} · leave
//   server → client   welcome · joined · left · away · back · play · pose · host · pong · error
//
// Every server message carries "time": server seconds (a steady clock); a client estimates its
// offset from ping/pong and plays a clip `start` at the same moment as everyone else.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "gestura/mocap/holistic_fit.hpp"
#include "gestura/serve/room_host.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::serve {

struct RoomLimits {
  int max_rooms = 64;
  int seats = 8;                       // participants in a room (the host comes on top)
  std::size_t max_message = 16 * 1024; // bytes of one client message (more: an error, the connection stays)
  std::size_t max_text = 2000;         // bytes of text one say signs
  double reconnect_grace = 60.0;       // seconds a seat is kept for a participant who lost the connection
  double messages_per_second = 20.0;   // a connection's messages (join, say, ping …), with a burst of twice that
  double poses_per_second = 30.0;      // landmarks messages, with a burst of one second's worth
  double lead = 0.5;                   // seconds between a clip being ready and everyone starting it
  double host_home_after = 6.0;        // seconds with nobody signing before the host walks back to its place
  int clips_kept = 16;                 // clips a room keeps for late joiners and slow fetchers
};

// A sentence signed for a room: the small clip .glb a player fetches and the timeline.
struct RoomClip {
  std::string glb;
  nlohmann::json timeline;  // glosses, duration … (app::to_json of the say result)
  double duration = 0.0;
};

// Joint rotations (local, x y z w) by H-Anim name, as a player sets them on its bones.
using JointRotations = std::vector<std::pair<std::string, std::array<float, 4>>>;

// What the rooms ask of the server; every callback may be called from any thread.
struct RoomServices {
  // Signs `text` on the look (slow: call from Post only). Throws AppError for a bad request.
  std::function<RoomClip(const std::string& text, float speed, const std::string& look)> say;
  // Fits the look's body to one frame of MediaPipe Holistic landmarks (a landmarks message, checked
  // already: landmarks_json.hpp); slow: call from Post only. Throws for a frame it cannot fit.
  std::function<JointRotations(const HolisticFrame& landmarks, const std::string& look)> capture;
  // The host's head and eyes turned toward a point (world, metres), the host standing at `host`;
  // quick, never blocks: none while the host's body is not built yet. prepare_host builds it (slow:
  // called through post, once).
  std::function<std::optional<JointRotations>(const SeatView& host, const vec3& point)> gaze;
  std::function<void()> prepare_host;
  // The world's walk cycle on the host's body along `body` (its root moving in world space), as the
  // small clip .glb a player fetches; slow: call from Post only. None while the host's body is not
  // built yet. Without it the host only turns its head.
  std::function<std::optional<std::string>(const RootTrajectory& body)> walk;
  // Runs slow work elsewhere; the default runs it at once, on the caller's thread.
  std::function<void(std::function<void()>)> post;
};

// Where a seat is in the shared scene: on an arc facing its middle, the host at the arc's middle.
struct Seat {
  vec3 position{0.0f};
  float yaw = 0.0f;  // radians about +Y; 0 faces +Z
};
Seat seat_place(int seat);  // seat -1 is the host's
bool valid_room_name(std::string_view name);
bool valid_look(std::string_view look);

class Rooms {
 public:
  using Send = std::function<void(const std::string& text)>;  // must not block; called under the rooms' lock
  using Close = std::function<void()>;                         // ends a connection (replaced, too slow, flooding)

  explicit Rooms(RoomServices services, RoomLimits limits = {});
  ~Rooms();

  // A new connection to a room (created when missing). Null when the name is not valid or the
  // server has max_rooms rooms; then nothing was created.
  std::optional<std::uint64_t> connect(const std::string& room, Send send, Close close);
  // One text message of a connection. Never throws: a malformed one gets an error message.
  void receive(std::uint64_t connection, std::string_view text);
  // A message too large to read (the adapter stopped reading it at `size` bytes).
  void oversized(std::uint64_t connection, std::size_t size);
  // The connection is gone (closed, lost, replaced). Its seat waits reconnect_grace for the token.
  void disconnect(std::uint64_t connection);
  // Ends clips that have finished, frees seats whose grace has passed, moves the host's gaze,
  // drops empty rooms. The server calls it a few times a second.
  void tick();

  // A clip of a room (the .glb bytes), while the room keeps it.
  std::optional<std::string> clip(const std::string& room, const std::string& id) const;
  // A room's state as a late joiner's welcome shows it (null when there is no such room), and the
  // list of rooms.
  nlohmann::json state(const std::string& room) const;
  nlohmann::json list() const;

  double now() const;  // server seconds
  // Where slow work runs (the server's compute threads); set before the first connection.
  void set_post(std::function<void(std::function<void()>)> post) { services_.post = std::move(post); }
  const RoomLimits& limits() const { return limits_; }

 private:
  struct Participant;
  struct Connection;
  struct Room;

  void handle(Connection& c, const nlohmann::json& message);
  void join(Connection& c, const nlohmann::json& message);
  void say(Connection& c, Participant& p, const nlohmann::json& message);
  void landmarks(Connection& c, Participant& p, const nlohmann::json& message);
  void leave(Connection& c);
  void finish_say(const std::string& room, const std::string& participant, std::uint64_t generation, const std::string& text, RoomClip clip);
  void receive_locked(std::uint64_t connection, std::string_view text);
  void disconnect_locked(std::uint64_t connection);
  void tick_locked();
  // Slow work is queued under the lock and posted after it is released (a post that runs the work
  // at once must not find the lock held).
  void defer(std::function<void()> job);
  void run_deferred();
  void fail(Connection& c, int status, const std::string& category, const std::string& message, const std::string& field = {});
  void fail_current(Connection& c);
  void broadcast(Room& room, nlohmann::json message, std::uint64_t except = 0);
  void send(Connection& c, nlohmann::json message);
  void update_host(Room& room);
  void prepare_host_once();
  void start_walk(Room& room, int goal);
  void remove_participant(Room& room, const std::string& id, const std::string& why);
  nlohmann::json state_locked(const Room& room) const;
  nlohmann::json participant_json(const Participant& p) const;
  Room* room_of(const Connection& c);
  Participant* participant_of(const Connection& c);

  RoomServices services_;
  RoomLimits limits_;
  std::chrono::steady_clock::time_point epoch_;
  mutable std::mutex mutex_;
  std::map<std::string, std::unique_ptr<Room>> rooms_;
  std::map<std::uint64_t, std::unique_ptr<Connection>> connections_;
  std::uint64_t next_connection_ = 1;
  std::uint64_t next_clip_ = 1;
  bool host_preparing_ = false;
  std::shared_ptr<RoomWorld> world_;  // the floor and the seats the host walks among
  std::vector<std::function<void()>> deferred_;
  std::shared_ptr<bool> alive_;  // posted work checks it before touching the rooms
};

}  // namespace gestura::serve
