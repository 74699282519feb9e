// ozz-animation's side: the subject converted once into ozz's skeleton, animations and SoA poses,
// then ozz's jobs as its documentation and samples use them.
#include <cstring>
#include <map>
#include <memory>

#include "harness.hpp"
#include "ozz/animation/offline/animation_builder.h"
#include "ozz/animation/offline/animation_optimizer.h"
#include "ozz/animation/offline/raw_animation.h"
#include "ozz/animation/offline/raw_skeleton.h"
#include "ozz/animation/offline/skeleton_builder.h"
#include "ozz/animation/runtime/animation.h"
#include "ozz/animation/runtime/blending_job.h"
#include "ozz/animation/runtime/ik_aim_job.h"
#include "ozz/animation/runtime/ik_two_bone_job.h"
#include "ozz/animation/runtime/local_to_model_job.h"
#include "ozz/animation/runtime/sampling_job.h"
#include "ozz/animation/runtime/skeleton.h"
#include "ozz/base/maths/simd_math.h"
#include "ozz/base/maths/simd_quaternion.h"
#include "ozz/base/maths/soa_transform.h"
#include "ozz/geometry/runtime/skinning_job.h"

namespace anchors {

namespace {

namespace oa = ozz::animation;
namespace om = ozz::math;
using SoaPose = std::vector<om::SoaTransform>;

struct OzzSubject {
  ozz::unique_ptr<oa::Skeleton> skeleton;
  std::vector<int> index;  // gestura joint → ozz joint (ozz orders joints its own way)
  ozz::unique_ptr<oa::Animation> raw_animation;            // every key (W1, W2)
  std::map<float, ozz::unique_ptr<oa::Animation>> optimised;  // per bound (W8)
  SoaPose a, b, c, additive;
  std::vector<om::SimdFloat4> upper, lower;
};

// A SoaTransform is 40 floats: tx ty tz, rx ry rz rw, sx sy sz, four joints each.
SoaPose to_soa(const Pose& pose, const std::vector<int>& index) {
  SoaPose out((pose.size() + 3) / 4, om::SoaTransform::identity());
  for (std::size_t j = 0; j < pose.size(); ++j) {
    const int o = index[j];
    float f[40];
    std::memcpy(f, &out[static_cast<std::size_t>(o / 4)], sizeof f);
    const int lane = o % 4;
    const float values[10] = {pose.translations[j].x, pose.translations[j].y, pose.translations[j].z,
                              pose.rotations[j].x,    pose.rotations[j].y,    pose.rotations[j].z,
                              pose.rotations[j].w,    pose.scales[j].x,       pose.scales[j].y,
                              pose.scales[j].z};
    for (int c = 0; c < 10; ++c) f[c * 4 + lane] = values[c];
    std::memcpy(&out[static_cast<std::size_t>(o / 4)], f, sizeof f);
  }
  return out;
}

Pose from_soa(const SoaPose& soa, const std::vector<int>& index) {
  Pose out;
  out.resize(index.size());
  for (std::size_t j = 0; j < index.size(); ++j) {
    const int o = index[j];
    float f[40];
    std::memcpy(f, &soa[static_cast<std::size_t>(o / 4)], sizeof f);
    const int lane = o % 4;
    auto at = [&](int c) { return f[c * 4 + lane]; };
    out.translations[j] = vec3(at(0), at(1), at(2));
    out.rotations[j] = quat(at(6), at(3), at(4), at(5));
    out.scales[j] = vec3(at(7), at(8), at(9));
  }
  return out;
}

std::vector<om::SimdFloat4> to_soa_weights(const std::vector<float>& w, const std::vector<int>& index) {
  std::vector<float> flat(((w.size() + 3) / 4) * 4, 0.0f);
  for (std::size_t j = 0; j < w.size(); ++j) flat[static_cast<std::size_t>(index[j])] = w[j];
  std::vector<om::SimdFloat4> out(flat.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = om::simd_float4::LoadPtrU(&flat[i * 4]);
  return out;
}

oa::offline::RawSkeleton::Joint make_joint(const Skeleton& s, std::size_t j,
                                           const std::vector<std::vector<std::size_t>>& children) {
  oa::offline::RawSkeleton::Joint joint;
  joint.name = s.names[j].c_str();
  const vec3 t = s.rest_translations[j], sc = s.rest_scales[j];
  const quat r = s.rest_rotations[j];
  joint.transform.translation = om::Float3(t.x, t.y, t.z);
  joint.transform.rotation = om::Quaternion(r.x, r.y, r.z, r.w);
  joint.transform.scale = om::Float3(sc.x, sc.y, sc.z);
  for (std::size_t c : children[j]) joint.children.push_back(make_joint(s, c, children));
  return joint;
}

const OzzSubject& ozz_subject() {
  static const std::unique_ptr<OzzSubject> o = [] {
    const Subject& s = subject();
    auto out = std::make_unique<OzzSubject>();
    const std::size_t n = s.skeleton.size();
    std::vector<std::vector<std::size_t>> children(n);
    oa::offline::RawSkeleton raw_skeleton;
    for (std::size_t j = 0; j < n; ++j)
      if (s.skeleton.parents[j] >= 0) children[static_cast<std::size_t>(s.skeleton.parents[j])].push_back(j);
    for (std::size_t j = 0; j < n; ++j)
      if (s.skeleton.parents[j] < 0) raw_skeleton.roots.push_back(make_joint(s.skeleton, j, children));
    out->skeleton = oa::offline::SkeletonBuilder()(raw_skeleton);
    out->index.resize(n);
    const auto names = out->skeleton->joint_names();
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t o = 0; o < names.size(); ++o)
        if (s.skeleton.names[j] == names[o]) out->index[j] = static_cast<int>(o);

    // The clip as ozz keys: one per frame on every track (a still joint gets its rest value once).
    oa::offline::RawAnimation raw;
    raw.duration = s.clip.duration;
    raw.tracks.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      auto& track = raw.tracks[static_cast<std::size_t>(out->index[j])];
      const bool rotates = !s.clip.rotations[j].times.empty(), moves = !s.clip.translations[j].times.empty();
      for (std::size_t f = 0; f < s.frames.size(); ++f) {
        const float t = std::min(static_cast<float>(f) / s.rate, raw.duration);
        if (f == 0 || rotates) {
          const quat q = s.frames[f].rotations[j];
          track.rotations.push_back({t, om::Quaternion(q.x, q.y, q.z, q.w)});
        }
        if (f == 0 || moves) {
          const vec3 v = s.frames[f].translations[j];
          track.translations.push_back({t, om::Float3(v.x, v.y, v.z)});
        }
      }
      const vec3 sc = s.frames[0].scales[j];
      track.scales.push_back({0.0f, om::Float3(sc.x, sc.y, sc.z)});
    }
    out->raw_animation = oa::offline::AnimationBuilder()(raw);
    for (const float bound : {kFineBound, kCoarseBound}) {
      oa::offline::AnimationOptimizer optimizer;
      optimizer.setting = oa::offline::AnimationOptimizer::Setting(bound, kVirtualPointDistance);
      oa::offline::RawAnimation optimised;
      optimizer(raw, *out->skeleton, &optimised);
      out->optimised[bound] = oa::offline::AnimationBuilder()(optimised);
    }

    out->a = to_soa(s.blend_a, out->index);
    out->b = to_soa(s.blend_b, out->index);
    out->c = to_soa(s.blend_c, out->index);
    out->additive = to_soa(s.additive, out->index);
    std::vector<float> lower(n);
    for (std::size_t j = 0; j < n; ++j) lower[j] = 1.0f - s.upper_body[j];
    out->upper = to_soa_weights(s.upper_body, out->index);
    out->lower = to_soa_weights(lower, out->index);

    // What the optimiser kept, measured with the ACL metric on gestura's side.
    for (const auto& [bound, animation] : out->optimised) {
      oa::SamplingJob::Context context(animation->num_tracks());
      SoaPose soa(static_cast<std::size_t>(out->skeleton->num_soa_joints()));
      std::vector<Pose> decoded;
      for (std::size_t f = 0; f < s.frames.size(); ++f) {
        oa::SamplingJob job;
        job.animation = animation.get();
        job.context = &context;
        job.ratio = std::min(1.0f, static_cast<float>(f) / s.rate / animation->duration());
        job.output = ozz::make_span(soa);
        job.Run();
        decoded.push_back(from_soa(soa, out->index));
        for (std::size_t j = 0; j < n; ++j) decoded.back().scales[j] = s.frames[f].scales[j];
      }
      const float error = max_virtual_point_error(s.skeleton, s.frames, decoded, kVirtualPointDistance);
      char line[256];
      std::snprintf(line, sizeof line, "ozz optimiser at tolerance %.2f cm, distance %.0f cm: %zu bytes, max error %.4f cm",
                    bound * 100.0, kVirtualPointDistance * 100.0, animation->size(), error * 100.0);
      note(line);
    }
    return out;
  }();
  return *o;
}

Side sampling(const oa::Animation* (*pick)(), bool forward, float step) {
  struct State {
    std::unique_ptr<oa::SamplingJob::Context> context;
    SoaPose out;
    float t = 0.0f;
    std::size_t k = 0;
  };
  auto state = std::make_shared<State>();
  return {"ozz", [pick, forward, step, state](std::size_t n) {
            const OzzSubject& o = ozz_subject();
            const oa::Animation* animation = pick();
            if (!state->context) {
              state->context = std::make_unique<oa::SamplingJob::Context>(animation->num_tracks());
              state->out.resize(static_cast<std::size_t>(o.skeleton->num_soa_joints()));
            }
            const std::vector<float>& times = random_times();
            oa::SamplingJob job;
            job.animation = animation;
            job.context = state->context.get();
            job.output = ozz::make_span(state->out);
            for (std::size_t i = 0; i < n; ++i) {
              if (forward) {
                state->t += step;
                if (state->t > animation->duration()) state->t = 0.0f;
                job.ratio = state->t / animation->duration();
              } else {
                job.ratio = times[state->k++ & 4095] / animation->duration();
              }
              job.Run();
              keep(state->out.data());
            }
          }};
}

const oa::Animation* raw_animation() { return ozz_subject().raw_animation.get(); }
const oa::Animation* fine_animation() { return ozz_subject().optimised.at(kFineBound).get(); }
const oa::Animation* coarse_animation() { return ozz_subject().optimised.at(kCoarseBound).get(); }

void local_to_model(std::size_t n) {
  const OzzSubject& o = ozz_subject();
  static std::vector<om::Float4x4> model(static_cast<std::size_t>(o.skeleton->num_joints()));
  oa::LocalToModelJob job;
  job.skeleton = o.skeleton.get();
  job.input = ozz::make_span(o.a);
  job.output = ozz::make_span(model);
  for (std::size_t i = 0; i < n; ++i) {
    job.Run();
    keep(model.data());
  }
}

void blend_three(std::size_t n) {
  const OzzSubject& o = ozz_subject();
  static SoaPose out(o.a.size());
  oa::BlendingJob::Layer layers[3];
  layers[0].transform = ozz::make_span(o.a), layers[0].weight = 0.5f;
  layers[1].transform = ozz::make_span(o.b), layers[1].weight = 0.3f;
  layers[2].transform = ozz::make_span(o.c), layers[2].weight = 0.2f;
  oa::BlendingJob job;
  job.layers = layers;
  job.rest_pose = o.skeleton->joint_rest_poses();
  job.output = ozz::make_span(out);
  for (std::size_t i = 0; i < n; ++i) {
    job.Run();
    keep(out.data());
  }
}

// Two layers masked to complementary halves (legs from one, upper body from the other) plus one
// additive layer: the job gestura does with priorities and apply_additive.
void blend_masked_additive(std::size_t n) {
  const OzzSubject& o = ozz_subject();
  static SoaPose out(o.a.size());
  oa::BlendingJob::Layer layers[2], additive[1];
  layers[0].transform = ozz::make_span(o.a), layers[0].weight = 1.0f, layers[0].joint_weights = ozz::make_span(o.lower);
  layers[1].transform = ozz::make_span(o.b), layers[1].weight = 1.0f, layers[1].joint_weights = ozz::make_span(o.upper);
  additive[0].transform = ozz::make_span(o.additive), additive[0].weight = 0.7f;
  oa::BlendingJob job;
  job.layers = layers;
  job.additive_layers = additive;
  job.rest_pose = o.skeleton->joint_rest_poses();
  job.output = ozz::make_span(out);
  for (std::size_t i = 0; i < n; ++i) {
    job.Run();
    keep(out.data());
  }
}

om::Float4x4 matrix(const vec3& t, const quat& r) {
  return om::Float4x4::FromAffine(om::simd_float4::Load(t.x, t.y, t.z, 1.0f), om::simd_float4::Load(r.x, r.y, r.z, r.w),
                                  om::simd_float4::one());
}

void two_bone(std::size_t n) {
  static const TwoBoneCase c;
  const quat id(1, 0, 0, 0);
  static const om::Float4x4 start = matrix(c.start, id), mid = matrix(c.mid, id), end = matrix(c.end, id);
  om::SimdQuaternion start_correction, mid_correction;
  bool reached = false;
  oa::IKTwoBoneJob job;
  job.start_joint = &start, job.mid_joint = &mid, job.end_joint = &end;
  job.mid_axis = om::simd_float4::Load(c.mid_axis.x, c.mid_axis.y, c.mid_axis.z, 0.0f);
  const vec3 pole = c.pole - c.start;  // ozz takes the pole as a model-space direction from the start
  job.pole_vector = om::simd_float4::Load(pole.x, pole.y, pole.z, 0.0f);
  job.soften = c.soften;
  job.start_joint_correction = &start_correction;
  job.mid_joint_correction = &mid_correction;
  job.reached = &reached;
  static std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const vec3 t = c.targets[k++ & 3];
    job.target = om::simd_float4::Load(t.x, t.y, t.z, 1.0f);
    keep(job.target);
    job.Run();
    keep(start_correction);
    keep(mid_correction);
  }
}

void aim(std::size_t n) {
  static const AimCase c;
  static const om::Float4x4 joint = matrix(c.position, c.parent_rotation * c.rotation);
  om::SimdQuaternion correction;
  oa::IKAimJob job;
  job.joint = &joint;
  job.forward = om::simd_float4::z_axis();
  job.up = om::simd_float4::y_axis();
  job.pole_vector = om::simd_float4::y_axis();
  job.joint_correction = &correction;
  static std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const vec3 t = c.targets[k++ & 3];
    job.target = om::simd_float4::Load(t.x, t.y, t.z, 1.0f);
    keep(job.target);
    job.Run();
    keep(correction);
  }
}

Side skin(bool normals) {
  return {"ozz", [normals](std::size_t n) {
            const Subject& s = subject();
            static const std::vector<om::Float4x4> matrices = [&] {
              std::vector<om::Float4x4> m(s.skinning.size());
              for (std::size_t j = 0; j < m.size(); ++j)
                for (int c = 0; c < 4; ++c) m[j].cols[c] = om::simd_float4::LoadPtrU(&s.skinning[j][c][0]);
              return m;
            }();
            const std::size_t count = s.mesh.vertex_count();
            static std::vector<vec3> positions(count), out_normals(count);
            ozz::geometry::SkinningJob job;
            job.vertex_count = static_cast<int>(count);
            job.influences_count = 4;
            job.joint_matrices = ozz::make_span(matrices);
            job.joint_indices = {&s.mesh.joints[0].x, count * 4};
            job.joint_indices_stride = sizeof(JointIndices);
            job.joint_weights = {&s.mesh.weights[0].x, count * 4};
            job.joint_weights_stride = sizeof(vec4);
            job.in_positions = {&s.mesh.positions[0].x, count * 3};
            job.in_positions_stride = sizeof(vec3);
            job.out_positions = {&positions[0].x, count * 3};
            job.out_positions_stride = sizeof(vec3);
            if (normals) {
              job.in_normals = {&s.mesh.normals[0].x, count * 3};
              job.in_normals_stride = sizeof(vec3);
              job.out_normals = {&out_normals[0].x, count * 3};
              job.out_normals_stride = sizeof(vec3);
            }
            for (std::size_t i = 0; i < n; ++i) {
              job.Run();
              keep(positions.data());
              keep(out_normals.data());
            }
          }};
}

}  // namespace

void add_ozz_workloads(std::vector<Workload>& out) {
  auto add = [&](const std::string& key, const std::string& what, Side anchor) {
    out.push_back({key, what, gestura_side(key), std::move(anchor)});
  };
  add("W1_SampleForward30Hz", "sample 67 joints playing forward at 30 Hz (every key kept)",
      sampling(raw_animation, true, 1.0f / 30.0f));
  add("W1_LocalToModel", "local → model matrices, 67 joints", {"ozz", local_to_model});
  add("W2_RandomSeek", "sample at random times (every key kept)", sampling(raw_animation, false, 0.0f));
  add("W3_Blend3Layers", "blend three full poses, weights 0.5 / 0.3 / 0.2", {"ozz", blend_three});
  add("W3_Blend2MaskedPlusAdditive", "two masked layers (legs / upper body) + one additive at 0.7",
      {"ozz", blend_masked_additive});
  add("W4_TwoBone", "two-bone IK, soften 0.97, pole", {"ozz", two_bone});
  add("W4_Aim", "aim a joint at a target", {"ozz", aim});
  if (subject().has_mesh) {
    add("W5_LbsPositions/avx2", "LBS positions, MakeHuman mesh (ozz: SSE2)", skin(false));
    add("W5_LbsPositions/portable", "LBS positions, MakeHuman mesh, gestura's portable path", skin(false));
    add("W5_LbsPositionsNormals/avx2", "LBS positions + normals (gestura renormalises, ozz does not)", skin(true));
    add("W5_LbsPositionsNormals/portable", "the same on gestura's portable path", skin(true));
  }
  add("W8_DecompressForward/0.01cm", "decompress the pose playing forward at 60 fps (ozz optimised at 0.01 cm)",
      sampling(fine_animation, true, kForwardStep));
  add("W8_DecompressForward/0.3cm", "the same at 0.3 cm", sampling(coarse_animation, true, kForwardStep));
  add("W8_DecompressRandom/0.01cm", "decompress the pose at random times", sampling(fine_animation, false, 0.0f));
}

}  // namespace anchors
