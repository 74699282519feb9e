#pragma once
// The places a sign's notation names, found on one avatar: body sites (the chin, the left cheek,
// the chest beside the hand's side), neutral signing space, parts of the other hand, and where the
// palm centre must be so that the part of the hand that faces a place (or the part the notation
// names, "the index fingertip at the chin") is at it, at the distance the notation's proximity
// gives. The hand's own points are the ones the performer measures (hand_geometry.hpp).
#include <optional>
#include <string_view>

#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hand_geometry.hpp"

namespace gestura {

class PlaceResolver {
 public:
  // Contract: `rig` outlives the resolver.
  explicit PlaceResolver(const SigningRig& rig);

  // A body site by name (body_sites.hpp), approached horizontally where the site allows: a hand
  // signs in the space in front of (or beside) a site, not along a surface normal that may point
  // down (the chin) or up. Empty when the avatar has no such site.
  std::optional<SurfacePoint> body_site(std::string_view name) const;

  // Neutral signing space: in front of the lower chest, on the hand's own side; farther out to
  // the side when both hands sign.
  SurfacePoint neutral_space(Hand hand, bool both_hands) const;

  // A part of the other hand or its forearm (hand constellations, hand sites), for the other hand
  // in state `other`; empty for a site that is not on the hand or arm.
  std::optional<SurfacePoint> other_hand_site(Hand other_hand, const HandState& other, sign::Site site) const;

  // Where a notated site is for `hand`: on the other hand when the notation says so (or names a
  // part of a hand, or an arm site while the other hand signs), else on the body (sites the body
  // has twice on the hand's own side, arm sites on the other arm), shifted beside it or to its
  // side as `side` says. A site the avatar lacks falls back to neutral space.
  SurfacePoint site(Hand hand, sign::Site site, sign::Side side, bool on_other_hand, const HandState& other,
                    bool both_hands) const;

  // Palm-centre position that puts the part of the hand facing the site `gap` metres out from
  // its point: the hand's ends (palm faces, tips, knuckles) nearest the body along the site's
  // normal (averaged when several are about as near, like a flat palm) land on it.
  vec3 place_at(Hand hand, const HandState& state, const SurfacePoint& site, float gap);

  // Palm-centre position that puts a named part of the hand (HamNoSys "hamchin hamseqbegin
  // hamfingertip hamseqend": the fingertips at the chin) `gap` metres out from the site's point.
  // place_at for a part that is not on the hand.
  vec3 place_part_at(Hand hand, const HandState& state, const SurfacePoint& site, float gap, const sign::SitePoint& part);

  // The hand points of a state relative to its palm centre (hand_geometry.hpp's planned_hand_points).
  HandPoints hand_points(Hand hand, const HandState& state);

  const SigningRig& rig() const { return rig_; }

 private:
  const SigningRig& rig_;
  Pose scratch_;
};

}  // namespace gestura
