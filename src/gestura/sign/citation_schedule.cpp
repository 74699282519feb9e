#include "gestura/sign/citation_schedule.hpp"

namespace gestura {

namespace {

constexpr float kTouchGap = 0.0f;
constexpr float kCloseGap = 0.025f;
constexpr float kNearGap = 0.07f;
constexpr float kFarGap = 0.25f;
constexpr float kTrunkNearExtra = 0.05f;  // "near" the trunk is this much farther out

}  // namespace

float contact_gap(std::optional<sign::Proximity> proximity, sign::SiteRegion region) {
  if (!proximity) return region == sign::SiteRegion::trunk ? kNearGap + kTrunkNearExtra : kNearGap;
  switch (*proximity) {
    case sign::Proximity::touch:
    case sign::Proximity::brushing:
    case sign::Proximity::interlocked:
    case sign::Proximity::crossed: return kTouchGap;
    case sign::Proximity::close: return kCloseGap;
    case sign::Proximity::far: return kFarGap;
    case sign::Proximity::behind: return kCloseGap;
  }
  return kNearGap;
}

quat turn_hand(const quat& current, const TurnTarget& target, Hand hand) {
  const HandFrame now = hand_frame_from_vectors(current * vec3(0, 1, 0), current * vec3(0, 0, 1), hand);
  const vec3 finger = target.finger.value_or(now.finger);
  vec3 palm = now.palm;
  if (target.palm) {
    const auto frontal = palm_orientation_of(*target.palm);
    palm = frontal ? palm_normal(finger, *frontal) : direction_vector(*target.palm);
    if (target.palm_between) palm = glm::normalize(palm + *target.palm_between);
  }
  // Keep the palm perpendicular to the fingers.
  palm = palm - glm::dot(palm, finger) * finger;
  if (glm::length(palm) < 1e-3f) palm = glm::cross(finger, vec3(0, 1, 0.3f));
  return hand_frame_from_vectors(finger, glm::normalize(palm), hand).rotation;
}

}  // namespace gestura
