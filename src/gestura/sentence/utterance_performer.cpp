#include "gestura/sentence/utterance_performer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "gestura/core/error.hpp"
#include "gestura/sign/movement_timing.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/sign_performer.hpp"

namespace gestura {

namespace {

constexpr float kTimeEpsilon = 1e-4f;
// A joint-space transition counts as entering the body when a hand point is this deep inside.
constexpr float kPenetrationTolerance = 0.004f;
// Transitions whose ends keep the palm centre farther than this from the body are not checked: the
// hand (palm centre to fingertip ≤ ~12 cm) cannot reach it between two such postures.
constexpr float kNearBody = 0.15f;
// Fraction of a re-solved transition over which it fades from and back to the joint-space path.
constexpr float kEscapeFade = 0.15f;

// What one hand does over one interval of the utterance.
struct Piece {
  enum class Kind : std::uint8_t { Cached, Blend, Solved };
  Kind kind = Kind::Blend;
  float t0 = 0.0f, t1 = 0.0f;
  const CachedSignSpan* sign = nullptr;  // Cached
  std::size_t a = 0, b = 0;              // Blend: offsets of the end postures in HandMotion::keys
  bool linear = false;                   // Blend: constant speed (the plan's linear_blend)
  int vias = 0;                          // Blend: bent through 0, 1, 3 or 7 via postures, evenly spaced
  std::size_t v = 0;                     // offset of the first via posture in HandMotion::keys
  bool escape = false;                   // Blend: fade to the IK-solved Cartesian path in the middle
};

struct HandMotion {
  std::vector<Piece> pieces;
  std::vector<quat> keys;  // postures at segment ends, joints() each
};

float citation_time(const CachedSignSpan& s, float t) {
  return std::clamp((t - s.moving) * s.tempo, 0.0f, s.motion->movement());
}

class HandPerformer {
 public:
  HandPerformer(Hand hand, const HandTimeline& timeline, std::vector<const CachedSignSpan*> spans, SignMotionCache& cache,
                float fps)
      : hand_(hand), timeline_(timeline), spans_(std::move(spans)), cache_(cache), n_(cache.joints(hand).size()), fps_(fps) {}

  HandMotion build(UtteranceStats& stats) {
    HandMotion m;
    std::size_t k = 0;  // the span that may contain the segment (spans are in time order)
    std::size_t emitted = 0;
    for (const HandSegment& seg : timeline_.segments) {
      while (k < spans_.size() && seg.end > spans_[k]->end + kTimeEpsilon) ++k;
      if (k < spans_.size() && seg.start >= spans_[k]->start - kTimeEpsilon && seg.end <= spans_[k]->end + kTimeEpsilon) {
        if (emitted <= k) {
          Piece p;
          p.kind = Piece::Kind::Cached;
          p.t0 = spans_[k]->start, p.t1 = spans_[k]->end;
          p.sign = spans_[k];
          m.pieces.push_back(p);
          emitted = k + 1;
        }
        continue;
      }
      Piece p;
      p.t0 = seg.start, p.t1 = seg.end;
      if (!seg.paths.empty() || seg.oscillation != Oscillation::None) {
        p.kind = Piece::Kind::Solved;  // a path outside the cached signs: solved frame by frame
        m.pieces.push_back(p);
        continue;
      }
      p.linear = seg.linear_blend;
      p.a = add_key(m, seg.start, seg.from);
      p.b = add_key(m, seg.end, seg.to);
      const bool moves = !std::equal(m.keys.begin() + static_cast<std::ptrdiff_t>(p.a),
                                     m.keys.begin() + static_cast<std::ptrdiff_t>(p.a + n_),
                                     m.keys.begin() + static_cast<std::ptrdiff_t>(p.b));
      if ((seg.from.active || seg.to.active) && moves) {
        ++stats.transitions;
        if (near_body(seg) && enters_body(m, p, seg)) {
          // Bend the path through points of the Cartesian transition solved by IK with the hand
          // pushed out of the body (stored, so once per pair of signs): the midpoint, else three,
          // else seven points; if that is still not enough, solve every frame.
          ++stats.via;
          bool inside = true;
          for (int vias : {1, 3}) {
            p.vias = vias;
            p.v = m.keys.size();
            Piece straight = p;
            straight.vias = 0;
            for (int i = 1; i <= vias; ++i) {
              const float u = static_cast<float>(i) / static_cast<float>(vias + 1);
              blend(m, straight, u, scratch_posture_);
              const HandJointPosture& q =
                  cache_.posture_from(hand_, sample_hand(timeline_, seg.start + (seg.end - seg.start) * u), scratch_posture_);
              m.keys.insert(m.keys.end(), q.begin(), q.end());
            }
            if (!(inside = enters_body(m, p, seg))) break;
          }
          p.escape = inside;
          stats.escaped += p.escape ? 1 : 0;
        }
      }
      m.pieces.push_back(p);
    }
    return m;
  }

  // The hand's joint rotations at time t; `cursor` walks the pieces forward as t grows. Contract:
  // `out` holds the posture of the previous frame (or the rest posture before the first).
  void evaluate(const HandMotion& m, float t, std::size_t& cursor, std::span<quat> out) const {
    while (cursor + 1 < m.pieces.size() && t > m.pieces[cursor].t1) ++cursor;
    const Piece& p = m.pieces[cursor];
    const float u = p.t1 > p.t0 ? std::clamp((t - p.t0) / (p.t1 - p.t0), 0.0f, 1.0f) : 1.0f;
    switch (p.kind) {
      case Piece::Kind::Cached: p.sign->motion->sample(hand_, citation_time(*p.sign, t), out); return;
      case Piece::Kind::Solved: {
        // `out` still holds the previous frame's posture: the solver continues from it.
        const HandJointPosture q = cache_.solve_from(hand_, sample_hand(timeline_, t), out);
        std::copy(q.begin(), q.end(), out.begin());
        return;
      }
      case Piece::Kind::Blend: break;
    }
    blend(m, p, u, out);
    if (!p.escape) return;
    // Fade from the joint-space path to the Cartesian one solved with the hand kept out of the
    // body, and back, each over the first and last 15 % of the piece (a hand leaving a sign made
    // on the face must follow the pushed-out path almost at once): the weight is 0 with zero slope
    // at both ends, so the piece still starts and ends exactly at its postures.
    const HandJointPosture q = cache_.solve_from(hand_, sample_hand(timeline_, t), out);
    auto ease = [](float x) { return x * x * (3.0f - 2.0f * x); };
    const float w = ease(std::min(1.0f, u / kEscapeFade)) * ease(std::min(1.0f, (1.0f - u) / kEscapeFade));
    for (std::size_t j = 0; j < n_; ++j) out[j] = nlerp(out[j], q[j], w);
  }

 private:
  void blend(const HandMotion& m, const Piece& p, float u, std::span<quat> out) const {
    const float s = p.linear ? u : minimum_jerk(u);
    if (p.vias == 0) {
      for (std::size_t j = 0; j < n_; ++j) out[j] = nlerp(m.keys[p.a + j], m.keys[p.b + j], s);
      return;
    }
    // The straight joint-space blend, rotated by a correction that is the identity at the ends and
    // turns the blend into each via posture at its instant, eased between (zero slope at the knots).
    const float knots = static_cast<float>(p.vias + 1);
    const int k = std::min(static_cast<int>(u * knots), p.vias);  // interval [k, k + 1] / knots
    const float w = std::clamp(u * knots - static_cast<float>(k), 0.0f, 1.0f);
    const float ease = w * w * (3.0f - 2.0f * w);
    const float sk = p.linear ? static_cast<float>(k) / knots : minimum_jerk(static_cast<float>(k) / knots);
    const float sk1 = p.linear ? static_cast<float>(k + 1) / knots : minimum_jerk(static_cast<float>(k + 1) / knots);
    for (std::size_t j = 0; j < n_; ++j) {
      const quat& a = m.keys[p.a + j];
      const quat& b = m.keys[p.b + j];
      // Correction at knot i: via posture · inverse(straight blend there); identity at the ends.
      auto correction = [&](int i, float si) {
        if (i <= 0 || i > p.vias) return quat(1, 0, 0, 0);
        return m.keys[p.v + static_cast<std::size_t>(i - 1) * n_ + j] * glm::inverse(nlerp(a, b, si));
      };
      const quat c = nlerp(correction(k, sk), correction(k + 1, sk1), ease);
      out[j] = glm::normalize(c * nlerp(a, b, s));
    }
  }

  // Appends the posture at a segment end: a cached sign's first or last posture when one starts
  // or ends there, else the state solved once by IK (stored in the cache).
  std::size_t add_key(HandMotion& m, float time, const HandState& state) {
    const std::size_t offset = m.keys.size();
    m.keys.resize(offset + n_);
    const std::span<quat> out(m.keys.data() + offset, n_);
    for (const CachedSignSpan* s : spans_) {
      if (std::abs(s->start - time) < kTimeEpsilon || std::abs(s->end - time) < kTimeEpsilon) {
        s->motion->sample(hand_, citation_time(*s, time), out);
        return offset;
      }
      if (s->start > time) break;
    }
    const HandJointPosture& q = cache_.posture(hand_, state);
    std::copy(q.begin(), q.end(), out.begin());
    return offset;
  }

  // Whether a segment starts or ends with the palm close enough to the body for a joint-space path
  // to reach it (the collision body does not move while the arms sign, so the bind pose places it).
  bool near_body(const HandSegment& seg) const {
    const SigningRig& rig = cache_.rig();
    for (const HandState* s : {&seg.from, &seg.to})
      if (s->active && body_signed_distance(rig, rig.bind_model, s->position) < kNearBody) return true;
    return false;
  }

  // Whether the joint-space path of a piece takes a hand point deeper into the body than its ends
  // are (a sign touching the body may end a few millimetres in), checked at every output frame. An
  // end at rest does not count, nor the half next to it: the hanging hand lies inside the coarse
  // torso capsule, which the real body does not fill there.
  bool enters_body(const HandMotion& m, const Piece& p, const HandSegment& seg) const {
    float allowed = kPenetrationTolerance;
    if (seg.from.active) allowed = std::max(allowed, penetration(m, p, 0.0f) + kPenetrationTolerance);
    if (seg.to.active) allowed = std::max(allowed, penetration(m, p, 1.0f) + kPenetrationTolerance);
    // At the frames that will be shown (a hand sweeping past the chin crosses it in two frames).
    for (float t = std::ceil(p.t0 * fps_) / fps_; t < p.t1; t += 1.0f / fps_) {
      const float u = (t - p.t0) / (p.t1 - p.t0);
      if (u <= 0.0f || (u < 0.5f && !seg.from.active) || (u > 0.5f && !seg.to.active)) continue;
      if (penetration(m, p, u) > allowed) return true;
    }
    return false;
  }

  // How deep the hand's deepest point is inside the body at u along the piece (≤ 0 when outside).
  float penetration(const HandMotion& m, const Piece& p, float u) const {
    const SigningRig& rig = cache_.rig();
    const std::vector<int>& joints = cache_.joints(hand_);
    blend(m, p, u, scratch_posture_);
    for (std::size_t j = 0; j < n_; ++j) scratch_pose_.rotations[joint_slot(joints[j])] = scratch_posture_[j];
    update_model();
    return hand_penetration(rig, hand_, scratch_model_, scratch_points_);
  }

  // scratch_model_ from scratch_pose_, in which only the hand's joints move: the first time the
  // whole body, then only the arm's subtree (clavicle to fingertips), whose joints follow one another
  // in the skeleton; the same products as local_to_model over the whole body.
  void update_model() const {
    const Skeleton& s = cache_.rig().skeleton();
    if (!model_ready_) {
      local_to_model(s, scratch_pose_, scratch_model_);
      model_ready_ = true;
      subtree_ = arm_subtree(s);
      for (std::size_t i = subtree_[0]; i < subtree_[1]; ++i)
        subtree_parents_.push_back(static_cast<std::int16_t>(i == subtree_[0] ? -1 : s.parents[i] - static_cast<int>(subtree_[0])));
      return;
    }
    if (subtree_[1] == 0) {
      local_to_model(s, scratch_pose_, scratch_model_);
      return;
    }
    const std::size_t first = subtree_[0], count = subtree_[1] - subtree_[0];
    const int parent = s.parents[first];
    local_to_model(subtree_parents_, std::span(scratch_pose_.translations).subspan(first, count),
                   std::span(scratch_pose_.rotations).subspan(first, count), std::span(scratch_pose_.scales).subspan(first, count),
                   std::span(scratch_model_).subspan(first, count),
                   parent < 0 ? mat4(1.0f) : scratch_model_[static_cast<std::size_t>(parent)]);
  }

  // [first, end) of the joints below and including the hand's first joint when they are contiguous
  // and hold all its joints; {0, 0} otherwise (then the whole body is recomputed).
  std::array<std::size_t, 2> arm_subtree(const Skeleton& s) const {
    const std::vector<int>& joints = cache_.joints(hand_);
    const std::size_t n = s.size(), first = joint_slot(*std::min_element(joints.begin(), joints.end()));
    std::vector<char> below(n, 0);
    below[first] = 1;
    std::size_t end = first + 1;
    while (end < n && s.parents[end] >= 0 && below[static_cast<std::size_t>(s.parents[end])]) below[end++] = 1;
    for (std::size_t i = end; i < n; ++i)
      if (s.parents[i] >= 0 && below[static_cast<std::size_t>(s.parents[i])]) return {0, 0};
    for (int j : joints)
      if (!below[joint_slot(j)]) return {0, 0};
    return {first, end};
  }

  Hand hand_;
  const HandTimeline& timeline_;
  std::vector<const CachedSignSpan*> spans_;
  SignMotionCache& cache_;
  std::size_t n_;
  float fps_;
  // Scratch for the body checks (the rest of the body stays in the signing rig's neutral pose).
  mutable Pose scratch_pose_ = cache_.rig().neutral;
  mutable std::vector<mat4> scratch_model_ = std::vector<mat4>(cache_.rig().skeleton().size());
  mutable HandPoints scratch_points_;
  mutable std::vector<quat> scratch_posture_ = std::vector<quat>(n_);
  mutable bool model_ready_ = false;
  mutable std::array<std::size_t, 2> subtree_{};
  mutable std::vector<std::int16_t> subtree_parents_;
};

}  // namespace

Clip perform_utterance(const SignPlan& plan, std::span<const CachedSignSpan> signs, SignMotionCache& cache,
                       float fps, UtteranceStats* stats) {
  if (!(fps >= 1.0f && fps <= 240.0f)) throw Error("fps must be between 1 and 240");
  const SigningRig& rig = cache.rig();
  const Skeleton& s = rig.skeleton();
  const std::size_t frames = std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(plan.duration() * fps)) + 1);
  UtteranceStats st;
  st.frames = static_cast<int>(frames);

  Clip clip;
  clip.name = "sign";
  clip.duration = static_cast<float>(frames - 1) / fps;
  clip.resize_joints(s.size());
  for (Hand hand : kBothHands) {
    const HandTimeline& timeline = plan.hand(hand);
    const std::vector<int>& joints = cache.joints(hand);
    std::vector<QuatTrack*> tracks;
    for (int j : joints) {
      QuatTrack& tr = clip.rotations[joint_slot(j)];
      tr.interpolation = Interpolation::Linear;
      tr.times.resize(frames);
      tr.values.resize(frames);
      tracks.push_back(&tr);
    }
    const HandJointPosture& rest = cache.posture(hand, rest_hand_state(rig, hand));
    std::vector<quat> posture(rest.begin(), rest.end());
    if (timeline.segments.empty()) {
      // A hand the utterance never uses rests throughout.
      for (std::size_t f = 0; f < frames; ++f)
        for (std::size_t j = 0; j < joints.size(); ++j) {
          tracks[j]->times[f] = static_cast<float>(f) / fps;
          tracks[j]->values[f] = posture[j];
        }
      continue;
    }
    std::vector<const CachedSignSpan*> spans;
    for (const CachedSignSpan& sign : signs)
      if (sign.hand == hand) spans.push_back(&sign);
    HandPerformer performer(hand, timeline, std::move(spans), cache, fps);
    const HandMotion motion = performer.build(st);
    std::size_t cursor = 0;
    for (std::size_t f = 0; f < frames; ++f) {
      const float t = static_cast<float>(f) / fps;
      performer.evaluate(motion, t, cursor, posture);
      // Stored unit length and continuous (make_continuous, in the same pass).
      for (std::size_t j = 0; j < joints.size(); ++j) {
        quat q = glm::normalize(posture[j]);
        if (f > 0 && glm::dot(q, tracks[j]->values[f - 1]) < 0) q = -q;
        tracks[j]->times[f] = t;
        tracks[j]->values[f] = q;
      }
    }
  }
  if (stats) *stats = st;
  return clip;
}

}  // namespace gestura
