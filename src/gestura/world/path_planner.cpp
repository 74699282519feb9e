#include "gestura/world/path_planner.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "gestura/world/clearance.hpp"

namespace gestura {
namespace {

constexpr float kArcStep = deg(8.0f);     // circumscribed arc: ≤ 0.2 % longer than the true arc
constexpr float kRadiusSlack = 0.002f;    // arcs at radius + 2 mm, so rounding never grazes the radius
constexpr float kCheckTolerance = 0.001f;

vec2 xz(const vec3& v) { return {v.x, v.z}; }
vec2 perp(const vec2& v) { return {-v.y, v.x}; }
vec2 rotate(const vec2& v, float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// One element of the taut string: a point (start, goal) or an obstacle corner it wraps.
struct Wrap {
  vec2 centre{0.0f};
  float side = 0.0f;   // +1 counter-clockwise (turning left in x–z), −1 clockwise, 0 = a point
  float y = 0.0f;      // ground height near it
};

// The tangent from element a to element b: the points where the straight piece leaves a and meets b.
std::optional<std::pair<vec2, vec2>> tangent(const Wrap& a, const Wrap& b, float r) {
  const vec2 w = b.centre - a.centre;
  const float d = glm::length(w);
  if (d < 1e-6f) return std::nullopt;
  const vec2 u0 = w / d;
  float theta = 0.0f;
  if (a.side == 0.0f && b.side == 0.0f) return std::make_pair(a.centre, b.centre);
  if (a.side == 0.0f) {
    if (d <= r) return std::nullopt;
    theta = -std::asin(b.side * r / d);
  } else if (b.side == 0.0f) {
    if (d <= r) return std::nullopt;
    theta = std::asin(a.side * r / d);
  } else if (a.side == b.side) {
    theta = 0.0f;
  } else {
    if (d <= 2.0f * r) return std::nullopt;
    theta = std::asin(2.0f * a.side * r / d);
  }
  const vec2 u = rotate(u0, theta);
  const vec2 ta = a.side == 0.0f ? a.centre : a.centre - a.side * r * perp(u);
  const vec2 tb = b.side == 0.0f ? b.centre : b.centre - b.side * r * perp(u);
  return std::make_pair(ta, tb);
}

// The polyline of a wrap sequence, or none when a wrap cannot be joined (element inside a circle,
// circles too close for the turn asked). Wraps the string does not bend around are dropped.
// `owner[k]` tells which wrap produced output point k.
std::optional<std::vector<vec2>> taut(std::vector<Wrap>& wraps, float r, std::vector<float>& heights,
                                      std::vector<std::size_t>& owner) {
  for (int pass = 0; pass < 64; ++pass) {
    std::vector<std::pair<vec2, vec2>> t;
    for (std::size_t i = 0; i + 1 < wraps.size(); ++i) {
      const auto seg = tangent(wraps[i], wraps[i + 1], r);
      if (!seg) return std::nullopt;
      t.push_back(*seg);
    }
    // A wrap whose arc would run backwards (more than half round) is not touched by the string.
    std::size_t drop = 0;
    float worst = 0.0f;
    std::vector<float> sweep(wraps.size(), 0.0f);
    for (std::size_t i = 1; i + 1 < wraps.size(); ++i) {
      const vec2 e = t[i - 1].second - wraps[i].centre, x = t[i].first - wraps[i].centre;
      float phi = wraps[i].side * (std::atan2(x.y, x.x) - std::atan2(e.y, e.x));
      while (phi < 0.0f) phi += 2.0f * kPi;
      while (phi >= 2.0f * kPi) phi -= 2.0f * kPi;
      sweep[i] = phi;
      if (phi > kPi && phi - kPi > worst) worst = phi - kPi, drop = i;
    }
    if (drop) {
      wraps.erase(wraps.begin() + static_cast<std::ptrdiff_t>(drop));
      continue;
    }
    std::vector<vec2> out{wraps.front().centre};
    heights.assign(1, wraps.front().y);
    owner.assign(1, 0);
    for (std::size_t i = 1; i + 1 < wraps.size(); ++i) {
      const vec2 e = t[i - 1].second - wraps[i].centre;
      const float phi = sweep[i];
      const int m = std::max(1, static_cast<int>(std::ceil(phi / kArcStep)));
      const float delta = phi / static_cast<float>(m);
      const float reach = r / std::cos(delta * 0.5f);
      const float start = std::atan2(e.y, e.x);
      for (int k = 1; k <= m; ++k) {
        const float a = start + wraps[i].side * (delta * 0.5f + static_cast<float>(k - 1) * delta);
        out.push_back(wraps[i].centre + reach * vec2(std::cos(a), std::sin(a)));
        heights.push_back(wraps[i].y);
        owner.push_back(i);
      }
    }
    out.push_back(wraps.back().centre);
    heights.push_back(wraps.back().y);
    owner.push_back(wraps.size() - 1);
    return out;
  }
  return std::nullopt;
}

std::vector<vec3> lift(const Environment& env, const std::vector<vec2>& points, const std::vector<float>& heights) {
  std::vector<vec3> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float hint = heights[std::min(i, heights.size() - 1)];
    const auto g = ground_below(env, vec3(points[i].x, hint + env.max_climb + 0.05f, points[i].y), env.max_climb * 2.0f + 0.1f);
    out.push_back(vec3(points[i].x, g ? g->height : hint, points[i].y));
  }
  return out;
}

std::string format_point(const vec3& p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", p.x, p.y, p.z);
  return text;
}

}  // namespace

float path_length(std::span<const vec3> points) {
  float length = 0.0f;
  for (std::size_t i = 1; i < points.size(); ++i) length += glm::length(xz(points[i]) - xz(points[i - 1]));
  return length;
}

float path_clearance(const Environment& env, std::span<const vec3> points, float body_height, float search) {
  float best = search;
  for (std::size_t i = 1; i < points.size(); ++i)
    best = std::min(best, segment_clearance(env, points[i - 1], points[i], body_height, search).distance);
  return best;
}

std::vector<vec3> tighten_path(const Environment& env, std::span<const vec3> corners, float radius, float body_height,
                               bool* tightened) {
  if (tightened) *tightened = false;
  std::vector<vec3> fallback(corners.begin(), corners.end());
  if (corners.size() < 2) return fallback;
  const float r = radius + kRadiusSlack;
  const float near = radius + 0.25f;  // a corner this close to an obstacle is wrapped around it

  std::vector<Wrap> wraps{{xz(corners.front()), 0.0f, corners.front().y}};
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    const vec2 din = xz(corners[i]) - xz(corners[i - 1]), dout = xz(corners[i + 1]) - xz(corners[i]);
    const float turn = cross2(din, dout);
    if (std::abs(turn) < 1e-8f) continue;
    const Clearance c = segment_clearance(env, corners[i], corners[i], body_height, near);
    if (c.object < 0) continue;  // nothing near: the corner is not needed
    wraps.push_back({c.obstacle, turn > 0.0f ? 1.0f : -1.0f, corners[i].y});
  }
  wraps.push_back({xz(corners.back()), 0.0f, corners.back().y});

  // Merge wraps about the same corner.
  for (std::size_t i = 1; i + 1 < wraps.size();) {
    if (i + 2 < wraps.size() && glm::length(wraps[i].centre - wraps[i + 1].centre) < 0.01f && wraps[i].side == wraps[i + 1].side)
      wraps.erase(wraps.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    else ++i;
  }

  for (int attempt = 0; attempt < 24; ++attempt) {
    std::vector<float> heights;
    std::vector<std::size_t> owner;
    std::vector<Wrap> current = wraps;
    const auto flat = taut(current, r, heights, owner);
    if (!flat) return fallback;
    const std::vector<vec3> path = lift(env, *flat, heights);
    // Check every segment; the first one too near an obstacle gets that obstacle wrapped too.
    bool ok = true;
    for (std::size_t i = 1; i < path.size() && ok; ++i) {
      const Clearance c = segment_clearance(env, path[i - 1], path[i], body_height, radius + 0.01f);
      if (c.distance >= radius - kCheckTolerance) continue;
      ok = false;
      const vec2 dir = xz(path[i]) - xz(path[i - 1]);
      const float side = cross2(dir, c.obstacle - c.on_path) > 0.0f ? 1.0f : -1.0f;
      // The new wrap goes right after the wrap the segment leaves.
      const std::size_t insert_at = std::min(owner[i - 1] + 1, current.size() - 1);
      const float y = 0.5f * (path[i - 1].y + path[i].y);
      current.insert(current.begin() + static_cast<std::ptrdiff_t>(insert_at), Wrap{c.obstacle, side, y});
    }
    if (ok) {
      if (tightened) *tightened = true;
      return path;
    }
    wraps = current;
  }
  return fallback;
}

PathPlanner::PathPlanner(const Environment& env, const NavMeshSettings& base) : env_(&env), base_(base) {}

const NavMesh& PathPlanner::navmesh(float radius, bool generous) {
  const auto key = std::make_pair(static_cast<int>(std::lround(radius * 1000.0f)), generous);
  auto it = meshes_.find(key);
  if (it == meshes_.end()) {
    NavMeshSettings s = base_;
    s.agent_radius = radius;
    s.margin_cells = generous ? -1.0f : base_.margin_cells;
    it = meshes_.emplace(key, NavMesh::build(*env_, s)).first;
  }
  return it->second;
}

PlannedPath PathPlanner::plan(const PathRequest& request) {
  PlannedPath out;
  if (!is_finite(request.start) || !is_finite(request.goal) || !(request.radius > 0.0f)) {
    out.reason = "no path: the start, goal or radius is not a finite number";
    return out;
  }
  const float body = base_.agent_height;
  const vec3 snap = request.approach ? request.approach_extent : vec3(request.radius + 0.25f, 0.6f, request.radius + 0.25f);
  auto finish = [&](std::vector<vec3> points, bool tightened) {
    out.points = std::move(points);
    out.tightened = tightened;
    out.status = PathStatus::Found;
    out.length = path_length(out.points);
    out.min_clearance = path_clearance(*env_, out.points, body, request.radius * 2.0f);
    out.reason.clear();
    return out;
  };

  // The generous mesh first: the shortest way, if its tightened path keeps the radius. Detour's
  // corridor gives a first path; the visibility graph of the floor's corners then looks for a
  // shorter way round the obstacles within that length (A* over polygons can pass an obstacle on
  // the longer side: its costs run between edge midpoints).
  const NavMesh& generous = navmesh(request.radius, true);
  if (!generous.empty()) {
    const NavPath raw = generous.find_path(request.start, request.goal, snap);
    if (raw.status == NavQueryStatus::Found || (request.approach && raw.status == NavQueryStatus::Disconnected && !raw.points.empty())) {
      bool tight = false;
      std::vector<vec3> points = tighten_path(*env_, raw.points, request.radius, body, &tight);
      float best = tight ? path_length(points) : path_length(raw.points) * 1.5f;
      if (const auto shorter = generous.visibility_path(raw.points.front(), raw.points.back(), best)) {
        bool tight2 = false;
        std::vector<vec3> other = tighten_path(*env_, *shorter, request.radius, body, &tight2);
        if (tight2 && path_length(other) < best) points = std::move(other), tight = true, best = path_length(points);
      }
      if (tight) return finish(std::move(points), true);
    }
  }
  // The strict mesh: its path keeps the radius even where tightening fails.
  const NavMesh& mesh = navmesh(request.radius, false);
  if (mesh.empty()) {
    out.reason = "no path: the scene has no floor a character of radius " + std::to_string(request.radius).substr(0, 4) +
                 " m can stand on";
    return out;
  }
  const NavPath raw = mesh.find_path(request.start, request.goal, snap);
  switch (raw.status) {
    case NavQueryStatus::StartOffMesh:
      out.reason = "no path: the start " + format_point(request.start) + " is not on the floor (inside an obstacle, off the floor, or too near a wall)";
      return out;
    case NavQueryStatus::GoalOffMesh:
      out.reason = "no path: the goal " + format_point(request.goal) + " is not on the floor (inside an obstacle, off the floor, or too near a wall)";
      return out;
    case NavQueryStatus::Disconnected:
      if (!request.approach || raw.points.empty()) {
        out.reason = "no path: the goal " + format_point(request.goal) + " cannot be reached from " + format_point(request.start) +
                     " (no way through for a radius of " + std::to_string(request.radius).substr(0, 4) + " m)";
        return out;
      }
      break;  // approach: the nearest reachable point will do
    case NavQueryStatus::Found: break;
  }
  bool tight = false;
  std::vector<vec3> points = tighten_path(*env_, raw.points, request.radius, body, &tight);
  return finish(std::move(points), tight);
}

}  // namespace gestura
