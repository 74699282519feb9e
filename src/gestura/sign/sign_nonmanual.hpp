#pragma once
// Performing the non-manual tiers of a SiGML sign (<hamnosys_nonmanual>: hnm_head, hnm_eyebrows,
// hnm_mouthpicture, ...) on the avatar, with the face layer's machinery: morph channels through
// face actions, head movements through head actions (vc4 + skullbase), shoulders, body and eyes
// through joint offsets, the eyes aimed at a hand every frame, mouth pictures (SAMPA) through the
// viseme track. Everything enters and leaves with the §5.2.5 sinusoidal ramps.
//
// Timing: SiGML's <hamnosys_nonmanual> gives no timing of its own, and JASigning performs several
// elements of one tier together, so every tier value spans the sign's articulation [start, end]
// (first posture reached → end of the final hold). The gestural form's tiers are sequences: a
// value spans its share of the sign (NonManual::from, to). Mouth pictures and spoken mouth gestures start
// with the sign and share its span as mouthing does, but never run slower than about 6–7 phonemes
// a second: in a long sign the word is said at the start and the mouth rests afterwards.
//
// Values (the ViSiCAST/eSIGN SiGML tag sets; "left"/"right" are the signer's):
//   shoulder   UL UR UB raised, HL HR HB hunched forward, SL SR SB shrugged once (sternoclaviculars)
//   body       RL RR rotated, TL TR tilted sideways, TF TB tilted forwards/back, SI sigh, HE heave,
//              ST straight, RD rounded (lumbar and thoracic spine)
//   head       NO nod, SH shake, SL SR turned, TL TR tilted, NF NB tilted forwards/back, PF PB pushed
//              forwards/back, LI turned with the eye gaze (by half a fixed direction; at a hand,
//              by what is beyond the eyes' own range)
//   eye gaze   AD FR NO ahead, UP DN LE RI LU LD RU RD (and UL UR DL DR), HD at the hands (between
//              them when both are up), HI at the dominant hand, HC at the non-dominant hand, RO rolling
//   eyebrows   RB raised, RL RR one raised, FU furrowed
//   eyelids    WB WL WR wide, SB SL SR narrowed, CB CL CR closed, TB TL TR shut tight, BB a blink at the end
//   nose       WR wrinkled (no nose morph: brows drawn down and eyes narrowed, as the wrinkle pulls
//              them); TW twitching and WI widened nostrils need nostril shapes: warned, not performed
//   cheeks     the cheek mouth gestures C01–C13
//   mouth gesture  HamNoSys mouth gesture codes D01–D09 (teeth), J01–J04 (jaw), L01–L35 (lips),
//              C01–C13 (cheeks), T01–T17 (tongue): sounds ("prrr", "bam") as SAMPA through the
//              visemes, shapes (pursed lips, puffed cheeks, tongue out) as morph weights
//   mouth picture  SAMPA (face/sampa.hpp) → visemes, jaw and lip rounding
// Anything else is reported with its XML line and skipped.
#include <span>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/face/face_action.hpp"
#include "gestura/face/head_motion.hpp"
#include "gestura/face/joint_offsets.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

struct NonManualWarning {
  int line = 0;  // XML line of the tier element
  std::string message;
};

// The eyes following one hand over [start, end] at full weight between §5.2.5 ramps; with
// `both_hands`, the point between the palms whenever the other hand is up from rest too.
// With `with_head` (head tier LI) the head joins for the part beyond the eyes' own range, as in
// fingerspelling (face/eye_aim.hpp).
struct HandGaze {
  Hand hand = Hand::Right;
  float start = 0.0f, end = 0.0f;
  bool both_hands = false;
  bool with_head = false;
};

struct SignNonManualActions {
  std::vector<face::FaceAction> face;    // morph channels and jaw_open
  std::vector<face::HeadAction> head;    // vc4 + skullbase
  std::vector<face::JointOffset> joints; // clavicles, spine, neck, eyes, jaw sideways
  std::vector<HandGaze> gaze;
  std::vector<NonManualWarning> warnings;
  int values = 0;  // tier values read (empty tags are not values)
  int mapped = 0;  // values performed, exactly or by the nearest shape the avatar has
};

// The actions of the tiers over the sign's span [start, end] (seconds). Never throws for unknown
// values (they become warnings); throws gestura::Error for non-finite or reversed times.
SignNonManualActions plan_sign_nonmanuals(std::span<const sign::NonManual> tiers, float start, float end);

// Aims both eyeball joints at the hand's palm centre (face/eye_aim.hpp, the aiming the fingerspelling
// gaze uses too), blended in by each gaze's ramps, keyed at `fps` and at the ramp steps (the clip's
// arm tracks give the hand's position). Replaces the eyeball tracks. Eyes only, within their limits,
// unless the gaze is `with_head`: HamNoSys writes the head on its own tier (hnm_head LI: turned with
// the eye gaze), so the head does not join uninvited as it does in fingerspelling, where nothing
// else says what the head does. A joining head's turn is added to vc4 and skullbase. Returns false
// (and writes nothing) when the skeleton has no eyeball joints; throws gestura::Error when a head
// that joins has no vc4/skullbase.
bool write_hand_gaze(std::span<const HandGaze> gaze, const SigningRig& rig, float fps, Clip& clip);

// plan_sign_nonmanuals, then everything written into the clip (face channels, head, jaw from
// jaw_open, hand gaze, joint offsets). Returns the warnings, including joints the avatar lacks.
std::vector<NonManualWarning> add_sign_nonmanuals(std::span<const sign::NonManual> tiers, float start, float end,
                                                  const SigningRig& rig, float fps, Clip& clip);

}  // namespace gestura
