#include "gestura/io/avatar_import.hpp"

#include <algorithm>
#include <cctype>
#include <limits>
#include <map>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/face_channel_map.hpp"

namespace gestura {
namespace {

constexpr const char* kFingers[] = {"thumb", "index", "middle", "ring", "pinky"};

// A skeleton whose rest rotations are all the identity, kept as joints with model positions while
// joints are added and re-parented; turned into a Skeleton (parents first) at the end.
struct Rig {
  std::vector<std::string> names;
  std::vector<int> parents;
  std::vector<vec3> positions;

  int find(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
  }
  int add(const std::string& name, int parent, const vec3& position) {
    names.push_back(name), parents.push_back(parent), positions.push_back(position);
    return static_cast<int>(names.size()) - 1;
  }
  bool is_ancestor(int a, int j) const {
    for (int p = j; p >= 0; p = parents[static_cast<std::size_t>(p)])
      if (p == a) return true;
    return false;
  }
};

Rig rig_of(const Skeleton& s) {
  Rig r;
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  for (std::size_t j = 0; j < s.size(); ++j) r.add(s.names[j], s.parents[j], vec3(model[j][3]));
  return r;
}

// The rig as a Skeleton in parents-first order; `moved[old] = new` index for re-pointing skins.
Skeleton skeleton_of(const Rig& r, std::vector<int>& moved) {
  const std::size_t n = r.names.size();
  moved.assign(n, -1);
  Skeleton s;
  std::vector<std::uint8_t> done(n, 0);
  for (std::size_t placed = 0; placed < n;) {
    const std::size_t before = placed;
    for (std::size_t j = 0; j < n; ++j) {
      if (done[j]) continue;
      const int p = r.parents[j];
      if (p >= 0 && !done[static_cast<std::size_t>(p)]) continue;
      const vec3 offset = p >= 0 ? r.positions[j] - r.positions[static_cast<std::size_t>(p)] : r.positions[j];
      moved[j] = s.add_joint(r.names[j], p >= 0 ? moved[static_cast<std::size_t>(p)] : -1, offset);
      done[j] = 1;
      ++placed;
    }
    if (placed == before) throw Error("avatar import: the joints form a cycle");
  }
  return s;
}

void repoint(Mesh& mesh, const std::vector<int>& moved) {
  for (JointIndices& j : mesh.joints)
    for (int k = 0; k < 4; ++k) j[k] = static_cast<std::uint16_t>(moved[j[k]]);
}

// Inserts `name` on the chain between `below` and its descendant `above`, at `position`: the
// child of `below` that leads to `above` is re-parented under the new joint.
void insert_between(Rig& r, const std::string& name, int below, int above, const vec3& position) {
  const int m = r.add(name, below, position);
  for (std::size_t c = 0; c < r.names.size(); ++c)
    if (r.parents[c] == below && static_cast<int>(c) != m && r.is_ancestor(static_cast<int>(c), above)) {
      r.parents[c] = m;
      break;
    }
}

// Puts each missing joint of `chain` (ordered from the root up) between its nearest present
// neighbours, at the height fraction it has between them in the reference skeleton.
void fill_chain(Rig& r, const std::vector<std::string>& chain, const std::vector<vec3>& ref_pos, const Skeleton& ref,
                std::vector<std::string>& added) {
  for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
    if (r.find(chain[i]) >= 0) continue;
    int lo = -1, hi = -1;
    std::size_t lo_i = 0, hi_i = 0;
    for (std::size_t k = i; k-- > 0;)
      if ((lo = r.find(chain[k])) >= 0) { lo_i = k; break; }
    for (std::size_t k = i + 1; k < chain.size(); ++k)
      if ((hi = r.find(chain[k])) >= 0) { hi_i = k; break; }
    if (lo < 0 || hi < 0 || !r.is_ancestor(lo, hi)) continue;
    const auto y = [&](std::size_t k) { return ref_pos[static_cast<std::size_t>(ref.find(chain[k]))].y; };
    const float span = y(hi_i) - y(lo_i);
    const float t = std::abs(span) > 1e-6f ? std::clamp((y(i) - y(lo_i)) / span, 0.05f, 0.95f) : 0.5f;
    insert_between(r, chain[i], lo, hi, glm::mix(r.positions[static_cast<std::size_t>(lo)], r.positions[static_cast<std::size_t>(hi)], t));
    added.push_back(chain[i]);
  }
}

// The rotation taking the frame (a, b) — a primary direction and a second one across it — to (c, d).
quat frame_rotation(vec3 a, vec3 b, vec3 c, vec3 d) {
  const auto basis = [](vec3 x, vec3 y) {
    x = glm::normalize(x);
    vec3 z = glm::cross(x, y);
    if (glm::length(z) < 1e-6f) z = glm::cross(x, std::abs(x.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0));
    z = glm::normalize(z);
    return mat3(x, glm::cross(z, x), z);
  };
  return glm::normalize(glm::quat_cast(basis(c, d) * glm::transpose(basis(a, b))));
}

// Re-poses the arms, hands and fingers onto the reference skeleton's rest directions and makes
// that the bind pose (mesh skinned into it). Works on the baked skeleton (identity rest rotations).
void pose_limbs_like(Skeleton& s, Mesh& mesh, const Skeleton& ref) {
  const std::vector<vec3> ref_pos = rest_joint_positions(ref);
  const auto ref_at = [&](const std::string& n) { return ref_pos[static_cast<std::size_t>(ref.find(n))]; };
  std::vector<mat4> bind(s.size());
  local_to_model(s, rest_pose(s), bind);
  const auto at = [&](int j) { return vec3(bind[static_cast<std::size_t>(j)][3]); };
  std::vector<quat> world(s.size(), quat(1, 0, 0, 0));  // accumulated model-space rotation per joint
  Pose posed = rest_pose(s);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const int p = s.parents[j];
    const quat parent_world = p >= 0 ? world[static_cast<std::size_t>(p)] : quat(1, 0, 0, 0);
    quat extra(1, 0, 0, 0);
    const std::string& name = s.names[j];
    const auto bone = [&](const std::string& child) -> std::optional<std::pair<vec3, vec3>> {
      const int c = s.find(child);
      if (c < 0 || ref.find(name) < 0 || ref.find(child) < 0) return std::nullopt;
      const vec3 now = parent_world * (at(c) - at(static_cast<int>(j)));
      const vec3 want = ref_at(child) - ref_at(name);
      if (glm::length(now) < 1e-6f || glm::length(want) < 1e-6f) return std::nullopt;
      return std::pair{glm::normalize(now), glm::normalize(want)};
    };
    const std::string side = name.size() > 2 && name[1] == '_' ? name.substr(0, 2) : "";
    if (!side.empty()) {
      if (name == side + "shoulder") {
        if (auto b = bone(side + "elbow")) extra = glm::rotation(b->first, b->second);
      } else if (name == side + "elbow") {
        if (auto b = bone(side + "wrist")) extra = glm::rotation(b->first, b->second);
      } else if (name == side + "wrist") {
        const int m = s.find(side + "middle1"), i = s.find(side + "index1"), k = s.find(side + "pinky1");
        if (m >= 0 && i >= 0 && k >= 0)
          extra = frame_rotation(parent_world * (at(m) - at(static_cast<int>(j))), parent_world * (at(k) - at(i)),
                                 ref_at(side + "middle1") - ref_at(name), ref_at(side + "pinky1") - ref_at(side + "index1"));
        else if (auto b = bone(side + "middle1"))
          extra = glm::rotation(b->first, b->second);
      } else {
        for (const char* f : kFingers)
          for (int k = 1; k <= 3; ++k)
            if (name == side + f + std::to_string(k))
              if (auto b = bone(side + f + (k < 3 ? std::to_string(k + 1) : std::string("_tip")))) extra = glm::rotation(b->first, b->second);
      }
    }
    world[j] = extra * parent_world;
    posed.rotations[j] = glm::inverse(parent_world) * world[j];
  }
  std::vector<mat4> model(s.size()), skin(s.size());
  local_to_model(s, posed, model);
  for (std::size_t j = 0; j < s.size(); ++j) skin[j] = model[j] * glm::inverse(bind[j]);
  std::vector<vec3> positions(mesh.positions.size()), normals(mesh.normals.size());
  skin_positions_normals(skin, mesh.joints, mesh.weights, mesh.positions, mesh.normals, positions, normals);
  // Morph offsets turn with their vertices.
  for (MorphTarget& m : mesh.morphs)
    for (std::size_t k = 0; k < m.vertices.size() && k < m.position_deltas.size(); ++k) {
      const JointIndices& ji = mesh.joints[m.vertices[k]];
      const vec4& w = mesh.weights[m.vertices[k]];
      mat3 r(0.0f);
      for (int q = 0; q < 4; ++q) r += w[q] * mat3(skin[ji[q]]);
      m.position_deltas[k] = r * m.position_deltas[k];
    }
  mesh.positions = std::move(positions);
  mesh.normals = std::move(normals);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const vec3 here(model[j][3]);
    s.rest_translations[j] = s.parents[j] < 0 ? here : here - vec3(model[static_cast<std::size_t>(s.parents[j])][3]);
  }
}

// How far the skin dominated by `joint` reaches along `direction` from the joint (0 when it has
// no skin of its own).
float skin_reach(const Mesh& mesh, int joint, const vec3& from, const vec3& direction) {
  float reach = 0.0f;
  int count = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (mesh.weights[v][k] > mesh.weights[v][best]) best = k;
    if (mesh.joints[v][best] != joint) continue;
    reach = std::max(reach, glm::dot(mesh.positions[v] - from, direction));
    ++count;
  }
  return count >= 4 ? reach : 0.0f;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

bool is_avatar_file(const std::string& spec) {
  const std::string s = lower(spec);
  return s.ends_with(".vrm") || s.ends_with(".glb") || s.ends_with(".gltf");
}

ImportedAvatar import_avatar(VrmAvatar file, const std::string& source) {
  ImportedAvatar out;
  Mesh& mesh = file.mesh;
  if (mesh.positions.empty() || mesh.indices.empty()) throw Error(source + ": no mesh to show (the file has no triangles)");
  {
    std::vector<std::string> lacking;
    const std::pair<const char*, const char*> needed[] = {
        {"humanoid_root", "hips"},          {"skullbase", "head"},         {"l_shoulder", "left upper arm"},
        {"r_shoulder", "right upper arm"}, {"l_elbow", "left forearm"},   {"r_elbow", "right forearm"},
        {"l_wrist", "left hand"},          {"r_wrist", "right hand"}};
    for (const auto& [joint, what] : needed)
      if (file.skeleton.find(joint) < 0) lacking.push_back(std::string(what) + " (" + joint + ")");
    if (!lacking.empty()) {
      std::string list;
      for (const std::string& l : lacking) list += (list.empty() ? "" : ", ") + l;
      throw Error(source + ": the rig has no bone for the " + list + "; gestura needs hips, head, upper arms, forearms and "
                  "hands (" + file.kind + (file.kind == "glTF" ? ": joints are recognised by name, e.g. Mixamo, VRoid, MakeHuman, CMU" : "") + ")");
    }
  }
  const Skeleton ref = build_avatar_skeleton();
  const std::vector<vec3> ref_pos = rest_joint_positions(ref);
  Rig rig = rig_of(file.skeleton);

  // VRM 0.x looks down -Z: half a turn about +Y makes it face +Z like everything else here.
  if (file.faces_minus_z) {
    const auto turn = [](vec3 v) { return vec3(-v.x, v.y, -v.z); };
    for (vec3& p : rig.positions) p = turn(p);
    for (vec3& p : mesh.positions) p = turn(p);
    for (vec3& n : mesh.normals) n = turn(n);
    for (MorphTarget& m : mesh.morphs) {
      for (vec3& d : m.position_deltas) d = turn(d);
      for (vec3& d : m.normal_deltas) d = turn(d);
    }
  }
  // Feet on the floor.
  float floor = std::numeric_limits<float>::max(), top = -floor;
  for (const vec3& p : mesh.positions) floor = std::min(floor, p.y), top = std::max(top, p.y);
  for (vec3& p : mesh.positions) p.y -= floor;
  for (vec3& p : rig.positions) p.y -= floor;

  // The spine and neck joints the signing rig works with, and the clavicles.
  std::vector<std::string> added;
  fill_chain(rig, {"humanoid_root", "vl5", "vl3", "vt12", "vt6", "vt1", "vc7", "vc4", "skullbase"}, ref_pos, ref, added);
  for (const char* side : {"l_", "r_"}) {
    const std::string p = side;
    if (rig.find(p + "sternoclavicular") >= 0) continue;
    const int shoulder = rig.find(p + "shoulder");
    const int parent = rig.parents[static_cast<std::size_t>(shoulder)];
    if (parent < 0) continue;
    const vec3 r_sc = ref_pos[static_cast<std::size_t>(ref.find(p + "sternoclavicular"))];
    const vec3 r_sh = ref_pos[static_cast<std::size_t>(ref.find(p + "shoulder"))];
    const vec3 r_top = ref_pos[static_cast<std::size_t>(ref.find("vt1"))];
    const float t = std::clamp(glm::dot(r_sc - r_top, r_sh - r_top) / std::max(1e-6f, glm::dot(r_sh - r_top, r_sh - r_top)), 0.0f, 0.9f);
    insert_between(rig, p + "sternoclavicular", parent, shoulder,
                   glm::mix(rig.positions[static_cast<std::size_t>(parent)], rig.positions[static_cast<std::size_t>(shoulder)], t));
    added.push_back(p + "sternoclavicular");
  }

  // Finger tips where each finger's own skin ends (else as far again as its middle bone), the crown.
  std::vector<std::string> no_fingers;
  for (const char* side : {"l_", "r_"}) {
    int present = 0;
    for (const char* f : kFingers) {
      const std::string base = std::string(side) + f;
      const int d = rig.find(base + "3"), m = rig.find(base + "2");
      present += d >= 0;
      if (d < 0 || m < 0 || rig.find(base + "_tip") >= 0) continue;
      const vec3 pd = rig.positions[static_cast<std::size_t>(d)], pm = rig.positions[static_cast<std::size_t>(m)];
      const vec3 dir = glm::normalize(pd - pm);
      const float reach = skin_reach(mesh, d, pd, dir);
      rig.add(base + "_tip", d, pd + dir * (reach > 0.002f ? reach : 0.8f * glm::length(pd - pm)));
    }
    if (present < 5) no_fingers.push_back(side[0] == 'l' ? "left" : "right");
  }
  if (rig.find("skull_tip") < 0) {
    const int skull = rig.find("skullbase");
    const vec3 base = rig.positions[static_cast<std::size_t>(skull)];
    float crown = base.y;
    for (const vec3& p : mesh.positions)
      if (std::abs(p.x - base.x) < 0.03f && std::abs(p.z - base.z) < 0.08f) crown = std::max(crown, p.y);
    rig.add("skull_tip", skull, vec3(base.x, std::max(crown, base.y + 0.1f), base.z));
  }

  std::vector<int> moved;
  Skeleton s = skeleton_of(rig, moved);
  repoint(mesh, moved);
  pose_limbs_like(s, mesh, ref);

  // Hands without (some) finger bones: the default hand's finger joints, scaled to this forearm,
  // placed from the re-posed wrist. They move no skin: the hand keeps its modelled shape.
  if (!no_fingers.empty()) {
    Rig r = rig_of(s);
    for (const char* side : {"l_", "r_"}) {
      const std::string p = side;
      const float scale = glm::distance(r.positions[static_cast<std::size_t>(r.find(p + "elbow"))], r.positions[static_cast<std::size_t>(r.find(p + "wrist"))]) /
                          glm::distance(ref_pos[static_cast<std::size_t>(ref.find(p + "elbow"))], ref_pos[static_cast<std::size_t>(ref.find(p + "wrist"))]);
      for (const char* f : kFingers)
        for (const std::string part : {"1", "2", "3", "_tip"}) {
          const std::string name = p + f + part;
          if (r.find(name) >= 0) continue;
          // Under the nearest reference ancestor the rig has (the wrist, for a finger's CMC joint).
          const int ref_joint = ref.find(name);
          int ref_parent = ref.parents[static_cast<std::size_t>(ref_joint)];
          while (ref_parent >= 0 && r.find(ref.names[static_cast<std::size_t>(ref_parent)]) < 0)
            ref_parent = ref.parents[static_cast<std::size_t>(ref_parent)];
          if (ref_parent < 0) continue;
          const int parent = r.find(ref.names[static_cast<std::size_t>(ref_parent)]);
          r.add(name, parent, r.positions[static_cast<std::size_t>(parent)] +
                                  scale * (ref_pos[static_cast<std::size_t>(ref_joint)] - ref_pos[static_cast<std::size_t>(ref_parent)]));
        }
    }
    s = skeleton_of(r, moved);
    repoint(mesh, moved);
  }
  for (std::size_t j = 0; j < s.size(); ++j)
    if (const int k = ref.find(s.names[j]); k >= 0) s.dofs[j] = ref.dofs[static_cast<std::size_t>(k)];
  s.validate();

  const FaceChannelReport face = map_face_channels(mesh, file.face_channels);

  out.avatar.skeleton = std::move(s);
  out.avatar.mesh = std::move(mesh);
  out.avatar.params.height = top - floor;
  out.notes.push_back(source + ": " + file.kind + " avatar, " + std::to_string(out.avatar.mesh.vertex_count()) + " vertices, " +
                      std::to_string(out.avatar.skeleton.size()) + " joints, " + std::to_string(out.avatar.params.height).substr(0, 4) + " m tall");
  if (!added.empty()) {
    std::string list;
    for (const std::string& a : added) list += (list.empty() ? "" : " ") + a;
    out.notes.push_back(source + ": joints added between the rig's own (the signing rig uses them): " + list);
  }
  for (const std::string& side : no_fingers)
    out.notes.push_back(source + ": the " + side + " hand has no finger bones: handshapes will not show on it (its fingers "
                        "stay as modelled; signs still place and move the hand)");
  if (face.mapped.empty()) {
    out.notes.push_back(source + ": no face shapes (no VRM expressions, ARKit blend shapes or gestura morphs): mouthing, "
                        "blinks, brows and facial expressions will not show");
  } else if (!face.missing.empty()) {
    std::string list;
    for (const std::string& m : face.missing) list += (list.empty() ? "" : " ") + m;
    out.notes.push_back(source + ": face: " + std::to_string(face.mapped.size()) + " of " +
                        std::to_string(face.mapped.size() + face.missing.size()) + " face channels (" + std::to_string(face.from_own) +
                        " own, " + std::to_string(face.from_arkit) + " from ARKit blend shapes, " + std::to_string(face.from_expressions) +
                        " from VRM expressions); not shown: " + list);
  }
  return out;
}

ImportedAvatar load_file_avatar(const std::string& path) {
  const std::string l = lower(path);
  return import_avatar(l.ends_with(".vrm") ? load_vrm(path) : load_rigged_gltf(path), path);
}

}  // namespace gestura
