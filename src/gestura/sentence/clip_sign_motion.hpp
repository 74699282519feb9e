#pragma once
// A clip sign (a keyframed sign from the studio's timeline, lexicon/clip_sign.hpp) made ready for an
// utterance like a notated sign's cached citation form (sign_motion_cache.hpp): its hands' joint
// rotations sampled at the citation rate, and a plan read back from them by forward kinematics
// (where each palm is and how it is turned), so the utterance reaches the clip's first posture and
// leaves its last by the same transitions as any sign, on the one TwoHandTimeline. A hand the clip
// does not move stays out of it (it rests, or waits low in front, as for a one-handed sign). Its
// face channels, and the turns it gives the head, neck and torso (any joint outside the hands'
// chains), are laid over the utterance's at the sign's time (add_clip_sign_face, add_clip_sign_body).
// Made at places of the signing space (an agreement verb from one place to another, an index at a
// locus), its plan is changed as a notated sign's is and each sample's arm solved again to follow
// it, the fingers as recorded (clip_sign_in_space).
#include <memory>
#include <string_view>

#include "gestura/anim/clip.hpp"
#include "gestura/sentence/sign_motion_cache.hpp"

namespace gestura {

struct ClipSignMotion {
  CitationMotion motion;  // time 0 at the clip's start; movement() = the clip's duration
  Clip face;              // the clip's scalar channels only (visemes, expressions, brows)
  Clip body;              // rotations of the joints outside the hands' chains that the clip turns
                          // from rest (head, neck, spine): one track per joint, empty elsewhere
};

// A hand counts as moved by the clip when one of its joints turns this far from the skeleton's rest.
inline constexpr float kClipHandMovedDegrees = 3.0f;
// A joint outside the hands' chains counts as keyed by the clip when it turns this far from rest.
inline constexpr float kClipBodyMovedDegrees = 1.0f;

// Contract: `rig` is the avatar's the clip was made on. Throws gestura::Error naming `gloss` for a
// clip whose joints are not the rig's skeleton's, or one that moves neither hand.
std::unique_ptr<ClipSignMotion> clip_sign_motion(const Clip& clip, const SigningRig& rig, std::string_view gloss);

// The clip sign made at places of the signing space: `placed` is its plan changed by
// sentence/signing_space.hpp's in_space. Each sample's arm is solved again from the recorded one
// (cache.solve_from) to put the palm where and as `placed` has it; the fingers keep the recording.
std::unique_ptr<ClipSignMotion> clip_sign_in_space(const ClipSignMotion& recorded, const SignPlan& placed,
                                                   const SignMotionCache& cache);

// Where one clip sign sits in an utterance (as its CachedSignSpan): citation time
// c = clamp((t − moving) · tempo, 0, duration) on [start, end].
struct ClipSignFace {
  const Clip* face = nullptr;
  const Clip* body = nullptr;
  float start = 0.0f, moving = 0.0f, end = 0.0f, tempo = 1.0f;
};

// Seconds over which a clip sign's face fades in before its start and out after its end.
inline constexpr float kClipFaceFade = 0.12f;

// Adds the clip sign's face channels to `out`'s (added to what is there, kept in 0..1), keyed at
// `fps` over the sign and its fades; keys of `out` elsewhere are kept.
void add_clip_sign_face(const ClipSignFace& sign, float fps, Clip& out);

// Adds the clip sign's body turns to `out`'s rotations: at each time the utterance's rotation of the
// joint turned by the clip's turn from `skeleton`'s rest, faded in and out as the face is; keys of
// `out` elsewhere are kept.
void add_clip_sign_body(const ClipSignFace& sign, const Skeleton& skeleton, float fps, Clip& out);

}  // namespace gestura
