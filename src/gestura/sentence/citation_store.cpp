#include "gestura/sentence/citation_store.hpp"

#include <link.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "gestura/lexicon/lexicon.hpp"

namespace gestura {

namespace {

// Bumped when the stored layout or what a form depends on changes in a way the build id does not
// show (it always changes with the code, so this is for the blob layout alone).
constexpr std::uint32_t kFormat = 2;
// A cache must never make say() wait: a busy database is a miss, not a pause.
constexpr int kBusyTimeoutMs = 100;

// FNV-1a, 64 bits: detects change, nothing more (the key text is checked on load).
struct Hasher {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  void f(float v) { bytes(&v, sizeof v); }
  void i(std::int64_t v) { bytes(&v, sizeof v); }
  void v3(const vec3& v) { f(v.x), f(v.y), f(v.z); }
  void q(const quat& v) { f(v.w), f(v.x), f(v.y), f(v.z); }
  void s(std::string_view text) { i(static_cast<std::int64_t>(text.size())), bytes(text.data(), text.size()); }
  void m(const mat4& v) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) f(v[c][r]);
  }
};

std::uint64_t rig_hash(const SigningRig& rig) {
  Hasher h;
  const Skeleton& s = rig.skeleton();
  for (std::size_t j = 0; j < s.size(); ++j) {
    h.s(s.names[j]), h.i(s.parents[j]), h.v3(s.rest_translations[j]), h.q(s.rest_rotations[j]), h.v3(s.rest_scales[j]);
    const JointDofs& d = s.dofs[j];
    h.i(static_cast<int>(d.order)), h.i(d.axes), h.v3(d.min_angle), h.v3(d.max_angle);
  }
  for (const mat4& m : rig.bind_model) h.m(m);
  for (const Pose* pose : {&rig.rest, &rig.neutral}) {
    for (const vec3& t : pose->translations) h.v3(t);
    for (const quat& r : pose->rotations) h.q(r);
    for (const vec3& sc : pose->scales) h.v3(sc);
  }
  for (const BodySite& site : rig.sites) h.s(site.name), h.i(site.joint), h.v3(site.local_offset), h.v3(site.local_normal);
  for (Hand hand : kBothHands) {
    const HandRig& r = rig.hand(hand);
    h.i(r.clavicle), h.i(r.shoulder), h.i(r.elbow), h.i(r.wrist);
    for (const auto& finger : r.fingers)
      for (int j : finger) h.i(j);
    h.q(r.rest_wrist_rotation), h.v3(r.palm_centre_local), h.f(r.palm_half_thickness);
  }
  for (const CollisionCapsule& c : rig.body) h.s(c.name), h.i(c.joint), h.v3(c.a), h.v3(c.b), h.f(c.radius);
  return h.h;
}

// The GNU build id of the running program (the linker writes one per distinct binary); when there
// is none, the executable's size and modification time.
std::string program_build_id() {
  std::string id;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) -> int {
        // The first object listed is the program itself.
        auto& found = *static_cast<std::string*>(out);
        for (int p = 0; p < info->dlpi_phnum; ++p) {
          const ElfW(Phdr)& ph = info->dlpi_phdr[p];
          if (ph.p_type != PT_NOTE) continue;
          const char* note = reinterpret_cast<const char*>(info->dlpi_addr + ph.p_vaddr);
          const char* end = note + ph.p_memsz;
          while (note + sizeof(ElfW(Nhdr)) <= end) {
            ElfW(Nhdr) header;
            std::memcpy(&header, note, sizeof header);
            const char* name = note + sizeof header;
            const char* desc = name + ((header.n_namesz + 3u) & ~3u);
            if (desc + header.n_descsz > end) break;
            if (header.n_type == NT_GNU_BUILD_ID && header.n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0) {
              static const char* digits = "0123456789abcdef";
              for (std::size_t i = 0; i < header.n_descsz; ++i) {
                const auto byte = static_cast<unsigned char>(desc[i]);
                found.push_back(digits[byte >> 4]), found.push_back(digits[byte & 15]);
              }
              return 1;
            }
            note = desc + ((header.n_descsz + 3u) & ~3u);
          }
        }
        return 1;
      },
      &id);
  if (!id.empty()) return id;
  struct stat st {};
  if (::stat("/proc/self/exe", &st) == 0)
    return "exe:" + std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
  return {};
}

std::int64_t as_column(std::uint64_t v) { return static_cast<std::int64_t>(v); }

// The plan is stored field by field. A field added to one of these types must be written and
// read here too (the sizes below are to make that hard to miss); a stored form is only ever read
// by the build that wrote it, so the layout need not stay compatible across versions.
static_assert(sizeof(HandState) == 124 && sizeof(HandPosture) == 88, "store the new field of HandState (write/read below)");
static_assert(sizeof(MovementPath) == 136 && sizeof(Movement) == 152, "store the new field of Movement (write/read below)");
static_assert(sizeof(HandSegment) == 312 && sizeof(SignPlan) == 56, "store the new field of HandSegment (write/read below)");

struct Writer {
  std::vector<std::uint8_t> out;
  template <class T>
  void raw(const T& v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    out.insert(out.end(), p, p + sizeof v);
  }
  void f(float v) { raw(v); }
  void u(std::uint32_t v) { raw(v); }
  void v3(const vec3& v) { f(v.x), f(v.y), f(v.z); }
  void q(const quat& v) { f(v.w), f(v.x), f(v.y), f(v.z); }
};

// Reads what Writer wrote; `ok` turns false (and stays) at the first read past the end or value
// that is not finite.
struct Reader {
  const std::uint8_t* p;
  const std::uint8_t* end;
  bool ok = true;
  template <class T>
  T raw() {
    T v{};
    if (static_cast<std::size_t>(end - p) < sizeof v) {
      ok = false;
      return v;
    }
    std::memcpy(&v, p, sizeof v);
    p += sizeof v;
    return v;
  }
  float f() {
    const float v = raw<float>();
    ok = ok && std::isfinite(v);
    return v;
  }
  std::uint32_t u() { return raw<std::uint32_t>(); }
  // A count of items of at least `min_bytes` each that the rest of the blob can hold.
  std::uint32_t count(std::size_t min_bytes) {
    const std::uint32_t n = u();
    if (static_cast<std::size_t>(end - p) / min_bytes < n) ok = false;
    return ok ? n : 0;
  }
  vec3 v3() {
    const float x = f(), y = f(), z = f();
    return {x, y, z};
  }
  quat q() {
    const float w = f(), x = f(), y = f(), z = f();
    return quat(w, x, y, z);
  }
};

void write(Writer& w, const HandState& s) {
  w.v3(s.position), w.q(s.orientation);
  const HandPosture& p = s.shape;
  for (float v : {p.thumb.cmc_flexion, p.thumb.cmc_abduction, p.thumb.cmc_opposition, p.thumb.mcp, p.thumb.ip}) w.f(v);
  for (const FingerFlexion& finger : p.fingers) w.f(finger.mcp), w.f(finger.pip), w.f(finger.dip);
  for (float v : p.spread) w.f(v);
  w.raw(p.thumb_tip_contacts), w.raw(p.middle_crosses_index);
  w.raw(s.active), w.raw(s.at_body), w.f(s.body_weight);
}

HandState read_state(Reader& r) {
  HandState s;
  s.position = r.v3();
  s.orientation = r.q();
  HandPosture& p = s.shape;
  for (float* v : {&p.thumb.cmc_flexion, &p.thumb.cmc_abduction, &p.thumb.cmc_opposition, &p.thumb.mcp, &p.thumb.ip}) *v = r.f();
  for (FingerFlexion& finger : p.fingers) finger.mcp = r.f(), finger.pip = r.f(), finger.dip = r.f();
  for (float& v : p.spread) v = r.f();
  p.thumb_tip_contacts = r.raw<FingerSet>();
  p.middle_crosses_index = r.raw<bool>();
  s.active = r.raw<bool>();
  s.at_body = r.raw<bool>();
  s.body_weight = r.f();
  return s;
}

void write(Writer& w, const Movement& m) {
  const MovementPath& p = m.path;
  w.raw(p.kind), w.v3(p.direction), w.f(p.length), w.v3(p.bulge), w.f(p.bulge_ratio), w.v3(p.axis), w.f(p.radius);
  w.v3(p.start_radial), w.f(p.turns);
  w.u(static_cast<std::uint32_t>(p.points.size()));
  for (const vec3& point : p.points) w.v3(point);
  w.raw(p.stop_at_corners), w.raw(p.modifier), w.f(p.modifier_amplitude), w.raw(p.modifier_cycles);
  w.v3(p.modifier_axis), w.v3(p.modifier_binormal);
  w.raw(m.profile), w.raw(m.passes), w.raw(m.repeat), w.f(m.duration);
}

Movement read_movement(Reader& r) {
  Movement m;
  MovementPath& p = m.path;
  p.kind = r.raw<PathKind>();
  p.direction = r.v3(), p.length = r.f(), p.bulge = r.v3(), p.bulge_ratio = r.f(), p.axis = r.v3(), p.radius = r.f();
  p.start_radial = r.v3(), p.turns = r.f();
  p.points.resize(r.count(3 * sizeof(float)));
  for (vec3& point : p.points) point = r.v3();
  p.stop_at_corners = r.raw<bool>(), p.modifier = r.raw<PathModifier>(), p.modifier_amplitude = r.f();
  p.modifier_cycles = r.raw<int>();
  p.modifier_axis = r.v3(), p.modifier_binormal = r.v3();
  m.profile = r.raw<VelocityProfile>(), m.passes = r.raw<int>(), m.repeat = r.raw<RepeatMode>(), m.duration = r.f();
  return m;
}

void write(Writer& w, const SignPlan& plan) {
  w.f(plan.sign_start), w.f(plan.sign_end);
  for (Hand hand : {Hand::Right, Hand::Left}) {
    const HandTimeline& timeline = plan.hand(hand);
    w.u(static_cast<std::uint32_t>(timeline.segments.size()));
    for (const HandSegment& s : timeline.segments) {
      w.f(s.start), w.f(s.end);
      write(w, s.from), write(w, s.to);
      w.u(static_cast<std::uint32_t>(s.paths.size()));
      for (const Movement& m : s.paths) write(w, m);
      w.raw(s.oscillation), w.f(s.oscillation_cycles), w.raw(s.oscillating_fingers), w.raw(s.linear_blend);
      w.v3(s.detour), w.raw(s.long_turn);
    }
  }
}

SignPlan read_plan(Reader& r) {
  SignPlan plan;
  plan.sign_start = r.f(), plan.sign_end = r.f();
  for (Hand hand : {Hand::Right, Hand::Left}) {
    HandTimeline& timeline = plan.hand(hand);
    timeline.segments.resize(r.count(sizeof(float) * 2));
    for (HandSegment& s : timeline.segments) {
      s.start = r.f(), s.end = r.f();
      s.from = read_state(r), s.to = read_state(r);
      s.paths.resize(r.count(sizeof(float)));
      for (Movement& m : s.paths) m = read_movement(r);
      s.oscillation = r.raw<Oscillation>(), s.oscillation_cycles = r.f(), s.oscillating_fingers = r.raw<FingerSet>();
      s.linear_blend = r.raw<bool>(), s.detour = r.v3(), s.long_turn = r.raw<bool>();
    }
  }
  return plan;
}

// The stored blob: the format, the rate, the first posture's time, the frames, the joints per
// hand, each hand's samples (w, x, y, z), then the plan.
std::vector<std::uint8_t> encode(const CitationMotion& m) {
  Writer w;
  w.u(kFormat), w.f(m.rate), w.f(m.first_posture), w.raw(static_cast<std::int32_t>(m.frames));
  for (Hand hand : {Hand::Right, Hand::Left}) w.u(static_cast<std::uint32_t>(m.joints[hand]));
  for (Hand hand : {Hand::Right, Hand::Left})
    for (const quat& q : m.samples[hand]) w.q(q);
  write(w, m.plan);
  return std::move(w.out);
}

// Empty when the blob does not hold a whole form with the joints a form of this rig has.
std::unique_ptr<CitationMotion> decode(const std::vector<std::uint8_t>& blob, const ByHand<std::size_t>& expected_joints) {
  Reader r{blob.data(), blob.data() + blob.size()};
  if (r.u() != kFormat) return nullptr;
  auto m = std::make_unique<CitationMotion>();
  m->rate = r.f();
  m->first_posture = r.f();
  m->frames = r.raw<std::int32_t>();
  for (Hand hand : {Hand::Right, Hand::Left}) m->joints[hand] = r.u();
  if (!r.ok || !(m->rate > 0.0f) || m->first_posture < 0.0f || m->frames < 2) return nullptr;
  for (Hand hand : {Hand::Right, Hand::Left}) {
    if (m->joints[hand] != expected_joints[hand]) return nullptr;
    const std::size_t quats = static_cast<std::size_t>(m->frames) * m->joints[hand];
    if (static_cast<std::size_t>(r.end - r.p) / (4 * sizeof(float)) < quats) return nullptr;
    m->samples[hand].resize(quats);
    for (quat& q : m->samples[hand]) q = r.q();
  }
  m->plan = read_plan(r);
  if (!r.ok || r.p != r.end) return nullptr;
  return m;
}

constexpr const char* kCreateTable =
    "CREATE TABLE IF NOT EXISTS citation_cache ("
    " avatar INTEGER NOT NULL, solver TEXT NOT NULL, sign_hash INTEGER NOT NULL, sign TEXT NOT NULL,"
    " motion BLOB NOT NULL, PRIMARY KEY (avatar, solver, sign_hash))";

}  // namespace

std::string CitationStore::solver_version() {
  static const std::string version = "f" + std::to_string(kFormat) + ":" + program_build_id();
  return version;
}

CitationStore::CitationStore(const std::string& path, const SigningRig& rig) : avatar_(rig_hash(rig)), solver_(solver_version()) {
  for (Hand hand : kBothHands) joints_[hand] = hand_motion_joints(rig, hand).size();
  try {
    if (solver_.size() <= 3) throw std::runtime_error("this program has no build id to tell its solver apart");
    const bool existed = std::filesystem::exists(path);
    if (!existed) {
      // A new file is a proper (empty) user lexicon, so the lexicon layers open it as one.
      if (const auto folder = std::filesystem::path(path).parent_path(); !folder.empty())
        std::filesystem::create_directories(folder);
      (void)Lexicon::open(path, kBusyTimeoutMs);
    }
    // access() also sees read-only mounts and immutable files, which SQLite would only report at
    // the first write.
    const std::string folder = std::filesystem::path(path).parent_path().string();
    if (::access(path.c_str(), W_OK) != 0 || ::access(folder.empty() ? "." : folder.c_str(), W_OK) != 0)
      throw std::runtime_error(path + " cannot be written");
    db_ = std::make_unique<sqlite::Database>(path, sqlite::Access::write, kBusyTimeoutMs);
    writable_ = true;
  } catch (const std::exception& e) {
    problem_ = e.what();
  }
  if (!db_) {
    // Read-only file, folder or mount: stored forms can still be read.
    try {
      db_ = std::make_unique<sqlite::Database>(path, sqlite::Access::read, kBusyTimeoutMs);
      problem_ += problem_.empty() ? "" : "; ";
      problem_ += "read-only: solved signs are not stored";
    } catch (const std::exception& e) {
      problem_ += problem_.empty() ? "" : "; ";
      problem_ += e.what();
      db_.reset();
      return;
    }
  }
  if (!writable_) return;
  try {
    // Only this connection: a cache write need not reach the disk before say() returns.
    db_->exec("PRAGMA synchronous = NORMAL");
    db_->exec(kCreateTable);
    auto stale = db_->prepare("DELETE FROM citation_cache WHERE solver <> ?1");
    stale.bind(1, solver_).run();
  } catch (const std::exception& e) {
    disable_writes(e.what());
  }
}

CitationStore::~CitationStore() = default;

void CitationStore::disable_writes(const std::string& why) {
  writable_ = false;
  problem_ += problem_.empty() ? "" : "; ";
  problem_ += why;
}

std::string CitationStore::problem() const {
  const std::lock_guard lock(mutex_);
  return problem_;
}

std::unique_ptr<CitationMotion> CitationStore::load(std::string_view key) {
  const std::lock_guard lock(mutex_);
  if (!db_) return nullptr;
  Hasher sign;
  sign.s(key);
  try {
    auto& row = db_->cached("SELECT sign, motion FROM citation_cache WHERE avatar = ?1 AND solver = ?2 AND sign_hash = ?3");
    row.bind(1, as_column(avatar_)).bind(2, solver_).bind(3, as_column(sign.h));
    std::unique_ptr<CitationMotion> motion;
    if (row.step() && row.text(0) == key) motion = decode(row.blob(1), joints_);
    row.reset();
    if (motion) ++loaded_;
    return motion;
  } catch (const std::exception& e) {
    // A table another program damaged or a file that went away: solve from now on.
    problem_ += problem_.empty() ? "" : "; ";
    problem_ += e.what();
    db_.reset();
    return nullptr;
  }
}

void CitationStore::save(std::string_view key, const CitationMotion& motion) {
  const std::lock_guard lock(mutex_);
  if (!db_ || !writable_) return;
  Hasher sign;
  sign.s(key);
  try {
    auto& insert = db_->cached(
        "INSERT OR REPLACE INTO citation_cache (avatar, solver, sign_hash, sign, motion) VALUES (?1, ?2, ?3, ?4, ?5)");
    insert.bind(1, as_column(avatar_)).bind(2, solver_).bind(3, as_column(sign.h)).bind(4, key).bind(5, encode(motion));
    insert.run();
    insert.reset();
    ++saved_;
  } catch (const std::exception& e) {
    // Full disk, a lock held too long, a damaged page: the sign stays solved in memory.
    disable_writes(e.what());
  }
}

}  // namespace gestura
