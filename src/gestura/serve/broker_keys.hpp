#pragma once
// The layout of the job broker in Redis, shared by the API servers (redis_render_jobs) and the
// workers (render_worker). docs/api.md describes it for operators.
//
//   gestura:jobs          stream; an entry per job: id, payload (the POST /api/video JSON)
//                         consumer group "render": each entry goes to one worker, stays pending
//                         until that worker stored the video and acknowledged it (then deleted),
//                         and is claimed again by another worker when its holder stops renewing
//                         its claim (XAUTOCLAIM after --claim-after seconds of silence)
//   gestura:job:ID        hash; status (queued running done failed cancelled), stage, done,
//                         total, format, content_type, error (the API's error JSON), worker,
//                         attempts, cancel, version (grows with every change)
//   gestura:video:ID      string; the finished video's bytes
//   gestura:dead          stream; dead letters: entries no worker can run (malformed payloads,
//                         jobs that took down every worker that held them), with the reason
//   gestura:workers       sorted set; worker name → last time seen (ms since the epoch)
#include <string>

namespace gestura::serve::broker {

inline constexpr const char* kStream = "gestura:jobs";
inline constexpr const char* kGroup = "render";
inline constexpr const char* kDead = "gestura:dead";
inline constexpr const char* kWorkers = "gestura:workers";
inline std::string job_key(const std::string& id) { return "gestura:job:" + id; }
inline std::string video_key(const std::string& id) { return "gestura:video:" + id; }

// A job's record and its video are kept this long after it finished (seconds).
inline constexpr int kKeepSeconds = 24 * 3600;
// A worker not seen for this long no longer counts as present in /metrics (ms).
inline constexpr long long kWorkerSeenMs = 30000;
// A job delivered this many times without finishing is dead-lettered (it kills its workers).
inline constexpr long long kMaxDeliveries = 4;

// Cancel: a queued job is cancelled at once; a running one is flagged (its worker stops it).
// Returns 1 when cancelled or flagged, 0 when there is no such job, -1 when it has finished.
inline constexpr const char* kCancelScript = R"(
local s = redis.call('HGET', KEYS[1], 'status')
if not s then return 0 end
if s == 'queued' then
  redis.call('HSET', KEYS[1], 'status', 'cancelled', 'cancel', '1')
  redis.call('HINCRBY', KEYS[1], 'version', 1)
  return 1
end
if s == 'running' then redis.call('HSET', KEYS[1], 'cancel', '1') return 1 end
return -1
)";

// A worker takes a job: queued (or running, when claimed from a dead worker) becomes running by
// ARGV[1]. Returns the status the job had: a worker renders only when it was queued or running.
inline constexpr const char* kStartScript = R"(
local s = redis.call('HGET', KEYS[1], 'status')
if not s then return 'missing' end
if s ~= 'queued' and s ~= 'running' then return s end
if redis.call('HGET', KEYS[1], 'cancel') == '1' then
  redis.call('HSET', KEYS[1], 'status', 'cancelled')
  redis.call('HINCRBY', KEYS[1], 'version', 1)
  return 'cancelled'
end
redis.call('HSET', KEYS[1], 'status', 'running', 'worker', ARGV[1], 'stage', 'starting', 'done', '0', 'total', '0')
redis.call('HINCRBY', KEYS[1], 'attempts', 1)
redis.call('HINCRBY', KEYS[1], 'version', 1)
return s
)";

}  // namespace gestura::serve::broker
