#include "gestura/io/avatar_source.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string_view>

#include "gestura/body/avatar_look.hpp"
#include "gestura/io/avatar_import.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/makehuman.hpp"

namespace gestura {
namespace {

constexpr std::string_view kMakeHumanPrefix = "makehuman:";

// Eyeball vertices looking forward (+Z) from the eyeball's centre become iris, then pupil; the
// helper eye is a plain sphere, so the cosine to +Z is what separates the parts.
void paint_eye(const GroupedMesh& source, int group, Mesh& mesh) {
  if (group < 0) return;
  std::vector<std::uint8_t> in_eye(mesh.positions.size(), 0);
  for (std::size_t t = 0; t < source.triangle_groups.size(); ++t)
    if (source.triangle_groups[t] == group)
      for (std::size_t k = 0; k < 3; ++k) in_eye[mesh.indices[3 * t + k]] = 1;
  vec3 centre(0.0f);
  int count = 0;
  for (std::size_t v = 0; v < in_eye.size(); ++v)
    if (in_eye[v]) { centre += mesh.positions[v]; ++count; }
  if (count == 0) return;
  centre /= static_cast<float>(count);
  for (std::size_t v = 0; v < in_eye.size(); ++v) {
    if (!in_eye[v]) continue;
    const vec3 d = mesh.positions[v] - centre;
    const float facing = glm::length(d) > 0 ? d.z / glm::length(d) : 0.0f;
    const MaterialId m = facing > 0.97f ? MaterialId::Pupil : facing > 0.88f ? MaterialId::Iris : MaterialId::EyeWhite;
    mesh.materials[v] = static_cast<std::uint8_t>(m);
  }
}

// The upper thoracic joint of the H-Anim spine (vt1, just below C7) is not a MakeHuman bone: a site
// on the top spine bone, most of the way up to the neck. The crown (skull_tip) is a site on the
// head at the top of the mesh, above the skull base.
void add_missing_joints(Avatar& a) {
  Skeleton& s = a.skeleton;
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  const auto at = [&](int j) { return vec3(model[static_cast<std::size_t>(j)][3]); };
  const auto need = [&](const char* name) {
    const int j = s.find(name);
    if (j < 0) throw Error(std::string("MakeHuman rig: no joint '") + name + "' (needed by the signing rig)");
    return j;
  };
  if (s.find("vt1") < 0) {
    const int vt6 = need("vt6"), vc7 = need("vc7");
    const vec3 p = glm::mix(at(vt6), at(vc7), 0.8f);
    s.add_joint("vt1", vt6, glm::inverse(glm::mat3(model[static_cast<std::size_t>(vt6)])) * (p - at(vt6)));
  }
  if (s.find("skull_tip") < 0) {
    const int skull = need("skullbase");
    const vec3 base = at(skull);
    float top = base.y;
    for (const vec3& p : a.mesh.positions)
      if (std::abs(p.x - base.x) < 0.03f && std::abs(p.z - base.z) < 0.06f) top = std::max(top, p.y);
    const vec3 p(base.x, top, base.z);
    s.add_joint("skull_tip", skull, glm::inverse(glm::mat3(model[static_cast<std::size_t>(skull)])) * (p - base));
  }
  s.validate();
}

// MakeHuman stands in an A-pose; the default avatar, whose ready posture and joint limits the signing
// rig reuses, has its arms hanging. Re-pose the upper and lower arms onto the default skeleton's
// directions, skin the mesh into that pose and make it the new bind pose (rest rotations stay identity,
// so only the joint offsets change).
void lower_arms_like_default(Avatar& a, const Skeleton& reference) {
  Skeleton& s = a.skeleton;
  const std::vector<vec3> ref = rest_joint_positions(reference);
  const Pose rest = rest_pose(s);
  std::vector<mat4> bind(s.size()), posed_model(s.size());
  local_to_model(s, rest, bind);
  const auto at = [&](int j) { return vec3(bind[static_cast<std::size_t>(j)][3]); };
  Pose posed = rest;
  for (const char* side : {"l_", "r_"}) {
    const std::string p = side;
    const int sh = s.find(p + "shoulder"), el = s.find(p + "elbow"), wr = s.find(p + "wrist");
    const int rsh = reference.find(p + "shoulder"), rel = reference.find(p + "elbow"), rwr = reference.find(p + "wrist");
    if (sh < 0 || el < 0 || wr < 0 || rsh < 0 || rel < 0 || rwr < 0) throw Error("MakeHuman rig: no " + p + "shoulder/elbow/wrist");
    const auto dir = [](const vec3& from, const vec3& to) { return glm::normalize(to - from); };
    const quat upper = glm::rotation(dir(at(sh), at(el)), dir(ref[static_cast<std::size_t>(rsh)], ref[static_cast<std::size_t>(rel)]));
    const quat fore = glm::rotation(upper * dir(at(el), at(wr)), dir(ref[static_cast<std::size_t>(rel)], ref[static_cast<std::size_t>(rwr)]));
    // The shoulder's parents keep their rest orientation (identity), so its local rotation is `upper`;
    // the elbow's model rotation is fore·upper, local inverse(upper)·fore·upper.
    posed.rotations[static_cast<std::size_t>(sh)] = upper;
    posed.rotations[static_cast<std::size_t>(el)] = glm::inverse(upper) * fore * upper;
  }
  local_to_model(s, posed, posed_model);
  std::vector<mat4> skinning(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) skinning[j] = posed_model[j] * glm::inverse(bind[j]);
  Mesh& m = a.mesh;
  std::vector<vec3> positions(m.positions.size()), normals(m.normals.size());
  skin_positions_normals(skinning, m.joints, m.weights, m.positions, m.normals, positions, normals);
  m.positions = std::move(positions);
  m.normals = std::move(normals);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const vec3 here(posed_model[j][3]);
    s.rest_translations[j] = s.parents[j] < 0 ? here : here - vec3(posed_model[static_cast<std::size_t>(s.parents[j])][3]);
  }
}

// MakeHuman's rig has no joint limits; the joints that share an H-Anim name with the default
// skeleton take its degrees of freedom and limits (valid once the arms hang like the default's).
void copy_limits(Skeleton& s, const Skeleton& reference) {
  for (std::size_t j = 0; j < s.size(); ++j)
    if (const int k = reference.find(s.names[j]); k >= 0) s.dofs[j] = reference.dofs[static_cast<std::size_t>(k)];
}

}  // namespace

Avatar load_makehuman_avatar(const std::string& directory) {
  if (!std::filesystem::is_directory(directory))
    throw Error("avatar makehuman:" + directory + ": no such directory (expected base.obj and rigs/ in it)");
  MakeHumanBody body = load_makehuman(directory);
  constexpr std::array<std::string_view, 3> kKept{"body", "helper-l-eye", "helper-r-eye"};
  GroupedMesh kept = keep_groups(body.mesh, kKept);
  Avatar a;
  a.skeleton = std::move(body.rig.skeleton);
  a.mesh = std::move(kept.mesh);

  // MakeHuman's origin is near the pelvis: lift everything so the soles touch y = 0. Rest rotations
  // are identity, so moving the roots moves every joint.
  float floor = std::numeric_limits<float>::max(), top = -floor;
  for (const vec3& p : a.mesh.positions) { floor = std::min(floor, p.y); top = std::max(top, p.y); }
  const vec3 lift(0.0f, -floor, 0.0f);
  for (vec3& p : a.mesh.positions) p += lift;
  for (std::size_t j = 0; j < a.skeleton.size(); ++j)
    if (a.skeleton.parents[j] < 0) a.skeleton.rest_translations[j] += lift;

  a.mesh.materials.assign(a.mesh.positions.size(), static_cast<std::uint8_t>(MaterialId::Skin));
  paint_eye(kept, kept.find_group("helper-l-eye"), a.mesh);
  paint_eye(kept, kept.find_group("helper-r-eye"), a.mesh);
  const Skeleton reference = build_avatar_skeleton();
  lower_arms_like_default(a, reference);
  add_missing_joints(a);
  copy_limits(a.skeleton, reference);
  a.params.height = top - floor;
  return a;
}

Avatar load_avatar(const std::string& spec, const AvatarParams& params, std::vector<std::string>* notes) {
  if (const AvatarLook* look = find_look(spec)) return build_avatar(with_given(look->params, params));
  if (is_avatar_file(spec)) {
    ImportedAvatar imported = load_file_avatar(spec);
    for (const std::string& note : imported.notes) {
      if (notes) notes->push_back(note);
      else std::fprintf(stderr, "note: %s\n", note.c_str());
    }
    return std::move(imported.avatar);
  }
  if (spec.starts_with(kMakeHumanPrefix)) {
    const std::string dir = spec.substr(kMakeHumanPrefix.size());
    if (dir.empty()) throw Error("avatar 'makehuman:': give the MakeHuman asset directory, e.g. makehuman:DIR");
    return load_makehuman_avatar(dir);
  }
  throw Error("unknown avatar '" + spec + "' (use a built-in look: " + look_names() +
              "; makehuman:DIR; or an avatar file FILE.vrm, FILE.glb, FILE.gltf)");
}

}  // namespace gestura
