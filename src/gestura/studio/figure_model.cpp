#include "gestura/studio/figure_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/io/bvh.hpp"

namespace gestura::studio {
namespace {

// "l_elbow" ↔ "r_elbow"; empty when the name has no side.
std::string other_side(const std::string& name) {
  if (name.size() > 2 && name[1] == '_' && (name[0] == 'l' || name[0] == 'r')) return std::string(1, name[0] == 'l' ? 'r' : 'l') + name.substr(1);
  return {};
}

bool good_name(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-' || c == '.'; });
}

// Reflection in the x = 0 plane.
vec3 reflect(const vec3& v) { return vec3(-v.x, v.y, v.z); }
quat reflect(const quat& q) { return quat(q.w, q.x, -q.y, -q.z); }
JointDofs reflect(const JointDofs& d) {
  JointDofs r = d;
  for (int axis = 1; axis < 3; ++axis) r.min_angle[axis] = -d.max_angle[axis], r.max_angle[axis] = -d.min_angle[axis];
  return r;
}

void push_joint(Skeleton& s, const Skeleton& from, int j, const std::string& name, int parent) {
  const std::size_t u = static_cast<std::size_t>(j);
  s.names.push_back(name);
  s.parents.push_back(static_cast<std::int16_t>(parent));
  s.rest_translations.push_back(from.rest_translations[u]);
  s.rest_rotations.push_back(from.rest_rotations[u]);
  s.rest_scales.push_back(from.rest_scales[u]);
  s.dofs.push_back(from.dofs[u]);
  if (!s.dh.empty() || !from.dh.empty()) {
    s.dh.resize(s.names.size() - 1);
    s.dh.push_back(u < from.dh.size() ? from.dh[u] : std::nullopt);
  }
}

nlohmann::json dofs_json(const Skeleton& s, std::size_t j) {
  const JointDofs& d = s.dofs[j];
  std::string axes;
  for (int a = 0; a < 3; ++a)
    if (d.free(a)) axes += "xyz"[a];
  nlohmann::json o{{"order", std::string(to_string(d.order))},
                   {"axes", axes},
                   {"min_degrees", {glm::degrees(d.min_angle.x), glm::degrees(d.min_angle.y), glm::degrees(d.min_angle.z)}},
                   {"max_degrees", {glm::degrees(d.max_angle.x), glm::degrees(d.max_angle.y), glm::degrees(d.max_angle.z)}}};
  if (j < s.dh.size() && s.dh[j]) {
    const DenavitHartenberg& h = *s.dh[j];
    o["dh"] = {{"a", h.a}, {"alpha_degrees", glm::degrees(h.alpha)}, {"d", h.d}, {"theta_degrees", glm::degrees(h.theta)}};
  }
  return o;
}

// Angles (degrees) and lengths in a figure file, as any value of a skeleton file (kBvhMaxMagnitude):
// past float's range a number would become infinite and be saved as null, a file the editor
// could not read back.
constexpr double kMaxFigureNumber = kBvhMaxMagnitude;

bool figure_number(const nlohmann::json& v) { return v.is_number() && std::abs(v.get<double>()) <= kMaxFigureNumber; }

vec3 vec3_field(const nlohmann::json& o, const char* key, const std::string& where) {
  const auto it = o.find(key);
  if (it == o.end() || !it->is_array() || it->size() != 3 || !figure_number((*it)[0]) || !figure_number((*it)[1]) ||
      !figure_number((*it)[2]))
    throw Error(where + ": '" + key + "' must be three numbers of magnitude at most 1e7");
  return vec3((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
}

float number_field(const nlohmann::json& o, const char* key, const std::string& where) {
  const auto it = o.find(key);
  if (it == o.end() || !figure_number(*it)) throw Error(where + ": '" + key + "' must be a number of magnitude at most 1e7");
  return it->get<float>();
}

// An optional text field (nlohmann's value() throws its own type_error for a value of another type).
std::string text_field(const nlohmann::json& o, const char* key, const char* fallback, const std::string& where) {
  const auto it = o.find(key);
  if (it == o.end()) return fallback;
  if (!it->is_string()) throw Error(where + ": '" + key + "' must be a string");
  return it->get<std::string>();
}

std::string read_whole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(path + ": cannot read the file");
  return text.str();
}

void apply_sidecar(Skeleton& s, std::string_view text, const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number past a double
    throw Error(SourceLocation{path}, std::string("not a figure file: ") + e.what());
  }
  if (!j.is_object() || !j.contains("joints") || !j["joints"].is_object())
    throw Error(SourceLocation{path}, "not a figure file (a JSON object with \"joints\")");
  for (const auto& [name, o] : j["joints"].items()) {
    const std::string where = path + ": joint '" + name + "'";
    const int joint = s.find(name);
    if (joint < 0) throw Error(where + " is not in the skeleton file");
    if (!o.is_object()) throw Error(where + " must be an object");
    JointDofs d;
    const auto order = parse_rotation_order(text_field(o, "order", "XYZ", where));
    if (!order) throw Error(where + ": 'order' must be one of XYZ XZY YXZ YZX ZXY ZYX");
    d.order = *order;
    const std::string axes = text_field(o, "axes", "", where);
    for (const char c : axes) {
      if (c < 'x' || c > 'z') throw Error(where + ": 'axes' may hold only x, y and z");
      d.axes |= static_cast<std::uint8_t>(1u << (c - 'x'));
    }
    d.min_angle = glm::radians(vec3_field(o, "min_degrees", where));
    d.max_angle = glm::radians(vec3_field(o, "max_degrees", where));
    s.dofs[static_cast<std::size_t>(joint)] = d;
    if (o.contains("dh")) {
      const nlohmann::json& h = o["dh"];
      if (!h.is_object()) throw Error(where + ": 'dh' must be an object");
      s.dh.resize(s.size());
      s.dh[static_cast<std::size_t>(joint)] = DenavitHartenberg{number_field(h, "a", where), glm::radians(number_field(h, "alpha_degrees", where)),
                                                                number_field(h, "d", where), glm::radians(number_field(h, "theta_degrees", where))};
    }
  }
}

}  // namespace

std::string figure_sidecar_path(const std::string& bvh_path) {
  return std::filesystem::path(bvh_path).replace_extension(".figure.json").string();
}

FigureTexts write_figure(const Skeleton& skeleton, const std::string& bvh_file_name) {
  skeleton.validate();
  // The sidecar is JSON, whose text is UTF-8: a name from a BVH in another encoding cannot be
  // written there (the editor renames it; load refuses nothing so the figure can be repaired).
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    try {
      utf8::validate(skeleton.names[j]);
    } catch (const Error& e) {
      throw Error("joint " + std::to_string(j) + "'s name is not UTF-8 text (" + e.what() + "): rename it before saving");
    }
  }
  const std::size_t n = skeleton.size();
  BvhFile bvh;
  bvh.skeleton = skeleton;
  // BVH rest orientations are the identity: the rest rotations go into the one frame instead.
  std::fill(bvh.skeleton.rest_rotations.begin(), bvh.skeleton.rest_rotations.end(), quat(1, 0, 0, 0));
  bvh.skeleton.dh.clear();
  bvh.end_site.assign(n, 0);
  bvh.channels.resize(n);
  bvh.clip.resize_joints(n);
  bvh.frame_count = 1;
  bvh.frame_time = 1.0f / 30.0f;
  for (std::size_t j = 0; j < n; ++j) {
    BvhChannels& c = bvh.channels[j];
    if (skeleton.parents[j] < 0) {
      for (BvhChannel p : {BvhChannel::Xposition, BvhChannel::Yposition, BvhChannel::Zposition}) c.push(p);
      bvh.clip.translations[j].add(0.0f, skeleton.rest_translations[j]);
    }
    // The rotation channels in the joint's own order (outermost first), so the file says it.
    for (const int axis : axes_of(skeleton.dofs[j].order)) c.push(static_cast<BvhChannel>(static_cast<int>(BvhChannel::Xrotation) + axis));
    bvh.clip.rotations[j].add(0.0f, skeleton.rest_rotations[j]);
  }
  nlohmann::json side{{"format", "gestura figure"}, {"version", 1}, {"skeleton", bvh_file_name}};
  nlohmann::json& joints = side["joints"] = nlohmann::json::object();
  for (std::size_t j = 0; j < n; ++j) joints[skeleton.names[j]] = dofs_json(skeleton, j);
  return FigureTexts{write_bvh(bvh), side.dump(1) + "\n"};
}

void save_figure(const std::string& path, const Skeleton& skeleton) {
  const FigureTexts texts = write_figure(skeleton, std::filesystem::path(path).filename().string());
  write_file_atomically(figure_sidecar_path(path), texts.sidecar);
  write_file_atomically(path, texts.bvh);
}

Skeleton read_figure(std::string_view bvh_text, const std::string& bvh_source,
                     std::optional<std::string_view> sidecar_text, const std::string& sidecar_source) {
  BvhFile bvh = read_bvh(bvh_text, bvh_source);
  Skeleton s = bvh.skeleton;
  const std::size_t n = s.size();
  for (std::size_t j = 0; j < n; ++j) {
    if (!bvh.clip.rotations[j].empty()) s.rest_rotations[j] = glm::normalize(bvh.clip.rotations[j].values.front());
    if (s.parents[j] < 0 && !bvh.clip.translations[j].empty()) s.rest_translations[j] = bvh.clip.translations[j].values.front();
    // Without a sidecar: the file's rotation order, every axis with a rotation channel free.
    JointDofs d;
    d.order = bvh.channels[j].rotation_order();
    for (int i = 0; i < bvh.channels[j].count; ++i)
      if (!is_position(bvh.channels[j][i])) d.axes |= static_cast<std::uint8_t>(1u << axis_of(bvh.channels[j][i]));
    d.min_angle = vec3(-glm::pi<float>()), d.max_angle = vec3(glm::pi<float>());
    s.dofs[j] = d;
  }
  if (sidecar_text) apply_sidecar(s, *sidecar_text, sidecar_source);
  try {
    s.validate();
  } catch (const Error& e) {
    throw Error((sidecar_text ? sidecar_source : bvh_source) + ": " + e.what());
  }
  return s;
}

Skeleton load_figure(const std::string& path) {
  const std::string bvh = read_whole(path);
  const std::string sidecar_path = figure_sidecar_path(path);
  std::optional<std::string> sidecar;
  if (std::filesystem::exists(sidecar_path)) sidecar = read_whole(sidecar_path);  // else a plain BVH
  return read_figure(bvh, path, sidecar ? std::optional<std::string_view>(*sidecar) : std::nullopt, sidecar_path);
}

FigureEditor::FigureEditor(Skeleton skeleton) : skeleton_(std::move(skeleton)) {}

bool FigureEditor::fail(std::string message) {
  error_ = std::move(message);
  return false;
}

bool FigureEditor::apply(Skeleton next, const std::string& merge_key) {
  try {
    next.validate();
  } catch (const Error& e) {
    return fail(e.what());
  }
  if (merge_key.empty() || merge_key != last_key_ || undo_.empty()) undo_.push_back(skeleton_);
  if (undo_.size() > 200) undo_.erase(undo_.begin());
  redo_.clear();
  last_key_ = merge_key;
  skeleton_ = std::move(next);
  error_.clear();
  ++revision_;
  return true;
}

bool FigureEditor::rename(int joint, const std::string& name) {
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return fail("no joint selected");
  if (!good_name(name)) return fail("'" + name + "' is not a joint name (letters, digits, _ - .)");
  if (const int other = skeleton_.find(name); other >= 0 && other != joint) return fail("there is already a joint '" + name + "'");
  Skeleton next = skeleton_;
  next.names[static_cast<std::size_t>(joint)] = name;
  return apply(std::move(next), {});
}

int FigureEditor::add_joint(int parent, const std::string& name, const vec3& rest_offset) {
  if (parent < 0 || parent >= static_cast<int>(skeleton_.size())) return fail("no parent joint selected"), -1;
  if (!good_name(name)) return fail("'" + name + "' is not a joint name (letters, digits, _ - .)"), -1;
  if (skeleton_.find(name) >= 0) return fail("there is already a joint '" + name + "'"), -1;
  Skeleton next = skeleton_;
  const int index = next.add_joint(name, parent, rest_offset);
  next.dofs.resize(next.size());
  if (!next.dh.empty()) next.dh.resize(next.size());
  return apply(std::move(next), {}) ? index : -1;
}

bool FigureEditor::remove_joint(int joint) {
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return fail("no joint selected");
  const std::size_t u = static_cast<std::size_t>(joint);
  const int parent = skeleton_.parents[u];
  if (parent < 0) return fail("the root cannot be removed");
  Skeleton next;
  const Skeleton& s = skeleton_;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (j == u) continue;
    int p = s.parents[j];
    const bool child = p == joint;
    if (child) p = parent;
    push_joint(next, s, static_cast<int>(j), s.names[j], p > joint ? p - 1 : p);
    if (child) {  // keep its rest place: the removed joint's transform folds into it
      next.rest_translations.back() = s.rest_translations[u] + s.rest_rotations[u] * (s.rest_scales[u] * s.rest_translations[j]);
      next.rest_rotations.back() = glm::normalize(s.rest_rotations[u] * s.rest_rotations[j]);
    }
  }
  return apply(std::move(next), {});
}

std::vector<int> FigureEditor::branch(int joint) const {
  std::vector<int> out;
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return out;
  std::vector<bool> in(skeleton_.size(), false);
  in[static_cast<std::size_t>(joint)] = true;
  out.push_back(joint);
  for (std::size_t j = static_cast<std::size_t>(joint) + 1; j < skeleton_.size(); ++j)
    if (skeleton_.parents[j] >= 0 && in[static_cast<std::size_t>(skeleton_.parents[j])]) in[j] = true, out.push_back(static_cast<int>(j));
  return out;
}

int FigureEditor::copy_branch(int joint, const std::string& suffix) {
  const std::vector<int> joints = branch(joint);
  if (joints.empty()) return fail("no joint selected"), -1;
  if (skeleton_.parents[static_cast<std::size_t>(joint)] < 0) return fail("the root's branch is the whole figure; copy a limb"), -1;
  Skeleton next = skeleton_;
  std::vector<int> copy_of(skeleton_.size(), -1);
  for (const int j : joints) {
    const std::string name = skeleton_.names[static_cast<std::size_t>(j)] + suffix;
    if (next.find(name) >= 0) return fail("there is already a joint '" + name + "'"), -1;
    const int p = skeleton_.parents[static_cast<std::size_t>(j)];
    copy_of[static_cast<std::size_t>(j)] = static_cast<int>(next.size());
    push_joint(next, skeleton_, j, name, j == joint ? p : copy_of[static_cast<std::size_t>(p)]);
  }
  const int first = copy_of[static_cast<std::size_t>(joint)];
  return apply(std::move(next), {}) ? first : -1;
}

int FigureEditor::mirror_branch(int joint) {
  const std::vector<int> joints = branch(joint);
  if (joints.empty()) return fail("no joint selected"), -1;
  if (other_side(skeleton_.names[static_cast<std::size_t>(joint)]).empty())
    return fail("'" + skeleton_.names[static_cast<std::size_t>(joint)] + "' has no side (l_ or r_): nothing to mirror onto"), -1;
  Skeleton next = skeleton_;
  int written = 0;
  for (const int j : joints) {
    const std::size_t u = static_cast<std::size_t>(j);
    std::string name = other_side(skeleton_.names[u]);
    if (name.empty()) name = skeleton_.names[u] + "_mirror";
    int target = next.find(name);
    if (target < 0) {
      const int p = skeleton_.parents[u];
      const std::string parent_name = other_side(skeleton_.names[static_cast<std::size_t>(p)]);
      int mirrored_parent = parent_name.empty() ? p : next.find(parent_name);
      if (mirrored_parent < 0) mirrored_parent = p;
      push_joint(next, skeleton_, j, name, mirrored_parent);
      target = static_cast<int>(next.size()) - 1;
    }
    const std::size_t t = static_cast<std::size_t>(target);
    next.rest_translations[t] = reflect(skeleton_.rest_translations[u]);
    next.rest_rotations[t] = reflect(skeleton_.rest_rotations[u]);
    next.rest_scales[t] = skeleton_.rest_scales[u];
    next.dofs[t] = reflect(skeleton_.dofs[u]);
    if (u < skeleton_.dh.size() || t < next.dh.size()) {
      next.dh.resize(next.size());
      next.dh[t] = u < skeleton_.dh.size() ? skeleton_.dh[u] : std::nullopt;
    }
    ++written;
  }
  return apply(std::move(next), {}) ? written : -1;
}

bool FigureEditor::set_rest_offset(int joint, const vec3& offset, const std::string& merge_key) {
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return fail("no joint selected");
  if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z) || glm::length(offset) > 10.0f)
    return fail("a rest offset must be finite and under 10 m");
  Skeleton next = skeleton_;
  next.rest_translations[static_cast<std::size_t>(joint)] = offset;
  return apply(std::move(next), merge_key);
}

bool FigureEditor::set_dofs(int joint, const JointDofs& dofs, const std::string& merge_key) {
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return fail("no joint selected");
  for (int a = 0; a < 3; ++a)
    if (dofs.free(a) && dofs.min_angle[a] > dofs.max_angle[a]) return fail(std::string("the ") + "xyz"[a] + " limit's minimum is above its maximum");
  Skeleton next = skeleton_;
  next.dofs[static_cast<std::size_t>(joint)] = dofs;
  return apply(std::move(next), merge_key);
}

bool FigureEditor::set_dh(int joint, const std::optional<DenavitHartenberg>& dh, const std::string& merge_key) {
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return fail("no joint selected");
  if (dh && !(std::isfinite(dh->a) && std::isfinite(dh->alpha) && std::isfinite(dh->d) && std::isfinite(dh->theta)))
    return fail("DH parameters must be finite");
  Skeleton next = skeleton_;
  next.dh.resize(next.size());
  next.dh[static_cast<std::size_t>(joint)] = dh;
  return apply(std::move(next), merge_key);
}

DenavitHartenberg FigureEditor::dh_from_rest(int joint) const {
  if (joint < 0 || joint >= static_cast<int>(skeleton_.size())) return {};
  const vec3 o = skeleton_.rest_translations[static_cast<std::size_t>(joint)];
  const float a = std::sqrt(o.x * o.x + o.y * o.y);
  return DenavitHartenberg{a, 0.0f, o.z, a > 0.0f ? std::atan2(o.y, o.x) : 0.0f};
}

void FigureEditor::save(const std::string& path) {
  save_figure(path, skeleton_);
  file_ = path;
}

bool FigureEditor::load(const std::string& path) {
  try {
    Skeleton loaded = load_figure(path);
    if (!apply(std::move(loaded), {})) return false;
    file_ = path;
    return true;
  } catch (const Error& e) {
    return fail(e.what());
  }
}

bool FigureEditor::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(std::move(skeleton_));
  skeleton_ = std::move(undo_.back());
  undo_.pop_back();
  last_key_.clear();
  ++revision_;
  return true;
}

bool FigureEditor::redo() {
  if (redo_.empty()) return false;
  undo_.push_back(std::move(skeleton_));
  skeleton_ = std::move(redo_.back());
  redo_.pop_back();
  last_key_.clear();
  ++revision_;
  return true;
}

}  // namespace gestura::studio
