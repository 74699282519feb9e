// Fuzz target: the studio's skeleton files (the figure editor's BVH and its FILE.figure.json
// sidecar, studio/figure_model). An input holding a NUL byte is a pair: the BVH before the first
// NUL, the sidecar after it (nothing after it: a BVH without a sidecar). Any other input is a
// sidecar beside the avatar's own skeleton file. Then the editor's promise: a figure that loads is
// saved (write_figure) and must load back with the same joints, parents, axes, orders, limits, DH
// parameters and rest transforms (else abort: a finding); a save that throws anything but
// gestura::Error is a finding too (the studio catches only that: it would end, losing the user's
// work).
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "fuzz_target.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/studio/figure_model.hpp"

namespace {

using namespace gestura;

bool near(float a, float b) { return std::abs(a - b) <= 1e-5f + 1e-5f * std::max(std::abs(a), std::abs(b)); }
bool near(const vec3& a, const vec3& b) { return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z); }

// The skeleton file read back must be the figure that was saved (joints compared by name: BVH
// lists them depth-first, so the order may change).
void expect_same_figure(const Skeleton& saved, const Skeleton& back) {
  if (saved.size() != back.size()) std::abort();
  for (std::size_t j = 0; j < saved.size(); ++j) {
    const int found = back.find(saved.names[j]);
    if (found < 0) std::abort();
    const auto b = static_cast<std::size_t>(found);
    const int p = saved.parents[j], q = back.parents[b];
    if ((p < 0) != (q < 0) || (p >= 0 && saved.names[static_cast<std::size_t>(p)] != back.names[static_cast<std::size_t>(q)]))
      std::abort();
    if (!near(saved.rest_translations[j], back.rest_translations[b])) std::abort();
    if (!(std::abs(glm::dot(saved.rest_rotations[j], back.rest_rotations[b])) > 0.9999f)) std::abort();
    const JointDofs &d = saved.dofs[j], &e = back.dofs[b];
    if (d.axes != e.axes || d.order != e.order || !near(d.min_angle, e.min_angle) || !near(d.max_angle, e.max_angle))
      std::abort();
    const bool has_dh = j < saved.dh.size() && saved.dh[j], back_has_dh = b < back.dh.size() && back.dh[b];
    if (has_dh != back_has_dh) std::abort();
    if (has_dh) {
      const DenavitHartenberg &h = *saved.dh[j], &k = *back.dh[b];
      if (!near(h.a, k.a) || !near(h.alpha, k.alpha) || !near(h.d, k.d) || !near(h.theta, k.theta)) std::abort();
    }
  }
}

bool names_are_utf8(const Skeleton& s) {
  for (const std::string& name : s.names) {
    char32_t cp;
    for (std::size_t at = 0; at < name.size();)
      if (!utf8::decode(name, at, cp)) return false;
  }
  return true;
}

const std::string& avatar_skeleton_file() {
  static const std::string text = studio::write_figure(build_avatar_skeleton(), "avatar.bvh").bvh;
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = fuzz::text_of(data, size);
  const std::size_t nul = input.find('\0');
  std::string_view bvh = avatar_skeleton_file();
  std::optional<std::string_view> sidecar = input;
  if (nul != std::string_view::npos) {
    bvh = input.substr(0, nul);
    sidecar = input.substr(nul + 1);
    if (sidecar->empty()) sidecar.reset();
  }
  std::optional<Skeleton> figure;
  fuzz::expect_result_or_error([&] { figure = studio::read_figure(bvh, "fuzz.bvh", sidecar, "fuzz.figure.json"); });
  if (!figure) return 0;
  // What loads must save (unless a joint's name is not UTF-8: refused by name, to be renamed), and
  // what is saved must load back as the same figure.
  std::optional<studio::FigureTexts> saved;
  try {
    saved = studio::write_figure(*figure, "saved.bvh");
  } catch (const Error&) {
    if (names_are_utf8(*figure)) std::abort();
    return 0;
  }
  try {
    expect_same_figure(*figure, studio::read_figure(saved->bvh, "saved.bvh", std::string_view(saved->sidecar), "saved.figure.json"));
  } catch (const Error&) {
    std::abort();
  }
  return 0;
}
