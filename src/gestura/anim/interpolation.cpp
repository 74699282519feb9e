#include "gestura/anim/interpolation.hpp"

#include <cctype>
#include <string>

namespace gestura {

std::string_view to_string(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::Step: return "step";
    case Interpolation::Linear: return "linear";
    case Interpolation::Cardinal: return "cardinal";
    case Interpolation::CatmullRom: return "catmull-rom";
    case Interpolation::KochanekBartels: return "kochanek-bartels";
    case Interpolation::Slerp: return "slerp";
    case Interpolation::Squad: return "squad";
  }
  return "linear";
}

std::optional<Interpolation> parse_interpolation(std::string_view text) {
  std::string t(text);
  for (char& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (int i = 0; i <= static_cast<int>(Interpolation::Squad); ++i) {
    const auto candidate = static_cast<Interpolation>(i);
    if (to_string(candidate) == t) return candidate;
  }
  if (t == "kb" || t == "tcb") return Interpolation::KochanekBartels;
  if (t == "catmullrom") return Interpolation::CatmullRom;
  return std::nullopt;
}

quat quat_log(const quat& q) {
  const float v = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  if (v < 1e-7f) return quat(0, 0, 0, 0);
  const float angle = std::atan2(v, q.w);
  const float k = angle / v;
  return quat(0, q.x * k, q.y * k, q.z * k);
}

quat quat_exp(const quat& q) {
  const float a = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  if (a < 1e-7f) return quat(1, q.x, q.y, q.z);
  const float k = std::sin(a) / a;
  return quat(std::cos(a), q.x * k, q.y * k, q.z * k);
}

quat squad_control(const quat& prev, const quat& q, const quat& next) {
  const quat inv = glm::conjugate(q);
  quat to_next = inv * next, to_prev = inv * prev;
  if (to_next.w < 0) to_next = -to_next;  // shortest arcs
  if (to_prev.w < 0) to_prev = -to_prev;
  const quat l_next = quat_log(to_next), l_prev = quat_log(to_prev);
  const quat sum(0, -(l_next.x + l_prev.x) * 0.25f, -(l_next.y + l_prev.y) * 0.25f, -(l_next.z + l_prev.z) * 0.25f);
  return glm::normalize(q * quat_exp(sum));
}

quat squad(const quat& q0, const quat& q1, const quat& s0, const quat& s1, float u) {
  // Squad's inner slerps must not take the shortest path of their own (that would break C1 at keys).
  const quat a = glm::slerp(q0, q1, u);
  const quat b = glm::mix(s0, s1, u);
  return glm::normalize(glm::mix(a, b, 2 * u * (1 - u)));
}

}  // namespace gestura
