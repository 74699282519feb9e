#pragma once
// Spatial grammar, the performing half (docs/grammar.md): where the places of the signing space are
// on one avatar, and how a lexicon sign's citation plan is changed to use them.
//
// Places lie on a horizontal arc in front of the lower chest: the signer (1) at the chest, the
// addressee (2) straight ahead, third-person loci (3a, 3b, …) to the sides — 3a 40° to the signer's
// right, 3b 40° to the left, 3c and 3d 70° out, then round again. A pointing sign is turned so the
// fingers point at its place; an agreement verb's path is turned, stretched and moved so it runs
// from one place to the other; a plural pointing sign sweeps an arc over its places.
//
// Each change is a map of the plan in space: hand positions, turns and the movement paths'
// directions, so the sign keeps its handshape, its movement's shape and its timing.
#include <span>
#include <string>

#include "gestura/sign/sign_planner.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "gestura/text/gloss.hpp"

namespace gestura {

inline constexpr float kLocusReach = 0.40f;     // metres in front of the chest the places lie at
inline constexpr float kLocusSideDegrees = 40.0f;  // 3a, 3b: off straight ahead
inline constexpr float kLocusFarDegrees = 70.0f;   // 3c, 3d

// The direction of a place seen from the signer's chest: the yaw in radians (+ toward the avatar's
// left, +X), 0 straight ahead for the addressee. The signer's own place (1) has yaw 0 too.
float locus_yaw(Locus locus);

// Where a place is on this avatar: `reach` metres out from the chest at the place's yaw, at the
// height of the lower chest, where the hands sign. The signer's place (1) is just in front of the
// chest.
vec3 locus_point(const SigningRig& rig, Locus locus, float reach = kLocusReach);

// A pointing sign (IX, POSS) aimed at `locus`: turned about the vertical through the dominant
// hand so its fingers (their horizontal direction at the sign's end) point at the place, and
// moved a little toward the place's side.
SignPlan aimed_at(const SignPlan& citation, const SigningRig& rig, Locus locus);

// An agreement verb from place `from` to place `to`: the dominant hand's path (first position to
// last) turned, stretched and moved to run from the one place to the other; the other hand moves
// with it unstretched. A path that starts at the signer (from = 1) keeps its citation start.
SignPlan moved_between(const SignPlan& citation, const SigningRig& rig, Locus from, Locus to);

// A plural pointing sign over several places: the dominant hand points at the first place and
// sweeps in an arc to the last (one place: an arc of ±25° about it).
SignPlan swept_over(const SignPlan& citation, const SigningRig& rig, std::span<const Locus> places);

// Whether a gloss is signed at places its citation form does not have (a third-person locus, an
// agreement verb's two places, a plural arc), its cache key ("@3a", "3a→3b", "3a+3b"), and its
// citation plan changed accordingly (one of the three changes above, or the citation itself).
bool uses_space(const GlossToken& g);
std::string space_key(const GlossToken& g);
SignPlan in_space(const SignPlan& citation, const SigningRig& rig, const GlossToken& g);

}  // namespace gestura
