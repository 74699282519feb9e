#include "gestura/sign/phonology_direction.hpp"

#include <cmath>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

constexpr std::string_view kDirectionNames[kDirectionCount] = {
    "u",  "d",  "l",  "r",  "o",  "i",  "ul",  "ur",  "dl",  "dr",  "ol",  "or",  "il",
    "ir", "uo", "ui", "do", "di", "uol", "uor", "uil", "uir", "dol", "dor", "dil", "dir"};
constexpr std::string_view kPalmNames[kPalmOrientationCount] = {"u", "ur", "r", "dr", "d", "dl", "l", "ul"};

// Axis counts of a direction name: (+X left, +Y up, +Z out) each in {−1, 0, 1}.
glm::ivec3 axes_of(std::string_view letters) {
  glm::ivec3 a{0};
  for (char c : letters) {
    switch (c) {
      case 'u': a.y += 1; break;
      case 'd': a.y -= 1; break;
      case 'l': a.x += 1; break;
      case 'r': a.x -= 1; break;
      case 'o': a.z += 1; break;
      case 'i': a.z -= 1; break;
      default: return glm::ivec3{9};
    }
  }
  return a;
}

std::optional<Direction> direction_from_axes(glm::ivec3 a) {
  if (a == glm::ivec3{0}) return std::nullopt;
  for (std::size_t k = 0; k < kDirectionCount; ++k)
    if (axes_of(kDirectionNames[k]) == a) return static_cast<Direction>(k);
  return std::nullopt;
}

std::string_view strip_prefix(std::string_view name) {
  for (std::string_view prefix : {"hamextfinger", "hammove", "hamcircle", "hampalm"})
    if (name.substr(0, prefix.size()) == prefix) return name.substr(prefix.size());
  return name;
}

// Shortest rotation carrying +Z (fingers "o") onto the unit vector f. For f = −Z (fingers "i")
// the shortest arc is not unique; we turn about +Y (a horizontal swing of the forearm), so the
// up/down palm orientations keep their meaning.
quat carry_from_out(vec3 f) {
  const vec3 out{0.0f, 0.0f, 1.0f};
  if (glm::dot(out, f) < -1.0f + 1e-6f) return glm::angleAxis(kPi, vec3{0.0f, 1.0f, 0.0f});
  return glm::rotation(out, f);
}

HandFrame frame_from_orthonormal(vec3 finger, vec3 palm, Hand hand) {
  HandFrame frame;
  frame.finger = finger;
  frame.palm = palm;
  const vec3 local_x = glm::cross(finger, palm);
  frame.thumb_side = hand == Hand::Right ? local_x : -local_x;
  frame.rotation = glm::normalize(glm::quat_cast(mat3{local_x, finger, palm}));
  return frame;
}

}  // namespace

DirectionComponents components(Direction direction) {
  const glm::ivec3 a = axes_of(kDirectionNames[static_cast<std::size_t>(direction)]);
  return {static_cast<std::int8_t>(a.y), static_cast<std::int8_t>(a.x), static_cast<std::int8_t>(a.z)};
}

std::optional<Direction> direction_from_components(DirectionComponents c) {
  return direction_from_axes(glm::ivec3(c.lateral, c.vertical, c.sagittal));
}

vec3 direction_vector(Direction direction) {
  const glm::ivec3 a = axes_of(kDirectionNames[static_cast<std::size_t>(direction)]);
  return glm::normalize(vec3(a));
}

std::string_view to_string(Direction direction) { return kDirectionNames[static_cast<std::size_t>(direction)]; }

std::optional<Direction> parse_direction(std::string_view name) {
  name = strip_prefix(name);
  if (name.empty() || name.size() > 3) return std::nullopt;
  const glm::ivec3 a = axes_of(name);
  // Each axis may be named at most once ("uu" and "ud" are not directions).
  int letters = 0;
  for (int k = 0; k < 3; ++k) {
    if (a[k] < -1 || a[k] > 1) return std::nullopt;
    letters += a[k] != 0;
  }
  if (letters != static_cast<int>(name.size())) return std::nullopt;
  return direction_from_axes(a);
}

std::optional<Direction> combine(Direction a, Direction b) {
  // Axis by axis: an axis named by one symbol is taken from it; named by both it must agree
  // (ul + uo → uol); opposite components (u + dl) are not a combination.
  const glm::ivec3 x = axes_of(to_string(a)), y = axes_of(to_string(b));
  glm::ivec3 merged{0};
  for (int j = 0; j < 3; ++j) {
    if (x[j] != 0 && y[j] != 0 && x[j] != y[j]) return std::nullopt;
    merged[j] = x[j] != 0 ? x[j] : y[j];
  }
  return direction_from_axes(merged);
}

Direction mirror_left_right(Direction direction) {
  glm::ivec3 a = axes_of(to_string(direction));
  a.x = -a.x;
  return *direction_from_axes(a);
}

vec3 palm_reference_vector(PalmOrientation palm) {
  const glm::ivec3 a = axes_of(kPalmNames[static_cast<std::size_t>(palm)]);
  return glm::normalize(vec3(a));
}

std::string_view to_string(PalmOrientation palm) { return kPalmNames[static_cast<std::size_t>(palm)]; }

std::optional<PalmOrientation> parse_palm_orientation(std::string_view name) {
  name = strip_prefix(name);
  for (std::size_t k = 0; k < kPalmOrientationCount; ++k)
    if (name == kPalmNames[k]) return static_cast<PalmOrientation>(k);
  // Letter order is free ("lu" = "ul").
  if (name.size() == 2 && name[0] != name[1]) {
    const std::string swapped{name[1], name[0]};
    for (std::size_t k = 0; k < kPalmOrientationCount; ++k)
      if (swapped == kPalmNames[k]) return static_cast<PalmOrientation>(k);
  }
  return std::nullopt;
}

PalmOrientation mirror_left_right(PalmOrientation palm) {
  static constexpr PalmOrientation kMirror[kPalmOrientationCount] = {
      PalmOrientation::U, PalmOrientation::UL, PalmOrientation::L, PalmOrientation::DL,
      PalmOrientation::D, PalmOrientation::DR, PalmOrientation::R, PalmOrientation::UR};
  return kMirror[static_cast<std::size_t>(palm)];
}

std::optional<PalmOrientation> palm_orientation_of(Direction direction) {
  return parse_palm_orientation(to_string(direction));
}

vec3 palm_normal(vec3 finger, PalmOrientation palm) {
  const vec3 f = glm::normalize(finger);
  const vec3 reference = palm_reference_vector(palm);
  const vec3 projected = reference - glm::dot(reference, f) * f;
  // Over the 26 × 8 notated combinations the projection is either exactly zero or at least 0.5
  // long, so 0.2 separates "along the finger axis" cleanly.
  if (glm::length(projected) >= 0.2f) return glm::normalize(projected);
  const vec3 carried = carry_from_out(f) * reference;
  // The carried vector is orthogonal up to rounding; re-project so the frame is exact.
  return glm::normalize(carried - glm::dot(carried, f) * f);
}

HandFrame hand_frame(Direction finger, PalmOrientation palm, Hand hand) {
  const vec3 f = direction_vector(finger);
  return frame_from_orthonormal(f, palm_normal(f, palm), hand);
}

HandFrame hand_frame_from_vectors(vec3 finger, vec3 palm, Hand hand) {
  if (!is_finite(finger) || !is_finite(palm)) throw Error("hand frame: finger or palm vector is not finite");
  const float finger_length = glm::length(finger);
  if (finger_length < 1e-6f) throw Error("hand frame: finger direction is zero");
  const vec3 f = finger / finger_length;
  const vec3 p = palm - glm::dot(palm, f) * f;
  const float palm_length = glm::length(p);
  if (palm_length < 1e-4f * std::max(1.0f, glm::length(palm)))
    throw Error("hand frame: palm direction is zero or parallel to the finger direction");
  return frame_from_orthonormal(f, p / palm_length, hand);
}

HandFrame hand_frame_from_joints(vec3 wrist, vec3 index_knuckle, vec3 middle_knuckle, vec3 pinky_knuckle, Hand hand) {
  if (!is_finite(wrist) || !is_finite(index_knuckle) || !is_finite(middle_knuckle) || !is_finite(pinky_knuckle))
    throw Error("hand frame from joints: a joint position is not finite");
  const vec3 finger = middle_knuckle - wrist;
  const vec3 radial = index_knuckle - pinky_knuckle;
  if (glm::length(finger) < 1e-6f || glm::length(radial) < 1e-6f)
    throw Error("hand frame from joints: the wrist and knuckles coincide");
  // Local +X is the radial side for the right hand, the ulnar side for the left; +Z = X × Y.
  const vec3 local_x = hand == Hand::Right ? radial : -radial;
  const vec3 palm = glm::cross(local_x, finger);
  if (glm::length(palm) < 1e-3f * glm::length(finger) * glm::length(radial))  // sin(angle) < 1e-3
    throw Error("hand frame from joints: the knuckle line is parallel to the finger direction");
  return hand_frame_from_vectors(finger, palm, hand);
}

quat wrist_rotation_for(const HandFrame& target, const quat& reference_frame, const quat& reference_wrist) {
  return glm::normalize(target.rotation * glm::inverse(reference_frame) * reference_wrist);
}

}  // namespace gestura
