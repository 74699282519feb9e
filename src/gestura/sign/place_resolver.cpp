#include "gestura/sign/place_resolver.hpp"

#include <string>

#include "gestura/sign/hand_part.hpp"

namespace gestura {

namespace {

using sign::Site;

constexpr float kBesideOffset = 0.07f;     // hamlrbeside: beside the site, on the hand's side
constexpr float kFaceSideOffset = 0.045f;  // hamlrat at a central head site: its side (temple, mouth corner)
constexpr float kTrunkSideOffset = 0.09f;  // hamlrat at a central trunk site: its side (below the nipple)
constexpr float kFacingTolerance = 0.004f;  // hand points this much farther from a site than the nearest still face it
// Neutral space relative to the chest site: lower, in front, out to the hand's side (farther when
// both hands sign, so that they do not meet).
constexpr vec3 kNeutralSpace{0.08f, -0.07f, 0.25f};
constexpr float kNeutralSpaceBothHands = 0.13f;
const vec3 kChestFallback(0, 1.25f, 0.12f);  // an avatar without a chest site

// The side a hand works on: −X for the right hand (the signer's right), +X for the left.
float outward(Hand hand) { return hand == Hand::Right ? -1.0f : 1.0f; }

}  // namespace

PlaceResolver::PlaceResolver(const SigningRig& rig) : rig_(rig), scratch_(rig.rest) {}

std::optional<SurfacePoint> PlaceResolver::body_site(std::string_view name) const {
  const BodySite* s = find_site(rig_.sites, std::string(name));
  if (!s) return std::nullopt;
  SurfacePoint out = site_surface(*s, rig_.bind_model);
  const vec3 flat(out.normal.x, 0.0f, out.normal.z);
  if (glm::length(flat) > 0.3f) out.normal = glm::normalize(flat);
  return out;
}

SurfacePoint PlaceResolver::neutral_space(Hand hand, bool both_hands) const {
  const std::optional<SurfacePoint> chest = body_site("chest");
  const vec3 base = chest ? chest->point : kChestFallback;
  const float across = both_hands ? kNeutralSpaceBothHands : kNeutralSpace.x;
  return {base + vec3(outward(hand) * across, kNeutralSpace.y, kNeutralSpace.z), vec3(0, 0, 1)};
}

std::optional<SurfacePoint> PlaceResolver::other_hand_site(Hand other_hand, const HandState& other, Site site) const {
  const vec3 finger = other.orientation * vec3(0, 1, 0), palm = other.orientation * vec3(0, 0, 1);
  const vec3 thumb = hand_frame_from_vectors(finger, palm, other_hand).thumb_side;
  const float t = rig_.hand(other_hand).palm_half_thickness;
  const vec3& at = other.position;
  switch (site) {
    case Site::palm: return SurfacePoint{at + palm * t, palm};
    case Site::thumb_ball: return SurfacePoint{at + palm * t - finger * 0.03f + thumb * 0.02f, palm};
    case Site::hand_back: return SurfacePoint{at - palm * t, -palm};
    case Site::thumb_side: return SurfacePoint{at + thumb * 0.045f, thumb};
    case Site::pinky_side: return SurfacePoint{at - thumb * 0.045f, -thumb};
    case Site::fingers: return SurfacePoint{at + finger * 0.11f, palm};
    case Site::wrist_back: return SurfacePoint{at - finger * 0.07f - palm * t, -palm};
    case Site::wrist_pulse: return SurfacePoint{at - finger * 0.07f + palm * t, palm};
    case Site::lower_arm: return SurfacePoint{at - finger * 0.17f - palm * 0.02f, -palm};
    case Site::elbow:
    case Site::elbow_inside: return SurfacePoint{at - finger * 0.30f, -palm};
    case Site::upper_arm: return SurfacePoint{at - finger * 0.42f, -palm};
    default: return std::nullopt;
  }
}

SurfacePoint PlaceResolver::site(Hand hand, Site site, sign::Side side, bool on_other_hand, const HandState& other,
                                 bool both_hands) const {
  const sign::SiteRegion region = sign::site_region(site);
  if (site == Site::neutral_space) return neutral_space(hand, both_hands);
  if (on_other_hand || region == sign::SiteRegion::hand || region == sign::SiteRegion::finger ||
      (region == sign::SiteRegion::arm && other.active))
    if (const auto p = other_hand_site(other_hand(hand), other, site)) return *p;
  const std::string own = hand == Hand::Right ? "r_" : "l_";
  const std::string other_side = hand == Hand::Right ? "l_" : "r_";
  std::string name;
  switch (site) {
    case Site::head: case Site::forehead: name = "forehead"; break;
    case Site::head_top: name = "head_top"; break;
    case Site::eyebrows: name = "eyebrows"; break;
    case Site::eyes: name = side == sign::Side::centre ? "eyebrows" : own + "eye"; break;
    case Site::nose: case Site::nostrils: name = "nose"; break;
    case Site::ear: case Site::earlobe: name = own + "ear"; break;
    case Site::cheek: name = own + "cheek"; break;
    case Site::lips: case Site::tongue: case Site::teeth: name = "lips"; break;
    case Site::chin: name = "chin"; break;
    case Site::under_chin: name = "under_chin"; break;
    case Site::neck: name = "neck"; break;
    case Site::shoulder_top: name = own + "shoulder_top"; break;
    case Site::shoulders: name = "upper_chest"; break;
    case Site::chest: name = "chest"; break;
    case Site::stomach: name = "stomach"; break;
    case Site::below_stomach: name = "belly"; break;
    // Arm sites are on the other arm, as signers use them.
    case Site::upper_arm: name = other_side + "upper_arm"; break;
    case Site::elbow: case Site::elbow_inside: name = other_side + "elbow"; break;
    case Site::lower_arm: case Site::wrist_pulse: name = other_side + "forearm"; break;
    case Site::wrist_back: name = other_side + "wrist_back"; break;
    default: name = "chest"; break;
  }
  SurfacePoint p = body_site(name).value_or(neutral_space(hand, both_hands));
  if (site == Site::earlobe) p.point.y -= 0.02f;
  if (site == Site::eyes && side == sign::Side::centre) p.point.y -= 0.02f;
  if (side == sign::Side::beside) p.point.x += outward(hand) * kBesideOffset;
  // hamlrat at a site the body has once, in the middle (forehead, chin, chest): that site's own
  // side, toward the hand (the temple side of the forehead, the right of the chest). Sites the
  // body has twice (cheek, eye, ear, shoulder) were named with the hand's side above.
  if (side == sign::Side::dominant_side && name.rfind(own, 0) != 0)
    p.point.x += outward(hand) * (region == sign::SiteRegion::trunk ? kTrunkSideOffset : kFaceSideOffset);
  return p;
}

HandPoints PlaceResolver::hand_points(Hand hand, const HandState& state) {
  return planned_hand_points(rig_, hand, state, scratch_);
}

vec3 PlaceResolver::place_at(Hand hand, const HandState& state, const SurfacePoint& site, float gap) {
  // The part facing the site is found among the hand's ends (palm faces, fingertips, knuckles),
  // not its middle joints, which keep_out still keeps off the body. The anatomical thumb's base
  // joint stands 7 mm nearer the chest than its tip on a flat hand held edge-on: as the one nearest
  // point it became the contact, 5.6 cm below the thumb tip, and lifted the hand by as much.
  const HandPoints all = hand_points(hand, state);
  const std::span<const vec3> points(all.data(), kMiddleJointPoints);
  float nearest = 1e9f;
  for (const vec3& p : points) nearest = std::min(nearest, glm::dot(p, site.normal));
  vec3 contact(0.0f);
  int count = 0;
  for (const vec3& p : points)
    if (glm::dot(p, site.normal) < nearest + kFacingTolerance) contact += p, ++count;
  contact /= static_cast<float>(count);
  contact -= site.normal * (glm::dot(contact, site.normal) - nearest);  // on the nearest plane
  return site.point + site.normal * gap - contact;
}

vec3 PlaceResolver::place_part_at(Hand hand, const HandState& state, const SurfacePoint& site, float gap,
                                  const sign::SitePoint& part) {
  apply_hand_posture(rig_, hand, state.shape, scratch_);
  clamp_to_limits(rig_.skeleton(), scratch_);
  const auto on_hand = hand_part_site(rig_, hand, scratch_, state.shape, part);
  if (!on_hand) return place_at(hand, state, site, gap);
  return site.point + site.normal * gap -
         planned_wrist_rotation(rig_, hand, state) * (on_hand->point - rig_.hand(hand).palm_centre_local);
}

}  // namespace gestura
