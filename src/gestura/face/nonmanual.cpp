#include "gestura/face/nonmanual.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/face/face_channels.hpp"

namespace gestura::face {
namespace {

constexpr float kDegree = 3.14159265358979f / 180.0f;
constexpr float kMinBlinkGap = 0.5f;  // seconds between two blinks at least
constexpr float kMaxPlanSeconds = 3600.0f;

void check(const NonManualPlan& plan) {
  for (std::size_t i = 0; i < plan.glosses.size(); ++i) {
    const TimedGloss& g = plan.glosses[i];
    if (!std::isfinite(g.start) || !std::isfinite(g.end) || g.end < g.start)
      throw Error("non-manual plan: gloss " + std::to_string(i) + " has non-finite or reversed times");
    if (std::abs(g.start) > kMaxPlanSeconds || std::abs(g.end) > kMaxPlanSeconds)
      throw Error("non-manual plan: gloss " + std::to_string(i) + " lies beyond an hour");
  }
  for (std::size_t i = 0; i < plan.spans.size(); ++i) {
    const NonManualSpan& s = plan.spans[i];
    if (s.first >= s.last || s.last > plan.glosses.size())
      throw Error("non-manual plan: span " + std::to_string(i) + " covers glosses [" + std::to_string(s.first) +
                  ", " + std::to_string(s.last) + ") of " + std::to_string(plan.glosses.size()));
    if (!std::isfinite(s.intensity))
      throw Error("non-manual plan: span " + std::to_string(i) + " has a non-finite intensity");
  }
  for (std::size_t i = 0; i < plan.boundaries.size(); ++i)
    if (!std::isfinite(plan.boundaries[i]))
      throw Error("non-manual plan: boundary " + std::to_string(i) + " is not finite");
}

// A small integer hash (the finaliser of MurmurHash3) turned into [0, 1).
float unit_random(std::uint32_t seed, std::uint32_t k) {
  std::uint32_t x = seed + k * 0x9E3779B9u;
  x ^= x >> 16;
  x *= 0x85EBCA6Bu;
  x ^= x >> 13;
  x *= 0xC2B2AE35u;
  x ^= x >> 16;
  return static_cast<float>(x >> 8) / static_cast<float>(1u << 24);
}

void add_both(std::vector<FaceAction>& out, std::string_view left, std::string_view right, float start,
              float end, float peak) {
  out.push_back(make_action(left, start, end, peak));
  out.push_back(make_action(right, start, end, peak));
}

void add_head(std::vector<HeadAction>& out, HeadAxis axis, float start, float end, float degrees,
              float frequency = 0.0f) {
  out.push_back(HeadAction{axis, start, end, degrees * kDegree, frequency});
}

}  // namespace

std::vector<float> blink_times(const NonManualPlan& plan) {
  check(plan);
  std::vector<float> boundary_blinks = plan.boundaries;
  std::sort(boundary_blinks.begin(), boundary_blinks.end());

  std::vector<float> blinks;
  auto keep = [&](float t) {
    if (blinks.empty() || t - blinks.back() >= kMinBlinkGap) blinks.push_back(t);
  };
  if (plan.glosses.empty()) {
    for (float b : boundary_blinks) keep(b);
    return blinks;
  }
  float t0 = plan.glosses.front().start, t1 = plan.glosses.front().end;
  for (const TimedGloss& g : plan.glosses) t0 = std::min(t0, g.start), t1 = std::max(t1, g.end);

  std::size_t next_boundary = 0;
  float previous = t0;
  for (std::uint32_t k = 0;; ++k) {
    const float candidate = previous + 2.0f + 3.0f * unit_random(plan.seed, k);
    if (next_boundary < boundary_blinks.size() &&
        boundary_blinks[next_boundary] < candidate + kMinBlinkGap) {
      previous = boundary_blinks[next_boundary++];
      keep(previous);
      continue;
    }
    if (candidate > t1) break;
    keep(candidate);
    previous = candidate;
  }
  for (; next_boundary < boundary_blinks.size(); ++next_boundary) keep(boundary_blinks[next_boundary]);
  return blinks;
}

NonManualActions plan_nonmanual(const NonManualPlan& plan) {
  check(plan);
  NonManualActions out;
  auto& face = out.face;
  auto& head = out.head;
  for (const NonManualSpan& span : plan.spans) {
    const float start = plan.glosses[span.first].start;
    float end = start;
    for (std::size_t i = span.first; i < span.last; ++i) end = std::max(end, plan.glosses[i].end);
    if (!(end > start)) continue;
    switch (span.kind) {
      case NonManualKind::yes_no_question:
        add_both(face, kBrowInnerUpL, kBrowInnerUpR, start, end, 0.8f);
        add_both(face, kBrowOuterUpL, kBrowOuterUpR, start, end, 0.8f);
        add_both(face, kEyeWideL, kEyeWideR, start, end, 0.3f);
        add_head(head, HeadAxis::pitch, start, end, kQuestionTiltDegrees);
        break;
      case NonManualKind::wh_question:
        add_both(face, kBrowDownL, kBrowDownR, start, end, 0.8f);
        add_both(face, kEyeSquintL, kEyeSquintR, start, end, 0.3f);
        add_head(head, HeadAxis::roll, start, end, 5.0f);
        add_head(head, HeadAxis::pitch, start, end, 3.0f);
        break;
      case NonManualKind::negation:
        add_both(face, kBrowDownL, kBrowDownR, start, end, 0.3f);
        add_head(head, HeadAxis::yaw, start, end, kHeadshakeDegrees, kHeadshakeHz);
        break;
      case NonManualKind::topic:
        add_both(face, kBrowInnerUpL, kBrowInnerUpR, start, end, 0.7f);
        add_both(face, kBrowOuterUpL, kBrowOuterUpR, start, end, 0.7f);
        add_head(head, HeadAxis::pitch, start, end, -3.0f);
        break;
      case NonManualKind::affect: {
        const float intensity = std::clamp(span.intensity, 0.0f, 1.0f);
        for (const auto& [channel, weight] : gestura::expression_weights(span.expression))
          face.push_back(make_action(channel, start, end, weight * intensity));
        break;
      }
    }
  }
  for (const TimedGloss& g : plan.glosses)
    if (g.kind == GlossKind::fingerspell && g.end > g.start) face.push_back(make_action(kGazeHands, g.start, g.end, 1.0f));
  for (float t : blink_times(plan)) {
    const float half = 0.5f * kBlinkSeconds;
    face.push_back(FaceAction{kEyeBlinkL, t - half, t + half, 1.0f, half, half});
    face.push_back(FaceAction{kEyeBlinkR, t - half, t + half, 1.0f, half, half});
  }
  return out;
}

void add_nonmanual_markers(const NonManualPlan& plan, const Skeleton& skeleton, Clip& clip) {
  const NonManualActions actions = plan_nonmanual(plan);
  write_face_channels(actions.face, clip);
  write_head_rotations(actions.head, skeleton, clip);
}

NonManualPlan apply_question_holds(const NonManualPlan& plan, float hold) {
  check(plan);
  if (!std::isfinite(hold) || hold < 0.0f) throw Error("question hold must be a non-negative number of seconds");
  NonManualPlan out = plan;
  std::vector<std::size_t> held;
  for (const NonManualSpan& s : plan.spans)
    if (s.kind == NonManualKind::yes_no_question) held.push_back(s.last - 1);
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  for (auto it = held.rbegin(); it != held.rend(); ++it) {
    const float after = plan.glosses[*it].end;  // original time: later shifts stack up
    out.glosses[*it].end += hold;
    for (std::size_t i = *it + 1; i < out.glosses.size(); ++i)
      out.glosses[i].start += hold, out.glosses[i].end += hold;
    for (std::size_t b = 0; b < out.boundaries.size(); ++b)
      if (plan.boundaries[b] >= after) out.boundaries[b] += hold;
  }
  return out;
}

}  // namespace gestura::face
