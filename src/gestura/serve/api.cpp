#include "gestura/serve/api.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <chrono>
#include <fstream>
#include <functional>
#include <random>

#include <nlohmann/json.hpp>

#include "gestura/app/gloss.hpp"
#include "gestura/app/lexicon.hpp"
#include "gestura/app/say.hpp"
#include "gestura/app/sign.hpp"
#include "gestura/body/avatar_look.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/io/gltf_export.hpp"
#include "gestura/serve/api_error.hpp"
#include "gestura/serve/clip_glb.hpp"
#include "gestura/serve/local_render_jobs.hpp"
#include "gestura/serve/redis_render_jobs.hpp"
#include "gestura/serve/look_choice.hpp"
#include "gestura/serve/room.hpp"
#include "gestura/serve/public_request.hpp"
#include "gestura/serve/request_json.hpp"
#include "gestura/serve/static_files.hpp"
#include "gestura/serve/random_hex.hpp"
#include "gestura/world/walk.hpp"
#include "gestura/world/walk_rig.hpp"

#ifndef GESTURA_VERSION
#define GESTURA_VERSION "0.1.0"
#endif

namespace gestura::serve {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr int kMaxLexiconLimit = 1000;

// The body as a JSON object; 415 for another media type, 400 for malformed JSON (binary bodies
// included: invalid UTF-8 is malformed JSON).
json body_json(const ApiRequest& request) {
  if (request.content_type != "application/json")
    throw app::AppError(app::ErrorCategory::usage, app::Place{"content-type", {}},
                        "send the request as application/json (got '" + request.content_type + "')");
  return parse_request_json(request.body);
}

template <class R>
R read_public(const json& body) {
  R r;
  app::read_json(body, r);
  return r;
}

// Query values arrive as text: set each through the field's own text parser.
template <class R>
R read_public_query(const ApiRequest& request, std::initializer_list<std::string_view> ignored) {
  R r;
  R::fields(r, [&](auto& value, const app::FieldInfo& field) {
    const auto it = request.query.find(std::string(field.name));
    if (it == request.query.end()) return;
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::vector<std::string>>) value.clear();
    app::set_from_text(value, it->second, field);
  });
  for (const auto& entry : request.query) {
    const std::string& key = entry.first;  // not a structured binding: clang 14 cannot capture one
    if (std::find(ignored.begin(), ignored.end(), key) != ignored.end()) continue;
    bool found = false;
    R::fields(r, [&](auto&, const app::FieldInfo& field) { found = found || field.name == key; });
    if (!found) app::usage_error(key, "unknown parameter");
  }
  return r;
}

// A look is a built-in look of the generated avatar (gestura avatar looks); a client names no
// avatar file of the server's.
void check_look(const std::string& look) {
  if (!valid_look(look)) app::usage_error("look", "is one of " + look_names() + ", not '" + look + "'");
}

void check_text(const std::string& text, int max_bytes) {
  if (text.size() > static_cast<std::size_t>(max_bytes))
    throw app::AppError(app::ErrorCategory::too_large, app::Place{"text", {}},
                        std::to_string(text.size()) + " bytes of text; this server signs at most " + std::to_string(max_bytes) +
                            " bytes per request (split longer text)");
}

bool wants_glb(const ApiRequest& request) {
  const auto f = request.query.find("format");
  if (f != request.query.end()) {
    if (f->second == "glb") return true;
    if (f->second == "json") return false;
    app::usage_error("format", "is json or glb, not '" + f->second + "'");
  }
  return request.accept.find("model/gltf-binary") != std::string::npos;
}

std::string quoted_hash(const std::string& bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "\"%016zx\"", std::hash<std::string>{}(bytes));
  return text;
}


// A performance as the client asked: JSON (timeline) or binary glTF (the animation, the timeline
// in its extras).
ApiResponse performance_response(const ApiRequest& request, json timeline, const Skeleton& skeleton, const Clip& clip, const Mesh& mesh) {
  if (!wants_glb(request)) return ApiResponse::json(200, timeline.dump());
  ApiResponse r;
  r.content_type = "model/gltf-binary";
  r.body = clip_glb(skeleton, clip, mesh, timeline);
  return r;
}

}  // namespace

Api::Api(ServeOptions options) : options_(std::move(options)) {
  app::check_fields(options_);
  if (options_.data.empty()) {
    // No --data: a fresh private folder (the server writes nowhere else).
    std::string templ = (fs::temp_directory_path() / "gestura-serve-XXXXXX").string();
    if (!mkdtemp(templ.data())) throw app::AppError(app::ErrorCategory::output, app::Place{"data", {}}, "cannot create a temporary folder");
    options_.data = templ;
  }
  std::error_code ec;
  fs::create_directories(options_.data, ec);
  if (ec || !fs::is_directory(options_.data))
    throw app::AppError(app::ErrorCategory::output, app::Place{"data", {}}, "cannot create folder " + options_.data + ": " + ec.message());
  data_ = fs::canonical(options_.data);
  if (!options_.web.empty()) {
    if (!fs::is_directory(options_.web, ec)) app::not_found("web", "no folder " + options_.web);
    web_ = fs::canonical(options_.web);
  }
  if (!options_.lexicon.empty()) setenv("GESTURA_LEXICON", options_.lexicon.c_str(), 1);  // the workspace's user lexicon
  // With a broker the workers render: this server needs no workspaces for jobs.
  workspaces_ = std::make_unique<WorkspacePool>(options_.threads + (options_.broker.empty() ? options_.jobs : 0),
                                                app::user_citation_store());
  if (options_.broker.empty()) {
    jobs_ = std::make_unique<LocalRenderJobs>((data_ / "jobs").string(), options_.jobs, static_cast<std::size_t>(options_.queue), *workspaces_);
  } else {
    BrokerUrl url = parse_broker_url(options_.broker);
    try {
      jobs_ = std::make_unique<RedisRenderJobs>(std::move(url), static_cast<std::size_t>(options_.queue));
    } catch (const std::exception& e) {
      throw app::AppError(app::ErrorCategory::usage, app::Place{"broker", {}}, e.what());
    }
  }
  RoomLimits room_limits;
  room_limits.max_text = static_cast<std::size_t>(options_.max_text);
  rooms_ = std::make_unique<Rooms>(room_services(), room_limits);
  add_routes();
}

Api::~Api() = default;

void Api::add_routes() {
  using namespace std::placeholders;
  router_.add("GET", "/health", "health", [this](ApiRequest&, const app::RunContext&) { return health(); });
  router_.add("GET", "/metrics", "metrics", [this](ApiRequest&, const app::RunContext&) {
    ApiResponse r;
    r.content_type = "text/plain; version=0.0.4";
    r.body = metrics_->prometheus(jobs_->waiting(), jobs_->running()) + jobs_->metrics();
    return r;
  });
  router_.add("POST", "/api/say", "say", [this](ApiRequest& q, const app::RunContext& c) { return say(q, c); });
  router_.add("POST", "/api/sign", "sign", [this](ApiRequest& q, const app::RunContext& c) { return sign(q, c); });
  router_.add("GET", "/api/gloss", "gloss", [this](ApiRequest& q, const app::RunContext& c) { return gloss(q, c); });
  router_.add("POST", "/api/gloss", "gloss", [this](ApiRequest& q, const app::RunContext& c) { return gloss(q, c); });
  router_.add("GET", "/api/lexicon", "lexicon", [this](ApiRequest& q, const app::RunContext& c) { return lexicon_search(q, c); });
  router_.add("GET", "/api/lexicon/{gloss}", "lexicon_entry", [this](ApiRequest& q, const app::RunContext& c) { return lexicon_entry(q, c); });
  router_.add("GET", "/api/avatar.glb", "avatar", [this](ApiRequest& q, const app::RunContext&) { return avatar(q); });
  router_.add("POST", "/api/video", "video", [this](ApiRequest& q, const app::RunContext&) { return video(q); });
  router_.add("GET", "/api/jobs/{id}", "job", [this](ApiRequest& q, const app::RunContext&) { return job(q); });
  router_.add("DELETE", "/api/jobs/{id}", "job_cancel", [this](ApiRequest& q, const app::RunContext&) { return job_cancel(q); });
  router_.add("GET", "/api/jobs/{id}/download", "job_download", [this](ApiRequest& q, const app::RunContext&) { return job_download(q); });
  router_.add("GET", "/api/jobs/{id}/events", "job_events", [](ApiRequest&, const app::RunContext&) {
    return error_response(426, "usage", "this is a WebSocket: connect with an Upgrade: websocket request");
  });
  router_.add("GET", "/api/looks", "looks", [](ApiRequest&, const app::RunContext&) {
    json looks = json::array();
    for (const AvatarLook& look : builtin_looks()) looks.push_back({{"name", look.name}, {"description", look.description}});
    ApiResponse r = ApiResponse::json(200, json{{"looks", looks}}.dump());
    r.headers.emplace_back("Cache-Control", "public, max-age=3600");
    return r;
  });
  router_.add("GET", "/api/rooms", "rooms", [this](ApiRequest&, const app::RunContext&) { return ApiResponse::json(200, rooms_->list().dump()); });
  router_.add("GET", "/api/rooms/{room}", "room", [this](ApiRequest& q, const app::RunContext&) {
    const json state = rooms_->state(q.params["room"]);
    if (state.is_null()) return error_response(404, "not_found", "no room " + q.params["room"] + " (a room exists while someone is in it)", "room");
    return ApiResponse::json(200, state.dump(-1, ' ', false, json::error_handler_t::replace));
  });
  router_.add("GET", "/api/rooms/{room}/clips/{id}", "room_clip", [this](ApiRequest& q, const app::RunContext&) {
    std::optional<std::string> glb = rooms_->clip(q.params["room"], q.params["id"]);
    if (!glb) return error_response(404, "not_found", "no clip " + q.params["id"] + " in room " + q.params["room"] + " (rooms keep their last clips only)", "id");
    ApiResponse r;
    r.content_type = "model/gltf-binary";
    r.body = std::move(*glb);
    r.headers.emplace_back("Cache-Control", "private, max-age=3600");  // a clip id is never reused
    return r;
  });
  router_.add("GET", "/ws/room/{room}", "room_socket", [](ApiRequest&, const app::RunContext&) {
    return error_response(426, "usage", "this is a room's WebSocket: connect with an Upgrade: websocket request");
  });
  router_.add("GET", "/*", "static", [this](ApiRequest& q, const app::RunContext&) {
    if (web_.empty()) {
      if (q.path == "/") return ApiResponse::json(200, json{{"service", "gestura"}, {"api", "/api"}, {"health", "/health"}}.dump());
      return error_response(404, "not_found", "no page is served (start with --web DIR)");
    }
    return static_file(web_, q);
  });
}

bool Api::job_events(const ApiRequest& request, std::string& job_id) const {
  const std::vector<std::string> parts = split_path(request.path);
  if (parts.size() != 4 || parts[0] != "api" || parts[1] != "jobs" || parts[3] != "events") return false;
  job_id = parts[2];
  return true;
}

bool Api::room_socket(const ApiRequest& request, std::string& room) const {
  const std::vector<std::string> parts = split_path(request.path);
  if (parts.size() != 3 || parts[0] != "ws" || parts[1] != "room") return false;
  room = parts[2];
  return true;
}

RoomServices Api::room_services() {
  RoomServices services;
  services.say = [this](const std::string& text, float speed, const std::string& look) {
    app::SayRequest say;
    say.text = text;
    say.speed = speed;
    say.avatar.avatar = look;
    const WorkspacePool::Lease workspace = workspaces_->acquire();
    app::RunContext context;
    context.workspace = workspace.get();
    const app::SayResult result = app::run(say, context);
    const Avatar& avatar = workspace->avatar(say.avatar);
    RoomClip clip;
    clip.timeline = app::to_json(result);
    clip.duration = result.performance.duration;
    clip.glb = clip_glb(avatar.skeleton, result.performance.clip, avatar.mesh, clip.timeline);
    return clip;
  };
  services.gaze = [this](const SeatView& host, const vec3& point) -> std::optional<JointRotations> {
    std::shared_ptr<const HostGaze> gaze;
    {
      std::lock_guard lock(host_mutex_);
      gaze = host_gaze_;
    }
    if (!gaze) return std::nullopt;
    return gaze->look_at(host, point);
  };
  services.walk = [this](const RootTrajectory& body) -> std::optional<std::string> {
    {
      std::lock_guard lock(host_mutex_);
      if (!host_gaze_) return std::nullopt;  // the host's body is not built yet
    }
    // The world's walk cycle (world/walk.hpp) on the host's avatar, on the room's flat floor.
    const WorkspacePool::Lease workspace = workspaces_->acquire();
    const Avatar& avatar = workspace->avatar(app::AvatarChoice{});
    const WalkRig rig = make_walk_rig(avatar);
    const WalkMotion motion = synthesize_walk(rig, body, nullptr);
    return clip_glb(avatar.skeleton, motion.clip, avatar.mesh, json{{"walk", true}, {"duration", body.duration()}});
  };
  services.prepare_host = [this] { host_gaze(); };
  services.capture = [this](const HolisticFrame& frame, const std::string& look) {
    const std::shared_ptr<const HolisticFit> fit = holistic_fit(look);
    const Pose pose = fit->fit(frame);
    JointRotations out;
    for (const int j : fit->driven_joints()) {
      const quat& q = pose.rotations[joint_slot(j)];
      out.push_back({fit->skeleton().names[joint_slot(j)], {q.x, q.y, q.z, q.w}});
    }
    return out;
  };
  return services;
}

std::shared_ptr<const HolisticFit> Api::holistic_fit(const std::string& look) {
  {
    std::lock_guard lock(fit_mutex_);
    if (const auto it = fits_.find(look); it != fits_.end()) return it->second;
  }
  // Built outside the lock (the look's avatar may take seconds the first time).
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  app::AvatarChoice choice;
  choice.avatar = look;
  auto fit = std::make_shared<const HolisticFit>(workspace->avatar(choice).skeleton);
  std::lock_guard lock(fit_mutex_);
  return fits_.emplace(look, std::move(fit)).first->second;
}

std::shared_ptr<const HostGaze> Api::host_gaze() {
  {
    std::lock_guard lock(host_mutex_);
    if (host_gaze_) return host_gaze_;
  }
  // Built outside the lock (seconds): gaze() answers "not yet" meanwhile instead of waiting.
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  const app::AvatarChoice host;
  const Avatar& avatar = workspace->avatar(host);
  auto gaze = std::make_shared<HostGaze>(std::make_shared<Skeleton>(avatar.skeleton), workspace->rig(host).bind_model);
  std::lock_guard lock(host_mutex_);
  if (!host_gaze_) host_gaze_ = std::move(gaze);
  return host_gaze_;
}

bool Api::quick(ApiRequest& request) const {
  const std::string name = router_.match(request).name;
  return name == "looks" || name == "rooms" || name == "room" || name == "room_clip" || name == "room_socket" || name == "health" || name == "metrics" || name == "job" || name == "job_cancel" || name == "static" ||
         name == "unmatched" || name == "job_events";
}

std::string Api::route_name(ApiRequest& request) const { return router_.match(request).name; }

ApiResponse Api::handle(ApiRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  const Router::Match match = router_.match(request);
  ApiResponse response;
  if (!match.handler) {
    response = match.status == 405 ? error_response(405, "method", request.method + " is not allowed here (allowed: " + match.allowed + ")")
                                   : error_response(404, "not_found", "no route " + request.path);
    if (match.status == 405) response.headers.emplace_back("Allow", match.allowed);
  } else {
    Deadlines::Guard deadline(deadlines_, std::chrono::seconds(options_.timeout));
    app::RunContext context;
    context.stop = deadline.token();  // handlers that compute lease a workspace into their own context
    try {
      response = (*match.handler)(request, context);
    } catch (const BrokerUnavailable& e) {
      response = error_response(503, "unavailable", std::string("the render queue is unreachable: ") + e.what());
      response.headers.emplace_back("Retry-After", "10");
    } catch (...) {
      response = current_error_response();
      if (deadline.expired())
        response = error_response(503, "timeout", "the request took longer than " + std::to_string(options_.timeout) + " s and was stopped");
    }
  }
  metrics_->record(match.name, response.status, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return response;
}

void Api::warm_up() {
  try {
    // Lease every workspace, then build and hand back one at a time: a request arriving meanwhile
    // gets the one just built (the pool hands out the last returned first).
    std::vector<std::optional<WorkspacePool::Lease>> all;
    for (int i = 0; i < workspaces_->size(); ++i) all.emplace_back(workspaces_->acquire());
    for (std::size_t i = 0; i < all.size(); ++i) {
      (*all[i])->signer(app::AvatarChoice{});
      if (i == 0) {
        avatar_bytes(**all[i], "default");
        all[i].reset();
        host_gaze();  // the rooms' host (leases the workspace just handed back)
      }
      all[i].reset();
    }
  } catch (...) {
    // The first request meets the same problem and reports it.
  }
}

ApiResponse Api::health() {
  return ApiResponse::json(200, json{{"status", "ok"},
                                     {"version", GESTURA_VERSION},
                                     {"jobs", {{"waiting", jobs_->waiting()}, {"running", jobs_->running()}}}}
                                    .dump());
}

ApiResponse Api::say(ApiRequest& request, const app::RunContext& context) {
  json body = body_json(request);
  const std::string look = take_look(body);
  app::SayRequest say = read_public<Public<app::SayRequest, SayFields>>(body).request;
  say.avatar.avatar = look;
  check_text(say.text, options_.max_text);
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  app::RunContext leased = context;
  leased.workspace = workspace.get();
  const app::SayResult result = app::run(say, leased);
  const Avatar& avatar = workspace->avatar(say.avatar);
  return performance_response(request, app::to_json(result), avatar.skeleton, result.performance.clip, avatar.mesh);
}

ApiResponse Api::sign(ApiRequest& request, const app::RunContext& context) {
  json body = body_json(request);
  // SiGML arrives as text (the postMessage of web players); the command layer reads it from a
  // file, so it goes to a private file under --data for the length of the request.
  std::string sigml_text;
  if (body.is_object() && body.contains("sigml")) {
    if (!body["sigml"].is_string()) app::usage_error("sigml", "expected the SiGML document as a string");
    sigml_text = body["sigml"].get<std::string>();
    body.erase("sigml");
    check_text(sigml_text, options_.max_body);
  }
  const std::string look = take_look(body);
  app::SignRequest sign = read_public<Public<app::SignRequest, SignFields>>(body).request;
  sign.avatar.avatar = look;
  struct Remove {
    fs::path path;
    ~Remove() {
      std::error_code ec;
      if (!path.empty()) fs::remove(path, ec);
    }
  } temporary;
  if (!sigml_text.empty()) {
    fs::create_directories(data_ / "tmp");
    temporary.path = data_ / "tmp" / (random_hex() + ".sigml");
    std::ofstream(temporary.path, std::ios::binary) << sigml_text;
    sign.source.sigml = temporary.path.string();
  }
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  // A document of several signs, none chosen by gloss: all of them, in order, as running signing on
  // one two-hand timeline (the Signer's, as for a sentence), each gloss timed.
  if (!sigml_text.empty() && sign.source.gloss.empty()) {
    std::vector<Signer::NotatedSign> signs;
    for (const sign::SigmlSign& s : sign::read_sigml(sigml_text, "sigml")) {
      std::string notation;
      for (const sign::Symbol symbol : s.symbols) utf8::append(notation, sign::symbol_info(symbol).codepoint);
      signs.push_back({s.gloss, std::move(notation)});
    }
    const bool notated = std::all_of(signs.begin(), signs.end(), [](const Signer::NotatedSign& s) { return !s.notation.empty(); });
    if (signs.size() > 1 && notated) {
      SayOptions options;
      options.speed = sign.speed;
      if (!(options.speed >= 0.25f && options.speed <= 2.0f)) app::usage_error("speed", "is between 0.25 and 2 for a document of several signs");
      context.check_stop();
      const SentencePerformance performed = workspace->signer(sign.avatar).sign_sequence(signs, options);
      json glosses = json::array();
      for (const PerformedGloss& g : performed.glosses) glosses.push_back({{"gloss", g.gloss}, {"start", g.start}, {"end", g.end}});
      const json timeline{{"duration", performed.duration}, {"glosses", glosses}, {"sign_start", performed.plan.sign_start},
                          {"sign_end", performed.plan.sign_end}, {"notes", performed.notes}};
      const Avatar& avatar = workspace->avatar(sign.avatar);
      return performance_response(request, timeline, avatar.skeleton, performed.clip, avatar.mesh);
    }
  }
  app::RunContext leased = context;
  leased.workspace = workspace.get();
  const app::SignResult result = app::perform(sign, leased);
  json timeline = app::to_json(result);
  timeline.erase("written");
  const Avatar& avatar = workspace->avatar(sign.avatar);
  return performance_response(request, timeline, avatar.skeleton, result.synthesis.clip, avatar.mesh);
}

ApiResponse Api::gloss(ApiRequest& request, const app::RunContext& context) {
  using R = Public<app::GlossRequest, GlossFields>;
  app::GlossRequest gloss = request.method == "GET" ? read_public_query<R>(request, {}).request : read_public<R>(body_json(request)).request;
  check_text(gloss.text, options_.max_text);
  gloss.db = options_.lexicon;
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  app::RunContext leased = context;
  leased.workspace = workspace.get();
  return ApiResponse::json(200, app::to_json(app::run(gloss, leased)).dump());
}

ApiResponse Api::lexicon_search(ApiRequest& request, const app::RunContext& context) {
  app::LexiconQuery query;
  for (const auto& [key, value] : request.query)
    if (key != "q" && key != "prefix" && key != "lang" && key != "limit") app::usage_error(key, "unknown parameter (known: q, prefix, lang, limit)");
  const auto get = [&](const char* key) { const auto it = request.query.find(key); return it == request.query.end() ? std::string() : it->second; };
  query.text = get("q");
  query.kind = query.text.empty() ? app::LexiconQueryKind::list : app::LexiconQueryKind::search;
  query.prefix = get("prefix") == "1" || get("prefix") == "true";
  query.lang = get("lang");
  query.db = options_.lexicon;
  check_text(query.text, options_.max_text);
  int limit = 100;
  if (const std::string l = get("limit"); !l.empty())
    limit = app::parse_number<int>(l, app::FieldInfo{.name = "limit", .min = 1, .max = kMaxLexiconLimit});
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  app::RunContext leased = context;
  leased.workspace = workspace.get();
  app::LexiconQueryResult result = app::run(query, leased);
  const std::size_t total = result.entries.size();
  if (result.entries.size() > static_cast<std::size_t>(limit)) result.entries.resize(static_cast<std::size_t>(limit));
  json out = app::to_json(result);
  out["total"] = total;
  return ApiResponse::json(200, out.dump());
}

ApiResponse Api::lexicon_entry(ApiRequest& request, const app::RunContext& context) {
  app::LexiconQuery query;
  query.kind = app::LexiconQueryKind::show;
  query.text = request.params["gloss"];
  for (const auto& [key, value] : request.query)
    if (key != "lang") app::usage_error(key, "unknown parameter (known: lang)");
  if (const auto it = request.query.find("lang"); it != request.query.end()) query.lang = it->second;
  query.db = options_.lexicon;
  const WorkspacePool::Lease workspace = workspaces_->acquire();
  app::RunContext leased = context;
  leased.workspace = workspace.get();
  return ApiResponse::json(200, app::to_json(app::run(query, leased)).dump());
}

void Api::avatar_bytes(app::Workspace& workspace, const std::string& look) {
  std::lock_guard lock(avatar_mutex_);
  if (avatar_glb_.count(look)) return;
  app::AvatarChoice choice;
  choice.avatar = look;
  const Avatar& a = workspace.avatar(choice);
  const std::vector<std::uint8_t> bytes = encode_glb(a.skeleton, a.mesh, "gestura");
  AvatarBytes& out = avatar_glb_[look];
  out.glb.assign(bytes.begin(), bytes.end());
  out.etag = quoted_hash(out.glb);
}

ApiResponse Api::avatar(ApiRequest& request) {
  for (const auto& [key, value] : request.query)
    if (key != "look") app::usage_error(key, "unknown parameter (known: look)");
  const std::string look = request.query.count("look") ? request.query.at("look") : std::string("default");
  check_look(look);
  bool built = false;  // else built here with a leased workspace (not under the lock: leasing may wait)
  {
    std::lock_guard lock(avatar_mutex_);
    built = avatar_glb_.count(look) > 0;
  }
  if (!built) {
    const WorkspacePool::Lease workspace = workspaces_->acquire();
    avatar_bytes(*workspace, look);
  }
  std::lock_guard lock(avatar_mutex_);
  const AvatarBytes& bytes = avatar_glb_.at(look);
  ApiResponse r;
  r.headers.emplace_back("ETag", bytes.etag);
  r.headers.emplace_back("Cache-Control", "public, max-age=86400");
  if (request.if_none_match == bytes.etag) {
    r.status = 304;
    r.content_type.clear();
    return r;
  }
  r.content_type = "model/gltf-binary";
  r.body = bytes.glb;
  return r;
}

ApiResponse Api::video(ApiRequest& request) {
  const json body = body_json(request);
  const VideoJob job = parse_video_job(body, options_.max_text);
  const std::optional<std::string> id = jobs_->submit(body, job);
  if (!id) {
    ApiResponse r = error_response(503, "busy", "the render queue is full; try again later");
    r.headers.emplace_back("Retry-After", "10");
    return r;
  }
  ApiResponse r = ApiResponse::json(202, json{{"id", *id}, {"status", "queued"}, {"url", "/api/jobs/" + *id}}.dump());
  r.headers.emplace_back("Location", "/api/jobs/" + *id);
  return r;
}

ApiResponse Api::job(ApiRequest& request) {
  const std::optional<JobState> s = jobs_->state(request.params["id"]);
  if (!s) return error_response(404, "not_found", "no job " + request.params["id"], "id");
  json out{{"id", s->id}, {"status", to_string(s->status)}, {"stage", s->stage}, {"done", s->done}, {"total", s->total},
           {"progress", s->status == JobStatus::done ? 1.0 : s->total > 0 ? double(s->done) / s->total : 0.0}};
  if (s->status == JobStatus::done) out["download"] = "/api/jobs/" + s->id + "/download";
  if (s->status == JobStatus::failed) {
    const json error = json::parse(s->error_json, nullptr, false);
    if (error.is_object() && error.contains("error")) out["error"] = error["error"];
  }
  return ApiResponse::json(200, out.dump());
}

ApiResponse Api::job_download(ApiRequest& request) {
  const std::optional<JobState> s = jobs_->state(request.params["id"]);
  if (!s) return error_response(404, "not_found", "no job " + request.params["id"], "id");
  if (s->status != JobStatus::done) return error_response(409, "conflict", "the job is " + to_string(s->status) + ", not done", "id");
  std::optional<JobResult> video = jobs_->result(s->id);
  if (!video) return error_response(404, "not_found", "the video of job " + s->id + " is no longer kept", "id");
  ApiResponse r;
  r.content_type = video->content_type;
  r.file = video->file;
  r.body = std::move(video->bytes);
  const std::string extension = r.content_type == "video/webm" ? ".webm" : ".mp4";
  r.headers.emplace_back("Content-Disposition", "attachment; filename=\"gestura-" + s->id + extension + "\"");
  return r;
}

ApiResponse Api::job_cancel(ApiRequest& request) {
  const std::string id = request.params["id"];
  if (!jobs_->state(id)) return error_response(404, "not_found", "no job " + id, "id");
  if (!jobs_->cancel(id)) return error_response(409, "conflict", "the job has finished", "id");
  return ApiResponse::json(200, json{{"id", id}, {"status", to_string(jobs_->state(id)->status)}}.dump());
}

}  // namespace gestura::serve
