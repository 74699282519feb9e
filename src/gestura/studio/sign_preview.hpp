#pragma once
// The notation editor's preview: the draft performed on the studio's avatar, the parse error at its
// symbol, and the problems `gestura check` would report (lenient-parse notes, IK misses, a hand in
// the body, joint limits), each with the symbol or moment it belongs to so the UI can mark it.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/core/math.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "gestura/skeleton/skeleton.hpp"
#include "gestura/studio/sign_draft.hpp"

namespace gestura::studio {

struct PreviewProblem {
  std::string text;
  int symbol = -1;     // the notation symbol it is about, -1: none
  float time = -1.0f;  // seconds into the clip it is about, -1: none
};

struct SignPreview {
  std::optional<Clip> clip;                 // none when the notation does not parse or cannot be performed
  float sign_start = 0.0f, sign_end = 0.0f; // the signing part of the clip (without moving in from rest)
  std::optional<NotationError> error;       // why there is no clip
  std::vector<PreviewProblem> problems;
  double synthesis_ms = 0.0;                // parse + plan + perform, wall clock
};

// Never throws for bad notation: it becomes `error`. The draft's non-manual tiers are performed over
// the sign; a value the avatar cannot perform becomes a problem, not an error.
SignPreview preview_sign(const SignDraft& draft, const SigningRig& rig, float fps = 30.0f);

// How bent the fingers of one hand are: the sum over index, middle, ring and pinky of the angle
// (degrees) between the wrist's frame and the finger's distal phalanx. About 0 for a flat hand,
// several hundred for a fist. `model`: joint model matrices of a pose on `skeleton`; `side` 'r' or 'l'.
// Returns -1 when the skeleton lacks those joints.
float finger_flexion_degrees(const Skeleton& skeleton, std::span<const mat4> model, char side);

}  // namespace gestura::studio
