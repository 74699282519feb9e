#include "gestura/sign/hamnosys_model.hpp"

#include <array>

namespace gestura::sign {
namespace {

// FingerSet's bits are the phonology's (finger_bit), so a set passes to it as it is.
static_assert(finger_bit(Finger::Thumb) == 1u && finger_bit(Finger::Pinky) == 1u << 4);

constexpr std::array<std::string_view, static_cast<std::size_t>(Site::fingers) + 1> kSiteNames{
    "head", "head top", "forehead", "eyebrows", "eyes", "nose", "nostrils", "ear", "earlobe", "cheek",
    "lips", "tongue", "teeth", "chin", "under chin", "neck", "shoulder top", "shoulders", "chest",
    "stomach", "below stomach", "neutral space", "upper arm", "elbow", "elbow inside", "lower arm",
    "wrist back", "wrist pulse", "thumb ball", "palm", "hand back", "thumb side", "pinky side", "fingers"};

}  // namespace

std::optional<Direction> merge_directions(Direction a, Direction b) {
  const DirectionComponents ca = components(a), cb = components(b);
  const std::int8_t pa[3] = {ca.vertical, ca.lateral, ca.sagittal};
  const std::int8_t pb[3] = {cb.vertical, cb.lateral, cb.sagittal};
  // Both must be two-axis diagonals agreeing on their one shared axis and covering all three.
  int shared = 0, covered = 0;
  for (int k = 0; k < 3; ++k) {
    if (pa[k] != 0 && pb[k] != 0) {
      if (pa[k] != pb[k]) return std::nullopt;
      ++shared;
    }
    if (pa[k] != 0 || pb[k] != 0) ++covered;
  }
  if (shared != 1 || covered != 3) return std::nullopt;
  DirectionComponents merged{static_cast<std::int8_t>(pa[0] ? pa[0] : pb[0]),
                             static_cast<std::int8_t>(pa[1] ? pa[1] : pb[1]),
                             static_cast<std::int8_t>(pa[2] ? pa[2] : pb[2])};
  return direction_from_components(merged);
}

SiteRegion site_region(Site s) {
  if (s <= Site::head_top) return SiteRegion::head;
  if (s <= Site::neck) return SiteRegion::face;
  if (s <= Site::below_stomach) return SiteRegion::trunk;
  if (s == Site::neutral_space) return SiteRegion::space;
  if (s <= Site::wrist_pulse) return SiteRegion::arm;
  if (s <= Site::pinky_side) return SiteRegion::hand;
  return SiteRegion::finger;
}

std::string_view site_name(Site s) { return kSiteNames[static_cast<std::size_t>(s)]; }

}  // namespace gestura::sign
