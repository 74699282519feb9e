#include "gestura/anim/retarget.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/skeleton/joint_names.hpp"

namespace gestura {
namespace {

// Model-space rotations by chaining local rotations (scales are ignored: bone directions only).
void model_rotations(const Skeleton& s, std::span<const quat> local, std::vector<quat>& out) {
  out.resize(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    const int p = s.parents[j];
    out[j] = p < 0 ? local[j] : out[static_cast<std::size_t>(p)] * local[j];
  }
}

std::vector<vec3> positions_of(const Skeleton& s, const Pose& pose) {
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  std::vector<vec3> out(s.size());
  model_positions(model, out);
  return out;
}

bool is_descendant(const Skeleton& s, int joint, int ancestor) {
  for (int j = joint; j >= 0; j = s.parents[static_cast<std::size_t>(j)])
    if (j == ancestor) return true;
  return false;
}

// The nearest ancestor of each joint that is paired, or -1.
std::vector<int> paired_ancestors(const Skeleton& target, const std::vector<int>& map) {
  std::vector<int> out(target.size(), -1);
  for (std::size_t j = 0; j < target.size(); ++j) {
    const int p = target.parents[j];
    if (p >= 0) out[j] = map[static_cast<std::size_t>(p)] >= 0 ? p : out[static_cast<std::size_t>(p)];
  }
  return out;
}

struct Chain {
  int upper = -1, middle = -1, end = -1;  // target joints, all paired
  bool leg = false;                       // hip-knee-ankle (else shoulder-elbow-wrist)
};

std::vector<Chain> limb_chains(const Skeleton& target, const std::vector<int>& map) {
  const std::vector<std::string> names = guess_hanim_names(target);
  auto find = [&](const std::string& n) {
    const auto it = std::find(names.begin(), names.end(), n);
    const int j = it == names.end() ? -1 : static_cast<int>(it - names.begin());
    return j >= 0 && map[static_cast<std::size_t>(j)] >= 0 ? j : -1;
  };
  std::vector<Chain> chains;
  for (const char* side : {"l_", "r_"}) {
    const std::string p = side;
    static constexpr const char* kLimbs[2][3] = {{"shoulder", "elbow", "wrist"}, {"hip", "knee", "ankle"}};
    for (const auto& limb : kLimbs) {
      const Chain c{find(p + limb[0]), find(p + limb[1]), find(p + limb[2]), &limb == &kLimbs[1]};
      if (c.upper >= 0 && c.middle >= 0 && c.end >= 0 && is_descendant(target, c.end, c.middle) &&
          is_descendant(target, c.middle, c.upper))
        chains.push_back(c);
    }
  }
  return chains;
}

// Moves the end of a two-bone chain to `goal`: bends the middle joint to the distance needed, then
// swings the upper joint so the end lies on the line to the goal. World rotations in `world` are
// updated for the three joints only; the caller turns them back into local rotations.
void two_bone_fixup(const vec3& a, const vec3& b, const vec3& c, const vec3& goal, quat& upper, quat& middle) {
  const float lab = glm::length(b - a), lbc = glm::length(c - b);
  if (lab < 1e-6f || lbc < 1e-6f) return;
  const float reach = std::clamp(glm::length(goal - a), std::abs(lab - lbc) + 1e-5f, lab + lbc - 1e-5f);
  const vec3 ba = glm::normalize(a - b), bc = glm::normalize(c - b);
  const float bend_now = std::acos(std::clamp(glm::dot(ba, bc), -1.0f, 1.0f));
  const float bend_goal = std::acos(std::clamp((lab * lab + lbc * lbc - reach * reach) / (2.0f * lab * lbc), -1.0f, 1.0f));
  vec3 axis = glm::cross(ba, bc);
  if (glm::length(axis) < 1e-6f) {  // straight limb: bend about any axis across it
    axis = glm::cross(ba, std::abs(ba.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0));
  }
  const quat bend = glm::angleAxis(bend_goal - bend_now, glm::normalize(axis));
  const vec3 c_bent = b + bend * (c - b);
  const vec3 from = c_bent - a, to = goal - a;
  if (glm::length(from) < 1e-6f || glm::length(to) < 1e-6f) return;
  const quat swing = glm::rotation(glm::normalize(from), glm::normalize(to));
  upper = swing * upper;
  middle = swing * bend * middle;
}

float chain_length(const std::vector<vec3>& rest, std::initializer_list<int> joints) {
  float length = 0.0f;
  int prev = -1;
  for (int j : joints) {
    if (prev >= 0) length += glm::length(rest[static_cast<std::size_t>(j)] - rest[static_cast<std::size_t>(prev)]);
    prev = j;
  }
  return length;
}

int top_paired(const std::vector<int>& map) {
  for (std::size_t j = 0; j < map.size(); ++j)
    if (map[j] >= 0) return static_cast<int>(j);
  return -1;
}

}  // namespace

float retarget_scale(const Skeleton& source, const Skeleton& target, const std::vector<int>& map) {
  const std::vector<vec3> src_rest = positions_of(source, rest_pose(source));
  const std::vector<vec3> tgt_rest = positions_of(target, rest_pose(target));
  for (const Chain& c : limb_chains(target, map)) {
    if (!c.leg) continue;
    const auto s = [&](int t) { return map[static_cast<std::size_t>(t)]; };
    const float src = chain_length(src_rest, {s(c.upper), s(c.middle), s(c.end)});
    const float tgt = chain_length(tgt_rest, {c.upper, c.middle, c.end});
    if (src > 1e-6f && tgt > 1e-6f) return tgt / src;
  }
  const int root = top_paired(map);
  if (root < 0) return 1.0f;
  auto height = [](const std::vector<vec3>& rest, int j) {
    float lowest = rest[static_cast<std::size_t>(j)].y;
    for (const vec3& p : rest) lowest = std::min(lowest, p.y);
    return rest[static_cast<std::size_t>(j)].y - lowest;
  };
  const float src = height(src_rest, map[static_cast<std::size_t>(root)]), tgt = height(tgt_rest, root);
  return src > 1e-6f && tgt > 1e-6f ? tgt / src : 1.0f;
}

Clip retarget(const Skeleton& source, const Clip& clip, const Skeleton& target, const RetargetOptions& options) {
  if (!(options.frame_time > 0.0f) || !std::isfinite(options.frame_time))
    throw Error("retarget: frame_time must be a positive number");
  if (clip.joint_count() != source.size())
    throw Error("retarget: the clip has " + std::to_string(clip.joint_count()) + " joint tracks, the source skeleton " +
                std::to_string(source.size()) + " joints");
  const std::vector<int> map = options.mapping.empty() ? match_joints(source, target) : options.mapping;
  if (map.size() != target.size())
    throw Error("retarget: the mapping has " + std::to_string(map.size()) + " entries for " +
                std::to_string(target.size()) + " target joints");
  for (std::size_t j = 0; j < map.size(); ++j)
    if (map[j] < -1 || map[j] >= static_cast<int>(source.size()))
      throw Error("retarget: mapping of target joint '" + target.names[j] + "' points outside the source");
  const int root = top_paired(map);
  if (root < 0) throw Error("retarget: no joint of the target skeleton matches one of the source");
  const auto src_of = [&](int t) { return static_cast<std::size_t>(map[static_cast<std::size_t>(t)]); };

  const Pose src_rest = rest_pose(source), tgt_rest = rest_pose(target);
  std::vector<quat> src_rest_world, tgt_rest_world;
  model_rotations(source, src_rest.rotations, src_rest_world);
  model_rotations(target, tgt_rest.rotations, tgt_rest_world);
  const std::vector<vec3> src_rest_pos = positions_of(source, src_rest);
  const std::vector<vec3> tgt_rest_pos = positions_of(target, tgt_rest);

  // Rest alignment per paired target joint (step 2 of the header).
  const std::vector<int> ancestor = paired_ancestors(target, map);
  std::vector<quat> align(target.size(), quat(1, 0, 0, 0));
  // Per paired joint, the source joints at the far end of its bone (its next paired descendants).
  std::vector<std::vector<std::size_t>> bone_ends(target.size());
  std::vector<vec3> src_rest_dir(target.size(), vec3(0.0f));
  {
    std::vector<vec3> tgt_sum(target.size(), vec3(0.0f));
    for (std::size_t d = 0; d < target.size(); ++d) {
      const int t = ancestor[d];
      if (map[d] < 0 || t < 0 || !is_descendant(source, map[d], map[static_cast<std::size_t>(t)])) continue;
      tgt_sum[static_cast<std::size_t>(t)] += tgt_rest_pos[d];
      bone_ends[static_cast<std::size_t>(t)].push_back(src_of(static_cast<int>(d)));
    }
    for (std::size_t t = 0; t < target.size(); ++t) {
      if (map[t] < 0) continue;
      if (ancestor[t] >= 0) align[t] = align[static_cast<std::size_t>(ancestor[t])];
      const std::size_t n = bone_ends[t].size();
      if (n == 0) continue;
      vec3 src_end(0.0f);
      for (std::size_t e : bone_ends[t]) src_end += src_rest_pos[e];
      const vec3 td = tgt_sum[t] / float(n) - tgt_rest_pos[t];
      const vec3 sd = src_end / float(n) - src_rest_pos[src_of(static_cast<int>(t))];
      if (glm::length(td) < 1e-6f || glm::length(sd) < 1e-6f) {
        bone_ends[t].clear();
        continue;
      }
      src_rest_dir[t] = glm::normalize(sd);
      if (ancestor[t] >= 0) align[t] = glm::rotation(glm::normalize(td), src_rest_dir[t]);
    }
  }

  const float scale = retarget_scale(source, target, map);
  const std::vector<Chain> chains = options.preserve_end_effectors ? limb_chains(target, map) : std::vector<Chain>{};
  const float duration = std::max(clip.duration, 0.0f);
  const int frames = static_cast<int>(std::floor(duration / options.frame_time + 0.5f)) + 1;
  if (frames > 10'000'000) throw Error("retarget: more than 10,000,000 frames at this frame time");

  Clip out;
  out.name = clip.name;
  out.duration = float(frames - 1) * options.frame_time;
  out.resize_joints(target.size());
  out.channel_names = clip.channel_names;
  out.channels = clip.channels;

  Pose src_pose, tgt_pose = tgt_rest;
  std::vector<quat> src_world, tgt_world, goal_world;
  for (int f = 0; f < frames; ++f) {
    const float time = std::min(float(f) * options.frame_time, duration);
    sample_clip(clip, time, WrapMode::Clamp, src_rest, src_pose);
    model_rotations(source, src_pose.rotations, src_world);
    const std::vector<vec3> src_pos = positions_of(source, src_pose);

    // Step 3: model-space rotations, then back to local.
    tgt_world.resize(target.size());
    for (std::size_t j = 0; j < target.size(); ++j) {
      const int p = target.parents[j];
      const quat parent = p < 0 ? quat(1, 0, 0, 0) : tgt_world[static_cast<std::size_t>(p)];
      if (map[j] >= 0) {
        const std::size_t s = src_of(static_cast<int>(j));
        const quat delta = src_world[s] * glm::inverse(src_rest_world[s]);
        quat swing(1, 0, 0, 0);
        if (!bone_ends[j].empty() && ancestor[j] >= 0) {
          // Twist-free correction so the bone points where the source bone points now, even when
          // unpaired source joints inside the bone (twist bones) bend it.
          vec3 end(0.0f);
          for (std::size_t e : bone_ends[j]) end += src_pos[e];
          const vec3 now = end / float(bone_ends[j].size()) - src_pos[s];
          if (glm::length(now) > 1e-6f) swing = glm::rotation(delta * src_rest_dir[j], glm::normalize(now));
        }
        tgt_world[j] = glm::normalize(swing * delta * align[j] * tgt_rest_world[j]);
        tgt_pose.rotations[j] = glm::normalize(glm::inverse(parent) * tgt_world[j]);
      } else {
        tgt_pose.rotations[j] = tgt_rest.rotations[j];
        tgt_world[j] = parent * tgt_pose.rotations[j];
      }
    }
    // Step 4: root displacement, scaled. Ancestors of the top paired joint are at rest.
    const std::size_t r = static_cast<std::size_t>(root);
    const vec3 root_goal = tgt_rest_pos[r] + scale * (src_pos[src_of(root)] - src_rest_pos[src_of(root)]);
    {
      const int p = target.parents[r];
      vec3 local = root_goal;
      if (p >= 0) {
        std::vector<mat4> model(target.size());
        local_to_model(target, tgt_pose, model);
        local = vec3(glm::inverse(model[static_cast<std::size_t>(p)]) * vec4(root_goal, 1.0f));
      }
      tgt_pose.translations[r] = local;
    }
    // Step 5: end effectors relative to the root, scaled.
    for (const Chain& c : chains) {
      const std::vector<vec3> pos = positions_of(target, tgt_pose);
      const vec3 goal = pos[r] + scale * (src_pos[src_of(c.end)] - src_pos[src_of(root)]);
      const auto u = static_cast<std::size_t>(c.upper), m = static_cast<std::size_t>(c.middle),
                 e = static_cast<std::size_t>(c.end);
      goal_world = tgt_world;
      two_bone_fixup(pos[u], pos[m], pos[e], goal, goal_world[u], goal_world[m]);
      // Re-express the three chosen model rotations as local ones, parents first.
      for (std::size_t j : {u, m, e}) {
        model_rotations(target, tgt_pose.rotations, tgt_world);
        const int p = target.parents[j];
        const quat parent = p < 0 ? quat(1, 0, 0, 0) : tgt_world[static_cast<std::size_t>(p)];
        tgt_pose.rotations[j] = glm::normalize(glm::inverse(parent) * goal_world[j]);
      }
      model_rotations(target, tgt_pose.rotations, tgt_world);
    }

    for (std::size_t j = 0; j < target.size(); ++j)
      if (map[j] >= 0)
        out.rotations[j].add(float(f) * options.frame_time, tgt_pose.rotations[j]);
    out.translations[r].add(float(f) * options.frame_time, tgt_pose.translations[r]);
  }
  for (QuatTrack& track : out.rotations) make_continuous(track);
  return out;
}

}  // namespace gestura
